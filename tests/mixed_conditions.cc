// DESCRIPTION: per-component mixed conditions on one boundary id (a
// Dirichlet condition on one component, a Neumann traction on the other):
// a block on rollers loaded on its top, whose top is also held in x, is in
// uniaxial strain; a linear field with one component prescribed and the
// other loaded on every side. Both are reproduced to round-off by the FEM
// (patch test: quadrilaterals with hanging nodes, triangles, degrees 1 and
// 2), and to quadrature accuracy by the BEM and the FEM-BEM estimator
#include <deal.II/base/function_parser.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include "plane_strain_hooke.h"
#include <ddcontact/adaptivity/fem_bem_estimator.h>
#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/body/elastic_body.h>

#include "test_tools.h"

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** One scene on the block (0, 2) x (0, 1) (ids 0 left, 1 right, 2
   * bottom, 3 top): its boundary entries and the exact linear field. */
  struct Scene
  {
    std::string              name;
    std::string              dirichlet;
    std::string              neumann;
    std::vector<std::string> u_exact;
    SymmetricTensor<2, 2>    sigma;
  };

  /** "a; b" with 17 digits. */
  std::string
  pair(const double a, const double b)
  {
    std::ostringstream s;
    s << std::setprecision(17) << a << "; " << b;
    return s.str();
  }

  void
  run(const Scene            &scene,
      const ElasticConstants &material,
      const std::string      &cell_type,
      const unsigned int      degree)
  {
    BodyParameters p;
    p.name         = "block";
    p.cell_type    = parse_selection<CellType>(cell_type);
    p.degree       = degree;
    p.corner_1     = Point<2>(0, 0);
    p.corner_2     = Point<2>(2, 1);
    p.subdivisions = {6, 3};
    p.material     = material;
    p.dirichlet    = scene.dirichlet;
    p.neumann      = scene.neumann;

    ElasticBody<2> body(p, Constants());
    body.make_mesh();
    auto &tria = body.get_triangulation();
    tria.refine_global(1);
    GridTools::distort_random(0.25, tria, true, 7);
    if (cell_type == "quadrilateral")
      // Hanging nodes, also on the mixed boundaries (left and top).
      for (unsigned int round = 0; round < 2; ++round)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->center()[0] - cell->center()[1] < -0.2 - 0.3 * round)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    body.setup_and_factorize();
    body.solve();

    // A linear field lies in every element space: the FEM solution is
    // exact up to round-off (condition number ~1e3 on these meshes, so a
    // relative 1e-10 is safe and far below any discretization error).
    FunctionParser<2> exact(2);
    exact.initialize("x,y", scene.u_exact, Constants());
    BodyVector error(body.n_dofs());
    VectorTools::interpolate(
      body.get_mapping(), body.get_dof_handler(), exact, error);
    const double u_scale = error.linfty_norm();
    error -= body.get_solution();
    double s_error = 0;
    for (const auto &cell_stress : body.stresses().at_quadrature_points())
      for (const auto &s : cell_stress)
        s_error = std::max(s_error, (s - scene.sigma).norm());

    const std::string label =
      scene.name + ", " + cell_type + " degree " + std::to_string(degree);
    std::cout << label << ": " << tria.n_active_cells() << " cells"
              << std::endl;
    check(label + ": FEM nodal error", error.linfty_norm() / u_scale, 1e-10);
    check(label + ": FEM stress error", s_error / scene.sigma.norm(), 1e-10);
    if (degree != 1)
      return;

    // The BEM (degree 1 only) with the same boundary data: mixed element
    // ends, a known traction in one component and an unknown one in the
    // other. Tolerances of bem_patch: it integrates a uniform state to
    // quadrature accuracy, not round-off.
    BoundaryElementSolver bem(material, body.get_boundary_conditions());
    bem.setup(body.get_dof_handler(), body.get_mapping());
    bem.solve();
    double u_error = 0;
    for (unsigned int i = 0; i < bem.n_nodes(); ++i)
      for (unsigned int c = 0; c < 2; ++c)
        u_error = std::max(u_error,
                           std::abs(bem.node_displacement(i)[c] -
                                    exact.value(bem.node_position(i), c)) /
                             u_scale);
    double bem_stress = 0;
    for (const auto &cell_stress :
         bem.stress_at_quadrature_points(body.get_dof_handler(),
                                         body.get_mapping(),
                                         body.get_cell_quadrature()))
      for (const auto &s : cell_stress)
        bem_stress = std::max(bem_stress, (s - scene.sigma).norm());
    check(label + ": BEM nodal error", u_error, 1e-8);
    check(label + ": BEM stress error at the quadrature points",
          bem_stress / scene.sigma.norm(),
          1e-7);

    FemBemEstimator estimator(body, EstimatorType::fem_bem_scaled);
    estimator.estimate(body.get_solution(), {});
    check(label + ": FEM-BEM estimate / ||sigma_B||",
          estimator.global_error() / estimator.stress_norm(),
          1e-7);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ElasticConstants                 material;
  material.youngs_modulus = 2.1e5;
  material.poisson_ratio  = 0.3;
  const double lambda = material.lambda(), mu = material.mu();

  // (a) Rollers on the left, right and bottom; the top is held in x and
  // pressed by p in y (mixed on id 3): uniaxial strain, u = (0, -p y /
  // (lambda + 2 mu)), sigma_yy = -p, sigma_xx = -lambda p / (lambda + 2 mu).
  const double p = 10.;
  Scene        roller;
  roller.name      = "roller with a load";
  roller.dirichlet = "0: x: 0; 0 | 1: x: 0; 0 | 2: y: 0; 0 | 3: x: 0; 0";
  roller.neumann   = "3: " + pair(0, -p);
  std::ostringstream u_y;
  u_y << std::setprecision(17) << -p / (lambda + 2 * mu) << "*y";
  roller.u_exact     = {"0", u_y.str()};
  roller.sigma[0][0] = -lambda * p / (lambda + 2 * mu);
  roller.sigma[1][1] = -p;

  // (b) u = G x: every side mixed, one component displaced and the other
  // loaded by sigma n (nonzero), the prescribed component written 0.
  const double          g11 = 1e-3, g12 = 2e-3, g21 = -5e-4, g22 = 1.5e-3;
  SymmetricTensor<2, 2> strain;
  strain[0][0]             = g11;
  strain[1][1]             = g22;
  strain[0][1]             = 0.5 * (g12 + g21);
  const auto         sigma = test::hooke(material, strain);
  std::ostringstream u;
  u << std::setprecision(17) << g11 << "*x + " << g12 << "*y; " << g21
    << "*x + " << g22 << "*y";
  const std::string u_pair = u.str();
  Scene             linear;
  linear.name      = "linear field, every side mixed";
  linear.dirichlet = "0: x: " + u_pair + " | 1: y: " + u_pair +
                     " | 2: y: " + u_pair + " | 3: x: " + u_pair;
  linear.neumann =
    "0: " + pair(0, -sigma[0][1]) + " | 1: " + pair(sigma[0][0], 0) +
    " | 2: " + pair(-sigma[0][1], 0) + " | 3: " + pair(0, sigma[1][1]);
  linear.u_exact = Utilities::split_string_list(u_pair, ';');
  linear.sigma   = sigma;

  for (const auto &scene : {roller, linear})
  {
    std::cout << scene.name << ": Dirichlet '" << scene.dirichlet
              << "', Neumann '" << scene.neumann << "'" << std::endl;
    for (const std::string cell_type : {"quadrilateral", "triangle"})
      for (const unsigned int degree : {1u, 2u})
        run(scene, material, cell_type, degree);
  }
  return report();
}
