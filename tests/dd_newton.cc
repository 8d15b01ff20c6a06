// DESCRIPTION: Solver = dd-newton (semismooth Newton on the contact pressure,
// CG with one set of body solves per iteration) gives the monolithic
// solver's penalty solution for c = 1e-8, 1e-3 and 1 (and the closed form
// with the pressure on the nodes of S_1), needs about as many
// body solves on a mesh 4 times finer, solves exact contact directly (nodal
// multipliers) to the closed form, and an augmented Lagrangian that stops
// short is reported; nested iteration needs two Newton steps per level;
// both bodies precondition exact contact where their zone meshes nest
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const std::string newton = "Contact solver/Solver=dd-newton";

  unsigned int
  body_solve_sets(const Simulation &s)
  {
    return s.get_contact_solver().counts().body_solve_sets;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  const std::string uniaxial = source_dir + "/prm/stability/uniaxial.prm";

  // 1. The same penalised problem (16) as the monolithic Newton solver, on
  //    non-matching meshes (triangles on quadrilaterals), from the stiff to
  //    the soft penalty. dd-newton stops at ||Phi||_W <= 1e-10 of the
  //    initial overlap; the displacement error is that times the condition
  //    of S on its range (the zone's H/h ~ 10 here). The monolithic solver
  //    is exact on its final active set up to the round-off of a system
  //    whose condition grows like 1/c: at c = 1e-8 it is 3e-9 off the closed
  //    form (doc/stability.md). 1e-8 covers both.
  for (const std::string c : {"1e-8", "1e-3", "1"})
  {
    const std::vector<std::string> common = {
      "Output directory=dd_newton_output",
      "Contact pair S/Penalty=" + c,
      "Contact solver/Tolerance=1e-10"};
    const auto reference =
      run_scene(uniaxial, common, {"Contact solver/Solver=monolithic"});
    const auto solution = run_scene(uniaxial, common, {newton});
    const auto counts   = solution->get_contact_solver().counts();
    std::cout << "c = " << c << ": force " << std::setprecision(12)
              << contact_force(*solution) << " against "
              << contact_force(*reference) << std::setprecision(6) << "; "
              << counts.body_solve_sets << " sets of body solves, "
              << counts.newton_steps << " Newton steps, "
              << counts.krylov_iterations << " CG iterations" << std::endl;
    check("c = " + c + ": force equals the monolithic solver's",
          relative(contact_force(*solution), contact_force(*reference)),
          1e-8);
    check("c = " + c + ": displacements equal the monolithic solver's",
          displacement_difference(*solution, *reference),
          1e-8);
    check(solution->summary().at("body_solve_sets") == counts.body_solve_sets &&
            solution->summary().at("contact_solver") == "dd-newton",
          "c = " + c + ": summary.json has the counts");

    // The pressure on the nodes of S_1 (Contact pressure = nodes): the
    // uniform pressure of the uniaxial scene makes the averaged gap the
    // pointwise one, so the penalised closed form
    // p = Delta / ((1 - nu^2) (H1 / E1 + H2 / E2) + theta) holds exactly,
    // theta = c H1 / E1.
    const auto nodal = run_scene(
      uniaxial, common, {newton, "Contact solver/Contact pressure=nodes"});
    const double L       = 4;
    const double p_exact = uniaxial_pressure(std::stod(c));
    std::cout << "c = " << c << ", pressure on the nodes: force "
              << std::setprecision(12) << contact_force(*nodal) << " against "
              << p_exact * L << std::setprecision(6) << "; "
              << body_solve_sets(*nodal) << " sets of body solves" << std::endl;
    check("c = " + c + ", nodes: force equals the closed form",
          relative(contact_force(*nodal), p_exact * L),
          1e-9);
  }

  // 2. The counts do not grow with the mesh: the paper's scene at c = 0.05
  //    on the coarse meshes and with both bodies refined twice more (h / 4).
  {
    std::vector<unsigned int> sets;
    for (const unsigned int r : {0u, 2u})
    {
      const auto sim = run_scene(
        source_dir + "/prm/paper_two_bodies.prm",
        {"Output directory=dd_newton_output",
         "Adaptation/Mode=none",
         "Contact solver/Tolerance=1e-8",
         newton},
        {"Body omega1/Mesh/Initial refinement=" + std::to_string(1 + r),
         "Body omega2/Mesh/Initial refinement=" + std::to_string(r)});
      sets.push_back(body_solve_sets(*sim));
      std::cout << "paper scene, refinement +" << r << ": " << sets.back()
                << " sets of body solves, force " << contact_force(*sim)
                << std::endl;
    }
    check(sets[1] <= 1.5 * sets[0] && sets[0] <= 1.5 * sets[1],
          "body solves on meshes h and h/4 within a factor 1.5");
  }

  // 3. Exact contact (Contact pair S/Formulation = exact selects it; dd-newton
  //    solves it directly with nodal multipliers, theta = 0, no Uzawa
  //    update). The uniaxial scene's exact pressure is uniform,
  //    p = Delta / ((1 - nu^2) (H1 / E1 + H2 / E2)), which the linear
  //    elements hold exactly (doc/verification.md): the force p L is exact
  //    up to the Newton tolerance 1e-10 times the condition of S (~10).
  //    Whatever the penalty: c = 100 (where the Uzawa loop stalls, item 4)
  //    gives the same.
  for (const std::string c : {"0.05", "100"})
  {
    const auto sim = run_scene(
      uniaxial,
      {"Output directory=dd_newton_output", newton},
      {"Contact pair S/Formulation=exact", "Contact pair S/Penalty=" + c});
    const double L       = 4;
    const double p_exact = uniaxial_pressure(0.);
    const auto   state   = sim->get_contact_solver().contact_state(0);
    std::cout << "exact contact, c = " << c << ": force "
              << std::setprecision(12) << contact_force(*sim) << " against "
              << p_exact * L << ", peak " << state.max_pressure
              << std::setprecision(6) << "; "
              << sim->get_contact_solver().n_uzawa_updates()
              << " Uzawa updates, " << body_solve_sets(*sim)
              << " sets of body solves" << std::endl;
    check("exact contact, c = " + c + ": force equals the closed form",
          relative(contact_force(*sim), p_exact * L),
          1e-9);
    check("exact contact, c = " + c + ": peak pressure equals the closed form",
          relative(state.max_pressure, p_exact),
          1e-9);
    check(sim->get_contact_solver().n_uzawa_updates() == 0 &&
            sim->summary().at("status") == "converged",
          "exact contact, c = " + c + ": converged without Uzawa updates");
  }

  // 4. No silent failure: at c = 100 each Uzawa update removes about 2 % of
  //    the penetration, so 30 updates leave most of it. The solvers with a
  //    Uzawa loop must stop with a DivergenceError naming the augmented
  //    Lagrangian, and never report "converged" (dd-newton converged to
  //    exact contact above).
  for (const std::string solver : {"dd", "monolithic"})
  {
    const std::string message = error_message<DivergenceError>(
      [&]
      {
        run_scene(uniaxial,
                  {"Output directory=dd_newton_output"},
                  {"Contact solver/Solver=" + solver,
                   "Contact pair S/Penalty=100",
                   "Contact pair S/Formulation=exact"});
      });
    std::cout << solver << ", c = 100: " << message.substr(0, 120) << "..."
              << std::endl;
    check(message_names(message, {"augmented Lagrangian stopped", "stalled"}),
          solver + ": an augmented Lagrangian that stops short is reported");
  }

  // 5. Nor at the floor of pointwise contact on non-matching meshes: on the
  //    coarse paper scene the Uzawa loop of the DD stops at 9.7e-4 of the
  //    approach; asked for 2e-4 it must say "stalled" and name dd-newton.
  {
    const std::string message = error_message<DivergenceError>(
      [&]
      {
        run_coarse_paper_scene(source_dir,
                               "dd_newton_output",
                               1,
                               {"Adaptation/Mode=none"},
                               {"Contact pair S/Formulation=exact",
                                "Contact solver/Uzawa/Tolerance=2e-4"});
      });
    std::cout << "dd, paper scene, Uzawa tolerance 2e-4: "
              << message.substr(0, 160) << "..." << std::endl;
    check(
      message_names(message, {"no longer decreases", "stalled", "dd-newton"}),
      "the floor of pointwise contact above the Uzawa tolerance is reported");
  }
  // 6. Nested iteration (Mode = uniform from a coarse mesh): the nodal
  //    multipliers move to the refined zone by linear interpolation, so
  //    the Newton method on the refined mesh needs about as many steps as a
  //    phase that is already settled (2 here; the piecewise constant
  //    transfer needed 5 at r = 5) and ends at the direct solve's answer on
  //    the same mesh (both to Tolerance = 1e-10).
  {
    const std::vector<std::string> exact = {"Output directory=dd_newton_output",
                                            "Contact pair S/Formulation=exact",
                                            "Contact solver/Tolerance=1e-10",
                                            newton,
                                            "Adaptation/Bodies=omega1, omega2",
                                            "Adaptation/Max level=12"};
    const auto direct = run_scene(source_dir + "/prm/paper_two_bodies.prm",
                                  exact,
                                  {"Adaptation/Mode=none",
                                   "Body omega1/Mesh/Initial refinement=2",
                                   "Body omega2/Mesh/Initial refinement=2"});
    const auto nested = run_scene(source_dir + "/prm/paper_two_bodies.prm",
                                  exact,
                                  {"Adaptation/Mode=uniform",
                                   "Adaptation/Max cycles=1",
                                   "Body omega1/Mesh/Initial refinement=1",
                                   "Body omega2/Mesh/Initial refinement=1"});
    // The first level of the nested run is the direct solve at r = 1.
    const unsigned int coarse_steps =
      run_scene(source_dir + "/prm/paper_two_bodies.prm",
                exact,
                {"Adaptation/Mode=none",
                 "Body omega1/Mesh/Initial refinement=1",
                 "Body omega2/Mesh/Initial refinement=1"})
        ->get_contact_solver()
        .counts()
        .newton_steps;
    const unsigned int fine_steps =
      nested->get_contact_solver().counts().newton_steps - coarse_steps;
    const double difference =
      std::abs(contact_force(*nested) - contact_force(*direct)) /
      contact_force(*direct);
    std::cout << "nested iteration r = 1 -> 2: " << coarse_steps << " + "
              << fine_steps << " Newton steps (direct at r = 2: "
              << direct->get_contact_solver().counts().newton_steps
              << "), force difference " << difference << std::endl;
    check(fine_steps <= 2, "at most 2 Newton steps on the refined mesh");
    check(difference < 1e-8, "the direct solve's force on the refined mesh");
  }
  // 7. A stack of three bodies (prm/three_bodies.prm): the plate is body 2
  //    of one pair and body 1 of the other, and its preconditioning solve
  //    holds its upper zone at the active nodes. Exact contact and the
  //    nodal penalty at c = 1e-8 then take at most 40 sets of body solves
  //    (the target of doc/contact-solvers.md; 61 and 59 without the held
  //    zone).
  for (const std::string mode : {"exact", "c = 1e-8"})
  {
    std::vector<std::string> overrides = {"Output directory=dd_newton_output",
                                          "Contact solver/Tolerance=1e-8"};
    if (mode == "exact")
      overrides.insert(overrides.end(),
                       {"Contact pair punch_on_plate/Formulation=exact",
                        "Contact pair plate_on_base/Formulation=exact"});
    else
      overrides.insert(overrides.end(),
                       {"Contact solver/Contact pressure=nodes",
                        "Contact pair punch_on_plate/Penalty=1e-8",
                        "Contact pair plate_on_base/Penalty=1e-8"});
    const auto sim =
      run_scene(source_dir + "/prm/three_bodies.prm", {newton}, overrides);
    std::cout << "three bodies, " << mode << ": " << body_solve_sets(*sim)
              << " sets of body solves" << std::endl;
    check(body_solve_sets(*sim) <= 40,
          "three bodies, " + mode + ": at most 40 sets of body solves");
  }
  // 8. Who preconditions exact contact (RobinPreconditioner): both bodies
  //    where every vertex of S_1 is a vertex of S_2 (the zone meshes of the
  //    paper scene nest: Omega_1 as fine as Omega_2, or coarser), body 1
  //    alone where Omega_2 is coarser (its trace misses every other node of
  //    S_1). All three converge. (On the nested meshes both bodies take
  //    fewer sets than body 1 alone: triangles on quadrilaterals,
  //    doc/contact-solvers.md section 5, 10 against 12 at r = 2.)
  struct Meshes
  {
    unsigned int r_1, r_2, both;
  };
  for (const Meshes m : {Meshes{1, 1, 1}, Meshes{0, 1, 1}, Meshes{1, 0, 0}})
  {
    const std::string name =
      "exact contact, Omega_1 at r = " + std::to_string(m.r_1) +
      ", Omega_2 at r = " + std::to_string(m.r_2);
    const auto sim = run_scene(
      source_dir + "/prm/paper_two_bodies.prm",
      {"Output directory=dd_newton_output", newton, "Adaptation/Mode=none"},
      {"Contact pair S/Formulation=exact",
       "Body omega1/Mesh/Initial refinement=" + std::to_string(m.r_1),
       "Body omega2/Mesh/Initial refinement=" + std::to_string(m.r_2)});
    const auto counts = sim->get_contact_solver().counts();
    std::cout << name << ": " << counts.pairs_preconditioned_by_both
              << " pair preconditioned by both bodies, "
              << counts.body_solve_sets << " sets of body solves" << std::endl;
    check(
      counts.pairs_preconditioned_by_both == m.both,
      name + ": " +
        (m.both ? "both bodies precondition" : "body 1 alone preconditions"));
    check(sim->summary().at("status") == "converged", name + ": converged");
  }
  return report();
}
