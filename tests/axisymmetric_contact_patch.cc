// DESCRIPTION: the contact patch test through an axisymmetric contact
// (prm/friction_patch.prm with Geometry = axisymmetric, frictionless): two
// solid cylinders of different materials, r in (0, 4), on non-matching
// meshes (triangles on quadrilaterals), the lower one's base held axially,
// the upper one's top pushed down by Delta, the mantles free. The exact
// solution is uniaxial, sigma_zz = -P with P = Delta / (H/E_1 + H/E_2) and
// u_r = nu_i P r / E_i, linear in r and z and so in every element's space:
// the pressure is P at every contact point to round-off, exact contact with
// the monolithic solver and dd-newton, and the force is P pi L^2. A
// multiplier basis or a contact integral not weighted by 2 pi r, or a
// missing hoop strain, gives a pressure that varies with r.
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // Heights H and radius L of prm/friction_patch.prm's blocks; the lower
  // cylinder's material differs from the upper one's (E_1 = 2.1e5, nu 0.3).
  const double H = 1, L = 4, Delta = 1e-3, E_1 = 2.1e5, E_2 = 7e4;
  const double P = Delta / (H / E_1 + H / E_2);

  for (const std::string solver : {"monolithic", "dd-newton"})
  {
    std::ostringstream delta;
    delta << std::setprecision(17) << "Constants=Delta=" << Delta
          << ", U=0, P=0, S=0, mu=0, g=0";
    const auto sim = run_scene(
      source_dir + "/prm/friction_patch.prm",
      {"Output directory=axisymmetric_contact_patch_output"},
      {"Geometry=axisymmetric",
       delta.str(),
       "Contact solver/Solver=" + solver,
       "Contact solver/Tolerance=1e-12",
       // monolithic's exact contact: Uzawa updates of the penalty to 1e-11
       "Contact solver/Uzawa/Tolerance=1e-11",
       "Contact pair S/Friction=none",
       "Body omega1/Boundary conditions/Dirichlet=3: y: 0; -Delta",
       "Body omega1/Boundary conditions/Neumann=",
       "Body omega2/Boundary conditions/Dirichlet=2: y: 0; 0",
       "Body omega2/Boundary conditions/Neumann=",
       "Body omega2/Material/Young's modulus=" + std::to_string(E_2),
       "Body omega2/Material/Poisson's ratio=0.2"});
    const auto  state  = sim->get_contact_solver().contact_state(0);
    const auto &points = sim->get_contact_pairs()[0]->points();

    // The discrete solution is the linear one: the direct solve's
    // round-off, or dd-newton's CG stopped at 1e-12 of the data, is the
    // only error (the systems' condition numbers are ~1e4).
    double p_error = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
      p_error = std::max(p_error, relative(-state.sigma_n[q], P));
    std::cout << std::setprecision(8) << solver << ": P = " << P << ", "
              << points.size()
              << " contact points, largest relative error of p " << p_error
              << "; normal force " << state.normal_force << " against "
              << P * numbers::PI * L * L << std::endl;
    check(
      solver + ": pressure P at every contact point, relative", p_error, 1e-9);
    // Over the ring: the force on the disc of radius L is P pi L^2.
    check(solver + ": normal force P pi L^2, relative",
          relative(state.normal_force, P * numbers::PI * L * L),
          1e-9);
    // The largest r of a contact point: a Gauss point of the last face of
    // S_1 (its 16 faces are h = L/16 long).
    check(solver + ": the contact radius within the last face, / h",
          (L - state.contact_radius) / (L / 16.),
          1.);
  }
  return report();
}
