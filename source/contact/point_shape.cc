#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/point_shape.h>

#include <cmath>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** PointShape at unit points of one cell (one FEValues per cell). */
    std::vector<PointShape>
    point_shapes(const ElasticBody<2>                      &body,
                 const DoFHandler<2>::active_cell_iterator &cell,
                 const std::vector<Point<2>>               &unit_points)
    {
      FEValues<2> fe_values(body.get_mapping(),
                            body.get_fe(),
                            Quadrature<2>(unit_points),
                            update_values);
      fe_values.reinit(cell);
      PointShape common;
      common.dofs.resize(body.get_fe().dofs_per_cell);
      cell->get_dof_indices(common.dofs);
      const auto &constraints = body.get_constraints();
      for (const auto dof : common.dofs)
      {
        if (!constraints.is_constrained(dof))
        {
          common.n_entries.push_back(-1);
          continue;
        }
        const auto *entries = constraints.get_constraint_entries(dof);
        common.n_entries.push_back(entries ? entries->size() : 0);
        if (entries)
          for (const auto &[master, weight] : *entries)
          {
            common.masters.push_back(master);
            common.weights.push_back(weight);
          }
      }
      std::vector<PointShape> shapes(unit_points.size(), common);
      for (unsigned int q = 0; q < unit_points.size(); ++q)
        for (unsigned int i = 0; i < common.dofs.size(); ++i)
          shapes[q].values.push_back(fe_values.shape_value(i, q));
      return shapes;
    }

    /** The normal-component coefficients of a point, and its load with the
     * constraints resolved (see ContactPoint). */
    void
    couple(const PointShape                     &shape,
           const FiniteElement<2>               &fe,
           const Tensor<1, 2>                   &normal,
           std::vector<types::global_dof_index> &dofs,
           std::vector<double>                  &a,
           std::vector<types::global_dof_index> &load_dofs,
           std::vector<double>                  &load)
    {
      dofs = shape.dofs;
      a.resize(dofs.size());
      load_dofs.clear();
      load.clear();
      for (unsigned int i = 0, e = 0; i < dofs.size(); ++i)
      {
        a[i] = shape.values[i] * normal[fe.system_to_component_index(i).first];
        if (shape.n_entries[i] < 0)
        {
          load_dofs.push_back(dofs[i]);
          load.push_back(a[i]);
        }
        else
          for (int k = 0; k < shape.n_entries[i]; ++k, ++e)
          {
            load_dofs.push_back(shape.masters[e]);
            load.push_back(a[i] * shape.weights[e]);
          }
      }
    }
  } // namespace

  std::vector<PointShape>
  point_shapes_at(const ElasticBody<2>                      &body,
                  const DoFHandler<2>::active_cell_iterator &cell,
                  const std::vector<Point<2>>               &points)
  {
    std::vector<Point<2>> unit_points;
    for (const auto &x : points)
      unit_points.push_back(
        body.get_mapping().transform_real_to_unit_cell(cell, x));
    return point_shapes(body, cell, unit_points);
  }

  std::vector<PointShape>
  remote_point_shapes(const ElasticBody<2>        &body,
                      const std::vector<Point<2>> &points,
                      const std::string           &section)
  {
    // Process 0 asks and sends the answer to all: a point on an edge
    // between two processes' cells has two equally valid answers that
    // differ in round-off, and the DD, replicated on every process, must
    // see the same numbers everywhere. One cell per point, else a point
    // on an edge would be loaded twice; the tolerance is in unit
    // coordinates.
    const MPI_Comm comm = body.get_triangulation().get_communicator();
    const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
    Utilities::MPI::RemotePointEvaluation<2> remote(1e-6, true);
    remote.reinit(root ? points : std::vector<Point<2>>(),
                  body.get_triangulation(),
                  body.get_mapping());
    if (Utilities::MPI::broadcast(comm, remote.all_points_found(), 0) == false)
      throw InputError(section +
                       ": a contact point lies in no cell of "
                       "body '" +
                       body.name() + "'");
    std::vector<PointShape> shapes, buffer;
    remote.evaluate_and_process<PointShape>(
      shapes,
      buffer,
      [&](const ArrayView<PointShape> &values, const auto &cell_data)
      {
        for (unsigned int c = 0; c < cell_data.cells.size(); ++c)
        {
          const DoFHandler<2>::active_cell_iterator cell(
            &body.get_triangulation(),
            cell_data.cells[c].first,
            cell_data.cells[c].second,
            &body.get_dof_handler());
          const unsigned int begin = cell_data.reference_point_ptrs[c],
                             end   = cell_data.reference_point_ptrs[c + 1];
          const auto in_cell =
            point_shapes(body,
                         cell,
                         std::vector<Point<2>>(
                           cell_data.reference_point_values.begin() + begin,
                           cell_data.reference_point_values.begin() + end));
          std::copy(in_cell.begin(), in_cell.end(), values.begin() + begin);
        }
      });
    shapes = Utilities::MPI::broadcast(comm, shapes, 0);
    AssertDimension(shapes.size(), points.size());
    return shapes;
  }

  void
  couple_point(ContactPoint         &p,
               const PointShape     &shape_1,
               const PointShape     &shape_2,
               const ElasticBody<2> &body_1,
               const ElasticBody<2> &body_2,
               const Function<2>    *friction,
               const std::string    &entry)
  {
    p.values_1 = shape_1.values;
    couple(shape_1,
           body_1.get_fe(),
           p.normal,
           p.dofs_1,
           p.a,
           p.load_dofs_1,
           p.load_1);
    // n_2 = -n_1 (small-gap assumption).
    couple(shape_2,
           body_2.get_fe(),
           -p.normal,
           p.dofs_2,
           p.b,
           p.load_dofs_2,
           p.load_2);
    if (!friction)
      return;
    // The tangent tau = n_1 turned by +90 degrees, tau_2 = -tau; the
    // same dofs and load dofs as the normal's.
    const Tensor<1, 2>                   tau({-p.normal[1], p.normal[0]});
    std::vector<types::global_dof_index> dofs, load_dofs;
    couple(shape_1, body_1.get_fe(), tau, dofs, p.at, load_dofs, p.load_t1);
    couple(shape_2, body_2.get_fe(), -tau, dofs, p.bt, load_dofs, p.load_t2);
    p.friction = friction->value(p.x);
    if (!std::isfinite(p.friction) || p.friction < 0)
    {
      std::ostringstream message;
      message << entry << ": " << p.friction << " at (" << p.x[0] << ", "
              << p.x[1]
              << ") of S_1; give an expression >= 0 and finite on the "
                 "whole zone";
      throw InputError(message.str());
    }
  }
} // namespace ddcontact
