// DESCRIPTION: what a run checks of its own answer before it writes
// "converged" (SelfChecks, issue 59): every check of the nodal contact law
// fed a state that breaks it, against the value of its formula, and one
// that keeps it; the finite and equilibrium checks fed a converged run
// whose displacements were spoiled; clamped blocks whose supports carry
// the contact force to round-off under both multiplier bases, with the
// same displacements; a push-out whose contact zone ends at nodes held on
// both sides, T = mu N from every solver (the prescribed slip); a Newton
// step that cannot be solved, which stops instead of "converged"; a
// floating pin in a bore with a clearance, whose plate carries its weight;
// the Interference in the gap reports and a clearance that touches
// nowhere; the warning of a finer multiplier side against the pressure's
// oscillation it announces; and a section touching the axis at a point,
// which stays on it
#include <ddcontact/io/self_checks.h>

#include "scene_tools.h"
#include "test_tools.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** The value of check @p name in @p checks (NaN if absent). */
  double
  value_of(const std::vector<SelfCheck> &checks, const std::string &name)
  {
    for (const auto &c : checks)
      if (c.name == name)
        return c.value;
    return std::numeric_limits<double>::quiet_NaN();
  }

  /** A pair's nodal law: pressures @p p, weak gaps @p d, penalty @p theta
   * at every node. */
  PairSolution
  nodes(const std::vector<double> &p,
        const std::vector<double> &d,
        const double               theta = 0)
  {
    PairSolution s;
    s.nodal_pressure = p;
    s.nodal_gap      = d;
    s.nodal_penalty.assign(p.size(), theta);
    return s;
  }

  /** The law's checks, each against its formula (issue 59's definitions,
   * include/ddcontact/io/self_checks.h), with the scale of the zone's
   * displacements A = 1 and the limit 1e-8. */
  void
  check_nodal_law()
  {
    std::cout << "The nodal law's checks:" << std::endl;
    const double limit = 1e-8;
    const auto   law   = [&](const PairSolution &s)
    { return SelfChecks::nodal_law(s, "S", 1., limit); };

    // Exact contact kept: closed nodes at d = 0, an open one at d < 0.
    const auto kept = law(nodes({1, 2, 0}, {0, 0, -0.1}));
    check(kept.size() == 3 && SelfChecks(kept).passed(),
          "exact contact kept: sign, gap and complementarity pass");
    // A tension: max(-p)+ / max |p| = 0.5 / 2.
    check("a tension: contact_sign = 1/4",
          std::abs(
            value_of(law(nodes({-0.5, 2, 0}, {0, 0, -0.1})), "contact_sign") -
            0.25),
          1e-15);
    // A penetration of 0.01 against A = 1.
    check(
      "a penetration: contact_gap = 0.01",
      std::abs(value_of(law(nodes({1, 2, 0}, {0.01, 0, -0.1})), "contact_gap") -
               0.01),
      1e-15);
    // A pressure across an open gap: p d / (max p A) = 0.5 * 0.1 / 2.
    check("pressure across a gap: complementarity = 0.025",
          std::abs(
            value_of(law(nodes({1, 2, 0.5}, {0, 0, -0.1})), "complementarity") -
            0.025),
          1e-15);
    // The penalty law p = d / theta holds, or the gap exceeds theta p.
    check(SelfChecks(law(nodes({1, 2}, {0.1, 0.2}, 0.1))).passed(),
          "penalty law kept: d = theta p passes");
    check("penalty law broken: contact_gap = 0.1",
          std::abs(
            value_of(law(nodes({1, 2}, {0.2, 0.2}, 0.1)), "contact_gap") - 0.1),
          1e-15);

    // Friction at two closed nodes with bound 0.3: one sticks below the
    // bound, one slips at it along its slip.
    const auto friction =
      [&](const std::vector<double> &t, const std::vector<double> &slip)
    {
      PairSolution s                  = nodes({1, 1}, {0, 0});
      s.friction.nodal_t              = t;
      s.friction.nodal_bound          = {0.3, 0.3};
      s.friction.nodal_inelastic_slip = slip;
      s.friction.nodal_slip_increment = slip;
      return law(s);
    };
    const auto frictional = friction({0.1, 0.3}, {0, 0.01});
    check(frictional.size() == 5 && SelfChecks(frictional).passed(),
          "friction kept: stick below the bound, slip at it");
    check("beyond the bound: friction_bound = 0.1 / 0.3",
          std::abs(value_of(friction({0.1, 0.4}, {0, 0.01}), "friction_bound") -
                   0.1 / 0.3),
          1e-15);
    check("slip below the bound: slip_at_bound = 0.01 * 0.2 / 0.3",
          std::abs(value_of(friction({0.1, 0.1}, {0, 0.01}), "slip_at_bound") -
                   0.01 * 0.2 / 0.3),
          1e-15);
    check("slip along the traction: slip_at_bound = 0.01 * 0.6 / 0.3",
          std::abs(value_of(friction({0.1, -0.3}, {0, 0.01}), "slip_at_bound") -
                   0.01 * 0.6 / 0.3),
          1e-15);
    check(!SelfChecks({{"x", std::nan(""), 1., "", ""}}).passed(),
          "a NaN fails its check");
  }

  /** The checks of @p s's current state. */
  SelfChecks
  checks_of(const Simulation &s, const double tolerance)
  {
    const RunReport::Results results{s.get_bodies(),
                                     s.get_distribution(),
                                     s.get_contact_pairs(),
                                     &s.get_contact_solver(),
                                     s.get_adaptations(),
                                     0};
    return SelfChecks(results, tolerance);
  }

  /** The clamped blocks under both bases; then the finite and equilibrium
   * checks fed the dual run with spoiled displacements. */
  void
  check_clamped_blocks(const std::string &source_dir)
  {
    std::cout << "Clamped blocks (both ends of S_2 held):" << std::endl;
    const std::string scene = source_dir + "/tests/scenes/clamped_blocks.prm";
    const auto        dual =
      run_scene(scene, {"Output directory=self_checks_dual"}, {});
    const auto standard =
      run_scene(scene,
                {"Output directory=self_checks_standard",
                 "Contact solver/Multiplier basis=standard"},
                {});
    for (const auto *s : {dual.get(), standard.get()})
    {
      const std::string basis = (s == dual.get()) ? "dual" : "standard";
      check(s->summary().at("status") == "converged" &&
              s->summary().at("self_checks").at("passed").get<bool>(),
            basis + ": converged, every self-check passed");
      // The reactions come from the loads the bodies received, and the
      // bodies are solved by a direct solver: the balance is round-off
      // (2 % short under the dual basis before).
      check(
        basis + ": force_imbalance (round-off)", largest_imbalance(*s), 1e-12);
      double lower = 0;
      for (const auto &b : s->summary().at("bodies"))
        if (b.at("name") == "lower")
          for (const auto &r : b.at("reactions"))
            lower += r.at("force")[1].get<double>();
      const double N =
        s->summary().at("contact")[0].at("normal_force").get<double>();
      check(basis + ": the lower supports carry the contact force",
            std::abs(lower - N) / N,
            1e-12);
    }
    // Every node of S_1 is closed: both bases enforce the same nodal
    // constraint, so the answers agree to the solver's Tolerance (1e-10).
    check("dual against standard: displacements",
          displacement_difference(*dual, *standard),
          1e-8);

    auto            &upper = *dual->get_bodies()[0];
    const BodyVector kept  = upper.get_solution();
    upper.get_solution() *= 1.01;
    const SelfChecks spoiled = checks_of(*dual, 1e-10);
    check(!spoiled.passed() &&
            message_names(spoiled.failure(),
                          {"self-check 'equilibrium'", "body 'upper'"}),
          "displacements 1 % off: the equilibrium check fails, naming the "
          "body (" +
            spoiled.failure() + ")");
    upper.get_solution()(0) = std::nan("");
    const SelfChecks broken = checks_of(*dual, 1e-10);
    check(
      message_names(broken.failure(), {"self-check 'finite'", "body 'upper'"}),
      "a NaN displacement: the finite check fails first");
    upper.get_solution() = kept;
    check(checks_of(*dual, 1e-10).passed(), "restored: every check passes");
  }

  /** A shaft pushed out of a hub with Coulomb friction mu = 0.15, both
   * ends of the shaft held axially (prm/shrink_fit.prm): the zone's end
   * nodes have their slip prescribed by both bodies' conditions, where a
   * stick condition made the first Newton step's system singular (it
   * wrote "converged" with a force of 9.7e19). The law takes the
   * prescribed slip: every node slips, T = mu N, and the shaft's supports
   * push with the tangential force, from dd-newton under both bases and
   * from the monolithic solver; the hub pushed instead (mu = 0.3) in 4
   * load steps ended in UMFPACK's failure. */
  void
  check_held_push_out(const std::string &source_dir)
  {
    std::cout << "Push-out with both ends held:" << std::endl;
    const std::string              scene   = source_dir + "/prm/shrink_fit.prm";
    const std::vector<std::string> coulomb = {
      "Contact pair fit/Friction=coulomb",
      "Contact pair fit/Friction coefficient=0.15",
      "Body shaft/Boundary conditions/Dirichlet=3: y: 0; -0.002*t | 2: y: 0; "
      "-0.002*t"};
    std::vector<double> normal_forces;
    for (const std::string solver :
         {"dd-newton, dual", "dd-newton, standard", "monolithic"})
    {
      auto overrides = coulomb;
      overrides.push_back("Output directory=self_checks_push_out");
      if (solver == "monolithic")
        overrides.push_back("Contact solver/Solver=monolithic");
      if (solver == "dd-newton, standard")
        overrides.push_back("Contact solver/Multiplier basis=standard");
      const auto   s       = run_scene(scene, overrides, {});
      const auto  &contact = s->summary().at("contact")[0];
      const double N       = contact.at("normal_force").get<double>();
      const double T = std::abs(contact.at("tangential_force").get<double>());
      double       push = 0;
      for (const auto &b : s->summary().at("bodies"))
        if (b.at("name") == "shaft")
          for (const auto &r : b.at("reactions"))
            push += r.at("force")[1].get<double>();
      std::cout << "  " << solver << ": N = " << N << ", T = " << T
                << std::endl;
      check(solver + ": T = mu N (every node slips)",
            std::abs(T - 0.15 * N) / N,
            1e-8);
      check(solver + ": the shaft's supports push with T",
            std::abs(std::abs(push) - T) / T,
            1e-8);
      normal_forces.push_back(N);
    }
    // The bases and solvers solve one discrete law (matching meshes): the
    // same N to the Tolerance (1e-10).
    check("dd-newton's bases and the monolithic solver: the same N",
          std::max(std::abs(normal_forces[1] - normal_forces[0]),
                   std::abs(normal_forces[2] - normal_forces[0])) /
            normal_forces[0],
          1e-8);

    const auto hub = run_scene(
      scene,
      {"Output directory=self_checks_push_hub",
       "Contact solver/Solver=monolithic",
       "Loading/Steps=4",
       "Contact pair fit/Friction=coulomb",
       "Contact pair fit/Friction coefficient=0.3",
       "Body hub/Boundary conditions/Dirichlet=2: y: 0; 0.002*t | 3: y: 0; "
       "0.002*t"},
      {});
    const auto &contact = hub->summary().at("contact")[0];
    check("hub pushed, monolithic, 4 steps: T = 0.3 N",
          std::abs(std::abs(contact.at("tangential_force").get<double>()) -
                   0.3 * contact.at("normal_force").get<double>()) /
            contact.at("normal_force").get<double>(),
          1e-8);
  }

  /** Both blocks' ends held in the normal direction with a penetration
   * prescribed there (the upper block's sides moved down with its top):
   * exact contact cannot hold at those nodes, the first Newton step's
   * system is singular, and its CG stops above its tolerance. The run
   * says so instead of going on (inner_solves). */
  void
  check_singular_step(const std::string &source_dir)
  {
    std::cout << "A Newton step that cannot be solved:" << std::endl;
    const std::string message = error_message<DivergenceError>(
      [&]()
      {
        run_scene(source_dir + "/tests/scenes/clamped_blocks.prm",
                  {"Output directory=self_checks_singular",
                   "Body upper/Boundary conditions/Dirichlet=3: xy: 0; "
                   "-Delta | 0: xy: 0; -Delta | 1: xy: 0; -Delta"},
                  {});
      });
    check(message_names(message, {"CG", "Newton step 1", "held on both"}),
          "stops at the CG, naming the cause: " + message);
  }

  /** A pin held only in x in a bore with a clearance of 0.02, loaded by
   * its weight: at p = 0 every node is open, the residual vanishes, and
   * the coarse correction of its free mode alone carries the load (the
   * CG then has nothing but round-off to reduce, which divided 0 by 0 on
   * the pin of issue 59's meshes). The plate carries the weight. */
  void
  check_floating_pin(const std::string &source_dir)
  {
    std::cout << "Floating pin in a bore:" << std::endl;
    const auto s =
      run_scene(source_dir + "/tests/pin_in_hole.prm",
                {"Output directory=self_checks_pin",
                 "Contact solver/Tolerance=1e-10",
                 "Body pin/Boundary conditions/Dirichlet=12: x: 0; 0",
                 "Body pin/Boundary conditions/Body force=0; -0.01"},
                {});
    const auto &summary = s->summary();
    check(summary.at("status") == "converged" &&
            summary.at("newton_steps").get<unsigned int>() < 15,
          "converged in " + summary.at("newton_steps").dump() +
            " Newton steps (< 15)");
    double weight = 0, carried = 0;
    for (const auto &b : summary.at("bodies"))
    {
      if (b.at("name") == "pin")
        weight = b.at("applied_load")[1].get<double>();
      else
        for (const auto &r : b.at("reactions"))
          carried += r.at("force")[1].get<double>();
    }
    check("the plate's supports carry the pin's weight",
          std::abs(carried + weight) / std::abs(weight),
          1e-8);
  }

  /** The Interference is part of the gap in use; a negative one is a
   * clearance that touches nowhere, and says so. */
  void
  check_interference(const std::string &source_dir)
  {
    std::cout << "Interference in the reports:" << std::endl;
    const std::string scene = source_dir + "/prm/shrink_fit.prm";
    const auto fit = run_scene(scene, {"Output directory=self_checks_fit"}, {});
    const auto &search = fit->summary().at("contact")[0].at("search");
    check("the fit's smallest gap is -Interference (meshes touching)",
          std::abs(search.at("min_initial_gap").get<double>() + 1e-3) / 1e-3,
          1e-12);
    const auto clearance = run_scene(scene,
                                     {"Output directory=self_checks_clearance",
                                      "Contact pair fit/Interference=-0.02"},
                                     {});
    bool       told      = false;
    for (const auto &w : clearance->summary().at("warnings"))
      told = told || message_names(w.get<std::string>(),
                                   {"no point is in contact", "clearance"});
    check(told, "a negative Interference: no contact, and why");
    // A hub meshed 0.02 into the shaft under the expression gap 0 and the
    // Interference: the meshes' overlap is said, not ignored.
    const auto overlap = run_scene(scene,
                                   {"Output directory=self_checks_overlap",
                                    "Output/Points=",
                                    "Body hub/Mesh/Corner 1=0.98, 0"},
                                   {});
    told               = false;
    for (const auto &w : overlap->summary().at("warnings"))
      told =
        told || message_names(w.get<std::string>(),
                              {"the meshes overlap by 0.02", "leaves out"});
    check(told, "meshes overlapping under an expression gap: said");
  }

  /** The largest deviation of the pressure from its local mean (five
   * points) over r < 0.5 of the punch. */
  double
  pressure_oscillation(const Simulation &s)
  {
    const auto          state = s.get_contact_solver().contact_state(0);
    const auto         &pts   = s.get_contact_pairs()[0]->points();
    std::vector<double> p;
    for (unsigned int q = 0; q < pts.size(); ++q)
      if (pts[q].x[0] < 0.5)
        p.push_back(-state.sigma_n[q]);
    double worst = 0;
    for (unsigned int i = 2; i + 2 < p.size(); ++i)
    {
      const double mean =
        (p[i - 2] + p[i - 1] + p[i] + p[i + 1] + p[i + 2]) / 5;
      worst = std::max(worst, std::abs(p[i] - mean) / mean);
    }
    return worst;
  }

  bool
  warns_of_finer_side(const Simulation &s)
  {
    for (const auto &w : s.summary().at("warnings"))
      if (message_names(w.get<std::string>(),
                        {"faces for every cell", "Body 1"}))
        return true;
    return false;
  }

  /** 1.25 faces of S_1 per cell of S_2: a smooth pressure and no warning;
   * 2: the multipliers oscillate, and the run warns. */
  void
  check_multiplier_side(const std::string &source_dir)
  {
    std::cout << "Finer multiplier side:" << std::endl;
    const std::string scene =
      source_dir + "/tests/scenes/flat_punch_axisymmetric.prm";
    const auto coarse =
      run_scene(scene, {"Output directory=self_checks_punch_1"}, {});
    const auto   fine   = run_scene(scene,
                                {"Output directory=self_checks_punch_2",
                                     "Body punch/Mesh/Subdivisions=51, 8"},
                                {});
    const double smooth = pressure_oscillation(*coarse);
    const double rough  = pressure_oscillation(*fine);
    std::cout << "  oscillation " << smooth << " at 1.25, " << rough << " at 2"
              << std::endl;
    check(smooth < 0.01 && !warns_of_finer_side(*coarse),
          "1.25 faces per cell: smooth (< 1 %), no warning");
    check(rough > 0.01 && warns_of_finer_side(*fine),
          "2 faces per cell: oscillates (> 1 %), and the run warns");
  }

  /** A section that touches the axis at one vertex: that point stays on
   * the axis (u_r = 0 exactly, a constrained dof), where only whole faces
   * on the axis were constrained before (u_r was 1.4e-9 against |u| =
   * 4.5e-4 on this mesh). */
  void
  check_axis_point(const std::string &source_dir)
  {
    std::cout << "A body touching the axis at a point:" << std::endl;
    const auto  s     = run_scene(source_dir + "/tests/scenes/horn_torus.prm",
                             {"Output directory=self_checks_torus"},
                             {});
    const auto &point = s->summary().at("points")[0];
    check(point.at("u")[0].get<double>() == 0. &&
            point.at("u")[1].get<double>() != 0.,
          "u_r = 0 at the axis point (u_z = " + point.at("u")[1].dump() + ")");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  check_nodal_law();
  check_clamped_blocks(source_dir);
  check_held_push_out(source_dir);
  check_singular_step(source_dir);
  check_floating_pin(source_dir);
  check_interference(source_dir);
  check_multiplier_side(source_dir);
  check_axis_point(source_dir);
  return report();
}
