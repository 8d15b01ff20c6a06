// DESCRIPTION: the BEM answer depends only on the boundary faces: a mesh
// with hanging nodes from local refinement gives the same nodal
// displacements, element-end tractions and interior stresses as a mesh
// with identical boundary faces but a different (conforming, or
// differently refined) interior; no boundary DoF of a locally refined mesh
// carries a hanging-node constraint and every BEM node is a vertex DoF
#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>

#include <ddcontact/bem/boundary_element_solver.h>

#include "bem_test_tools.h"

#include <iomanip>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** A non-uniform load on the top: shear 0.3 x, pressure
   * 1 + 0.5 x - 0.2 x^2. */
  class TopLoad : public Function<2>
  {
  public:
    TopLoad()
      : Function<2>(2)
    {
    }

    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      const double x = p[0];
      return c == 0 ? 0.3 * x : -(1. + 0.5 * x - 0.2 * x * x);
    }
  };

  /** The paper's Omega_2 = (-2,2) x (0,1) (doc/method.md section 6): bottom
   * clamped (id 2), a non-uniform pressure on top (id 3), sides free. */
  BoundaryConditions<2>
  scene()
  {
    BoundaryConditions<2> bc;
    bc.dirichlet[2] = {ComponentMask(2, true),
                       std::make_shared<Functions::ZeroFunction<2>>(2)};
    bc.neumann[3]   = std::make_shared<TopLoad>();
    return bc;
  }

  void
  make_coarse(Triangulation<2> &tria)
  {
    GridGenerator::subdivided_hyper_rectangle(
      tria, {8, 2}, Point<2>(-2, 0), Point<2>(2, 1), true);
    tria.refine_global(2);
  }

  struct Result
  {
    unsigned int                             n_nodes, n_elements, n_hanging;
    std::vector<Point<2>>                    x;
    std::vector<Tensor<1, 2>>                u;
    std::vector<std::array<Point<2>, 2>>     element_ends;
    std::vector<std::array<Tensor<1, 2>, 2>> t;
    std::vector<SymmetricTensor<2, 2>>       sigma;
  };

  Result
  solve(const Triangulation<2> &tria, const std::vector<Point<2>> &points)
  {
    const Q1Displacement space(tria);
    const auto          &dof_handler = space.dof_handler;
    const auto          &mapping     = space.mapping;

    AffineConstraints<double> hanging;
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    hanging.close();

    BoundaryElementSolver bem(steel(), scene());
    bem.setup(dof_handler, mapping);
    bem.solve();

    Result r;
    r.n_nodes    = bem.n_nodes();
    r.n_elements = bem.n_elements();
    r.n_hanging  = hanging.n_constraints();
    // Every BEM node is a boundary vertex whose DoFs are free of
    // hanging-node constraints: the trace of the constrained Q1 space is
    // the piecewise linear space on the boundary faces (26).
    std::vector<Point<2>> support(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
    unsigned int n_bad = 0;
    for (unsigned int i = 0; i < bem.n_nodes(); ++i)
    {
      r.x.push_back(bem.node_position(i));
      r.u.push_back(bem.node_displacement(i));
      for (const auto dof : bem.node_dof_indices(i))
        if (hanging.is_constrained(dof) ||
            support[dof].distance(bem.node_position(i)) > 1e-12)
          ++n_bad;
    }
    if (n_bad > 0)
    {
      std::cout << "  FAIL: " << n_bad
                << " BEM node DoFs are constrained or misplaced" << std::endl;
      ++failures;
    }
    for (unsigned int e = 0; e < bem.n_elements(); ++e)
    {
      const auto n = bem.element_nodes(e);
      r.element_ends.push_back(
        {{bem.node_position(n[0]), bem.node_position(n[1])}});
      r.t.push_back({{bem.element_traction(e, 0), bem.element_traction(e, 1)}});
    }
    r.sigma = bem.stress_at_points(points);
    return r;
  }

  void
  compare(const std::string &name, const Result &a, const Result &b)
  {
    std::cout << name << ": " << a.n_hanging << " vs " << b.n_hanging
              << " hanging-node constraints, " << a.n_elements << " vs "
              << b.n_elements << " boundary elements" << std::endl;
    if (a.n_nodes != b.n_nodes || a.n_elements != b.n_elements)
    {
      std::cout << "  FAIL: different boundary meshes" << std::endl;
      ++failures;
      return;
    }
    double u_scale = 0, u_error = 0;
    for (unsigned int i = 0; i < a.n_nodes; ++i)
    {
      // Node numbering follows the cell order, so match by position.
      unsigned int j = 0;
      while (j < b.n_nodes && b.x[j].distance(a.x[i]) > 1e-12)
        ++j;
      if (j == b.n_nodes)
      {
        std::cout << "  FAIL: node " << a.x[i] << " missing" << std::endl;
        ++failures;
        return;
      }
      u_scale = std::max(u_scale, a.u[i].norm());
      u_error = std::max(u_error, (a.u[i] - b.u[j]).norm());
    }
    double t_scale = 0, t_error = 0;
    for (unsigned int e = 0; e < a.n_elements; ++e)
    {
      unsigned int f = 0;
      while (f < b.n_elements &&
             (b.element_ends[f][0].distance(a.element_ends[e][0]) > 1e-12 ||
              b.element_ends[f][1].distance(a.element_ends[e][1]) > 1e-12))
        ++f;
      if (f == b.n_elements)
      {
        std::cout << "  FAIL: element missing or oriented differently"
                  << std::endl;
        ++failures;
        return;
      }
      for (unsigned int k = 0; k < 2; ++k)
      {
        t_scale = std::max(t_scale, a.t[e][k].norm());
        t_error = std::max(t_error, (a.t[e][k] - b.t[f][k]).norm());
      }
    }
    double s_scale = 0, s_error = 0;
    for (unsigned int q = 0; q < a.sigma.size(); ++q)
    {
      s_scale = std::max(s_scale, a.sigma[q].norm());
      s_error = std::max(s_error, (a.sigma[q] - b.sigma[q]).norm());
    }
    // Same boundary faces -> the same dense system up to the order of the
    // unknowns: differences are round-off of the LU (cond ~1e3).
    check("nodal displacements (max rel difference)", u_error / u_scale, 1e-11);
    check(
      "element-end tractions (max rel difference)", t_error / t_scale, 1e-11);
    check("interior stresses (max rel difference)", s_error / s_scale, 1e-11);
  }
} // namespace

