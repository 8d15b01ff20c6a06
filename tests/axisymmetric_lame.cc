// DESCRIPTION: axisymmetric bodies (Geometry = axisymmetric) against Lamé's
// closed-form thick cylinder: L2 and H1 rates of Q1 and Q2 (2, 1 and 3, 2)
// with hanging nodes, the hoop stress at the bore, the energy as the work of
// the pressure over the whole ring (2 pi r), a solid cylinder through the
// axis reproduced to round-off (u_r = A r is in Q1 and the axis gets
// u_r = 0 by itself), the rigid modes of a section, and r < 0 refused;
// the residual estimator with the hoop terms: the H1 rate on Lamé's
// cylinder and zero on the solid cylinder, which Q1 solves exactly
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <ddcontact/adaptivity/residual_estimator.h>
#include <ddcontact/body/elastic_body.h>

#include "test_tools.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /**
   * A cylinder a <= r <= b, 0 <= z <= L, held at u_z = 0 on its ends
   * (eps_zz = 0) and under the pressure p on its bore. Lamé:
   *   u_r = A r + B / r,  B = p a^2 b^2 / (2 mu (b^2 - a^2)),
   *                       A = p a^2 / (2 (lambda + mu) (b^2 - a^2)),
   *   sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2 (-p at a, 0 at b),
   *   sigma_tt = 2 (lambda + mu) A + 2 mu B / r^2,
   *   sigma_zz = 2 lambda A.
   * (From the equilibrium d sigma_rr/dr + (sigma_rr - sigma_tt)/r = 0 with
   * the two boundary values; a = 0 gives the solid cylinder u_r = A r
   * with A = -p_out / (2 (lambda + mu)) under an outer pressure p_out.)
   */
  struct Lame
  {
    double a, b, p, lambda, mu;

    double
    B() const
    {
      return p * a * a * b * b / (2. * mu * (b * b - a * a));
    }
    double
    A() const
    {
      return p * a * a / (2. * (lambda + mu) * (b * b - a * a));
    }
    double
    u_r(const double r) const
    {
      return A() * r + B() / r;
    }
    double
    sigma_tt(const double r) const
    {
      return 2. * (lambda + mu) * A() + 2. * mu * B() / (r * r);
    }
  };

  class LameDisplacement : public Function<2>
  {
  public:
    explicit LameDisplacement(const Lame &lame)
      : Function<2>(2)
      , lame(lame)
    {
    }
    double
    value(const Point<2> &x, const unsigned int c) const override
    {
      return c == 0 ? lame.u_r(x[0]) : 0.;
    }
    Tensor<1, 2>
    gradient(const Point<2> &x, const unsigned int c) const override
    {
      Tensor<1, 2> g;
      if (c == 0)
        g[0] = lame.A() - lame.B() / (x[0] * x[0]);
      return g;
    }

  private:
    const Lame lame;
  };

  BodyParameters
  cylinder(const double       a,
           const double       b,
           const double       L,
           const unsigned int degree,
           const unsigned int n_r)
  {
    BodyParameters p;
    p.name                    = "cylinder";
    p.geometry                = Geometry::axisymmetric;
    p.degree                  = degree;
    p.corner_1                = Point<2>(a, 0);
    p.corner_2                = Point<2>(b, L);
    p.subdivisions            = {n_r, 1};
    p.material.youngs_modulus = 200.;
    p.material.poisson_ratio  = 0.3;
    // Ids of the subdivided rectangle: 0 left (r = a), 1 right, 2 bottom,
    // 3 top.
    p.dirichlet = "2: y: 0; 0 | 3: y: 0; 0";
    return p;
  }

  /** The residual estimator's global estimate sqrt(sum eta_K^2). */
  double
  residual_estimate(const ElasticBody<2> &body, const BodyVector &u)
  {
    ResidualEstimator estimator(body);
    estimator.estimate(u, {});
    return estimator.indicators().l2_norm();
  }

  void
  thick_cylinder_rates(const unsigned int degree, const unsigned int n_cycles)
  {
    const double a = 1., b = 3., L = 0.5, pressure = 2.;
    auto         p = cylinder(a, b, L, degree, 4);
    p.neumann      = "0: " + std::to_string(pressure) + "; 0";
    // Hanging nodes near the bore, where the solution varies most.
    p.refinement_box = {a, 0, a + 0.5, L};
    p.box_refinement = 1;
    const Lame lame{a, b, pressure, p.material.lambda(), p.material.mu()};
    std::cout << "\nthick cylinder, Q" << degree << ": expected rates L2 "
              << degree + 1 << ", H1 " << degree << std::endl;

    ElasticBody<2> body(p, {});
    body.make_mesh();
    auto                  &tria = body.get_triangulation();
    const LameDisplacement exact(lame);
    const QGauss<2>        quadrature(degree + 2);
    RateTable              table;
    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
    {
      if (cycle > 0)
        tria.refine_global(1);
      body.setup_and_factorize();
      body.solve();
      Vector<double> cellwise(tria.n_active_cells());
      VectorTools::integrate_difference(body.get_mapping(),
                                        body.get_dof_handler(),
                                        body.get_solution(),
                                        exact,
                                        cellwise,
                                        quadrature,
                                        VectorTools::L2_norm);
      const double l2 =
        VectorTools::compute_global_error(tria, cellwise, VectorTools::L2_norm);
      VectorTools::integrate_difference(body.get_mapping(),
                                        body.get_dof_handler(),
                                        body.get_solution(),
                                        exact,
                                        cellwise,
                                        quadrature,
                                        VectorTools::H1_seminorm);
      const double h1 = VectorTools::compute_global_error(
        tria, cellwise, VectorTools::H1_seminorm);
      table.add_value("dofs", body.n_dofs());
      table.add_value("L2", l2);
      table.add_value("H1", h1);
      // The residual estimator bounds the energy error from above and
      // below (Verfuerth), so it converges at the H1 rate. Without the hoop
      // terms it would not: the bore's traction would miss lambda u_r / r
      // (a residual of O(1) on the face, rate 1/2) and, in Q2, the cell
      // residual would miss (lambda + 2 mu)(u_r' / r - u_r / r^2), O(1)
      // for Lamé's u_r = A r + B / r (rate 1 instead of 2).
      table.add_value("eta", residual_estimate(body, body.get_solution()));
    }
    print_with_rates(table, {"L2", "H1", "eta"});
    // Every rate between consecutive levels within 0.1 of the theory (the
    // levels are in the asymptotic range; measured in the output above).
    for (const auto &[key, rate] : std::vector<std::pair<std::string, double>>{
           {"L2", degree + 1.}, {"H1", 1. * degree}, {"eta", 1. * degree}})
    {
      const auto rates = table.log2_rates(key);
      for (unsigned int i = 0; i < rates.size(); ++i)
        check(key + " rate of cycle " + std::to_string(i + 1),
              std::abs(rates[i] - rate),
              0.1);
    }

    // On the finest mesh: the hoop stress at the bore (the largest stress
    // of the cylinder, at the cell centre next to it: an O(h) offset from
    // r = a, hence the tolerance of a few h |d sigma_tt / dr| / sigma_tt)
    // and the energy, which the pressure's work gives over the whole ring:
    // 1/2 a(u, u) = 1/2 p u_r(a) 2 pi a L, converging at twice the H1 rate.
    const auto   values = body.stresses().at_point(Point<2>(a + 1e-9, L / 2));
    const double hoop_exact = lame.sigma_tt(a);
    const double h = GridTools::minimal_cell_diameter(tria) / std::sqrt(2.);
    std::cout << "  sigma_tt at the bore " << values.out_of_plane << ", Lamé "
              << hoop_exact << std::endl;
    check("hoop stress at the bore, relative (O(h) in Q1, O(h^2) in Q2)",
          relative(values.out_of_plane, hoop_exact),
          degree == 1 ? 3. * h : 3. * h * h);
    const double energy = body.stresses().strain_energy();
    const double energy_exact =
      0.5 * pressure * lame.u_r(a) * 2. * numbers::PI * a * L;
    std::cout << "  energy " << energy << ", 1/2 p u_r(a) 2 pi a L "
              << energy_exact << std::endl;
    check("energy = work of the pressure on the ring, relative (O(h^2p))",
          relative(energy, energy_exact),
          degree == 1 ? 4. * h * h : 4. * h * h * h * h);
  }

  void
  solid_cylinder()
  {
    // u_r = A r, u_z = 0: constant strains and stresses, in the Q1 space;
    // every integrand of the weak form is then a polynomial that the
    // assembly's Gauss rule integrates exactly, so the discrete solution is
    // the exact one to round-off, the axis included (no condition is
    // written there).
    const double b = 2., L = 1., p_out = 3.;
    auto         p   = cylinder(0., b, L, 1, 3);
    p.neumann        = "1: " + std::to_string(-p_out) + "; 0";
    p.refinement_box = {0., 0., 0.5, 0.5};
    p.box_refinement = 1;
    ElasticBody<2> body(p, {});
    body.make_mesh();
    body.get_triangulation().refine_global(1);
    body.setup_and_factorize();
    body.solve();
    const double A = -p_out / (2. * (p.material.lambda() + p.material.mu()));
    std::cout << "\nsolid cylinder under an outer pressure, Q1 with hanging "
                 "nodes"
              << std::endl;
    double u_error = 0, stress_error = 0;
    for (const auto &x : {Point<2>(0., 0.5),
                          Point<2>(0.3, 0.1),
                          Point<2>(1.1, 0.7),
                          Point<2>(2., 1.)})
    {
      const auto v = body.stresses().at_point(x);
      u_error      = std::max({u_error,
                               std::abs(v.displacement[0] - A * x[0]),
                               std::abs(v.displacement[1])});
      // sigma_rr = sigma_tt = -p_out, sigma_zz = 2 lambda A, sigma_rz = 0.
      stress_error =
        std::max({stress_error,
                  std::abs(v.stress[0][0] + p_out),
                  std::abs(v.out_of_plane + p_out),
                  std::abs(v.stress[1][1] - 2. * p.material.lambda() * A),
                  std::abs(v.stress[0][1])});
    }
    check("u = (A r, 0) at four points, the axis included, / |A| b",
          u_error / (std::abs(A) * b),
          1e-12);
    check("stresses -p, -p, 2 lambda A, 0, / p", stress_error / p_out, 1e-11);
    // The exact solution has no residual: the outer face's traction
    // sigma n = -p_out e_r holds only with the hoop strain's lambda u_r / r
    // in sigma_rr. The scale: the estimate of u = 0, the load alone.
    const double eta  = residual_estimate(body, body.get_solution());
    const double load = residual_estimate(body, BodyVector(body.n_dofs()));
    std::cout << "  residual estimate " << eta << ", of u = 0: " << load
              << std::endl;
    check(
      "residual estimate of the exact solution / of u = 0", eta / load, 1e-11);
    // The ends carry the axial force sigma_zz pi b^2 as a reaction: no
    // rigid mode, since the ends hold the axial translation.
    check(body.get_rigid_modes().size() == 0,
          "a cylinder held at its ends has no free rigid mode");
  }

  void
  rigid_modes_and_refusal()
  {
    // With nothing held, a section of revolution can only translate along
    // its axis: the radial translation strains the hoops.
    auto p      = cylinder(1., 2., 1., 1, 2);
    p.dirichlet = "";
    ElasticBody<2> ring(p, {});
    ring.make_mesh();
    ring.setup_system();
    std::cout << "\nfree ring: " << ring.get_rigid_modes().description()
              << std::endl;
    check(ring.get_rigid_modes().size() == 1 &&
            ring.get_rigid_modes().description() == "translation in y",
          "a free ring has one rigid mode, the translation along the axis");

    auto       q       = cylinder(-0.5, 1., 1., 1, 2);
    const auto message = error_message<InputError>(
      [&]()
      {
        ElasticBody<2> body(q, {});
        body.make_mesh();
      });
    std::cout << "  " << message << std::endl;
    check(message.find("Body cylinder/Mesh") != std::string::npos &&
            message.find("r = x < 0") != std::string::npos,
          "a section reaching r < 0 is refused, naming the body");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Q1 from 8 x 2 cells (and a refined box), Q2 from the same: the rates
  // read within 0.05 of 2, 1 and 3, 2 from the second level on.
  thick_cylinder_rates(1, 5);
  thick_cylinder_rates(2, 4);
  solid_cylinder();
  rigid_modes_and_refusal();
  return report();
}
