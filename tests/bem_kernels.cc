// DESCRIPTION: Kelvin kernels U, T, D, S against the golden values of
// doc/bem-method.md §1.4, the fused Somigliana integrand against the explicit
// kernels, the balance of a point force, and the free term of corners (closed
// form of doc/bem-method.md §2.1 with the A ln(L_in/L_out) term) against the
// diagonal blocks the rigid-body trick produces in the assembled BEM system
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/bem/kelvin_solution.h>

#include "bem_test_tools.h"

#include <iomanip>
#include <iostream>
#include <random>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  // Diagonal blocks of the assembled system against c_ij + A ln(L_in/L_out)
  // [[0, 1], [-1, 0]] at every boundary node of the mesh.
  void
  check_free_terms(const std::string &name, Triangulation<2> &tria)
  {
    const double     nu = 0.3;
    ElasticConstants material;
    material.youngs_modulus = 7.;
    material.poisson_ratio  = nu;
    // Traction free everywhere: a floating body; the diagonal blocks do
    // not depend on the boundary conditions.
    BoundaryConditions<2> bc;

    const Q1Displacement  space(tria);
    BoundaryElementSolver bem(material, bc);
    bem.setup(space.dof_handler, space.mapping);

    const KelvinSolution kelvin(1., nu);
    const double         a = (1. - 2. * nu) / (4. * numbers::PI * (1. - nu));
    // Node -> (incoming element, outgoing element).
    std::vector<std::array<unsigned int, 2>> adjacent(bem.n_nodes());
    for (unsigned int e = 0; e < bem.n_elements(); ++e)
    {
      adjacent[bem.element_nodes(e)[1]][0] = e;
      adjacent[bem.element_nodes(e)[0]][1] = e;
    }
    double       error     = 0;
    unsigned int n_corners = 0, n_unequal = 0;
    for (unsigned int i = 0; i < bem.n_nodes(); ++i)
    {
      const auto   in      = bem.element_nodes(adjacent[i][0]);
      const auto   out     = bem.element_nodes(adjacent[i][1]);
      const auto   x       = bem.node_position(i);
      const auto   dir_in  = bem.node_position(in[0]) - x;
      const auto   dir_out = bem.node_position(out[1]) - x;
      const double l_in = dir_in.norm(), l_out = dir_out.norm();
      Tensor<2, 2> expected = kelvin.corner_free_term(dir_out, dir_in);
      expected[0][1] += a * std::log(l_in / l_out);
      expected[1][0] -= a * std::log(l_in / l_out);
      error = std::max(error, (bem.diagonal_block(i) - expected).norm());
      const double cross = dir_in[0] * dir_out[1] - dir_in[1] * dir_out[0];
      if (std::abs(cross) > 1e-8 * l_in * l_out)
        ++n_corners;
      if (std::abs(l_in / l_out - 1.) > 1e-8)
        ++n_unequal;
    }
    std::ostringstream what;
    what << name << ": " << bem.n_nodes() << " nodes, " << n_corners
         << " corners, " << n_unequal << " with L_in != L_out";
    check(what.str(), error, 1e-9);
  }
} // namespace

