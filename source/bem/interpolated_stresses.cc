#include <deal.II/distributed/tria_base.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <ddcontact/bem/boundary_element_solver.h>

namespace ddcontact
{
  namespace
  {
    /** On a distributed mesh (p4est) this process interpolates its own
     * cells only. */
    bool
    is_skipped(const DoFHandler<2>::active_cell_iterator &cell,
               const bool                                 distributed)
    {
      return distributed && !cell->is_locally_owned();
    }

    /** The points where sigma_B is evaluated: the support points (each
     * once) of the inner cells, then the quadrature points of the cells
     * with a vertex on the boundary, which keep their quadrature points. */
    struct EvaluationPoints
    {
      std::vector<Point<2>> points;
      // Per dof of the scalar element: its support point's index.
      std::vector<unsigned int> dof_point;
      // Per boundary cell: the index of its first quadrature point.
      std::vector<unsigned int> first_point;
    };

    EvaluationPoints
    evaluation_points(const DoFHandler<2> &scalar,
                      const Mapping<2>    &mapping,
                      const Quadrature<2> &quadrature,
                      const bool           distributed)
    {
      const auto             &tria = scalar.get_triangulation();
      const FiniteElement<2> &fe   = scalar.get_fe();
      std::vector<bool>       boundary_vertex(tria.n_vertices(), false);
      for (const auto &cell : tria.active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              for (const unsigned int v : face->vertex_indices())
                boundary_vertex[face->vertex_index(v)] = true;
      const auto touches_boundary = [&](const auto &cell)
      {
        for (const unsigned int v : cell->vertex_indices())
          if (boundary_vertex[cell->vertex_index(v)])
            return true;
        return false;
      };

      EvaluationPoints result;
      auto            &points = result.points;
      result.dof_point.assign(scalar.n_dofs(), numbers::invalid_unsigned_int);
      result.first_point.assign(tria.n_active_cells(),
                                numbers::invalid_unsigned_int);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      FEValues<2> values(mapping, fe, quadrature, update_quadrature_points);
      for (const auto &cell : scalar.active_cell_iterators())
        if (is_skipped(cell, distributed))
          continue;
        else if (touches_boundary(cell))
        {
          values.reinit(cell);
          result.first_point[cell->active_cell_index()] = points.size();
          const auto &q_points = values.get_quadrature_points();
          points.insert(points.end(), q_points.begin(), q_points.end());
        }
        else
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (result.dof_point[dofs[i]] == numbers::invalid_unsigned_int)
            {
              result.dof_point[dofs[i]] = points.size();
              points.push_back(mapping.transform_unit_to_real_cell(
                cell, fe.get_unit_support_points()[i]));
            }
        }
      return result;
    }
  } // namespace

  std::vector<std::vector<SymmetricTensor<2, 2>>>
  BoundaryElementSolver::interpolated_stress_at_quadrature_points(
    const DoFHandler<2> &dof_handler,
    const Mapping<2>    &mapping,
    const Quadrature<2> &quadrature,
    const MPI_Comm       communicator) const
  {
    const auto             &tria = dof_handler.get_triangulation();
    const FiniteElement<2> &fe   = dof_handler.get_fe().base_element(0);
    Assert(fe.n_components() == 1 && fe.has_support_points(),
           ExcInternalError());
    DoFHandler<2> scalar(tria);
    scalar.distribute_dofs(fe);
    // On a distributed mesh (p4est) this process interpolates its own
    // cells; the other cells' entries stay empty (no process needs them).
    const bool distributed =
      dynamic_cast<const parallel::DistributedTriangulationBase<2> *>(&tria);

    const unsigned int     n_q = quadrature.size();
    const EvaluationPoints evaluation =
      evaluation_points(scalar, mapping, quadrature, distributed);
    const auto                          &points      = evaluation.points;
    const auto                          &dof_point   = evaluation.dof_point;
    const auto                          &first_point = evaluation.first_point;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

    // The choice of the evaluation, and the boxes of the hierarchical one,
    // follow the whole mesh: the same on any number of processes. A
    // distributed mesh evaluates its own points.
    const bool hierarchical_evaluation =
      hierarchical(std::size_t(tria.n_global_active_cells()) * n_q);
    const auto stress =
      distributed
        ? evaluate_stress(
            points, hierarchical_evaluation, tria.get_communicator())
        : stress_at_points(points, communicator, hierarchical_evaluation);

    std::vector<std::vector<SymmetricTensor<2, 2>>> result(
      tria.n_active_cells(), std::vector<SymmetricTensor<2, 2>>(n_q));
    FEValues<2> shapes(mapping, fe, quadrature, update_values);
    for (const auto &cell : scalar.active_cell_iterators())
    {
      if (is_skipped(cell, distributed))
        continue;
      auto &cell_result = result[cell->active_cell_index()];
      if (const unsigned int first = first_point[cell->active_cell_index()];
          first != numbers::invalid_unsigned_int)
      {
        for (unsigned int q = 0; q < n_q; ++q)
          cell_result[q] = stress[first + q];
        continue;
      }
      // The cell's own Lagrange interpolant of sigma_B.
      shapes.reinit(cell);
      cell->get_dof_indices(dofs);
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int i = 0; i < dofs.size(); ++i)
          cell_result[q] +=
            shapes.shape_value(i, q) * stress[dof_point[dofs[i]]];
    }
    return result;
  }
} // namespace ddcontact
