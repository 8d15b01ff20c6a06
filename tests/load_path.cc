// DESCRIPTION: load steps that control their own error (Loading/Steps =
// auto, issue 48): LoadStepControl's dyadic steps on a given error
// function; proportional oblique loading of a cylinder on a flat of the
// same material (Q/P below mu) must stick everywhere (Mindlin: t = (Q/P) p,
// no slip, no dissipation), which Steps = auto reaches while one step slips;
// Check path with a fixed step names the step whose estimate exceeds the
// tolerance; steps over data without t are warned of
#include <ddcontact/loading/load_step_control.h>
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** Proportional loading: the bodies of prm/cattaneo_mindlin.prm (same E
   * and nu) pressed by Delta t and sheared by 0.001 t together. */
  std::unique_ptr<Simulation>
  run_proportional(const std::string              &source_dir,
                   const std::vector<std::string> &overrides)
  {
    return run_scene(
      source_dir + "/prm/cattaneo_mindlin.prm",
      {"Output directory=load_path_output",
       "Body upper/Boundary conditions/Dirichlet=3: xy: 0.001*t; -Delta*t",
       "Body upper/Mesh/Box refinement=5",
       "Body lower/Mesh/Box refinement=5"},
      overrides);
  }

  /** Points that slip, the largest |t - (Q/P) p| over the peak pressure,
   * and Q/P. */
  struct Stick
  {
    unsigned int n_slipping = 0;
    double       deviation  = 0;
    double       ratio      = 0;
  };

  Stick
  stick_of(const Simulation &sim)
  {
    const auto state = sim.get_contact_solver().contact_state(0);
    Stick      result;
    double     peak = 0;
    result.ratio    = std::abs(state.tangential_force) / state.normal_force;
    for (unsigned int q = 0; q < state.t.size(); ++q)
      peak = std::max(peak, -state.sigma_n[q]);
    for (unsigned int q = 0; q < state.t.size(); ++q)
      if (state.sigma_n[q] < 0)
      {
        result.deviation = std::max(
          result.deviation,
          std::abs(std::abs(state.t[q]) + result.ratio * state.sigma_n[q]) /
            peak);
        if (state.slip_state[q] == NodeState::slip)
          ++result.n_slipping;
      }
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // 1. The control alone, on the error e = h of a step of length h
  //    (tolerance 1/8): [0, 1], [0, 1/2] and [0, 1/4] are split, [0, 1/8]
  //    accepted, and no step doubles (e = 1/8 is not below tol / 4).
  {
    LoadStepControl control(0.125, 10);
    unsigned int    n_splits = 0;
    while (!control.finished())
      if (!control.judge(control.length()))
        ++n_splits;
    check(control.accepted().size() == 8, "e = h, tol 1/8: eight steps");
    check(n_splits == 3, "e = h, tol 1/8: three splits");
    check("e = h, tol 1/8: the path error is the sum of the steps'",
          control.path_error() - 1.,
          1e-15);
    // e = h^2: [0, 1] split, then 1/2 with e = 1/4 split, 1/4 with 1/16
    // accepted (not below 1/32: no doubling) four times.
    LoadStepControl squares(0.1, 10);
    while (!squares.finished())
      squares.judge(squares.length() * squares.length());
    check(squares.accepted().size() == 4, "e = h^2, tol 0.1: four steps");
    // An error that never falls: every step at the smallest length 2^-3,
    // accepted as over the tolerance.
    LoadStepControl stuck(1e-3, 3);
    while (!stuck.finished())
      stuck.judge(1.);
    check(stuck.accepted().size() == 8 && stuck.accepted()[0].over_tolerance,
          "an error above the tolerance at the smallest step: accepted, "
          "flagged");
    // After a step far below the tolerance the next doubles where the
    // dyadic grid allows: 1/2 split (e = 1), then 1/4, 1/4 (e tiny, but
    // [1/4, 3/4] is not dyadic), then [1/2, 1].
    LoadStepControl doubling(0.1, 10);
    doubling.judge(1.);
    doubling.judge(1.);
    doubling.judge(0.);
    check(doubling.start() == 0.25 && doubling.end() == 0.5,
          "no doubling off the dyadic grid");
    doubling.judge(0.);
    check(doubling.start() == 0.5 && doubling.end() == 1.,
          "doubling on the dyadic grid");
  }

  // 2. Proportional loading, Q/P about 0.13 below mu = 0.3: Mindlin's
  //    full stick. The spatial floor of |t - (Q/P) p| on this mesh (the
  //    zone's faces are 0.078 long, a = 0.38) is 1.1 % of the peak with
  //    256 uniform steps (0.9 % with 64, 3.0 % with 16); one step leaves
  //    6 of 30 points slipping and 12 %; auto reaches 0.99 %.
  {
    const auto  one  = run_proportional(source_dir, {"Loading/Steps=1"});
    const Stick s1   = stick_of(*one);
    const auto  sim  = run_proportional(source_dir, {"Loading/Steps=auto"});
    const Stick sa   = stick_of(*sim);
    const auto &path = sim->summary().at("load_path");
    std::cout << "one step: " << s1.n_slipping << " points slip, |t - (Q/P) p| "
              << s1.deviation << " of the peak; auto: " << sa.n_slipping
              << " slip, " << sa.deviation << ", Q/P " << sa.ratio << ", "
              << path.at("accepted_steps") << " steps, " << path.at("solves")
              << " solves, estimated path error " << path.at("path_error")
              << std::endl;
    check(sa.ratio < 0.3, "Q/P below mu: the closed form is full stick");
    check(s1.n_slipping > 0 && s1.deviation > 0.05,
          "one step does not follow the path (the test can tell)");
    check(sa.n_slipping == 0, "auto: no point slips");
    check("auto: t = (Q/P) p within twice the floor of 256 uniform steps",
          sa.deviation,
          0.025);
    // The energy dissipated over the path, against the scale mu P Delta
    // (mu = 0.3, Delta = 0.005): zero in the closed form; with uniform
    // steps 3e-6 (16 steps: the first node to enter the zone slips in its
    // step), 3e-7 (64), 2.5e-8 (256), measured on the scene's former
    // 0.2-deep box; auto 4.0e-6 on the shipped box, one step 8.2e-4.
    double dissipation = 0;
    for (const auto &step : sim->summary().at("load_steps"))
      dissipation +=
        std::abs(step.at("pairs")[0].at("dissipated_energy").get<double>());
    const double normal_force =
      sim->get_contact_solver().contact_state(0).normal_force;
    check("auto: the energy dissipated over the path, over mu P Delta",
          dissipation / (0.3 * normal_force * 0.005),
          1e-5);
    check(path.at("path_error").get<double>() <=
            1e-3 * path.at("accepted_steps").get<double>(),
          "auto: every accepted step within Path tolerance");
    check(path.at("over_tolerance").empty(),
          "auto: no step at the smallest length over the tolerance");
  }

  // 3. Check path with one fixed step: the estimate (one step against two
  //    halves) is far above the tolerance, and the run says so.
  {
    const auto sim = run_proportional(
      source_dir, {"Loading/Steps=1", "Loading/Check path=true"});
    const auto  &summary = sim->summary();
    const double error   = summary.at("load_path").at("path_error");
    bool         warned  = false;
    for (const auto &w : summary.at("warnings"))
      warned = warned || (w.get<std::string>().find("Path tolerance") !=
                          std::string::npos);
    std::cout << "Check path, one step: estimated path error " << error
              << std::endl;
    check(error > 1e-2 && warned,
          "Check path: one step's path error is estimated and warned of");
  }
  // 4. Steps over data without t: every step solves the same problem,
  //    which the run says (a t forgotten in the load path).
  {
    const auto sim = run_proportional(
      source_dir,
      {"Loading/Steps=2",
       "Body upper/Boundary conditions/Dirichlet=3: xy: 0.001; -Delta",
       "Body upper/Mesh/Box refinement=4",
       "Body lower/Mesh/Box refinement=4"});
    bool warned = false;
    for (const auto &w : sim->summary().at("warnings"))
      warned = warned || (w.get<std::string>().find(
                            "uses the load parameter t") != std::string::npos);
    check(warned, "steps over data without t: a warning");
  }
  return report();
}
