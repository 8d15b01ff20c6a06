// DESCRIPTION: BEM patch tests: a uniform stress state is reproduced (to
// quadrature accuracy) at the boundary and in the interior, including at
// points 1 % of an element length away from the boundary and at the cell
// quadrature points, for clamped edge, rollers, Dirichlet-Dirichlet
// corner, all-Dirichlet, traction only (floating) and a contact traction
// given at sample points; on a locally refined quadrilateral mesh and on
// a triangle mesh, with linear (Q1, P1) and quadratic (Q2, P2) boundary
// elements. Degree-3 elements are rejected with an InputError.
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/parameters.h>

#include "bem_test_tools.h"

#include <iomanip>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** u = eps x + omega (-y, x) + c: the displacement of a uniform stress
   * state sigma0 in plane strain (doc/bem-method.md §6a) plus a rigid motion.
   */
  class LinearField : public Function<2>
  {
  public:
    LinearField(const ElasticConstants      &material,
                const SymmetricTensor<2, 2> &sigma)
      : Function<2>(2)
    {
      const double E = material.youngs_modulus, nu = material.poisson_ratio;
      strain[0][0] =
        ((1 - nu * nu) * sigma[0][0] - nu * (1 + nu) * sigma[1][1]) / E;
      strain[1][1] =
        ((1 - nu * nu) * sigma[1][1] - nu * (1 + nu) * sigma[0][0]) / E;
      strain[0][1] = (1 + nu) * sigma[0][1] / E;
    }

    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      const Tensor<1, 2> rigid{{-omega * p[1] + 2e-4, omega * p[0] - 1e-4}};
      return (strain * p)[c] + rigid[c];
    }

    SymmetricTensor<2, 2> strain;
    const double          omega = 3e-4;
  };

  /** Traction sigma0 n on a boundary with fixed normal n. */
  class ConstantTraction : public Function<2>
  {
  public:
    ConstantTraction(const SymmetricTensor<2, 2> &sigma,
                     const Tensor<1, 2>          &normal)
      : Function<2>(2)
      , t(sigma * normal)
    {
    }

    double
    value(const Point<2> &, const unsigned int c) const override
    {
      return t[c];
    }

    const Tensor<1, 2> t;
  };

  // Rectangle (0,2)x(0,1), ids 0 left, 1 right, 2 bottom, 3 top.
  const std::array<Tensor<1, 2>, 4> side_normals{{Tensor<1, 2>{{-1., 0.}},
                                                  Tensor<1, 2>{{1., 0.}},
                                                  Tensor<1, 2>{{0., -1.}},
                                                  Tensor<1, 2>{{0., 1.}}}};

  struct Case
  {
    std::string                                 name;
    std::map<types::boundary_id, ComponentMask> dirichlet;
    bool                                        contact_top = false;
    bool                                        shear_free  = false;
  };

  void
  run_case(const Case          &test_case,
           const DoFHandler<2> &dof_handler,
           const Mapping<2>    &mapping,
           const Quadrature<2> &cell_quadrature)
  {
    const ElasticConstants material = steel();
    SymmetricTensor<2, 2>  sigma;
    sigma[0][0] = 120.;
    sigma[1][1] = -75.;
    sigma[0][1] = test_case.shear_free ? 0. : 40.;
    auto exact  = std::make_shared<LinearField>(material, sigma);

    BoundaryConditions<2> bc;
    for (types::boundary_id id = 0; id < 4; ++id)
      if (test_case.dirichlet.count(id))
        bc.dirichlet[id] = {test_case.dirichlet.at(id), exact};
      else if (id == 3 && test_case.contact_top)
        bc.contact.insert(3);
      else
        bc.neumann[id] =
          std::make_shared<ConstantTraction>(sigma, side_normals[id]);

    // The contact traction sigma0 n at the face Gauss points of the top.
    BoundaryTractionSamples samples;
    if (test_case.contact_top)
    {
      const QGauss<1> rule(2);
      for (const auto &face :
           dof_handler.get_triangulation().active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == 3)
          for (unsigned int q = 0; q < rule.size(); ++q)
          {
            samples.points.push_back(face->vertex(0) +
                                     rule.point(q)[0] *
                                       (face->vertex(1) - face->vertex(0)));
            samples.weights.push_back(rule.weight(q) * face->measure());
            samples.traction.push_back(sigma * side_normals[3]);
          }
    }

    BoundaryElementSolver bem(material, bc);
    bem.setup(dof_handler, mapping);
    bem.solve(samples);

    std::cout << test_case.name << ": " << bem.n_elements() << " elements, "
              << bem.n_unknowns() << " unknowns, "
              << bem.n_extra_collocation_rows() << " extra corner rows, "
              << bem.n_rigid_modes() << " rigid modes" << std::endl;

    // Nodal displacements. A floating body is determined up to a rigid
    // motion: remove the least-squares rigid part of the difference.
    const auto [u_error, u_max] = nodal_displacement_error(bem, *exact);

    // Element-end tractions, also the unknown ones on Dirichlet sides and
    // at D-D corners (two different normals meet there).
    double t_error = 0;
    for (unsigned int e = 0; e < bem.n_elements(); ++e)
    {
      const auto         x = bem.element_nodes(e);
      const Tensor<1, 2> tangent =
        bem.node_position(x[1]) - bem.node_position(x[0]);
      const Tensor<1, 2> normal =
        Tensor<1, 2>{{tangent[1], -tangent[0]}} / tangent.norm();
      for (unsigned int end = 0; end <= bem.degree(); ++end)
        t_error =
          std::max(t_error,
                   (bem.element_traction(e, end) - sigma * normal).norm() /
                     sigma.norm());
    }

    // Interior: every cell quadrature point, and two points per boundary
    // element at 1 % of its length from the boundary (above its midpoint
    // and above a point near its start, i.e. near the neighbour too).
    double     s_error = 0;
    const auto at_q =
      bem.stress_at_quadrature_points(dof_handler, mapping, cell_quadrature);
    for (const auto &cell_stress : at_q)
      for (const auto &s : cell_stress)
        s_error = std::max(s_error, (s - sigma).norm() / sigma.norm());
    std::vector<Point<2>> near_points;
    for (unsigned int e = 0; e < bem.n_elements(); ++e)
    {
      const auto     x  = bem.element_nodes(e);
      const Point<2> xa = bem.node_position(x[0]), xb = bem.node_position(x[1]);
      const Tensor<1, 2> tangent = xb - xa;
      const Tensor<1, 2> inward{{-tangent[1], tangent[0]}}; // length L
      for (const double s : {0.5, 0.05})
        near_points.push_back(xa + s * tangent + 0.01 * inward);
    }
    double     near_error = 0;
    const auto near       = bem.stress_at_points(near_points);
    for (const auto &s : near)
      near_error = std::max(near_error, (s - sigma).norm() / sigma.norm());

    // Interior displacement (Somigliana) at the centre.
    const auto   u_centre = bem.displacement_at_points({Point<2>(1.0, 0.5)})[0];
    Tensor<1, 2> u_centre_exact;
    for (unsigned int c = 0; c < 2; ++c)
      u_centre_exact[c] = exact->value(Point<2>(1.0, 0.5), c);

    // The linear field is represented exactly, so every error is a
    // quadrature error of the matrix entries and of the identity: the
    // distance-dependent rule of doc/bem-method.md §4.2 is accurate to ~1e-8
    // per element; a wrong sign, free term or corner treatment gives O(1e-2)
    // and more (doc/bem-method.md §2.7: tied corner tractions -> 61 %).
    check("boundary displacement (max, relative)", u_error, 1e-8);
    check("boundary traction at element ends (max, / |sigma0|)", t_error, 1e-7);
    check("stress at all cell quadrature points", s_error, 1e-7);
    check(
      "stress at 1 % of an element length from the boundary", near_error, 1e-7);
    if (bem.n_rigid_modes() == 0)
      check("displacement at the centre (Somigliana)",
            (u_centre - u_centre_exact).norm() / u_max,
            1e-8);
  }
} // namespace

