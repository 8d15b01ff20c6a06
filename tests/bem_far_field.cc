// DESCRIPTION: BEM interior stresses by the hierarchical far-field
// interpolation equal the direct Somigliana sums to 1e-6 of the largest
// stress, on a uniform and on a locally refined mesh with a
// concentrated load
#include <deal.II/grid/grid_generator.h>

#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/body/elastic_body.h>

#include "test_tools.h"

#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // The paper's Omega_2 clamped at the bottom, loaded on top by a pressure
  // concentrated around x1 = 0.3 (a contact-like load); refined toward the
  // load in the second case, so that boxes of very different sizes occur.
  for (const unsigned int local : {0u, 3u})
  {
    BodyParameters prm;
    prm.name                    = "block";
    prm.corner_1                = Point<2>(-2., 0.);
    prm.corner_2                = Point<2>(2., 1.);
    prm.subdivisions            = {32, 8};
    prm.initial_refinement      = 1;
    prm.refinement_box          = {0, 0.8, 0.6, 1};
    prm.box_refinement          = local;
    prm.material.youngs_modulus = 2.1e5;
    prm.material.poisson_ratio  = 0.3;
    prm.dirichlet               = "2: xy: 0; 0";
    prm.neumann                 = "3: 0; -100*exp(-20*(x-0.3)^2)";
    ElasticBody<2> body(prm, Constants());
    body.make_mesh();
    body.setup_and_factorize();

    BoundaryElementSolver bem(body.get_elastic_constants(),
                              body.get_boundary_conditions());
    bem.setup(body.get_dof_handler(), body.get_mapping());
    bem.solve();

    const auto fast = bem.stress_at_quadrature_points(
      body.get_dof_handler(), body.get_mapping(), body.get_cell_quadrature());
    bem.set_far_field_interpolation(false);
    const auto direct = bem.stress_at_quadrature_points(
      body.get_dof_handler(), body.get_mapping(), body.get_cell_quadrature());

    double largest = 0, difference = 0;
    for (unsigned int c = 0; c < direct.size(); ++c)
      for (unsigned int q = 0; q < direct[c].size(); ++q)
      {
        largest    = std::max(largest, direct[c][q].norm());
        difference = std::max(difference, (fast[c][q] - direct[c][q]).norm());
      }
    std::cout << body.get_triangulation().n_active_cells() << " cells, "
              << bem.n_elements()
              << " boundary elements: max |sigma| = " << largest
              << ", max difference " << difference << " ("
              << difference / largest << " relative)" << std::endl;
    // The interpolation error bound of the admissibility condition is about
    // 5e-8 of the far field per level of the tree (see stresses_in_box);
    // 1e-6 of the largest stress leaves room for the sum over the levels,
    // and is 40 times below the smallest BEM discretisation error of the
    // BEM tests (4e-5, bem_lame at 128 elements per arc).
    check(difference < 1e-6 * largest,
          "interpolated far field equals the direct sum");
  }

  return report();
}
