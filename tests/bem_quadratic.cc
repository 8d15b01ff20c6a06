// DESCRIPTION: quadratic boundary elements (the trace of Q2/P2, (22)-(23)):
// the exact singular moments against graded Gauss quadrature; a linear
// stress state (quadratic displacement), which quadratic elements hold and
// linear ones do not, reproduced to quadrature accuracy on Q2 and P2 meshes
// with clamped, all-Dirichlet and floating data; the smooth midpoint's
// diagonal block delta/2; and on the Timoshenko-Goodier cantilever the
// observed rates against the theory, degree 2 against degree 1
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <ddcontact/bem/boundary_integration.h>

#include "bem_test_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /**
   * Integral of f(t) over t = s - s0 in [-s0, 1 - s0], with a (log or, as
   * a principal value, 1/t) singularity at t = 0, independent of the closed
   * forms: 8-point Gauss on panels graded geometrically towards 0, the
   * same panels on both sides out to the shorter side's length m (so that
   * the odd 1/t part cancels as in the principal value), then 16 uniform
   * panels on the rest of the longer side (at distance >= m from 0). The
   * innermost 2^-50 m is left out: O(2^-50) of a bounded integrand,
   * 2^-50 ln 2^-50 of a log. Working in t keeps r = |t| L exact near 0.
   */
  template <typename Integrand>
  Tensor<2, 2>
  graded_integral(const Integrand &f, const double s0)
  {
    const QGauss<1> gauss(8);
    Tensor<2, 2>    sum;
    const auto      panel = [&](const double begin, const double end)
    {
      for (unsigned int q = 0; q < gauss.size(); ++q)
        sum += (gauss.weight(q) * (end - begin)) *
               f(begin + (end - begin) * gauss.point(q)[0]);
    };
    const double a = s0, b = 1. - s0;
    const double m = (a == 0. || b == 0.) ? 1. : std::min(a, b);
    for (unsigned int j = 0; j < 50; ++j)
    {
      const double outer = m * std::pow(0.5, j), inner = 0.5 * outer;
      if (outer <= b)
        panel(inner, outer);
      if (outer <= a)
        panel(-outer, -inner);
    }
    const double begin = b > m ? m : -a, end = b > m ? b : -m;
    for (unsigned int p = 0; p < 16 && end > begin; ++p)
      panel(begin + p * (end - begin) / 16,
            begin + (p + 1) * (end - begin) / 16);
    return sum;
  }

  /** 0. BoundaryIntegration::singular_element_blocks() for linear and
   * quadratic shapes, sources at the ends, the midpoint and an off-node
   * point, against graded_integral() of the Kelvin kernels. */
  void
  check_singular_moments()
  {
    const KelvinSolution kelvin(1., 0.3);
    const Tensor<1, 2>   tau{{0.6, 0.8}};
    const Tensor<1, 2>   n{{tau[1], -tau[0]}};
    const double         L = 0.3;
    for (const unsigned int degree : {1u, 2u})
    {
      Triangulation<2> tria;
      GridGenerator::hyper_cube(tria);
      const Q1Displacement space(tria, degree);
      BoundaryMesh         mesh;
      mesh.reinit(space.dof_handler, space.mapping);

      double g_error = 0, h_error = 0, scale = 0;
      for (const double s0 : {0., 1., 0.5, 0.25})
      {
        std::array<Tensor<2, 2>, 3> g, h;
        BoundaryIntegration::singular_element_blocks(
          mesh, kelvin, L, tau, n, s0, g, h);
        // The source at the origin, x = t L tau (t = s - s0).
        const Point<2> xi;
        for (unsigned int k = 0; k < mesh.n_element_nodes(); ++k)
        {
          const double n_k_s0 = mesh.shape_values(s0)[k];
          const auto   g_ref  = graded_integral(
            [&](const double t)
            {
              return (L * mesh.shape_values(s0 + t)[k]) *
                     kelvin.displacement_kernel(xi, Point<2>(t * L * tau));
            },
            s0);
          g_error = std::max(g_error, (g[k] - g_ref).norm());
          scale   = std::max(scale, g_ref.norm());
          // The principal value exists where N_k(s0) = 0 or s0 is inside.
          if (std::abs(n_k_s0) > 1e-14 && (s0 == 0. || s0 == 1.))
            continue;
          const auto h_ref = graded_integral(
            [&](const double t)
            {
              return (L * mesh.shape_values(s0 + t)[k]) *
                     kelvin.traction_kernel(xi, Point<2>(t * L * tau), n);
            },
            s0);
          h_error = std::max(h_error, (h[k] - h_ref).norm());
        }
      }
      // Exact moments against a quadrature accurate to ~1e-15: round-off.
      check("degree " + std::to_string(degree) +
              ": int U N_k exact (vs graded Gauss, relative)",
            g_error / scale,
            1e-12);
      check("degree " + std::to_string(degree) +
              ": PV int T N_k exact (vs graded Gauss)",
            h_error,
            1e-12);
    }
  }

  /**
   * A linear stress state sigma0 + c1 [[y, 0], [0, 0]] + c2 [[0, 0], [0, x]]
   * (equilibrated, compatible) in plane strain: the displacement is
   * quadratic, u = eps0 x + (a1 x y, b1 y^2/2 - a1 x^2/2) + (b2 x^2/2 -
   * a2 y^2/2, a2 x y) with a = (1-nu^2) c / E, b = -nu (1+nu) c / E.
   */
  class QuadraticField : public Function<2>
  {
  public:
    QuadraticField(const ElasticConstants &m)
      : Function<2>(2)
      , E(m.youngs_modulus)
      , nu(m.poisson_ratio)
    {
      sigma0[0][0] = 120.;
      sigma0[1][1] = -75.;
      sigma0[0][1] = 40.;
    }

    SymmetricTensor<2, 2>
    stress(const Point<2> &p) const
    {
      SymmetricTensor<2, 2> s = sigma0;
      s[0][0] += c1 * p[1];
      s[1][1] += c2 * p[0];
      return s;
    }

    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      const double x = p[0], y = p[1], f = (1 - nu * nu) / E,
                   g  = -nu * (1 + nu) / E;
      const double a1 = f * c1, b1 = g * c1, a2 = f * c2, b2 = g * c2;
      Tensor<1, 2> u;
      u[0] = (f * sigma0[0][0] + g * sigma0[1][1]) * x +
             (1 + nu) / E * sigma0[0][1] * y + a1 * x * y + b2 * x * x / 2 -
             a2 * y * y / 2;
      u[1] = (f * sigma0[1][1] + g * sigma0[0][0]) * y +
             (1 + nu) / E * sigma0[0][1] * x + b1 * y * y / 2 - a1 * x * x / 2 +
             a2 * x * y;
      return u[c];
    }

    const double          E, nu, c1 = 90., c2 = -60.;
    SymmetricTensor<2, 2> sigma0;
  };

  /** Traction sigma(x) n on a side with fixed normal n. */
  class SideTraction : public Function<2>
  {
  public:
    SideTraction(const QuadraticField &field, const Tensor<1, 2> &normal)
      : Function<2>(2)
      , field(field)
      , normal(normal)
    {
    }

    double
    value(const Point<2> &x, const unsigned int c) const override
    {
      return (field.stress(x) * normal)[c];
    }

    const QuadraticField &field;
    const Tensor<1, 2>    normal;
  };

  struct PatchErrors
  {
    double u = 0, t = 0, sigma = 0, midpoint_block = 0;
  };

  /** Solve the linear stress state on the rectangle (0,2)x(0,1) (ids 0
   * left, 1 right, 2 bottom, 3 top) with the displacement prescribed on
   * @p dirichlet_ids and the traction elsewhere; relative max errors. */
  PatchErrors
  linear_stress_patch(const DoFHandler<2>                   &dof_handler,
                      const Mapping<2>                      &mapping,
                      const std::vector<types::boundary_id> &dirichlet_ids)
  {
    const ElasticConstants material = steel();
    const auto             field = std::make_shared<QuadraticField>(material);
    const std::array<Tensor<1, 2>, 4> normals{{Tensor<1, 2>{{-1., 0.}},
                                               Tensor<1, 2>{{1., 0.}},
                                               Tensor<1, 2>{{0., -1.}},
                                               Tensor<1, 2>{{0., 1.}}}};
    BoundaryConditions<2>             bc;
    for (types::boundary_id id = 0; id < 4; ++id)
      if (std::count(dirichlet_ids.begin(), dirichlet_ids.end(), id))
        bc.dirichlet[id] = {ComponentMask(2, true), field};
      else
        bc.neumann[id] = std::make_shared<SideTraction>(*field, normals[id]);

    BoundaryElementSolver bem(material, bc);
    bem.setup(dof_handler, mapping);
    bem.solve();

    PatchErrors errors;
    double      s_max = 0;
    for (const Point<2> corner :
         {Point<2>(0, 0), Point<2>(2, 0), Point<2>(0, 1), Point<2>(2, 1)})
      s_max = std::max(s_max, field->stress(corner).norm());
    errors.u = nodal_displacement_error(bem, *field).first;

    // Tractions at every element node (ends and midpoint), and the
    // stress at two points per element at 2 % of its length inside.
    std::vector<Point<2>> near_points;
    for (unsigned int e = 0; e < bem.n_elements(); ++e)
    {
      const auto         v       = bem.element_nodes(e);
      const Point<2>     xa      = bem.node_position(v[0]);
      const Tensor<1, 2> tangent = bem.node_position(v[1]) - xa;
      const Tensor<1, 2> normal =
        Tensor<1, 2>{{tangent[1], -tangent[0]}} / tangent.norm();
      for (unsigned int end = 0; end <= bem.degree(); ++end)
      {
        const Point<2> x = xa + (end == 2 ? 0.5 : double(end)) * tangent;
        errors.t         = std::max(
          errors.t,
          (bem.element_traction(e, end) - field->stress(x) * normal).norm() /
            s_max);
      }
      for (const double s : {0.5, 0.1})
        near_points.push_back(xa + s * tangent -
                              0.02 * tangent.norm() * normal);
      if (bem.degree() == 2)
      {
        // The midpoint is a smooth point of its element: its diagonal
        // block (rigid-body trick) is the free term delta/2 plus the
        // principal value of T N_mid, zero by symmetry (doc/bem-method.md
        // §2.1).
        const Tensor<2, 2> half = 0.5 * unit_symmetric_tensor<2>();
        errors.midpoint_block   = std::max(
          errors.midpoint_block,
          (bem.diagonal_block(bem.element_midpoint_node(e)) - half).norm());
      }
    }
    near_points.push_back(Point<2>(1.0, 0.5));
    const auto stress = bem.stress_at_points(near_points);
    for (unsigned int p = 0; p < near_points.size(); ++p)
      errors.sigma =
        std::max(errors.sigma,
                 (stress[p] - field->stress(near_points[p])).norm() / s_max);
    return errors;
  }

  /** 1. The linear stress state on Q1, Q2 (locally refined) and P2. */
  void
  check_linear_stress_patch()
  {
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_rectangle(
      tria, {4, 2}, Point<2>(0, 0), Point<2>(2, 1));
    set_rectangle_ids(tria);
    tria.refine_global(1);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] < 0.6)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();

    Triangulation<2> triangles;
    GridGenerator::subdivided_hyper_rectangle_with_simplices(
      triangles, {6, 3}, Point<2>(0, 0), Point<2>(2, 1));
    set_rectangle_ids(triangles);
    FESystem<2>   fe_p2(FE_SimplexP<2>(2), 2);
    DoFHandler<2> p2(triangles);
    p2.distribute_dofs(fe_p2);
    const MappingFE<2> mapping_p(FE_SimplexP<2>(1));

    const Q1Displacement q1(tria, 1), q2(tria, 2);
    const std::vector<std::pair<std::string, std::vector<types::boundary_id>>>
      cases = {{"clamped left", {0}},
               {"all Dirichlet (D-D corners)", {0, 1, 2, 3}},
               {"traction only (floating)", {}}};
    for (const auto &[name, ids] : cases)
    {
      const auto e1 = linear_stress_patch(q1.dof_handler, q1.mapping, ids);
      const auto e2 = linear_stress_patch(q2.dof_handler, q2.mapping, ids);
      const auto ep = linear_stress_patch(p2, mapping_p, ids);
      std::cout << name << ": Q1 u " << e1.u << " t " << e1.t << " sigma "
                << e1.sigma << "; Q2 u " << e2.u << " t " << e2.t << " sigma "
                << e2.sigma << "; P2 u " << ep.u << " t " << ep.t << " sigma "
                << ep.sigma << std::endl;
      // In the quadratic space: only quadrature errors (~1e-8 per element
      // entry, doc/bem-method.md §4.2), as in bem_patch for linear fields.
      for (const auto &[fe, e] :
           {std::make_pair("Q2", e2), std::make_pair("P2", ep)})
      {
        check(name + ", " + fe + ": boundary displacement", e.u, 1e-8);
        check(name + ", " + fe + ": tractions at element nodes", e.t, 1e-7);
        check(name + ", " + fe + ": interior stress (2 % of h from Gamma)",
              e.sigma,
              1e-7);
        check(name + ", " + fe + ": midpoint diagonal block = delta/2",
              e.midpoint_block,
              1e-8);
      }
      // Not in the linear space: linear elements are off by far more than
      // quadrature (their discretisation error, O(h^2) ~ 1e-2 here).
      check(std::max(e1.u, e1.t) > 1e-4 && e1.sigma > 1e-4,
            name + ", Q1: the field is outside the linear space (u, t error " +
              std::to_string(std::max(e1.u, e1.t)) + ")");
    }
  }

  /**
   * 2. Convergence on the cantilever, degree 2 against degree 1, on the
   * mixed problem (exact u on x = 0) and on the traction-only one.
   *
   * Expected rates for quadratic elements (p = 2) on this polygon (no
   * geometry error; the exact u is cubic, the tractions quadratic):
   * - traction-only (a second-kind equation for u): u at O(h^(p+1)) = h^3,
   *   the interpolation order;
   * - mixed: the unknown traction on x = 0 solves a first-kind
   *   (single-layer, log-kernel) equation. For such equations collocation
   *   at the nodes is optimal for odd degrees only (Arnold & Wendland's
   *   analysis of spline collocation: even degrees need the collocation
   *   points at the midpoints of the spline knots); our C0 quadratics are
   *   collocated at their nodes, and we observe the loss of one order: t at
   *   O(h^p) = h^2 in the max norm, away from the corners too, and also
   *   with all sides Dirichlet (linear elements, odd, keep their h^2).
   *   u, coupled to it, follows at O(h^2) or better;
   * - interior stresses at fixed points: the Somigliana identity smooths
   *   the boundary errors, O(h^(p+1)) = h^3 (measured 2.8 mixed, 3.4
   *   traction-only; linear elements: 2).
   * Each observed rate (last two levels) must be within 0.5 of these.
   */
  void
  check_cantilever_rates()
  {
    ConvergenceTable                table;
    std::vector<cantilever::Errors> linear, quadratic, floating;
    for (unsigned int level = 1; level <= 3; ++level)
    {
      linear.push_back(cantilever::solve(level, 1));
      quadratic.push_back(cantilever::solve(level, 2));
      floating.push_back(cantilever::solve(level, 2, true));
      table.add_value("h", quadratic.back().h);
      table.add_value("unknowns p2", quadratic.back().unknowns);
      for (const auto &[name, e] : {std::make_pair("p1", linear.back()),
                                    std::make_pair("p2", quadratic.back())})
      {
        table.add_value(std::string("u ") + name, e.u);
        table.add_value(std::string("t ") + name, e.t);
        table.add_value(std::string("sigma ") + name, e.sigma);
      }
      table.add_value("u p2 floating", floating.back().u);
      table.add_value("sigma p2 floating", floating.back().sigma);
    }
    print_with_rates(table,
                     {"u p1",
                      "t p1",
                      "sigma p1",
                      "u p2",
                      "t p2",
                      "sigma p2",
                      "u p2 floating",
                      "sigma p2 floating"});
    const auto rate = [](const std::vector<cantilever::Errors> &errors,
                         const double cantilever::Errors::*member)
    { return std::log2(errors[1].*member / errors[2].*member); };
    const auto check_rate =
      [&](const std::string &what, const double observed, const double theory)
    {
      check(std::abs(observed - theory) <= 0.5 || observed > theory,
            what + ": rate " + std::to_string(observed) + " vs theory " +
              std::to_string(theory));
    };
    check_rate("mixed, interior stress",
               rate(quadratic, &cantilever::Errors::sigma),
               3.);
    check_rate("mixed, traction on x = 0 (max)",
               rate(quadratic, &cantilever::Errors::t),
               2.);
    check_rate(
      "mixed, nodal displacement", rate(quadratic, &cantilever::Errors::u), 2.);
    check_rate("traction-only, nodal displacement",
               rate(floating, &cantilever::Errors::u),
               3.);
    check_rate("traction-only, interior stress",
               rate(floating, &cantilever::Errors::sigma),
               3.);
    for (unsigned int l = 0; l < quadratic.size(); ++l)
      check(quadratic[l].u < linear[l].u && quadratic[l].t < linear[l].t &&
              quadratic[l].sigma < linear[l].sigma,
            "level " + std::to_string(l + 1) +
              ": degree 2 more accurate than degree 1 (u, t, sigma)");
  }
} // namespace

int
main()
{
  check_singular_moments();
  check_linear_stress_patch();
  check_cantilever_rates();
  return report();
}
