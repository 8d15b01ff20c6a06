// DESCRIPTION: The body's contract for a nonlinear material law (issue
// 61): ElasticBody::solve_nonlinear() solves internal force = load by
// Newton's method with the law's consistent tangent. A law defined here
// and registered in the table of laws, sigma = lambda tr(eps) I + 2 mu eps
// + k tr(eps)^3 I, on a block in uniaxial strain (rollers on its sides and
// bottom, a pressure p on top) has the homogeneous solution eps_yy = e
// with (lambda + 2 mu) e + k e^3 = -p, which Q1 holds exactly: the
// displacement and the stress match it to round-off, on a mesh with
// hanging nodes; Newton converges quadratically (each residual below a
// constant times the square of the last). The linear-elastic law through
// the same loop converges in one step to solve()'s answer.
#include <deal.II/base/function_parser.h>

#include <deal.II/grid/tria.h>

#include <deal.II/numerics/vector_tools.h>

#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/material_laws.h>

#include "test_tools.h"

#include <cmath>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** sigma = lambda tr(eps) I + 2 mu eps + k tr(eps)^3 I: a stiffening
   * bulk response, path-independent, with the tangent
   * C = (lambda + 3 k tr(eps)^2) I x I + 2 mu I_s. */
  class CubicBulkLaw : public MaterialLaw
  {
  public:
    CubicBulkLaw(const ElasticConstants &constants, const double k)
      : constants(constants)
      , k(k)
    {
    }

    std::string
    name() const override
    {
      return "cubic-bulk";
    }
    bool
    is_linear() const override
    {
      return false;
    }
    bool
    is_path_dependent() const override
    {
      return false;
    }
    const ElasticConstants &
    elastic_constants() const override
    {
      return constants;
    }

    void
    evaluate(const ArrayView<const SymmetricTensor<2, 3>> &strain,
             const ArrayView<const double> &,
             const ArrayView<SymmetricTensor<2, 3>> &stress,
             std::vector<MaterialTangent>           *tangent,
             const ArrayView<double> &) const override
    {
      const double lambda = constants.lambda(), mu = constants.mu();
      if (tangent)
        tangent->resize(strain.size());
      for (unsigned int q = 0; q < strain.size(); ++q)
      {
        const double t = trace(strain[q]);
        stress[q] = (lambda * t + k * t * t * t) * unit_symmetric_tensor<3>() +
                    2. * mu * strain[q];
        if (tangent)
          (*tangent)[q] =
            MaterialTangent::isotropic(lambda + 3. * k * t * t, mu);
      }
    }

  private:
    const ElasticConstants constants;
    const double           k;
  };

  const double k = 20.;

  BodyParameters
  block(const std::string &law, const double p)
  {
    BodyParameters b;
    b.name                    = "block";
    b.corner_1                = Point<2>(0, 0);
    b.corner_2                = Point<2>(2, 1);
    b.subdivisions            = {4, 2};
    b.material.youngs_modulus = 1.;
    b.material.poisson_ratio  = 0.3;
    b.material_law            = law;
    // Rollers on the sides (0, 1) and the bottom (2); p on top (3).
    b.dirichlet = "0: x: 0; 0 | 1: x: 0; 0 | 2: y: 0; 0";
    b.neumann   = "3: 0; " + std::to_string(-p);
    return b;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MaterialLawInfo                  row;
  row.name        = "cubic-bulk";
  row.description = "a test law";
  row.linear      = false;
  row.declare     = [](ParameterHandler &) {};
  row.parse       = [](ParameterHandler &, const std::string &)
  { return MaterialLawConstants(); };
  row.create = [](const ElasticConstants &c, const MaterialLawConstants &)
  { return std::make_shared<const CubicBulkLaw>(c, k); };
  register_material_law(row);

  // The closed form: (lambda + 2 mu) e + k e^3 = -p, by Newton on e.
  const double     p = 0.5;
  ElasticConstants c;
  c.youngs_modulus = 1.;
  c.poisson_ratio  = 0.3;
  const double M   = c.lambda() + 2. * c.mu();
  double       e   = -p / M;
  for (unsigned int i = 0; i < 50; ++i)
    e -= (M * e + k * e * e * e + p) / (M + 3. * k * e * e);
  std::cout << "  uniaxial strain e = " << e << " (linear " << -p / M << ")"
            << std::endl;

  ElasticBody<2> body(block("cubic-bulk", p), Constants());
  body.make_mesh();
  // Hanging nodes: refine the left half once more.
  auto &tria = body.get_triangulation();
  tria.refine_global(1);
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->center()[0] < 1.)
      cell->set_refine_flag();
  tria.execute_coarsening_and_refinement();
  body.setup_and_factorize();
  BodyVector             u;
  const BodyNewtonReport newton = body.solve_nonlinear(BodyVector(), u);
  std::cout << "  Newton residuals (of the load's " << newton.load_norm << "):";
  for (const double r : newton.residuals)
    std::cout << " " << r;
  std::cout << std::endl;

  // u_y = e y exactly; u_x = 0.
  FunctionParser<2> exact(2);
  exact.initialize(
    "x,y", std::vector<std::string>{"0", "e*y"}, Constants{{"e", e}});
  BodyVector interpolated(body.n_dofs());
  VectorTools::interpolate(
    body.get_mapping(), body.get_dof_handler(), exact, interpolated);
  interpolated -= u;
  check("u = (0, e y) of the closed form",
        interpolated.linfty_norm() / std::abs(e),
        1e-10);
  double     stress_error = 0;
  const auto stress       = body.stresses(u).at_quadrature_points();
  for (const auto &cell_stress : stress)
    for (const auto &s : cell_stress)
      stress_error =
        std::max(stress_error, std::abs(s[1][1] + p) + std::abs(s[0][1]));
  check("sigma_yy = -p, sigma_xy = 0", stress_error / p, 1e-10);
  check(newton.n_steps() >= 3 && newton.n_steps() <= 10,
        "Newton took 3 to 10 steps (" + std::to_string(newton.n_steps()) + ")");
  // Quadratic: r_{k+1} <= C r_k^2 with one C for every step (the law's
  // curvature over its tangent, scaled by the load's norm), while the
  // residuals are above round-off.
  double worst = 0;
  for (unsigned int i = 1; i + 1 < newton.residuals.size(); ++i)
    if (newton.residuals[i + 1] > 1e-13 * newton.load_norm)
      worst = std::max(worst,
                       newton.residuals[i + 1] * newton.load_norm /
                         (newton.residuals[i] * newton.residuals[i]));
  check(
    "quadratic convergence: r_k+1 / r_k^2 (load-scaled) bounded", worst, 10.);

  // The linear law through the same loop: one step, solve()'s answer.
  ElasticBody<2> linear(block("linear-elastic", p), Constants());
  linear.make_mesh();
  linear.setup_and_factorize();
  linear.solve();
  const BodyVector direct = linear.get_solution();
  BodyVector       v;
  const auto       linear_newton = linear.solve_nonlinear(BodyVector(), v);
  v -= direct;
  check(linear_newton.n_steps() == 1,
        "the linear law converges in one Newton step");
  check(
    "... to solve()'s answer", v.linfty_norm() / direct.linfty_norm(), 1e-12);
  return report();
}
