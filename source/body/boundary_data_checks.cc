#include <deal.II/fe/fe_values.h>

#include <ddcontact/body/boundary_data_checks.h>
#include <ddcontact/body/elastic_body.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** Whether every entry of @p v is finite (Vector::l2_norm() asserts
     * that in Debug builds instead of answering). */
    bool
    finite(const Vector<double> &v)
    {
      return std::all_of(
        v.begin(), v.end(), [](const double x) { return std::isfinite(x); });
    }

  } // namespace

  template <int dim>
  void
  check_dirichlet_values(const ElasticBody<dim> &body)
  {
    // The prescribed displacements at the vertices and midpoints of the
    // Dirichlet faces (where interpolation evaluates them for degree 1
    // and 2): a NaN would enter the constraints and every solution.
    const auto    &boundary_conditions = body.get_boundary_conditions();
    Vector<double> value(dim);
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
          {
            const auto it =
              boundary_conditions.dirichlet.find(cell->face(f)->boundary_id());
            if (it == boundary_conditions.dirichlet.end())
              continue;
            for (const auto &x : {cell->face(f)->vertex(0),
                                  cell->face(f)->vertex(1),
                                  cell->face(f)->center()})
            {
              it->second.displacement->vector_value(x, value);
              if (!finite(value))
              {
                std::ostringstream s;
                s << ("Body " + body.name())
                  << "/Boundary conditions/Dirichlet: the displacement on "
                     "boundary id "
                  << it->first << " is not finite at (" << x[0] << ", " << x[1]
                  << "); give expressions finite on the whole "
                  << "boundary";
                throw InputError(s.str());
              }
            }
          }
  }

  template <int dim>
  void
  throw_non_finite_load(const ElasticBody<dim> &body)
  {
    // Which expression, and where: the body force at the cells'
    // quadrature points, then the tractions on their Neumann faces.
    const auto where = [](const Point<dim> &x)
    {
      std::ostringstream s;
      s << std::setprecision(6) << " at (" << x[0] << ", " << x[1] << ")";
      return s.str();
    };
    const std::string section = "Body " + body.name() + "/Boundary conditions/";
    const auto       &boundary_conditions = body.get_boundary_conditions();
    Vector<double>    value(dim);
    FEValues<dim>     fe_values(body.get_mapping(),
                            body.get_fe(),
                            body.get_cell_quadrature(),
                            update_quadrature_points);
    FEFaceValues<dim> fe_face(body.get_mapping(),
                              body.get_fe(),
                              body.get_face_quadrature(),
                              update_quadrature_points);
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
    {
      if (!body.computes(cell))
        continue;
      if (boundary_conditions.body_force)
      {
        fe_values.reinit(cell);
        for (const auto &x : fe_values.get_quadrature_points())
        {
          boundary_conditions.body_force->vector_value(x, value);
          if (!finite(value))
            throw InputError(section + "Body force: not finite" + where(x) +
                             "; give expressions finite in the whole body");
        }
      }
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
        {
          const auto it =
            boundary_conditions.neumann.find(cell->face(f)->boundary_id());
          if (it == boundary_conditions.neumann.end())
            continue;
          fe_face.reinit(cell, f);
          for (const auto &x : fe_face.get_quadrature_points())
          {
            it->second->vector_value(x, value);
            if (!finite(value))
              throw InputError(section +
                               "Neumann: the traction on boundary "
                               "id " +
                               std::to_string(it->first) + " is not finite" +
                               where(x) +
                               "; give expressions finite on the whole "
                               "boundary");
          }
        }
    }
    throw InputError(section + "the load vector is not finite");
  }

  template void
  check_dirichlet_values(const ElasticBody<2> &);
  template void
  throw_non_finite_load(const ElasticBody<2> &);
} // namespace ddcontact