int
main()
{
  std::vector<Point<2>> points;
  for (const double x : {-1.9, -1.0, 0.0, 0.7, 1.95})
    for (const double y : {0.02, 0.5, 0.97})
      points.emplace_back(x, y);

  // (1) Interior cells only refined (twice): hanging nodes inside, the
  // boundary faces are those of the conforming mesh.
  {
    // The conforming mesh is built directly on the fine level: a
    // different cell order, so different node and unknown numbering.
    Triangulation<2> conforming, refined;
    GridGenerator::subdivided_hyper_rectangle(
      conforming, {32, 8}, Point<2>(-2, 0), Point<2>(2, 1), true);
    make_coarse(refined);
    for (unsigned int round = 0; round < 2; ++round)
    {
      for (const auto &cell : refined.active_cell_iterators())
      {
        // The second round stays one cell away from the boundary cells, so
        // that keeping the mesh one-irregular never refines them.
        const auto c = cell->center();
        if (!cell->at_boundary() && c[0] < 0.5 &&
            (round == 0 || (c[0] > -1.6 && c[1] > 0.3 && c[1] < 0.7)))
          cell->set_refine_flag();
      }
      refined.execute_coarsening_and_refinement();
    }
    const auto a = solve(refined, points);
    const auto b = solve(conforming, points);
    if (a.n_hanging == 0)
    {
      std::cout << "FAIL: the refined mesh has no hanging node" << std::endl;
      ++failures;
    }
    compare("interior refinement vs conforming mesh", a, b);
  }

  // (2) Local refinement reaching the boundary (boundary elements of
  // different lengths, hanging nodes next to the boundary) against the
  // same mesh with more interior-only refinement.
  {
    Triangulation<2> local, more;
    for (auto *tria : {&local, &more})
    {
      make_coarse(*tria);
      for (unsigned int round = 0; round < 2; ++round)
      {
        for (const auto &cell : tria->active_cell_iterators())
          if (cell->center().distance(Point<2>(-2, 1)) < 0.8 - 0.3 * round)
            cell->set_refine_flag();
        tria->execute_coarsening_and_refinement();
      }
    }
    for (const auto &cell : more.active_cell_iterators())
      if (!cell->at_boundary() && cell->center()[0] > 0)
        cell->set_refine_flag();
    more.execute_coarsening_and_refinement();
    const auto a = solve(local, points);
    const auto b = solve(more, points);
    compare("refinement at the boundary vs extra interior refinement", a, b);
  }

  return report();
}
