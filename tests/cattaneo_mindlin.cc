// DESCRIPTION: Cattaneo-Mindlin partial slip (prm/cattaneo_mindlin.prm,
// Coulomb, exact contact, monolithic and dd-newton): the Hertz blocks
// pressed first, then sheared in a second load step. The normal solution stays
// Hertz's and does not change with the shear (elastically similar bodies); the
// stick zone's half-width c gives c/a = sqrt(1 - Q/(mu P)) to within half a
// cell on two meshes; |t| <= mu p, the slip goes along t and the dissipation is
// >= 0 at every point; loading in proportion (shear and pressure growing
// together) sticks nearly everywhere instead (path dependence); dd-newton's
// body-by-body solution agrees with the monolithic one at every point
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <array>
#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  // prm/cattaneo_mindlin.prm (prm/hertz.prm's blocks).
  const double R = 50, E = 1000, nu = 0.3, mu = 0.3;
  const double E_star = 1. / (2. * (1. - nu * nu) / E);

  /** The scene with @p settings, solved by @p solver. */
  std::unique_ptr<Simulation>
  run(const std::string              &source_dir,
      const std::string              &solver,
      const std::vector<std::string> &settings)
  {
    auto all = settings;
    all.push_back("Contact solver/Solver=" + solver);
    return run_scene(source_dir + "/prm/cattaneo_mindlin.prm",
                     {"Output directory=cattaneo_mindlin_output"},
                     all);
  }

  /** The largest difference of p and of t at the points between the two
   * solvers' runs, relative to the peak pressure. */
  void
  check_agreement(const Simulation  &monolithic,
                  const Simulation  &dd_newton,
                  const std::string &name)
  {
    const auto a = monolithic.get_contact_solver().contact_state(0);
    const auto b = dd_newton.get_contact_solver().contact_state(0);
    check(a.sigma_n.size() == b.sigma_n.size(),
          name + ": both solvers on the same points");
    double p_difference = 0, t_difference = 0;
    for (unsigned int q = 0; q < a.sigma_n.size(); ++q)
    {
      p_difference =
        std::max(p_difference, std::abs(a.sigma_n[q] - b.sigma_n[q]));
      t_difference = std::max(t_difference, std::abs(a.t[q] - b.t[q]));
    }
    std::cout << name << ": dd-newton against monolithic, largest difference "
              << "of p " << p_difference / a.max_pressure << ", of t "
              << t_difference / a.max_pressure << " (of the peak pressure)"
              << std::endl;
    // Both solve the same discrete problem; dd-newton stops at Tolerance
    // (1e-10) of the data, which bounds the multipliers' error by about
    // 1e-10 times the condition of S on the zone (~ a/h, the zone's
    // elements): 1e-6 of the peak leaves a margin of 100.
    check(name + ": dd-newton's p agrees with the monolithic solver's",
          p_difference / a.max_pressure,
          1e-6);
    check(name + ": dd-newton's t agrees with the monolithic solver's",
          t_difference / a.max_pressure,
          1e-6);
  }

  /** The invariants of the law at every node of the last step (the law
   * holds node by node for the averaged slip): |t_i| <= mu p_i, t_i along
   * the slip increment; and |t| <= mu p at every point, which interpolates
   * the nodes. */
  void
  check_invariants(const Simulation &sim, const std::string &name)
  {
    const auto  points = sim.get_contact_solver().contact_state(0);
    const auto &nodes  = sim.get_contact_solver().solution_of(0).friction;
    double      excess = 0, against = 0, t_scale = 0, s_scale = 0;
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
    // Round-off of the direct solve (monolithic), or a sticking node's
    // slip of the order of dd-newton's Tolerance (1e-10 of the data)
    // against its t: the states hold exactly.
    check(name + ": |t| <= mu p at every node and point", excess, 1e-9);
    check(name + ": the slip goes along t at every node", against, 1e-9);
  }

  /**
   * The L2 errors of the pressure and of the tangential traction at the
   * points against Hertz's and Cattaneo-Mindlin's closed forms (at the
   * computed P, Q), each relative to the closed form's norm, and the same
   * errors of the closed forms' own interpolants on the nodes of S_1 (the
   * hat functions the reported fields are made of): the best a piecewise
   * linear field on these nodes does, up to a factor near 1. The order is
   * {p, t, interpolant of p, interpolant of t}.
   */
  std::array<double, 4>
  l2_errors(const Simulation &sim, const double P, const double Q)
  {
    const auto   state = sim.get_contact_solver().contact_state(0);
    const auto  &pair  = *sim.get_contact_pairs()[0];
    const auto  &pts   = pair.points();
    const auto  &faces = pair.zone_faces_1();
    const double a     = std::sqrt(4. * P * R / (M_PI * E_star));
    const double p0    = 2. * P / (M_PI * a);
    const double c     = a * std::sqrt(1. - Q / (mu * P));
    const auto   root  = [](const double r, const double x)
    { return std::sqrt(std::max(0., r * r - x * x)); };
    const auto p_exact = [&](const double x) { return p0 / a * root(a, x); };
    // t > 0 against the upper body's slip along +e_1.
    const auto t_exact = [&](const double x)
    { return mu * p0 / a * (root(a, x) - root(c, x)); };
    std::array<double, 4> squares = {{0., 0., 0., 0.}};
    double                p_norm = 0, t_norm = 0;
    for (unsigned int q = 0; q < pts.size(); ++q)
    {
      const double x = pts[q].x[0], w = pts[q].JxW;
      const auto  &f           = faces[pts[q].face];
      const double s           = (x - f[0][0]) / (f[1][0] - f[0][0]);
      const auto   interpolant = [&](const auto &exact)
      { return (1. - s) * exact(f[0][0]) + s * exact(f[1][0]); };
      squares[0] += w * std::pow(-state.sigma_n[q] - p_exact(x), 2);
      squares[1] += w * std::pow(state.t[q] - t_exact(x), 2);
      squares[2] += w * std::pow(interpolant(p_exact) - p_exact(x), 2);
      squares[3] += w * std::pow(interpolant(t_exact) - t_exact(x), 2);
      p_norm += w * std::pow(p_exact(x), 2);
      t_norm += w * std::pow(t_exact(x), 2);
    }
    return {{std::sqrt(squares[0] / p_norm),
             std::sqrt(squares[1] / t_norm),
             std::sqrt(squares[2] / p_norm),
             std::sqrt(squares[3] / t_norm)}};
  }

  /** Part 1's checks of the run @p sim (normal load, then shear). */
  void
  check_partial_slip(const Simulation &sim, const std::string &name)
  {
    const auto  state = sim.get_contact_solver().contact_state(0);
    const auto &pts   = sim.get_contact_pairs()[0]->points();
    const auto &steps = sim.summary().at("load_steps");

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
    const double a       = hertz_half_width(sim);

    // The stick zone: mu p - |t| = mu p0/a sqrt(c^2 - x^2) there
    // (Mindlin), fitted over the points that stick; and its extent.
    std::vector<double> x, deficit;
    double              extent = 0;
    for (unsigned int q = 0; q < pts.size(); ++q)
      if (state.slip_state[q] == NodeState::stick)
      {
        x.push_back(pts[q].x[0]);
        deficit.push_back(mu * -state.sigma_n[q] - std::abs(state.t[q]));
        extent = std::max(extent, std::abs(pts[q].x[0]));
      }
    const double c       = root_profile_half_width(x, deficit);
    const double c_exact = a * std::sqrt(1 - Q / (mu * P));
    // The cells along the zone (both blocks' meshes match there).
    const double h =
      sim.get_bodies()[0]->get_mesh().min_cell_diameter() / std::sqrt(2.);
    std::cout << name << ": P " << P << ", Q/(mu P) " << Q / (mu * P) << ", a "
              << a << " (Hertz " << a_hertz << "), a/h " << a / h << "; c/a "
              << c / a << " fitted, " << extent / a
              << " from the extent, against " << c_exact / a << "; "
              << sim.summary().at("newton_steps") << " Newton steps"
              << std::endl;

    // The refinement box of the shipped scene reaches 0.45 deep, so the
    // field below the zone is resolved: a is 0.49 % and 0.12 % off and the
    // peak 0.47 % and 0.35 % high at refinements 6 and 7 (the former
    // 0.2-deep box: a 0.6-0.8 % low, the peak 0.9-1.4 % high, what these
    // bounds exclude); the blocks' finite size is below 0.1 %.
    // a from the root fit over the points with p > 0: those of the last
    // active face, where the field falls linearly to the first open node,
    // pull it outwards by a fraction of that face (measured: 0.15 of a
    // cell at refinement 6, 1.6 % of a). The L2 checks below bound the
    // profile as a whole.
    check(name + ": a against Hertz's, to a quarter of a cell",
          relative(a, a_hertz),
          std::max(0.01, 0.25 * h / a));
    check(name + ": peak pressure against Hertz's 2 P / (pi a)",
          relative(p0_1,
                   2. * P1 / (M_PI * std::sqrt(4. * P1 * R / (M_PI * E_star)))),
          0.01);
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

    // The fields against the closed forms in L2. The dual basis decouples
    // a sticking node from its slipping neighbour, so t follows the
    // closed form up to its interpolation error (measured: 0.98 and 0.99
    // of it at refinements 6 and 7, p 1.00 and 1.02); with the hat
    // functions as test functions the weak slip of the stick zone's last
    // nodes is tied to the slip zone through the mass matrix, and t
    // zigzags there (Multiplier basis = standard: 2.1 times the
    // interpolation error at refinement 7, doc/friction.md 5.2).
    const auto errors = l2_errors(sim, P, Q);
    std::cout << name << ": L2 error of p " << errors[0] << " (interpolant "
              << errors[2] << "), of t " << errors[1] << " (interpolant "
              << errors[3] << ")" << std::endl;
    check(name + ": L2 error of p within 1.5 times the interpolant's",
          errors[0] / errors[2],
          1.5);
    check(name + ": L2 error of t within 1.5 times the interpolant's",
          errors[1] / errors[3],
          1.5);
    check_invariants(sim, name);
    check(steps[1].at("pairs")[0].at("dissipated_energy").get<double>() > 0,
          name + ": the shear step dissipates");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // 1. Normal load, then shear (two load steps), on two meshes, by both
  //    solvers.
  for (const unsigned int level : {6u, 7u})
  {
    const std::string              levels = std::to_string(level);
    const std::vector<std::string> mesh   = {
        "Body upper/Mesh/Box refinement=" + levels,
        "Body lower/Mesh/Box refinement=" + levels};
    const auto monolithic = run(source_dir, "monolithic", mesh);
    const auto dd_newton  = run(source_dir, "dd-newton", mesh);
    check_partial_slip(*monolithic, "monolithic, refinement " + levels);
    check_partial_slip(*dd_newton, "dd-newton, refinement " + levels);
    check_agreement(*monolithic, *dd_newton, "refinement " + levels);
  }

  // 2. Path dependence: pressure and shear grown together in ten steps to
  //    the same end. Mindlin and Deresiewicz: with Q/P < mu at every step
  //    no point slips (the traction follows mu-times-smaller multiples of
  //    the pressure); loaded in this order the zone keeps c/a ~ 0.57.
  for (const std::string solver : {"monolithic", "dd-newton"})
  {
    const std::string name = solver + ", proportional loading";
    const auto        sim =
      run(source_dir,
          solver,
          {"Body upper/Mesh/Box refinement=6",
           "Body lower/Mesh/Box refinement=6",
           "Loading/Steps=10",
           // Nearly all nodes stick, so the largest slip increment, the
           // scale of check_invariants(), is that of an edge node: a
           // sticking node's slip of the order of the Tolerance counts
           // 10 times more than in the shear step (1.6e-9 at 1e-10).
           "Contact solver/Tolerance=1e-11",
           "Body upper/Boundary conditions/Dirichlet=3: xy: U*t; -Delta*t"});
    const auto   state = sim->get_contact_solver().contact_state(0);
    const double P = state.force_1[1], Q = -state.tangential_force;
    unsigned int n_contact = 0, n_stick = 0;
    for (const auto s : state.slip_state)
    {
      n_contact += (s != NodeState::open);
      n_stick += (s == NodeState::stick);
    }
    // The points of the outermost face at each end: the pressure falls to
    // zero there, and the bound mu p with it; a node that enters contact
    // within a step may slip (doc/friction.md 4.4).
    unsigned int per_face = 0;
    for (const auto &point : sim->get_contact_pairs()[0]->points())
      per_face += (point.face == sim->get_contact_pairs()[0]->points()[0].face);
    std::cout << name << ": Q/(mu P) " << Q / (mu * P) << ", " << n_stick
              << " of " << n_contact
              << " points in contact stick; the stick half-width "
              << state.stick_half_width << " of " << state.half_width << ", "
              << per_face << " points per face" << std::endl;
    check(Q < mu * P, name + ": Q < mu P");
    check(n_stick + 2 * per_face >= n_contact,
          name + ": every point sticks but those of the zone's two "
                 "outermost faces (Cattaneo: about 57 %)");
    check_invariants(*sim, name);
  }
  return report();
}
