// DESCRIPTION: the monolithic semismooth Newton solver with the pressure on
// the nodes of S_1 (Contact pressure = nodes) gives the nodal penalised
// closed form on the uniaxial scene for c = 1e-8, 1e-3 and 1, equals
// dd-newton with nodes on the coarse paper scene for c = 1e-7, 1e-4 and
// 0.05 in force and peak pressure, and needs few Newton steps at c = 1e-7;
// with the points, damping settles the active set that cycled at c = 1e-7
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const std::string monolithic = "Contact solver/Solver=monolithic";
  const std::string dd_newton  = "Contact solver/Solver=dd-newton";
  const std::string nodes      = "Contact solver/Contact pressure=nodes";

  ContactState
  state(const Simulation &s)
  {
    return s.get_contact_solver().contact_state(0);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // 1. The uniaxial scene: a uniform pressure makes the averaged gap of
  //    every node the pointwise one, and the linear elements hold the
  //    uniaxial displacement exactly, so the nodal penalty gives the
  //    penalised closed form p = Delta / ((1 - nu^2)(H1/E1 + H2/E2) +
  //    theta), theta = c H1 / E1, force p L. The Newton method is exact on
  //    its final active set (all nodes), up to the round-off of the direct
  //    solve.
  for (const std::string c : {"1e-8", "1e-3", "1"})
  {
    const auto sim =
      run_scene(source_dir + "/prm/stability/uniaxial.prm",
                {"Output directory=monolithic_nodes_output"},
                {monolithic, nodes, "Contact pair S/Penalty=" + c});
    const double L       = 4;
    const double p_exact = uniaxial_pressure(std::stod(c));
    const auto   s       = state(*sim);
    std::cout << "uniaxial, c = " << c << ": force " << std::setprecision(15)
              << s.force_1.norm() << " against " << p_exact * L << ", peak "
              << s.max_pressure << " against " << p_exact
              << std::setprecision(6) << "; "
              << relative(s.force_1.norm(), p_exact * L) << ", "
              << relative(s.max_pressure, p_exact) << " off; "
              << sim->summary().at("newton_steps") << " Newton steps"
              << std::endl;
    check("uniaxial, c = " + c + ": force equals the closed form",
          relative(s.force_1.norm(), p_exact * L),
          1e-12);
    check("uniaxial, c = " + c + ": peak pressure equals the closed form",
          relative(s.max_pressure, p_exact),
          1e-12);
    check(sim->summary().at("contact_solver") == "monolithic" &&
            sim->summary().at("status") == "converged",
          "uniaxial, c = " + c + ": summary.json names the solver");
  }

  // 2. The coarse paper scene (curved contact zone, non-matching meshes):
  //    the same nodal penalty solved by dd-newton to ||Phi||_M <= 1e-12 of
  //    the initial overlap. The monolithic solution is exact on its active
  //    set; the difference is dd-newton's tolerance times the condition of
  //    S (~1e2 here) and the monolithic round-off, far below 1e-8.
  for (const std::string c : {"1e-7", "1e-4", "0.05"})
  {
    const std::vector<std::string> common    = {"Adaptation/Mode=none",
                                                nodes,
                                                "Contact pair S/Penalty=" + c,
                                                "Contact solver/Tolerance=1e-12"};
    const auto                     reference = run_coarse_paper_scene(
      source_dir, "monolithic_nodes_output", 1, common, {dd_newton});
    const auto sim = run_coarse_paper_scene(
      source_dir, "monolithic_nodes_output", 1, common, {monolithic});
    const auto         s = state(*sim), r = state(*reference);
    const unsigned int steps =
      sim->summary().at("newton_steps").get<unsigned int>();
    std::cout << "paper scene, c = " << c << ": force " << std::setprecision(12)
              << s.force_1.norm() << " against " << r.force_1.norm()
              << ", peak " << s.max_pressure << " against " << r.max_pressure
              << std::setprecision(6) << "; " << steps
              << " monolithic Newton steps, "
              << reference->summary().at("newton_steps") << " dd-newton steps"
              << std::endl;
    check("paper scene, c = " + c + ": force equals dd-newton's",
          relative(s.force_1.norm(), r.force_1.norm()),
          1e-8);
    check("paper scene, c = " + c + ": peak pressure equals dd-newton's",
          relative(s.max_pressure, r.max_pressure),
          1e-8);
    if (c == "1e-7")
      check(steps <= 15, "paper scene, c = 1e-7: at most 15 Newton steps");
  }

  // 3. The points at c = 1e-7 on the paper scene's default meshes: the
  //    active set cycled without damping, and now, once an active set comes
  //    back, the damped steps settle it. The answer is the pointwise penalty's,
  //    a different discretisation of the same contact than the nodes': the
  //    forces differ by O(h) (4e-4 measured at c = 1e-8 and 1e-4 on these
  //    meshes), well within 1e-3.
  {
    const std::vector<std::string> common = {
      "Output directory=monolithic_nodes_output",
      "Adaptation/Mode=none",
      monolithic,
      "Contact pair S/Penalty=1e-7",
      "Contact solver/Monolithic/Max Newton iterations=200"};
    const std::string paper  = source_dir + "/prm/paper_two_bodies.prm";
    const auto        points = run_scene(paper, common, {});
    const auto        nodal  = run_scene(paper, common, {nodes});
    std::cout << "paper scene, points, c = 1e-7: "
              << points->summary().at("newton_steps") << " Newton steps, "
              << points->summary().at("status") << ", force "
              << std::setprecision(8) << state(*points).force_1.norm()
              << " against " << state(*nodal).force_1.norm()
              << " on the nodes (" << nodal->summary().at("newton_steps")
              << " Newton steps)" << std::setprecision(6) << std::endl;
    check(points->summary().at("status") == "converged",
          "paper scene, points, c = 1e-7: the damped Newton method settles");
    check("paper scene, points, c = 1e-7: force near the nodes' one",
          relative(state(*points).force_1.norm(), state(*nodal).force_1.norm()),
          1e-3);
  }
  return report();
}
