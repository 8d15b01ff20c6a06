// DESCRIPTION: Hertz contact of a sphere on a half-space, axisymmetric
// (prm/hertz_sphere.prm): contact radius and peak pressure against
// a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2) at the computed total
// force P, the pressure profile p0 sqrt(1 - r^2/a^2), the force balance
// over the ring, and convergence of p0 under refinement; with Coulomb
// friction on similar materials the tangential force vanishes to
// round-off; on a half-space of another material, Hertz with the combined
// modulus E*
#include <ddcontact/body/reaction_forces.h>
#include <ddcontact/simulation.h>

#include "scene_tools.h"
#include "test_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const double R = 50;

  /** 1 / E* = (1 - nu_1^2) / E_1 + (1 - nu_2^2) / E_2. */
  double
  contact_modulus(const double E_1,
                  const double nu_1,
                  const double E_2,
                  const double nu_2)
  {
    return 1. / ((1. - nu_1 * nu_1) / E_1 + (1. - nu_2 * nu_2) / E_2);
  }

  /** Runs prm/hertz_sphere.prm at box refinement @p level with the
   * entries @p settings, checks it against Hertz with the modulus
   * @p E_star, and returns the relative error of p0. */
  double
  check_sphere(const std::string              &source_dir,
               const unsigned int              level,
               const std::vector<std::string> &settings,
               const double                    E_star,
               const std::string              &name)
  {
    const std::string        levels = std::to_string(level);
    std::vector<std::string> entries{"Body upper/Mesh/Box refinement=" + levels,
                                     "Body lower/Mesh/Box refinement=" +
                                       levels};
    entries.insert(entries.end(), settings.begin(), settings.end());
    const auto simulation = run_scene(source_dir + "/prm/hertz_sphere.prm",
                                      {"Output directory=hertz_sphere_output"},
                                      entries);
    const auto state      = simulation->get_contact_solver().contact_state(0);
    // The total force over the ring: the axial component (the radial
    // forces of a ring have no resultant; force_1[0] is their sum).
    const double P        = state.force_1[1];
    const double a_exact  = std::cbrt(3. * P * R / (4. * E_star));
    const double p0_exact = 3. * P / (2. * numbers::PI * a_exact * a_exact);
    // The contact zone's cells: the box's (the coarse cells of 10 / 4
    // halved level times).
    const double h = 10. / 4. / std::pow(2., level);

    // The radius from the whole profile: p^2 is linear in r^2.
    const double a_fit = hertz_half_width(*simulation);
    std::cout << std::setprecision(6) << "\n"
              << name << ", box refinement " << level << ": P " << P << ", a "
              << a_fit << " (largest r in contact " << state.contact_radius
              << "), Hertz " << a_exact << "; p0 " << state.max_pressure
              << ", Hertz " << p0_exact << std::endl;
    check(name + ": contact radius from the profile, relative",
          relative(a_fit, a_exact),
          0.005);
    // The reported contact radius (ZoneExtent: the edge inside its cell
    // by the square-root profile of the last two nodal pressures) to 2 %
    // (issue 60; before, the largest r of a point in contact: +2.45 %),
    // and the half-width of a zone about the axis is its radius.
    check(name + ": reported contact radius, relative",
          relative(state.contact_radius, a_exact),
          0.02);
    check(name + ": half-width = contact radius, relative",
          relative(state.half_width, state.contact_radius),
          1e-12);
    check(name + ": edge resolution = the cell at the edge, / h",
          std::abs(state.extent_resolution - h) / h,
          0.5);

    // The profile at every point in contact, against p0 sqrt(1 - r^2/a^2)
    // with the closed-form p0 and a: the error is largest at the edge,
    // where the square root's slope is infinite and a cell of the mesh
    // smears it (bounded by p0 sqrt(2 h / a)).
    const auto &points  = simulation->get_contact_pairs()[0]->points();
    double      profile = 0, edge = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
    {
      const double r = points[q].x[0];
      const double hertz =
        r < a_exact ? p0_exact * std::sqrt(1. - r * r / (a_exact * a_exact))
                    : 0.;
      const double error = std::abs(-state.sigma_n[q] - hertz) / p0_exact;
      if (r < a_exact - 2. * h)
        profile = std::max(profile, error);
      else
        edge = std::max(edge, error);
    }
    // Inside, the error is O(h): measured 0.23 h/a at box refinement 6, 7
    // and 8 (1.3 %, 0.62 %, 0.29 %); half a cell's h/a bounds it.
    check(name +
            ": pressure profile inside a - 2h, max relative to p0, / (h/a)",
          profile / (h / a_exact),
          0.5);
    check(name + ": pressure profile near the edge, max relative to p0",
          edge,
          std::sqrt(2. * h / a_exact) + 0.01);

    // The contact force is the support's reaction of the lower body
    // (both totals over the ring).
    const auto &lower = *simulation->get_bodies()[1];
    BodyVector  load;
    lower.reinit_vector(load);
    simulation->get_contact_pairs()[0]->add_unconstrained_contact_load(
      state.sigma_n, lower, load);
    const ReactionForces<2> reactions(lower, lower.get_solution(), load);
    std::cout << std::setprecision(6) << "  reaction of the lower body's base "
              << reactions.supports()[0].force[1] << ", tangential force "
              << state.tangential_force << std::endl;
    check(name + ": axial reaction of the base = P, relative",
          relative(reactions.supports()[0].force[1], P),
          1e-8);
    // For similar materials (Dundurs' beta = 0) the normal load makes no
    // tangential traction, with or without friction; dissimilar ones
    // would, were there friction.
    check(name + ": tangential force / P",
          std::abs(state.tangential_force) / P,
          1e-9);
    return relative(state.max_pressure, p0_exact);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  const double E = 1000, nu = 0.3;
  // Box refinement 6 and 7 (the scene's 8 takes 20 s in Debug): p0 0.5 %
  // and 0.19 % off, the fitted a 0.1 % (measured).
  const double E_star = contact_modulus(E, nu, E, nu);
  check_sphere(source_dir, 6, {}, E_star, "similar");
  // The peak pressure converges (the finite cylinders are 14 a wide and
  // deep: their effect on p0 is below 0.1 %; on the scene's own mesh, box
  // refinement 8, p0 is 0.04 % off).
  check("p0 within 0.5 % on the finer mesh",
        check_sphere(source_dir, 7, {}, E_star, "similar"),
        0.005);

  // Coulomb friction on similar materials changes nothing (beta = 0).
  check_sphere(source_dir,
               6,
               {"Contact pair S/Friction=coulomb",
                "Contact pair S/Friction coefficient=0.3"},
               E_star,
               "similar, Coulomb mu = 0.3");

  // A half-space 3 times as stiff with another Poisson ratio: Hertz with
  // the combined modulus, frictionless (the normal problem does not see
  // Dundurs' beta without friction).
  const double E_2 = 3000, nu_2 = 0.2;
  check(
    "dissimilar: p0 within 0.5 %",
    check_sphere(source_dir,
                 7,
                 {"Body lower/Material/Young's modulus=" + std::to_string(E_2),
                  "Body lower/Material/Poisson's ratio=0.2"},
                 contact_modulus(E, nu, E_2, nu_2),
                 "dissimilar"),
    0.005);
  return report();
}
