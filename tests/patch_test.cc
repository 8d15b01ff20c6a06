// DESCRIPTION: patch test: a uniform stress state is reproduced to round-off on
// a distorted quadrilateral mesh with hanging nodes and on a triangle mesh,
// degrees 1 and 2; so is its L2 projection (the smoothed stresses of the VTU)
#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include "plane_strain_hooke.h"
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/smoothed_stresses.h>

#include <deal.II/base/function_parser.h>

#include "test_tools.h"

#include <array>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // A linear displacement u = G x gives a uniform strain; Dirichlet data on
  // the left (0) and bottom (2), the matching tractions sigma n on the
  // right (1) and top (3). Every element here contains linear fields, so
  // the finite element solution must equal it up to round-off (the
  // condition number of these small systems is ~1e3, so 1e-10 relative is
  // a safe bound that any real error, O(h) or larger, would exceed).
  const double     g11 = 1e-3, g12 = 2e-3, g21 = -5e-4, g22 = 1.5e-3;
  ElasticConstants material;
  material.youngs_modulus = 2.1e5;
  material.poisson_ratio  = 0.3;
  SymmetricTensor<2, 2> strain;
  strain[0][0]     = g11;
  strain[1][1]     = g22;
  strain[0][1]     = 0.5 * (g12 + g21);
  const auto sigma = test::hooke(material, strain);

  Constants constants = {
    {"g11", g11}, {"g12", g12}, {"g21", g21}, {"g22", g22}};
  const std::string u = "g11*x + g12*y; g21*x + g22*y";

  for (const std::string cell_type : {"quadrilateral", "triangle"})
    for (const unsigned int degree : {1u, 2u})
    {
      BodyParameters p;
      p.name         = "patch";
      p.cell_type    = parse_selection<CellType>(cell_type);
      p.degree       = degree;
      p.corner_1     = Point<2>(0, 0);
      p.corner_2     = Point<2>(2, 1);
      p.subdivisions = {6, 3};
      p.material     = material;
      p.dirichlet    = "0: xy: " + u + " | 2: xy: " + u;
      std::ostringstream n;
      n << std::setprecision(17) << "1: " << sigma[0][0] << "; " << sigma[0][1]
        << " | 3: " << sigma[0][1] << "; " << sigma[1][1];
      p.neumann = n.str();

      ElasticBody<2> body(p, constants);
      body.make_mesh();
      auto &tria = body.get_triangulation();
      tria.refine_global(1);
      GridTools::distort_random(0.25, tria, true, 42);
      if (cell_type == "quadrilateral")
        // Two rounds of local refinement: hanging nodes, also on the
        // Neumann and Dirichlet boundaries.
        for (unsigned int round = 0; round < 2; ++round)
        {
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->center()[0] + cell->center()[1] < 1.2 - 0.3 * round)
              cell->set_refine_flag();
          tria.execute_coarsening_and_refinement();
        }
      body.setup_and_factorize();
      body.solve();

      // Nodal values against the exact field.
      FunctionParser<2> exact(2);
      exact.initialize(
        "x,y",
        std::vector<std::string>{"g11*x + g12*y", "g21*x + g22*y"},
        constants);
      BodyVector interpolated(body.n_dofs());
      VectorTools::interpolate(
        body.get_mapping(), body.get_dof_handler(), exact, interpolated);
      interpolated -= body.get_solution();
      const double u_error =
        interpolated.linfty_norm() / body.get_solution().linfty_norm();

      double     s_error = 0;
      const auto stress  = body.stresses().at_quadrature_points();
      for (const auto &cell_stress : stress)
        for (const auto &s : cell_stress)
          s_error = std::max(s_error, (s - sigma).norm() / sigma.norm());

      // The L2 projection of the stress written to the VTU (the smoothed
      // fields) reproduces a uniform stress: the shape functions sum to
      // one, so the mass matrix times the constant is the load.
      const SmoothedStresses<2>   smoothed(body, body.get_solution());
      const std::array<double, 5> smoothed_exact = {
        {sigma[0][0],
         sigma[1][1],
         sigma[0][1],
         test::plane_strain_sigma_33(material, sigma),
         von_mises_stress(sigma,
                          test::plane_strain_sigma_33(material, sigma))}};
      double smoothed_error = 0;
      for (unsigned int c = 0; c < smoothed_exact.size(); ++c)
        for (const double value : smoothed.fields()[c])
          smoothed_error = std::max(
            smoothed_error, std::abs(value - smoothed_exact[c]) / sigma.norm());

      unsigned int hanging = 0;
      for (const auto &line : body.get_constraints().get_lines())
        if (!line.entries.empty())
          ++hanging;

      const std::string label = cell_type + " degree " + std::to_string(degree);
      std::cout << label << ": " << tria.n_active_cells() << " cells, "
                << hanging << " hanging-node constraints" << std::endl;
      check(label + ": max nodal error", u_error, 1e-10);
      check(label + ": max stress error", s_error, 1e-10);
      check(label + ": max smoothed stress error", smoothed_error, 1e-10);
      if (cell_type == "quadrilateral")
        check(hanging > 0, label + ": the mesh has hanging nodes");
    }
  return report();
}
