// DESCRIPTION: the combined algorithm (Fig. 2) on a coarse paper scene:
// refinement concentrates at the ends of the contact zone, the adapted mesh
// stays one-irregular, the point displacement moves toward the converged
// value as delta decreases, the nested loop agrees, and scenes that do not
// need a BEM never build one
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** The paper's scene on a coarse start mesh (Omega_2: 16 x 4 cells,
   * h = 0.25), adapted by the given overrides. */
  std::unique_ptr<Simulation>
  run(const std::string &source_dir, const std::vector<std::string> &overrides)
  {
    return run_coarse_paper_scene(source_dir,
                                  "combined_output",
                                  0,
                                  {"Adaptation/Bodies=omega2",
                                   "Adaptation/Estimator=fem-bem-scaled",
                                   "Adaptation/Max level=5"},
                                  overrides);
  }

  double
  u2_at_point(const Simulation &sim)
  {
    return sim.summary().at("points").at(0).at("u").at(1).get<double>();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // The converged value of u_2(0.5, 0.75): the same scene on a fine
  // uniform mesh (h = 1/32), whose own discretisation error is about a
  // quarter of the coarsest adaptive run's.
  const auto reference =
    run(source_dir,
        {"Adaptation/Mode=none", "Body omega2/Mesh/Initial refinement=3"});
  const double u_ref = u2_at_point(*reference);
  std::cout << "reference u_2(0.5, 0.75) = " << u_ref << std::endl;

  // 1. Combined algorithm with two thresholds.
  std::vector<double> errors;
  for (const std::string delta : {"0.1", "0.05"})
  {
    const auto sim = run(
      source_dir, {"Adaptation/Mode=combined", "Adaptation/Delta=" + delta});
    const auto  &tria = sim->get_bodies()[1]->get_triangulation();
    const auto  &json = sim->summary();
    const double u2   = u2_at_point(*sim);
    errors.push_back(std::abs(u2 - u_ref));
    std::cout << "delta = " << delta << ": " << tria.n_active_cells()
              << " cells, " << json.at("adaptation_cycles").get<double>()
              << " adaptation steps, " << json.at("dd_iterations").get<double>()
              << " DD iterations, u_2 = " << u2 << std::endl;

    check(json.at("adaptation_cycles").get<double>() > 0,
          "the mesh was adapted");
    check(one_irregular(tria), "adapted mesh is one-irregular");

    // Where the refinement went: the finest cells lie at the ends of the
    // contact area x1 = +-a on S, where the pressure has its square-root
    // edge, or at the ends of the clamped bottom, where the Dirichlet-
    // Neumann junction makes the exact stress singular; most at the
    // contact edges. "At" means within 0.4 (1.6 cells of the start mesh)
    // on S and within 0.3 of the clamped corners.
    const double a = json.at("contact").at(0).at("half_width").get<double>();
    int          max_level = 0;
    for (const auto &cell : tria.active_cell_iterators())
      max_level = std::max(max_level, cell->level());
    unsigned int finest = 0, at_contact_edges = 0, at_clamp_ends = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->level() == max_level)
      {
        ++finest;
        const auto c = cell->center();
        at_contact_edges += (c[1] > 0.75 && std::abs(std::abs(c[0]) - a) < 0.4);
        at_clamp_ends += (c[1] < 0.3 && std::abs(std::abs(c[0]) - 2.) < 0.3);
      }
    std::cout << "  half-width a = " << a << "; finest level " << max_level
              << ": " << finest << " cells, " << at_contact_edges
              << " within 0.4 of (+-a, 1), " << at_clamp_ends
              << " within 0.3 of (+-2, 0)" << std::endl;
    check(max_level > 0 && at_contact_edges + at_clamp_ends == finest,
          "finest cells at the contact edges or the clamped corners");
    check(at_contact_edges >= finest / 2,
          "at least half of them at the contact edges");
  }
  check(errors[1] < errors[0],
        "u_2(0.5, 0.75) moves toward the converged value as delta decreases");

  // 2. The classical nested loop reaches the same mesh-converged answer
  //    class: its error is of the same size as the combined one.
  {
    const auto sim =
      run(source_dir, {"Adaptation/Mode=nested", "Adaptation/Delta=0.05"});
    const double e = std::abs(u2_at_point(*sim) - u_ref);
    std::cout << "nested, delta = 0.05: error " << e << " (combined "
              << errors[1] << ")" << std::endl;
    check(e < 2 * errors[1] + 1e-12 && errors[1] < 2 * e + 1e-12,
          "nested and combined errors agree within a factor 2");
  }

  // 3. Pay only for what is needed: Kelly adaptation builds no BEM.
  {
    const auto sim = run(source_dir,
                         {"Adaptation/Mode=nested",
                          "Adaptation/Estimator=kelly",
                          "Adaptation/Marking=fraction",
                          "Adaptation/Max cycles=1"});
    check(sim->get_adaptations().size() == 1 &&
            sim->get_adaptations()[0]->fem_bem() == nullptr,
          "Kelly adaptation has no BEM");
    check(!sim->summary().at("timings").contains("BEM setup (assembly, LU)"),
          "and no BEM timings");
    const auto plain = run(source_dir, {"Adaptation/Mode=none"});
    check(plain->get_adaptations().empty() &&
            !plain->summary().contains("adaptation_cycles"),
          "a scene that does not adapt keeps no estimator");
  }

  return report();
}
