// DESCRIPTION: floating bodies (held only by contact, pressed by a force)
// with dd-newton's coarse problem: the uniaxial punch pressed by the force
// of the displacement-driven run gives that run's solution; with its
// rotation free, the contact pressure balances the load's force and
// moment; the Hertz cylinder pressed by a force matches the
// displacement-driven run at the same force; and the cases contact cannot
// hold are refused in one line
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const std::string newton = "Contact solver/Solver=dd-newton";

  /** The vertical contact force on body 1 of the first pair. */
  double
  vertical_force(const Simulation &s)
  {
    return s.get_contact_solver().contact_state(0).force_1[1];
  }

  /** The moment about x = @p x0 of the pressure on S_1 (contact points and
   * weights of the first pair). */
  double
  pressure_moment(const Simulation &s, const double x0)
  {
    const auto  state  = s.get_contact_solver().contact_state(0);
    const auto &points = s.get_contact_pairs()[0]->points();
    double      moment = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
      moment += -state.sigma_n[q] * (points[q].x[0] - x0) * points[q].JxW;
    return moment;
  }

  double
  summary_number(const Simulation &s, const std::string &key)
  {
    return s.summary().at("contact")[0].at(key).get<double>();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  const std::string uniaxial = source_dir + "/prm/stability/uniaxial.prm";
  const std::string floating_upper =
    "Body omega1/Boundary conditions/Dirichlet=0: x: 0; 0";

  // 1. The uniaxial scene of doc/stability.md (two blocks on rollers, L = 4,
  //    H1 = H2 = 1, the contact zone the whole common side): the upper block
  //    pressed by u_2 = -Delta on its top, and then by the traction
  //    q = F / L of that run's force F instead, held only by contact (its
  //    vertical translation is free). Both are the same discrete problem,
  //    so they agree to the solvers' tolerance (Tolerance = 1e-11 times
  //    the condition of S, 10 to 100 here: with the dual basis the
  //    difference is 1.4e-9 at Tolerance = 1e-10), for exact contact and
  //    for the penalty on the contact points.
  for (const std::string exact : {"true", "false"})
  {
    const std::vector<std::string> common = {
      "Output directory=floating_body_output",
      newton,
      std::string("Contact pair S/Formulation=") +
        (exact == "true" ? "exact" : "penalty"),
      "Contact solver/Tolerance=1e-11"};
    const auto         pressed = run_scene(uniaxial, common, {});
    const double       F       = vertical_force(*pressed);
    std::ostringstream traction;
    traction << std::setprecision(17)
             << "Body omega1/Boundary conditions/Neumann=3: 0; " << -F / 4;
    const auto loaded =
      run_scene(uniaxial, common, {floating_upper, traction.str()});
    const auto counts = loaded->get_contact_solver().counts();
    std::cout << "exact contact " << exact << ": force "
              << std::setprecision(12) << vertical_force(*loaded) << " against "
              << F << std::setprecision(6) << "; " << counts.body_solve_sets
              << " sets of body solves, " << counts.newton_steps
              << " Newton steps" << std::endl;
    check(loaded->get_bodies()[0]->is_floating() &&
            loaded->get_bodies()[0]->get_rigid_modes().description() ==
              "translation in y",
          "exact " + exact + ": the loaded block is floating, free in y");
    check("exact " + exact + ": the contact force equals the load",
          relative(vertical_force(*loaded), F),
          1e-12);
    check("exact " + exact + ": displacements equal the pressed run's",
          displacement_difference(*loaded, *pressed),
          1e-9);
    check(loaded->summary().at("status") == "converged",
          "exact " + exact + ": converged");
    if (exact == "true")
    {
      // p = Delta / ((1 - nu^2) (H1 / E1 + H2 / E2)).
      const double p_exact = 1.366e-3 / (2 * (1 - 0.09) / 2.1e5);
      check("exact contact: force equals the closed form",
            relative(F, 4 * p_exact),
            1e-10);
    }
  }

  // 2. The rotation: the upper block on rollers on its top (u_1 = 0, so it
  //    can move down and turn about a point of its top) under the linear
  //    traction q(x) = q0 (1 + (x - 2) / 4). Its equilibrium fixes the
  //    force sum_q w_q p_q = q0 L and the moment about x = 2,
  //    sum_q w_q p_q (x_q - 2) = q0 int_0^4 (x - 2)^2 / 4 dx = 4 q0 / 3.
  //    The load of the multipliers is sum_i p_i phi_i. With the hat
  //    functions (Multiplier basis = standard) that is the reported field,
  //    and both hold to round-off: the rigid modes are exact in the finite
  //    element space and the Gauss rules integrate the linear load exactly.
  //    With the dual basis the load's moment is sum_i m_i p_i (x_i - 2)
  //    (int phi_i x = m_i x_i, biorthogonality), and the reported field
  //    sum_i p_i psi_i differs from it by p^T (M - D) (x - 2): zero at
  //    every inner node of a uniform zone, h^2/6 and -h^2/6 at the first and
  //    last, so by (h^2/6) (p_first - p_last), with the end values q(0) =
  //    q0 / 2 and q(4) = 3 q0 / 2 up to O(h) (allowed: 10 %). The force is
  //    sum_i m_i p_i either way.
  for (const std::string basis : {"standard", "dual"})
  {
    const double q0 = 150;
    const auto   turned =
      run_scene(uniaxial,
                {"Output directory=floating_body_output",
                 newton,
                 "Contact pair S/Formulation=exact",
                 "Contact solver/Tolerance=1e-10",
                 "Contact solver/Multiplier basis=" + basis},
                {"Body omega1/Boundary conditions/Dirichlet=3: x: 0; 0",
                 "Body omega1/Boundary conditions/Neumann=3: 0; -150 * (1 + (x "
                 "- 2) / 4)"});
    const double moment = pressure_moment(*turned, 2.);
    const auto  &faces  = turned->get_contact_pairs()[0]->zone_faces_1();
    const double h      = faces[0][0].distance(faces[0][1]);
    std::cout << std::setprecision(10) << "turning block, " << basis
              << " basis: force " << vertical_force(*turned) << ", moment "
              << moment << ", peak pressure "
              << summary_number(*turned, "max_pressure") << ", h " << h
              << std::endl;
    check(turned->get_bodies()[0]->get_rigid_modes().description() ==
            "translation in y and rotation",
          "rollers on the top leave the translation in y and a rotation");
    check("turning block, " + basis +
            " basis: the contact force equals the load",
          relative(vertical_force(*turned), 4 * q0),
          1e-10);
    if (basis == "standard")
      check("turning block: the contact moment equals the load's",
            relative(moment, 4 * q0 / 3),
            1e-9);
    else
    {
      double uniform = 0;
      for (const auto &f : faces)
        uniform = std::max(uniform, std::abs(f[0].distance(f[1]) - h));
      check("turning block: a uniform zone", uniform, 1e-12);
      const double predicted = h * h / 6 * (q0 / 2 - 3 * q0 / 2);
      check("turning block, dual basis: the reported moment differs from "
            "the load's by (h^2/6) (p_first - p_last)",
            relative(moment - 4 * q0 / 3, predicted),
            0.1);
    }
  }

  // 3. Hertz pressed by a force (prm/hertz_force.prm, half model): the
  //    cylinder loaded by a uniform pressure q on its top, against the same
  //    meshes pressed by u_2 = -Delta on a roller top, at the same vertical
  //    force. The two loadings differ by a self-equilibrated traction on
  //    the top, R = 5 away from a zone of half-width a = 0.15, whose effect
  //    on the zone decays like (a / R)^2 ~ 1e-3 (Saint-Venant): the peak
  //    pressure and the approach agree to that. The contact force equals the
  //    load to round-off.
  {
    const std::string              scene  = source_dir + "/prm/hertz_force.prm";
    const std::vector<std::string> common = {
      "Output directory=floating_body_output"};
    const auto pressed = run_scene(
      scene,
      common,
      {"Body cylinder/Boundary conditions/Neumann=",
       "Body cylinder/Boundary conditions/Dirichlet=13: x: 0; 0 | 12: y: 0; "
       "-0.01"});
    const double       F = vertical_force(*pressed);
    std::ostringstream q;
    q << std::setprecision(17) << "Constants=R=5, q=" << F / 5;
    const auto loaded = run_scene(scene, common, {q.str()});
    std::cout << std::setprecision(10) << "Hertz: force "
              << vertical_force(*loaded) << " against " << F
              << "; peak pressure " << summary_number(*loaded, "max_pressure")
              << " against " << summary_number(*pressed, "max_pressure")
              << "; approach " << summary_number(*loaded, "approach")
              << " against " << summary_number(*pressed, "approach") << "; "
              << loaded->get_contact_solver().counts().body_solve_sets
              << " sets of body solves" << std::endl;
    check("Hertz: the contact force equals the load",
          relative(vertical_force(*loaded), F),
          1e-12);
    check("Hertz: peak pressure equals the pressed run's",
          relative(summary_number(*loaded, "max_pressure"),
                   summary_number(*pressed, "max_pressure")),
          1e-3);
    check("Hertz: approach equals the pressed run's",
          relative(summary_number(*loaded, "approach"),
                   summary_number(*pressed, "approach")),
          1e-3);
  }

  // 4. What contact cannot hold is refused in one line: a floating body
  //    with another solver, a block free to slide along a flat zone, and
  //    the half cylinder on rollers on its top, which can turn about its
  //    axis without moving any gap (a mechanism).
  {
    const std::vector<std::string> common = {
      "Output directory=floating_body_output",
      "Contact pair S/Formulation=exact"};
    const std::string load =
      "Body omega1/Boundary conditions/Neumann=3: 0; -150";
    std::string message = error_message<InputError>(
      [&]
      {
        run_scene(
          uniaxial, common, {"Contact solver/Solver=dd", floating_upper, load});
      });
    std::cout << message << std::endl;
    check(message_names(message, {"Body omega1/Dirichlet", "dd-newton"}),
          "the DD refuses a floating body, naming dd-newton");
    message = error_message<InputError>(
      [&]
      {
        run_scene(uniaxial,
                  common,
                  {newton, "Body omega1/Boundary conditions/Dirichlet=", load});
      });
    std::cout << message << std::endl;
    check(message_names(message, {"Body omega1/Dirichlet", "translation in x"}),
          "a block free to slide is refused, naming its Dirichlet entry");
    message = error_message<DivergenceError>(
      [&]
      {
        run_scene(source_dir + "/prm/hertz_cylinder.prm",
                  {"Output directory=floating_body_output"},
                  {"Body cylinder/Boundary conditions/Dirichlet=12: x: 0; 0",
                   "Body cylinder/Boundary conditions/Neumann=12: 0; -0.2"});
      });
    std::cout << message << std::endl;
    check(message_names(message, {"mechanism", "cylinder"}),
          "a cylinder free to turn about its axis is reported");
  }

  return report();
}
