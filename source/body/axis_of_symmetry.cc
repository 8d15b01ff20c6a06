#include <deal.II/grid/grid_tools.h>

#include <ddcontact/body/axis_of_symmetry.h>
#include <ddcontact/parameter_tools.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ddcontact
{
  double
  AxisOfSymmetry::tolerance(const Triangulation<2> &triangulation)
  {
    // The coarse vertices (every process holds all of them, also on a
    // p4est mesh), so that every process finds the same.
    const auto &vertices = triangulation.get_vertices();
    Point<2>    low = vertices.front(), high = vertices.front();
    for (const auto &x : vertices)
      for (unsigned int d = 0; d < 2; ++d)
      {
        low[d]  = std::min(low[d], x[d]);
        high[d] = std::max(high[d], x[d]);
      }
    const double size = low.distance(high);
    return 1e-10 * std::max(size, 1e-300);
  }

  void
  AxisOfSymmetry::check_meridian_section(const Triangulation<2> &triangulation,
                                         const std::string      &body_name)
  {
    const double tol = tolerance(triangulation);
    for (const auto &x : triangulation.get_vertices())
      if (x[0] < -tol)
      {
        std::ostringstream message;
        message << "Body " << body_name << "/Mesh: the vertex (" << x[0] << ", "
                << x[1]
                << ") lies at r = x < 0; an axisymmetric section "
                   "(Geometry = axisymmetric) lies in x >= 0, with the axis "
                   "at x = 0";
        throw InputError(message.str());
      }
  }

  void
  AxisOfSymmetry::constrain_axis(const DoFHandler<2>       &dof_handler,
                                 AffineConstraints<double> &constraints)
  {
    const double tol = tolerance(dof_handler.get_triangulation());
    const auto  &fe  = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_face());
    // The face's vertex dofs come first, n_dofs_per_vertex() per vertex.
    const unsigned int per_vertex = fe.n_dofs_per_vertex();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
          {
            // A whole face on the axis, or one vertex of a face that only
            // touches it (a body meeting the axis at a point: issue 59,
            // u_r there was 3 % of the largest displacement).
            const bool whole = on_axis(face, tol);
            face->get_dof_indices(dofs);
            for (unsigned int k = 0; k < dofs.size(); ++k)
            {
              const bool on =
                whole || (k < 2 * per_vertex &&
                          std::abs(face->vertex(k / per_vertex)[0]) <= tol);
              if (on && fe.face_system_to_component_index(k).first == 0 &&
                  constraints.can_store_line(dofs[k]) &&
                  !constraints.is_constrained(dofs[k]))
                constraints.add_line(dofs[k]);
            }
          }
  }
} // namespace ddcontact