int
main()
{
  const ComponentMask     xy(std::vector<bool>{true, true});
  const ComponentMask     x_only(std::vector<bool>{true, false});
  const ComponentMask     y_only(std::vector<bool>{false, true});
  const std::vector<Case> cases = {
    {"clamped bottom edge", {{2, xy}}, false, false},
    {"rollers (x on left, y on bottom)",
     {{0, x_only}, {2, y_only}},
     false,
     true},
    {"Dirichlet-Dirichlet corner (left and bottom)",
     {{0, xy}, {2, xy}},
     false,
     false},
    {"all Dirichlet", {{0, xy}, {1, xy}, {2, xy}, {3, xy}}, false, false},
    {"traction only (floating, bordered)", {}, false, false},
    {"clamped bottom, contact traction samples on top",
     {{2, xy}},
     true,
     false}};

  // Locally refined quadrilateral mesh (hanging nodes, boundary elements
  // of different lengths) and a triangle mesh, for degree 1 and 2.
  for (const unsigned int degree : {1u, 2u})
  {
    std::cout << "=== Q" << degree
              << ", locally refined quadrilateral mesh (hanging nodes, "
                 "boundary elements of different lengths)"
              << std::endl;
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_rectangle(
      tria, {4, 2}, Point<2>(0, 0), Point<2>(2, 1));
    set_rectangle_ids(tria);
    tria.refine_global(1);
    GridTools::distort_random(0.2, tria, true, 7);
    for (unsigned int round = 0; round < 2; ++round)
    {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->center()[0] + 0.5 * cell->center()[1] < 0.8 - 0.2 * round)
          cell->set_refine_flag();
      tria.execute_coarsening_and_refinement();
    }
    FESystem<2>   fe(FE_Q<2>(degree), 2);
    DoFHandler<2> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    for (const auto &c : cases)
      run_case(c, dof_handler, MappingQ<2>(1), QGauss<2>(degree + 1));

    std::cout << "=== P" << degree << ", triangle mesh" << std::endl;
    Triangulation<2> triangles;
    GridGenerator::subdivided_hyper_rectangle_with_simplices(
      triangles, {6, 3}, Point<2>(0, 0), Point<2>(2, 1));
    set_rectangle_ids(triangles);
    FESystem<2>   fe_p(FE_SimplexP<2>(degree), 2);
    DoFHandler<2> dofs_p(triangles);
    dofs_p.distribute_dofs(fe_p);
    MappingFE<2> mapping(FE_SimplexP<2>(1));
    for (const auto &c : cases)
      run_case(c, dofs_p, mapping, QGaussSimplex<2>(degree + 1));
  }

  {
    std::cout << "=== degree 3 is rejected" << std::endl;
    Triangulation<2> tria;
    GridGenerator::hyper_cube(tria);
    FESystem<2>   fe(FE_Q<2>(3), 2);
    DoFHandler<2> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    ElasticConstants material;
    material.youngs_modulus = 1;
    material.poisson_ratio  = 0.3;
    BoundaryElementSolver bem(material, BoundaryConditions<2>());
    bool                  thrown = false;
    try
    {
      bem.setup(dof_handler, MappingQ<2>(1));
    }
    catch (const InputError &e)
    {
      thrown = true;
      std::cout << "  InputError: " << e.what() << "  ok" << std::endl;
    }
    if (!thrown)
    {
      std::cout << "  FAIL: no InputError for FE_Q(3)" << std::endl;
      ++failures;
    }
  }

  return report();
}
