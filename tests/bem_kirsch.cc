// DESCRIPTION: BEM convergence for the Kirsch plate (square [-4,4]^2 with
// a hole of radius 1, Kirsch tractions on the outer sides, free hole):
// traction only, so the system is bordered with the rigid modes; interior
// stresses (r = 1.3 ... 3.5) and nodal displacements (rigid part removed)
// converge at rate ~2; finest errors against doc/bem-method.md §6(c)
#include <deal.II/base/function.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <ddcontact/bem/boundary_element_solver.h>

#include "bem_test_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const double radius = 1., s0 = 100.;

  SymmetricTensor<2, 2>
  exact_stress(const Point<2> &x)
  {
    const double r = x.norm(), theta = std::atan2(x[1], x[0]);
    const double q = radius * radius / (r * r);
    const double c = std::cos(2 * theta), s = std::sin(2 * theta);
    const double s_rr = s0 / 2 * (1 - q) + s0 / 2 * (1 - 4 * q + 3 * q * q) * c;
    const double s_tt = s0 / 2 * (1 + q) - s0 / 2 * (1 + 3 * q * q) * c;
    const double s_rt = -s0 / 2 * (1 + 2 * q - 3 * q * q) * s;
    const Tensor<1, 2>    e_r = x / r, e_t{{-e_r[1], e_r[0]}};
    SymmetricTensor<2, 2> sigma;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        sigma[i][j] = s_rr * e_r[i] * e_r[j] + s_tt * e_t[i] * e_t[j] +
                      s_rt * (e_r[i] * e_t[j] + e_t[i] * e_r[j]);
    return sigma;
  }

  Tensor<1, 2>
  exact_displacement(const Point<2> &x, const ElasticConstants &m)
  {
    const double mu = m.mu(), kappa = 3 - 4 * m.poisson_ratio;
    const double r = x.norm(), theta = std::atan2(x[1], x[0]);
    const double a2 = radius * radius, a4 = a2 * a2;
    const double c = std::cos(2 * theta), s = std::sin(2 * theta);
    const double u_r = s0 / (4 * mu) *
                       (r * ((kappa - 1) / 2 + c) +
                        a2 / r * (1 + (1 + kappa) * c) - a4 / (r * r * r) * c);
    const double u_t =
      s0 / (4 * mu) * ((1 - kappa) * a2 / r - r - a4 / (r * r * r)) * s;
    const Tensor<1, 2> e_r = x / r, e_t{{-e_r[1], e_r[0]}};
    return u_r * e_r + u_t * e_t;
  }

  /** Kirsch traction sigma n on one side of the square. */
  class SideTraction : public Function<2>
  {
  public:
    SideTraction(const Tensor<1, 2> &normal)
      : Function<2>(2)
      , normal(normal)
    {
    }

    double
    value(const Point<2> &x, const unsigned int c) const override
    {
      return (exact_stress(x) * normal)[c];
    }

    const Tensor<1, 2> normal;
  };

} // namespace

int
main()
{
  const ElasticConstants material = steel();

  // Colorized plate_with_a_hole: 0 left, 1 right, 2 bottom, 3 top, 4 hole
  // (traction free, not listed).
  BoundaryConditions<2> bc;
  bc.neumann[0] = std::make_shared<SideTraction>(Tensor<1, 2>{{-1., 0.}});
  bc.neumann[1] = std::make_shared<SideTraction>(Tensor<1, 2>{{1., 0.}});
  bc.neumann[2] = std::make_shared<SideTraction>(Tensor<1, 2>{{0., -1.}});
  bc.neumann[3] = std::make_shared<SideTraction>(Tensor<1, 2>{{0., 1.}});

  std::vector<Point<2>> interior_points;
  for (const double r : {1.3, 2.0, 3.5})
    for (const double theta : {0., 30., 60., 90., 135.})
      interior_points.emplace_back(r * std::cos(theta * numbers::PI / 180),
                                   r * std::sin(theta * numbers::PI / 180));

  ConvergenceStudy study("u (max rel)", "sigma/s0");
  double           sxx_bem = 0, sxx_exact = 0;
  for (unsigned int level = 1; level <= 4; ++level)
  {
    Triangulation<2> tria;
    GridGenerator::plate_with_a_hole(
      tria, radius, 2., 2., 2., 2., 2., Point<2>(), 0, 1, 1., 2, true);
    tria.refine_global(level);
    const Q1Displacement space(tria);

    unsigned int n_hole = 0;
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == 4)
        ++n_hole;

    BoundaryElementSolver bem(material, bc);
    bem.setup(space.dof_handler, space.mapping);
    bem.solve();
    if (bem.n_rigid_modes() != 3)
    {
      std::cout << "FAIL: a floating body needs 3 rigid modes, got "
                << bem.n_rigid_modes() << std::endl;
      return 1;
    }

    // Nodal displacements with the least-squares rigid part of the
    // difference removed (the bordered system fixes its own rigid part).
    std::vector<Tensor<1, 2>> difference(bem.n_nodes());
    double                    u_max = 0;
    for (unsigned int i = 0; i < bem.n_nodes(); ++i)
    {
      const auto u  = exact_displacement(bem.node_position(i), material);
      difference[i] = bem.node_displacement(i) - u;
      u_max         = std::max(u_max, u.norm());
    }
    remove_rigid_motion(bem, difference);
    double u_error = 0;
    for (const auto &d : difference)
      u_error = std::max(u_error, d.norm());

    double     s_error = 0;
    const auto stress  = bem.stress_at_points(interior_points);
    for (unsigned int q = 0; q < interior_points.size(); ++q)
      s_error = std::max(s_error,
                         (stress[q] - exact_stress(interior_points[q])).norm());
    sxx_bem   = bem.stress_at_points({Point<2>(0., 1.3)})[0][0][0];
    sxx_exact = exact_stress(Point<2>(0., 1.3))[0][0];

    study.table.add_value("N (hole)", n_hole);
    study.table.add_value("elements", bem.n_elements());
    study.add(u_error / u_max, s_error / s0);
  }
  study.print_table();
  std::cout << std::setprecision(6) << "sigma_xx at (0, 1.3): BEM "
            << sxx_bem / s0 << " s0, exact " << sxx_exact / s0 << " s0"
            << std::endl;

  // Smooth solution, corners of the square are Neumann-Neumann: both
  // converge at 2.0 in doc/bem-method.md §6(c).
  study.check_rates(1.7);
  // doc/bem-method.md §6(c) at N = 128 (hole): sigma/s0 2.2e-3, u 5.9e-4; same
  // order.
  check(study.sigma.back() < 2.2e-2, "finest sigma/s0 error < 10 x 2.2e-3");
  check(study.u.back() < 5.9e-3, "finest u error < 10 x 5.9e-4");

  return report();
}
