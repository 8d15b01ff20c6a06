// DESCRIPTION: the augmented Lagrangian (Uzawa) with every solver and
// adaptation mode: the uniaxial closed form p = (Delta - overlap)/C on fixed,
// uniformly refined and combined runs, by DD and monolithic Newton; the DD
// and Newton agree on the adaptively refined paper scene
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const std::string al = "Contact pair S/Formulation=exact";

  /**
   * prm/stability/uniaxial.prm with the augmented Lagrangian: on S the
   * pressure is uniform and the approach of the two blocks is C p, C =
   * (1 - nu^2)(H1/E1 + H2/E2). Uzawa drives the overlap Delta - C p to zero
   * by lambda <- -p (the error contracts by theta/(theta + C) = 0.027 per
   * update); the reported pressure must be the one of the reported
   * overlap, p = (Delta - overlap)/C, to the DD tolerance, and the overlap
   * must be within the Uzawa tolerance of the approach. Returning the
   * pressure of a multiplier that the iterate never saw (the error this
   * test was written for) is off by (C/theta) overlap/Delta, ~36 times the
   * tolerance.
   */
  void
  check_uniaxial(const std::string              &scene_file,
                 const std::vector<std::string> &overrides,
                 const std::string              &label,
                 const unsigned int              refinements = 0)
  {
    const double Delta = 1.366e-3, E = 2.1e5, nu = 0.3, H = 1, L = 4;
    const double C            = (1 - nu * nu) * (H / E + H / E);
    const double al_tolerance = 1e-3; // the default "Uzawa tolerance"

    const auto sim =
      run_scene(scene_file,
                {"Output directory=augmented_lagrangian_output", al},
                overrides);
    const auto   state   = sim->get_contact_solver().contact_state(0);
    const double p       = state.force_1.norm() / L;
    const double overlap = state.max_penetration;
    std::cout << label << ": p = " << p << ", theta = 0 closed form "
              << Delta / C << ", overlap " << overlap / Delta
              << " of the approach, "
              << sim->get_contact_solver().n_uzawa_updates() << " Uzawa updates"
              << std::endl;
    if (refinements > 0)
    {
      const auto &omega2 = sim->get_bodies()[1]->get_triangulation();
      check(omega2.n_levels() == refinements + 1,
            label + ": Omega_2 was refined " + std::to_string(refinements) +
              " times");
    }
    check(sim->get_contact_solver().n_uzawa_updates() >= 1,
          label + ": the Uzawa loop ran");
    check(overlap <= al_tolerance * Delta,
          label + ": overlap within the Uzawa tolerance of the approach");
    // The DD stops at a relative residual of 1e-10 with a condition of
    // about 40: the pressure is right to ~1e-8; 1e-7 leaves room.
    check(relative(p, (Delta - overlap) / C) < 1e-7,
          label + ": p = (Delta - overlap)/C to 1e-7");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  const std::string uniaxial = source_dir + "/prm/stability/uniaxial.prm";

  // 1. Fixed meshes: the DD and the monolithic Newton solver.
  check_uniaxial(uniaxial, {}, "DD, fixed mesh");
  check_uniaxial(
    uniaxial, {"Contact solver/Solver=monolithic"}, "monolithic, fixed mesh");

  // 2. Uniform refinement of Omega_2 (nested): the contact points of the
  //    common refinement of S move, the multipliers follow them, and the
  //    Uzawa loop starts afresh on the new mesh.
  for (const std::string solver : {"dd", "monolithic"})
    check_uniaxial(uniaxial,
                   {"Contact solver/Solver=" + solver,
                    "Adaptation/Mode=uniform",
                    "Adaptation/Bodies=omega2",
                    "Adaptation/Max cycles=2"},
                   solver + ", uniform refinement",
                   2);

  // 3. The combined algorithm: one DD step per cycle, refining a fixed
  //    fraction of Omega_2 by Kelly twice; the Uzawa phases run inside the
  //    combined loop.
  check_uniaxial(uniaxial,
                 {"Adaptation/Mode=combined",
                  "Adaptation/Bodies=omega2",
                  "Adaptation/Estimator=kelly",
                  "Adaptation/Marking=fraction",
                  "Adaptation/Fraction=0.3",
                  "Adaptation/Max cycles=2"},
                 "DD, combined",
                 2);

  // 4. The paper's scene refined adaptively by the nested loop: the DD and
  //    the Newton solver reach the same meshes and the same answer. The DD
  //    stops at a residual of 1e-10; 1e-6 leaves room for the condition of
  //    the contact problem (c = 0.05) and the Uzawa loop on each mesh.
  {
    const auto run = [&](const std::string &solver)
    {
      return run_coarse_paper_scene(source_dir,
                                    "augmented_lagrangian_output",
                                    0,
                                    {al,
                                     "Adaptation/Mode=nested",
                                     "Adaptation/Estimator=fem-bem-scaled",
                                     "Adaptation/Delta=0.1",
                                     "Adaptation/Max level=4"},
                                    {"Contact solver/Solver=" + solver});
    };
    const auto dd       = run("dd");
    const auto newton   = run("monolithic");
    const auto f_dd     = dd->get_contact_solver().contact_state(0);
    const auto f_newton = newton->get_contact_solver().contact_state(0);
    const auto cells    = [](const Simulation &s)
    { return s.get_bodies()[1]->get_triangulation().n_active_cells(); };
    std::cout << "paper scene, nested: force " << f_dd.force_1.norm()
              << " (DD) and " << f_newton.force_1.norm() << " (Newton), "
              << cells(*dd) << " and " << cells(*newton)
              << " cells, max overlap " << f_dd.max_penetration << std::endl;
    check(cells(*dd) == cells(*newton) && cells(*dd) > 64,
          "paper scene: DD and Newton refine alike");
    check(relative(f_dd.force_1.norm(), f_newton.force_1.norm()) < 1e-6,
          "paper scene: the DD's force equals the Newton solver's to 1e-6");
    check(f_dd.max_penetration < 1e-3 * 1.366e-3,
          "paper scene: overlap below 1e-3 of the approach");
  }

  return report();
}
