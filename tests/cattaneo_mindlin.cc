// DESCRIPTION: Cattaneo-Mindlin partial slip (prm/cattaneo_mindlin.prm,
// Coulomb, exact contact, monolithic): the Hertz blocks pressed first, then
// sheared in a second load step. The normal solution stays Hertz's and
// does not change with the shear (elastically similar bodies); the stick
// zone's half-width c gives c/a = sqrt(1 - Q/(mu P)) to within half a cell
// on two meshes; |t| <= mu p, the slip goes along t and the dissipation is
// >= 0 at every point; loading in proportion (shear and pressure growing
// together) sticks nearly everywhere instead (path dependence)
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  // prm/cattaneo_mindlin.prm (prm/hertz.prm's blocks).
  const double R = 50, E = 1000, nu = 0.3, mu = 0.3;
  const double E_star = 1. / (2. * (1. - nu * nu) / E);

  std::unique_ptr<Simulation>
  run(const std::string &source_dir, const std::vector<std::string> &settings)
  {
    return run_scene(source_dir + "/prm/cattaneo_mindlin.prm",
                     {"Output directory=cattaneo_mindlin_output"},
                     settings);
  }

  /** The invariants of the law at every node of the last step (the law
   * holds node by node for the averaged slip): |t_i| <= mu p_i, t_i along
   * the slip increment; and |t| <= mu p at every point, which interpolates
   * the nodes. */
  void
  check_invariants(const Simulation &sim, const std::string &name)
  {
    const auto  points = sim.get_contact_solver().contact_state(0);
    const auto &nodes =
      sim.get_contact_solver().get_problem().law(0).get_friction();
    double excess = 0, against = 0, t_scale = 0, s_scale = 0;
    for (unsigned int i = 0; i < nodes.nodal_t.size(); ++i)
    {
      t_scale = std::max(t_scale, std::abs(nodes.nodal_t[i]));
      s_scale = std::max(s_scale, std::abs(nodes.nodal_slip_increment[i]));
    }
    for (unsigned int i = 0; i < nodes.nodal_t.size(); ++i)
    {
      const double t = nodes.nodal_t[i];
      excess = std::max(excess, (std::abs(t) - nodes.nodal_bound[i]) / t_scale);
      against = std::max(
        against, -t * nodes.nodal_slip_increment[i] / (t_scale * s_scale));
    }
    for (unsigned int q = 0; q < points.t.size(); ++q)
      excess = std::max(
        excess, (std::abs(points.t[q]) + mu * points.sigma_n[q]) / t_scale);
    // Round-off of the direct solve: the states hold exactly.
    check(name + ": |t| <= mu p at every node and point", excess, 1e-9);
    check(name + ": the slip goes along t at every node", against, 1e-9);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // 1. Normal load, then shear (two load steps), on two meshes.
  for (const unsigned int level : {6u, 7u})
  {
    const std::string levels = std::to_string(level);
    const std::string name   = "refinement " + levels;
    const auto        sim    = run(source_dir,
                         {"Body upper/Mesh/Box refinement=" + levels,
                                    "Body lower/Mesh/Box refinement=" + levels});
    const auto        state  = sim->get_contact_solver().contact_state(0);
    const auto       &pts    = sim->get_contact_pairs()[0]->points();
    const auto       &steps  = sim->summary().at("load_steps");

    // The force on the upper body: P up, and -Q along tau = e_1 (the
    // traction -t tau, t > 0 against the upper body's slip along e_1).
    const double P  = state.force_1[1];
    const double Q  = -state.tangential_force;
    const double P1 = steps[0].at("pairs")[0].at("force")[1].get<double>();
    const double Q1 =
      steps[0].at("pairs")[0].at("tangential_force").get<double>();
    const double p0_1 =
      steps[0].at("pairs")[0].at("max_pressure").get<double>();

    // Hertz at the computed force; a from the whole profile.
    const double a_hertz = std::sqrt(4. * P * R / (M_PI * E_star));
    const double a       = hertz_half_width(*sim);

    // The stick zone: mu p - |t| = mu p0/a sqrt(c^2 - x^2) there
    // (Mindlin), fitted over the points that stick; and its extent.
    std::vector<double> x, deficit;
    double              extent = 0;
    for (unsigned int q = 0; q < pts.size(); ++q)
      if (state.slip_state[q] == ContactLaw::SlipState::stick)
      {
        x.push_back(pts[q].x[0]);
        deficit.push_back(mu * -state.sigma_n[q] - std::abs(state.t[q]));
        extent = std::max(extent, std::abs(pts[q].x[0]));
      }
    const double c       = root_profile_half_width(x, deficit);
    const double c_exact = a * std::sqrt(1 - Q / (mu * P));
    // The cells along the zone (both blocks' meshes match there).
    const double h =
      sim->get_bodies()[0]->get_mesh().min_cell_diameter() / std::sqrt(2.);
    std::cout << name << ": P " << P << ", Q/(mu P) " << Q / (mu * P) << ", a "
              << a << " (Hertz " << a_hertz << "), a/h " << a / h << "; c/a "
              << c / a << " fitted, " << extent / a
              << " from the extent, against " << c_exact / a << "; "
              << sim->summary().at("newton_steps") << " Newton steps"
              << std::endl;

    check(name + ": a against Hertz's", relative(a, a_hertz), 0.02);
    // Elastically similar bodies: the shear leaves the pressure alone (the
    // blocks mirror each other, so exactly, up to the solves' round-off).
    check(name + ": P unchanged by the shear", relative(P, P1), 1e-9);
    check(name + ": peak pressure unchanged by the shear",
          relative(state.max_pressure, p0_1),
          1e-9);
    check(name + ": no tangential force under the normal load alone",
          std::abs(Q1) / P1,
          1e-9);
    check(Q < mu * P && Q > 0.3 * mu * P,
          name + ": partial slip (0.3 mu P < Q < mu P)");
    // The edge of the stick zone lies between a node that sticks and one
    // that slips: half a cell of the zone.
    check(name + ": c/a fitted, to half a cell",
          std::abs(c - c_exact) / a,
          0.5 * h / a);
    check(name + ": c/a from the extent of the stick points, to a cell",
          std::abs(extent - c_exact) / a,
          h / a);
    check_invariants(*sim, name);
    check(steps[1].at("pairs")[0].at("dissipated_energy").get<double>() > 0,
          name + ": the shear step dissipates");
  }

  // 2. Path dependence: pressure and shear grown together in ten steps to
  //    the same end. Mindlin and Deresiewicz: with Q/P < mu at every step
  //    no point slips (the traction follows mu-times-smaller multiples of
  //    the pressure); loaded in this order the zone keeps c/a ~ 0.57.
  {
    const auto sim =
      run(source_dir,
          {"Body upper/Mesh/Box refinement=6",
           "Body lower/Mesh/Box refinement=6",
           "Loading/Steps=10",
           "Body upper/Boundary conditions/Dirichlet=3: xy: U*t; -Delta*t"});
    const auto   state = sim->get_contact_solver().contact_state(0);
    const double P = state.force_1[1], Q = -state.tangential_force;
    unsigned int n_contact = 0, n_stick = 0;
    for (const auto s : state.slip_state)
    {
      n_contact += (s != ContactLaw::SlipState::open);
      n_stick += (s == ContactLaw::SlipState::stick);
    }
    const double fraction = double(n_stick) / n_contact;
    std::cout << "proportional loading: Q/(mu P) " << Q / (mu * P) << ", "
              << n_stick << " of " << n_contact
              << " points in contact stick; the stick half-width "
              << state.stick_half_width << " of " << state.half_width
              << std::endl;
    check(Q < mu * P, "proportional loading: Q < mu P");
    check(fraction > 0.9,
          "proportional loading: (nearly) every point sticks (Cattaneo: "
          "about 57 %)");
    check_invariants(*sim, "proportional loading");
  }
  return report();
}
