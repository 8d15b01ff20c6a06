#include <deal.II/fe/fe_values.h>

#include <ddcontact/body/axis_of_symmetry.h>
#include <ddcontact/body/boundary_data_checks.h>
#include <ddcontact/body/elastic_body.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** Loading/Steps of the run (set_checked_load_steps()). */
    unsigned int n_load_steps = 1;

    /** Whether every entry of @p v is finite (Vector::l2_norm() asserts
     * that in Debug builds instead of answering). */
    bool
    finite(const Vector<double> &v)
    {
      return std::all_of(
        v.begin(), v.end(), [](const double x) { return std::isfinite(x); });
    }

    /** " at t = 0.5 (load step 2 of 4)"; nothing for a run of one step at
     * t = 1, whose data do not vary. */
    std::string
    at_time(const double t)
    {
      const unsigned int n = n_load_steps;
      if (n == 1 && t == 1.)
        return "";
      std::ostringstream s;
      s << std::setprecision(6) << " at t = " << t;
      const double k = std::round(t * n);
      if (k >= 1 && k <= n && std::abs(k / n - t) <= 1e-12)
        s << " (load step " << k << " of " << n << ")";
      return s.str();
    }

    template <int dim>
    std::string
    at_point(const Point<dim> &x)
    {
      std::ostringstream s;
      s << std::setprecision(6) << " at (x, y) = (" << x[0] << ", " << x[1]
        << ")";
      return s.str();
    }

    /** What to write instead, for a datum of the body or of its boundary. */
    std::string
    advice(const std::string &where)
    {
      return "; give expressions finite " + where +
             (n_load_steps > 1 ? " at every load time t = k / Steps" : "");
    }

    /**
     * The boundary data of a body (their functions) at the time they had
     * when this object was made; the checks below set other times, and the
     * destructor sets this one again, also when a check throws.
     */
    template <int dim>
    class DataTime
    {
    public:
      explicit DataTime(const BoundaryConditions<dim> &boundary_conditions)
      {
        for (const auto &[id, d] : boundary_conditions.dirichlet)
          functions.push_back(d.displacement.get());
        for (const auto &[id, traction] : boundary_conditions.neumann)
          functions.push_back(traction.get());
        if (boundary_conditions.body_force)
          functions.push_back(boundary_conditions.body_force.get());
        // ElasticBody::set_load_time() sets one t for all of them.
        if (!functions.empty())
          t = functions.front()->get_time();
      }

      ~DataTime()
      {
        for (auto *f : functions)
          f->set_time(t);
      }

      /** The time of the data (1 for a body without any). */
      double
      time() const
      {
        return t;
      }

    private:
      std::vector<Function<dim> *> functions;
      double                       t = 1.;
    };

    /**
     * The earliest of some times at which one of the data is not finite, and
     * the message that names it. Each datum is evaluated at a point at the
     * times before the earliest failure found so far, so a load that fails
     * at many times is evaluated once per time at most.
     */
    template <int dim>
    class EarliestNonFinite
    {
    public:
      explicit EarliestNonFinite(std::vector<double> times)
        : times(std::move(times))
        , first(this->times.size())
        , value(dim)
      {
      }

      /** Evaluate @p f at @p x; @p what names it ("Body a/.../Neumann: the
       * traction on boundary id 3"), @p where_finite the region for the
       * advice ("on the whole boundary"). */
      void
      check(Function<dim>     &f,
            const Point<dim>  &x,
            const std::string &what,
            const std::string &where_finite)
      {
        for (unsigned int i = 0; i < first; ++i)
        {
          f.set_time(times[i]);
          f.vector_value(x, value);
          if (!finite(value))
          {
            first   = i;
            message = what + " is not finite" + at_time(times[i]) +
                      at_point(x) + advice(where_finite);
            return;
          }
        }
      }

      void
      throw_if_found() const
      {
        if (first < times.size())
          throw InputError(message);
      }

    private:
      const std::vector<double> times;
      unsigned int              first;
      std::string               message;
      Vector<double>            value;
    };

    /** The prescribed displacements (5) at the vertices and midpoints of
     * the Dirichlet faces, where interpolation evaluates them for degree 1
     * and 2. */
    template <int dim>
    void
    check_dirichlet(const ElasticBody<dim> &body, EarliestNonFinite<dim> &check)
    {
      const auto &boundary_conditions = body.get_boundary_conditions();
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
            {
              const auto it = boundary_conditions.dirichlet.find(
                cell->face(f)->boundary_id());
              if (it == boundary_conditions.dirichlet.end())
                continue;
              const std::string what =
                "Body " + body.name() +
                "/Boundary conditions/Dirichlet: the displacement on "
                "boundary id " +
                std::to_string(it->first);
              for (const auto &x : {cell->face(f)->vertex(0),
                                    cell->face(f)->vertex(1),
                                    cell->face(f)->center()})
                check.check(
                  *it->second.displacement, x, what, "on the whole boundary");
            }
    }

    /** An axisymmetric body's u_r = u_x at the vertices of its Dirichlet
     * faces that prescribe x and lie on the axis r = 0 (whole faces, or a
     * face's end): symmetry holds u_r = 0 there (AxisOfSymmetry), and a
     * value prescribed otherwise would be replaced silently, its reaction
     * printed (issue 59). InputError at the first nonzero value. */
    template <int dim>
    void
    check_radial_on_axis(const ElasticBody<dim>    &body,
                         const std::vector<double> &times)
    {
      if (body.get_geometry() != Geometry::axisymmetric)
        return;
      const double on_axis =
        AxisOfSymmetry::tolerance(body.get_dof_handler().get_triangulation());
      const auto    &dirichlet = body.get_boundary_conditions().dirichlet;
      Vector<double> value(dim);
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto &face : cell->face_iterators())
          {
            if (!face->at_boundary())
              continue;
            const auto it = dirichlet.find(face->boundary_id());
            if (it == dirichlet.end() || !it->second.mask[0])
              continue;
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              if (std::abs(face->vertex(v)[0]) <= on_axis)
                for (const double t : times)
                {
                  auto &f = *it->second.displacement;
                  f.set_time(t);
                  f.vector_value(face->vertex(v), value);
                  if (std::abs(value[0]) > on_axis)
                  {
                    std::ostringstream s;
                    s << std::setprecision(6) << "Body " << body.name()
                      << "/Boundary conditions/Dirichlet: boundary id "
                      << it->first << " prescribes u_r = " << value[0]
                      << at_time(t) << at_point(face->vertex(v))
                      << " on the axis of symmetry (x = r = 0), where "
                         "symmetry holds u_r = 0; prescribe y alone there "
                         "(e.g. '"
                      << it->first << ": y: ...') or x = 0";
                    throw InputError(s.str());
                  }
                }
          }
    }

    /** The body force at the cells' quadrature points, then the tractions
     * at those of their Neumann faces, on the cells this process assembles.
     */
    template <int dim>
    void
    check_loads(const ElasticBody<dim> &body, EarliestNonFinite<dim> &check)
    {
      const std::string section =
        "Body " + body.name() + "/Boundary conditions/";
      const auto       &boundary_conditions = body.get_boundary_conditions();
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
            check.check(*boundary_conditions.body_force,
                        x,
                        section + "Body force",
                        "in the whole body");
        }
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
          {
            const auto it =
              boundary_conditions.neumann.find(cell->face(f)->boundary_id());
            if (it == boundary_conditions.neumann.end())
              continue;
            const std::string what = section +
                                     "Neumann: the traction on boundary id " +
                                     std::to_string(it->first);
            fe_face.reinit(cell, f);
            for (const auto &x : fe_face.get_quadrature_points())
              check.check(*it->second, x, what, "on the whole boundary");
          }
      }
    }
  } // namespace

  void
  set_checked_load_steps(const unsigned int n_steps)
  {
    n_load_steps = std::max(n_steps, 1u);
  }

  template <int dim>
  void
  check_dirichlet_values(const ElasticBody<dim> &body)
  {
    const DataTime<dim> data(body.get_boundary_conditions());
    if (data.time() != 1.)
    {
      EarliestNonFinite<dim> check({data.time()});
      check_dirichlet(body, check);
      check.throw_if_found();
      return;
    }
    // Every load time of the run, as Simulation computes them.
    std::vector<double> times;
    for (unsigned int k = 1; k <= n_load_steps; ++k)
      times.push_back(double(k) / n_load_steps);
    EarliestNonFinite<dim> check(times);
    check_dirichlet(body, check);
    check_loads(body, check);
    check.throw_if_found();
    check_radial_on_axis(body, times);
  }

  template <int dim>
  void
  throw_non_finite_load(const ElasticBody<dim> &body)
  {
    const DataTime<dim>    data(body.get_boundary_conditions());
    EarliestNonFinite<dim> check({data.time()});
    check_loads(body, check);
    check.throw_if_found();
    throw InputError("Body " + body.name() +
                     "/Boundary conditions: the load vector is not finite" +
                     at_time(data.time()));
  }

  template void
  check_dirichlet_values(const ElasticBody<2> &);
  template void
  throw_non_finite_load(const ElasticBody<2> &);
} // namespace ddcontact