int
main()
{
  const double         mu = 2.5, nu = 0.3;
  const KelvinSolution kelvin(mu, nu);
  const Point<2>       xi(0.1, -0.2), x(0.9, 0.3);
  const Tensor<1, 2>   n{{0.6, 0.8}};

  // Golden values of doc/bem-method.md §1.4, verified there against finite
  // differences of Hooke's law applied to U.
  const double u_ref[4] = {1.873439114403e-02,
                           1.021861592885e-02,
                           1.021861592885e-02,
                           8.771240613397e-03};
  const double t_ref[4] = {-2.066227103996e-01,
                           -8.366635311636e-02,
                           -1.184096472745e-01,
                           -1.081106602091e-01};
  const double d_ref[8] = {1.878388276360e-01,
                           1.173992672725e-01,
                           1.173992672725e-01,
                           1.653349094107e-02,
                           6.630618762824e-02,
                           9.828241837190e-02,
                           9.828241837190e-02,
                           6.142651148243e-02};
  const double s_ref[8] = {-9.615671146661e-01,
                           -9.610349622774e-01,
                           -9.610349622774e-01,
                           -2.927966945780e-01,
                           -9.610349622774e-01,
                           -2.927966945780e-01,
                           -2.927966945780e-01,
                           7.199215527202e-01};

  const auto u       = kelvin.displacement_kernel(xi, x);
  const auto t       = kelvin.traction_kernel(xi, x, n);
  const auto d       = kelvin.stress_traction_kernel(xi, x);
  const auto s       = kelvin.stress_displacement_kernel(xi, x, n);
  double     error_u = 0, error_t = 0, error_d = 0, error_s = 0;
  for (unsigned int i = 0; i < 2; ++i)
    for (unsigned int j = 0; j < 2; ++j)
    {
      error_u = std::max(error_u, std::abs(u[i][j] - u_ref[2 * i + j]));
      error_t = std::max(error_t, std::abs(t[i][j] - t_ref[2 * i + j]));
      for (unsigned int k = 0; k < 2; ++k)
      {
        error_d =
          std::max(error_d, std::abs(d[k][i][j] - d_ref[4 * k + 2 * i + j]));
        error_s =
          std::max(error_s, std::abs(s[k][i][j] - s_ref[4 * k + 2 * i + j]));
      }
    }
  // The golden values carry 13 significant digits.
  check("golden values U_ij", error_u, 1e-13);
  check("golden values T_ij", error_t, 1e-12);
  check("golden values D_kij", error_d, 1e-12);
  check("golden values S_kij", error_s, 1e-12);

  // The fused integrand D t - S u and U t - T u against the explicit
  // kernels at random configurations; S is totally symmetric in 2D.
  std::mt19937                           rng(3);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  double error_fused = 0, error_fused_u = 0, error_symmetry = 0;
  for (unsigned int trial = 0; trial < 100; ++trial)
  {
    const Point<2> p(uniform(rng), uniform(rng)), q(uniform(rng), uniform(rng));
    Tensor<1, 2>   normal{{uniform(rng), uniform(rng)}};
    normal /= normal.norm();
    const Tensor<1, 2>    traction{{uniform(rng), uniform(rng)}};
    const Tensor<1, 2>    displacement{{uniform(rng), uniform(rng)}};
    const auto            dk = kelvin.stress_traction_kernel(p, q);
    const auto            sk = kelvin.stress_displacement_kernel(p, q, normal);
    SymmetricTensor<2, 2> explicit_sum;
    for (unsigned int k = 0; k < 2; ++k)
      explicit_sum += traction[k] * dk[k] - displacement[k] * sk[k];
    const auto fused =
      kelvin.stress_integrand(p, q, normal, traction, displacement);
    error_fused = std::max(error_fused,
                           (fused - explicit_sum).norm() /
                             std::max(1., explicit_sum.norm()));
    Tensor<1, 2> explicit_u =
      kelvin.displacement_kernel(p, q) * traction -
      kelvin.traction_kernel(p, q, normal) * displacement;
    error_fused_u = std::max(
      error_fused_u,
      (kelvin.displacement_integrand(p, q, normal, traction, displacement) -
       explicit_u)
        .norm());
    // S_kij = S_ikj: swap the traction index with a stress index.
    error_symmetry = std::max({error_symmetry,
                               std::abs(sk[0][1][1] - sk[1][0][1]),
                               std::abs(sk[1][0][0] - sk[0][1][0])});
  }
  check("fused integrand D t - S u vs explicit kernels", error_fused, 1e-13);
  check("fused integrand U t - T u vs explicit kernels", error_fused_u, 1e-13);
  check("total symmetry of S_kij in 2D", error_symmetry, 1e-12);

  // A unit point force is balanced by the surrounding material: the
  // integral of T over a circle around xi with the normal pointing away
  // from xi is -delta_ij (doc/bem-method.md §1.5); this fixes the sign of T.
  {
    const QGauss<1> rule(32);
    Tensor<2, 2>    integral;
    const double    radius = 0.3;
    for (unsigned int q = 0; q < rule.size(); ++q)
    {
      const double       phi = 2. * numbers::PI * rule.point(q)[0];
      const Tensor<1, 2> e{{std::cos(phi), std::sin(phi)}};
      integral += kelvin.traction_kernel(xi, xi + radius * e, e) *
                  (rule.weight(q) * 2. * numbers::PI * radius);
    }
    check("closed circle: integral of T_ij = -delta_ij",
          (integral + Tensor<2, 2>(unit_symmetric_tensor<2>())).norm(),
          1e-12);
  }

  // Smooth point: c = delta/2.
  {
    const Tensor<1, 2> out{{1., 0.}}, in{{-1., 0.}};
    check("free term at a smooth point = delta/2",
          (kelvin.corner_free_term(out, in) -
           0.5 * Tensor<2, 2>(unit_symmetric_tensor<2>()))
            .norm(),
          1e-15);
  }

  // Free terms of the assembled systems: a general quadrilateral (four
  // corners with unequal edges), and an L-shaped domain (reentrant
  // corner) refined towards the reentrant corner (element length jumps at
  // straight nodes).
  {
    Triangulation<2> tria;
    GridGenerator::general_cell(tria,
                                std::vector<Point<2>>{Point<2>(0., 0.),
                                                      Point<2>(3., 0.2),
                                                      Point<2>(0.4, 1.7),
                                                      Point<2>(2.5, 2.2)});
    check_free_terms("general quadrilateral", tria);
    tria.refine_global(2);
    check_free_terms("general quadrilateral, refined twice", tria);
  }
  {
    Triangulation<2> tria;
    GridGenerator::hyper_L(tria, -1., 1.);
    tria.refine_global(1);
    for (unsigned int round = 0; round < 2; ++round)
    {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->center().norm() < 0.5)
          cell->set_refine_flag();
      tria.execute_coarsening_and_refinement();
    }
    check_free_terms("L-shape refined at the reentrant corner", tria);
  }

  return report();
}
