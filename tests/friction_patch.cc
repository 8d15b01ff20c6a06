// DESCRIPTION: frictional patch test (prm/friction_patch.prm): on
// non-matching meshes a uniform pressure and a uniform shear, sticking or
// slipping, Tresca and Coulomb, exact contact and the penalty, give the
// closed-form traction, slip and dissipated energy at every contact point
// to round-off; |t| <= bound, the slip goes along t and the dissipation is
// >= 0; in three load steps the slip and traction carry over, and a way
// back sticks where loading straight slips (path dependence), also with
// body 1 refined in every load step (the history moves to the new nodes);
// all of it with the monolithic solver and with dd-newton (Coulomb's bound
// by Newton with GMRES and by the fixed point); friction with
// the paper's DD is refused in one line
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  // prm/friction_patch.prm: E, nu, both heights H, width L.
  const double E = 2.1e5, nu = 0.3, H = 1, L = 4, Delta = 1e-3;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)); // constrained
  const double G = E / (2 * (1 + nu));

  struct Case
  {
    std::string name;
    std::string law;    // tresca or coulomb
    double      c;      // relative penalty; 0: exact contact
    double      U;      // tangential displacement of the top
    double      bound;  // g (Tresca) or mu (Coulomb)
    bool        sticks; // expected
  };

  /** The solver's entries: the monolithic solver as the scene has it, or
   * dd-newton, whose CG stops at Tolerance of the data (1e-12, so that
   * the iterate is as close to the discrete solution as the checks ask,
   * 1e-9), with Coulomb's bound by Newton (the default: a slipping node's
   * t = sigma mu p inside the step, GMRES); "dd-newton (fixed point)"
   * with Coulomb linearization = fixed-point (mu p lagged by a step). */
  std::vector<std::string>
  solver_settings(const std::string &solver)
  {
    if (solver == "monolithic")
      return {};
    if (solver == "dd-newton (fixed point)")
      return {"Contact solver/Solver=dd-newton",
              "Contact solver/DD-Newton/Coulomb linearization=fixed-point",
              "Contact solver/Tolerance=1e-12"};
    return {"Contact solver/Solver=" + solver,
            "Contact solver/Tolerance=1e-12"};
  }

  void
  run_case(const std::string &source_dir,
           const Case        &k,
           const std::string &solver)
  {
    // The closed form of prm/friction_patch.prm (theta = c H / E_1).
    const double theta   = k.c * H / E;
    const double P       = Delta / (2 * H / M + theta);
    const double limit   = k.law == "tresca" ? k.bound : k.bound * P;
    const double S_stick = k.U / (2 * H / G + theta);
    const double S       = k.sticks ? S_stick : std::copysign(limit, k.U);
    // The jump of u . tau across the zone: U less the blocks' shear.
    const double slip        = k.U - 2 * H * S / G;
    const double dissipation = k.sticks ? 0. : S * L * (slip - theta * S);
    check(k.sticks == (std::abs(S_stick) <= limit),
          k.name + ": the case is set up on the expected side of the bound");

    std::ostringstream constants;
    constants << std::setprecision(17) << "Constants=Delta=" << Delta
              << ", U=" << k.U << ", P=" << P << ", S=" << S
              << ", mu=" << k.bound << ", g=" << k.bound;
    std::vector<std::string> settings = solver_settings(solver);
    settings.push_back(constants.str());
    settings.push_back("Contact pair S/Friction=" + k.law);
    if (k.c > 0)
    {
      settings.push_back("Contact pair S/Formulation=penalty");
      settings.push_back("Contact pair S/Penalty=" + std::to_string(k.c));
    }
    const auto        sim   = run_scene(source_dir + "/prm/friction_patch.prm",
                               {"Output directory=friction_patch_output"},
                               settings);
    const std::string name  = solver + ", " + k.name;
    const auto        state = sim->get_contact_solver().contact_state(0);
    const auto       &pts   = sim->get_contact_pairs()[0]->points();

    // The discrete solution is the linear one (patch test): the direct
    // solve's round-off (monolithic), or the CG's tolerance of 1e-12
    // (dd-newton), relative to the values, is the only error.
    const double tolerance = 1e-9;
    double       p_error = 0, t_error = 0, slip_error = 0, bound_excess = 0;
    double       against_t = 0; // the largest -t slip_increment
    bool         states    = true;
    for (unsigned int q = 0; q < pts.size(); ++q)
    {
      const double p = -state.sigma_n[q], t = state.t[q];
      p_error    = std::max(p_error, relative(p, P));
      t_error    = std::max(t_error, relative(t, S));
      slip_error = std::max(
        slip_error, std::abs(state.slip_increment[q] - slip) / std::abs(k.U));
      const double b = k.law == "tresca" ? k.bound : k.bound * p;
      bound_excess   = std::max(bound_excess, (std::abs(t) - b) / b);
      against_t =
        std::max(against_t, -t * state.slip_increment[q] / std::abs(S * k.U));
      states = states && state.slip_state[q] ==
                           (k.sticks ? NodeState::stick : NodeState::slip);
    }
    std::cout << name << ": P = " << P << ", t = " << S << ", slip " << slip
              << "; largest relative errors: p " << p_error << ", t " << t_error
              << ", slip " << slip_error << "; tangential force "
              << state.tangential_force << ", dissipated " << state.dissipation
              << " against " << dissipation << "; "
              << sim->summary().at("newton_steps") << " Newton steps"
              << std::endl;
    check(name + ": pressure P at every point", p_error, tolerance);
    check(name + ": tangential traction at every point", t_error, tolerance);
    check(name + ": slip at every point", slip_error, tolerance);
    check(states,
          name + (k.sticks ? ": every point sticks" : ": every point slips"));
    check(name + ": |t| <= the bound", bound_excess, tolerance);
    check(name + ": the slip goes along t", against_t, tolerance);
    // The force on body 1 along tau is -t L.
    check(name + ": tangential force -S L",
          relative(state.tangential_force, -S * L),
          tolerance);
    check(name + ": dissipated energy",
          std::abs(state.dissipation - dissipation) / std::abs(S * L * k.U),
          tolerance);
    check(state.dissipation >= -tolerance * std::abs(S * L * k.U),
          name + ": dissipation >= 0");
  }

  /**
   * Path dependence in load steps (Loading/Steps = 3, Coulomb, exact
   * contact): the top goes to U = 3e-3 (slip), 4e-3 (more slip) and back
   * to 3.5e-3. The way back sticks: the slip of step 2 stays, and the
   * traction falls by G/(2H) times the way back, to t3 = G (U3 - s2)/(2H),
   * below mu P. Loading straight to 3.5e-3 slips instead, with t = mu P.
   */
  void
  check_load_path(const std::string              &source_dir,
                  const std::string              &solver,
                  const std::vector<std::string> &adaptation = {},
                  const std::string              &label      = "")
  {
    const double mu = 0.3, U1 = 3e-3, U2 = 4e-3, U3 = 3.5e-3;
    const double P = Delta / (2 * H / M), S = mu * P;
    const double s1 = U1 - 2 * H * S / G, s2 = U2 - 2 * H * S / G;
    const double t3 = G * (U3 - s2) / (2 * H);
    check(std::abs(t3) < S, "load path: the way back sticks");
    // The data of each step: U and the sides' shear S.
    std::ostringstream data;
    data << std::setprecision(17) << "Constants=Delta=" << Delta << ", P=" << P
         << ", mu=" << mu << ", g=0, U1=" << U1 << ", U2=" << U2
         << ", U3=" << U3 << ", S1=" << S << ", S3=" << t3;
    const std::string U     = "(t < 0.5 ? U1 : (t < 0.9 ? U2 : U3))";
    const std::string shear = "(t < 0.9 ? S1 : S3)";
    const std::string sides = "0: 3/7*P; -" + shear + " | 1: -3/7*P; " + shear;
    std::vector<std::string> settings = solver_settings(solver);
    settings.insert(settings.end(), adaptation.begin(), adaptation.end());
    for (const std::string &entry : std::vector<std::string>{
           data.str(),
           "Loading/Steps=3",
           "Body omega1/Boundary conditions/Dirichlet=3: xy: " + U + "; -Delta",
           "Body omega1/Boundary conditions/Neumann=" + sides,
           "Body omega2/Boundary conditions/Neumann=" + sides})
      settings.push_back(entry);
    const auto        sim   = run_scene(source_dir + "/prm/friction_patch.prm",
                               {"Output directory=friction_patch_output"},
                               settings);
    const std::string path  = solver + ", load path" + label;
    const auto       &steps = sim->summary().at("load_steps");
    check(steps.size() == 3, path + ": three load steps in summary.json");
    const double expected_t[]           = {S, S, t3};
    const double expected_dissipation[] = {S * L * s1, S * L * (U2 - U1), 0};
    for (unsigned int k = 0; k < steps.size(); ++k)
    {
      const auto  &pair       = steps[k].at("pairs")[0];
      const double force      = pair.at("tangential_force").get<double>();
      const double dissipated = pair.at("dissipated_energy").get<double>();
      std::cout << path + ", step " << k + 1 << ": tangential force " << force
                << " against " << -expected_t[k] * L << ", dissipated "
                << dissipated << " against " << expected_dissipation[k]
                << std::endl;
      check(path + ", step " + std::to_string(k + 1) + ": tangential force",
            relative(force, -expected_t[k] * L),
            1e-9);
      check(path + ", step " + std::to_string(k + 1) + ": dissipated energy",
            std::abs(dissipated - expected_dissipation[k]) / (S * L * U1),
            1e-9);
    }
    // The last step at every point: sticking, no slip increment, the slip
    // of step 2 kept.
    const auto state     = sim->get_contact_solver().contact_state(0);
    double     increment = 0, slip_error = 0;
    bool       sticks = true;
    for (unsigned int q = 0; q < state.t.size(); ++q)
    {
      increment  = std::max(increment, std::abs(state.slip_increment[q]));
      slip_error = std::max(slip_error, relative(state.slip[q], s2));
      sticks     = sticks && state.slip_state[q] == NodeState::stick;
    }
    check(sticks, path + ", step 3: every point sticks");
    check(path + ", step 3: no slip increment", increment / U1, 1e-9);
    check(path + ", step 3: the slip of step 2 stays", slip_error, 1e-9);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // mu P = 42.4 for exact contact; S = 20.2 at U = 5e-4, 121 at 3e-3.
  for (const Case &k :
       {Case{"Coulomb, exact, stick", "coulomb", 0, 5e-4, 0.3, true},
        Case{"Coulomb, exact, slip", "coulomb", 0, 3e-3, 0.3, false},
        Case{"Coulomb, exact, slip backwards", "coulomb", 0, -3e-3, 0.3, false},
        Case{"Tresca, exact, stick", "tresca", 0, 5e-4, 30, true},
        Case{"Tresca, penalty c = 0.05, stick", "tresca", 0.05, 5e-4, 30, true},
        Case{"Tresca, penalty c = 0.05, slip", "tresca", 0.05, 3e-3, 30, false},
        Case{"Coulomb, penalty c = 1e-3, slip",
             "coulomb",
             1e-3,
             3e-3,
             0.3,
             false}})
    for (const std::string solver :
         {"monolithic", "dd-newton", "dd-newton (fixed point)"})
      run_case(source_dir, k, solver);
  // Loading straight to U = 3.5e-3 slips (the case above at 3e-3 slips
  // too); in steps that come back to it, it sticks.
  for (const std::string solver :
       {"monolithic", "dd-newton", "dd-newton (fixed point)"})
    check_load_path(source_dir, solver);

  // The paper's DD iterates on the pressure at the points and refuses
  // friction in one line naming the pair's entry.
  {
    const auto message = error_message<InputError>(
      [&]()
      {
        run_scene(source_dir + "/prm/friction_patch.prm",
                  {"Output directory=friction_patch_output"},
                  {"Contact solver/Solver=dd"});
      });
    std::cout << "dd: " << message << std::endl;
    check(message_names(message, {"Contact pair S/Friction", "dd"}),
          "dd: friction refused naming Contact pair S/Friction");
  }
  const auto message = error_message<InputError>(
    [&]()
    {
      run_scene(source_dir + "/prm/friction_patch.prm",
                {"Output directory=friction_patch_output"},
                {"Contact solver/Contact pressure=points"});
    });
  std::cout << "points: " << message << std::endl;
  check(message_names(message, {"Contact pair S/Friction", "Contact pressure"}),
        "friction on the points refused naming Contact pressure");
  // Coulomb with mu = 0 is frictionless: the run says so in a warning
  // (console and summary.json), and the tangential traction vanishes.
  {
    const auto sim    = run_scene(source_dir + "/prm/friction_patch.prm",
                               {"Output directory=friction_patch_output"},
                               {"Contact pair S/Friction coefficient=0"});
    bool       warned = false;
    for (const auto &w : sim->summary().at("warnings"))
      warned |=
        w.get<std::string>().find(
          "Friction coefficient is 0 on the whole zone") != std::string::npos;
    check(warned,
          "mu = 0: summary.json warns that the contact is frictionless");
    check(
      "mu = 0: the tangential force",
      std::abs(sim->summary()["contact"][0]["tangential_force"].get<double>()),
      1e-12);
  }
  // The same path with body 1 (triangles) refined uniformly once in every
  // load step, between its two solves: its nodes on S_1 are bisected, and
  // the history of slip and traction moves to them. The tractions stay
  // uniform, so the closed form holds on every mesh; a history that did
  // not move (zero, or misplaced) would give another slip in steps 2 and
  // 3.
  for (const std::string solver : {"monolithic", "dd-newton"})
    check_load_path(source_dir,
                    solver,
                    {"Adaptation/Mode=uniform",
                     "Adaptation/Bodies=omega1",
                     "Adaptation/Max cycles=1"},
                    " with refinement in every step");
  return report();
}
