#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/contact_search.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** A boundary face of a zone, as a straight segment (linear mapping),
     * with its cell where this process holds it (invalid when the face
     * was gathered from another process of a distributed mesh). */
    struct ZoneFace
    {
      DoFHandler<2>::active_cell_iterator cell;
      Point<2>                            a, b;
      Tensor<1, 2>                        normal; // outward
    };

    /** The faces with boundary id @p id: all of them on every process
     * (on a distributed mesh each process finds those of its own cells and
     * the lists are gathered, in the order of the processes). */
    std::vector<ZoneFace>
    zone_faces(const ElasticBody<2> &body, const types::boundary_id id)
    {
      std::vector<ZoneFace> faces;
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
        if (body.computes(cell))
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
            {
              ZoneFace           z{cell,
                         cell->face(f)->vertex(0),
                         cell->face(f)->vertex(1),
                         Tensor<1, 2>()};
              const Tensor<1, 2> t = z.b - z.a;
              Tensor<1, 2>       n({t[1], -t[0]});
              n /= n.norm();
              if (n * (cell->face(f)->center() - cell->center()) < 0)
                n *= -1.;
              z.normal = n;
              faces.push_back(z);
            }
      if (!body.is_mesh_distributed())
        return faces;

      std::vector<std::array<double, 6>> mine;
      for (const auto &z : faces)
        mine.push_back(
          {{z.a[0], z.a[1], z.b[0], z.b[1], z.normal[0], z.normal[1]}});
      faces.clear();
      for (const auto &from_process : Utilities::MPI::all_gather(
             body.get_triangulation().get_communicator(), mine))
        for (const auto &g : from_process)
          faces.push_back({DoFHandler<2>::active_cell_iterator(),
                           Point<2>(g[0], g[1]),
                           Point<2>(g[2], g[3]),
                           Tensor<1, 2>({g[4], g[5]})});
      return faces;
    }

    /** "(x1, x2)" in full precision, for messages. */
    std::string
    coordinates(const Point<2> &x)
    {
      std::ostringstream s;
      s << std::setprecision(std::numeric_limits<double>::max_digits10) << '('
        << x[0] << ", " << x[1] << ')';
      return s.str();
    }

    /** "the gap is f at x = (x1, x2)", for messages. */
    std::string
    gap_at(const ContactPoint &p)
    {
      std::ostringstream s;
      s << std::setprecision(6) << "the gap is " << p.gap
        << " at x = " << coordinates(p.x);
      return s.str();
    }

    /**
     * What the cell holding a point knows of it: the cell's dofs, the
     * value of every shape function at the point (of its one nonzero
     * component), and the body's constraint of every dof (n_entries[i] < 0:
     * none; otherwise that many entries of masters/weights, none for a
     * Dirichlet dof). Sent between processes by RemotePointEvaluation.
     */
    struct PointShape
    {
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  values;
      std::vector<int>                     n_entries;
      std::vector<types::global_dof_index> masters;
      std::vector<double>                  weights;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &dofs &values &n_entries &masters &weights;
      }
    };

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

    /** PointShape at points given in real coordinates in one cell. */
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

    /** PointShape at @p points of a distributed mesh: the owners of the
     * cells around the points evaluate and send (collective). */
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
      if (Utilities::MPI::broadcast(comm, remote.all_points_found(), 0) ==
          false)
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
    /** Sample @p law, the pair's friction expression, on @p faces of
     * S_1: InputError where it is < 0 or not finite. */
    void
    check_friction_on(const std::vector<ZoneFace> &faces,
                      const Function<2>           &law,
                      const ContactPairParameters &parameters,
                      const std::string           &body_1)
    {
      // The law is evaluated at the contact points, which refinement moves
      // and adds: the expression is sampled at 17 points of every face of
      // S_1 (at every setup), so that a value < 0 or not finite between
      // the first contact points refuses the run before it solves anything.
      constexpr unsigned int n_samples = 16;
      for (const auto &face : faces)
        for (unsigned int i = 0; i <= n_samples; ++i)
        {
          const Point<2> x =
            face.a + (double(i) / n_samples) * (face.b - face.a);
          const double value = law.value(x);
          if (!std::isfinite(value) || value < 0)
          {
            std::ostringstream message;
            message << parameters.friction_entry() << ": " << value << " at ("
                    << x[0] << ", " << x[1] << ") of the zone S_1 (boundary id "
                    << parameters.boundary_id_1 << " of '" << body_1
                    << "'); give an expression >= 0 and finite on the whole "
                       "zone";
            throw InputError(message.str());
          }
        }
    }

  } // namespace

  ContactPair::ContactPair(const ContactPairParameters &parameters,
                           const ElasticBody<2>        &body_1,
                           const ElasticBody<2>        &body_2,
                           const Constants             &constants)
    : parameters(parameters)
    , body_1(body_1)
    , body_2(body_2)
  {
    if (parameters.gap_type == GapType::expression)
      gap_function = make_function(parameters.gap_expression,
                                   1,
                                   constants,
                                   "Contact pair " + parameters.name + "/Gap");
    if (has_friction())
      friction_function = make_function(parameters.friction_expression(),
                                        1,
                                        constants,
                                        parameters.friction_entry());
  }

  void
  ContactPair::setup()
  {
    const std::string section = "Contact pair " + parameters.name + "/";
    const auto        faces_1 = zone_faces(body_1, parameters.boundary_id_1);
    const auto        faces_2 = zone_faces(body_2, parameters.boundary_id_2);
    if (faces_1.empty())
      throw InputError(section + "Boundary id 1: body '" + body_1.name() +
                       "' has no face with boundary id " +
                       std::to_string(parameters.boundary_id_1));
    if (faces_2.empty())
      throw InputError(section + "Boundary id 2: body '" + body_2.name() +
                       "' has no face with boundary id " +
                       std::to_string(parameters.boundary_id_2));

    if (has_friction())
      check_friction_on(faces_1, *friction_function, parameters, body_1.name());

    // The contact search on S_2 (doc/method.md, section 1.1): R-trees of
    // its faces and vertices, O(n log n) in all.
    std::vector<std::array<Point<2>, 2>> segments_2;
    std::vector<Tensor<1, 2>>            normals_2;
    double                               h_max = 0;
    for (const auto &f : faces_2)
    {
      segments_2.push_back({{f.a, f.b}});
      normals_2.push_back(f.normal);
      h_max = std::max(h_max, f.a.distance(f.b));
    }
    for (const auto &f : faces_1)
      h_max = std::max(h_max, f.a.distance(f.b));
    const double        search_distance = parameters.search_distance > 0
                                            ? parameters.search_distance
                                            : default_search_distance(h_max);
    const ContactSearch search_2(segments_2, normals_2, search_distance);
    // Zones whose normals are nowhere opposed can never touch: a wrong
    // boundary id (issue 31's same-facing zones).
    if (std::none_of(faces_1.begin(),
                     faces_1.end(),
                     [&](const ZoneFace &f)
                     { return search_2.has_opposed_normal(f.normal); }))
      throw InputError(
        section + "Boundary id 2: no face of the zone of '" + body_1.name() +
        "' (boundary id " + std::to_string(parameters.boundary_id_1) +
        ") faces any face of the zone of '" + body_2.name() +
        "' (boundary id " + std::to_string(parameters.boundary_id_2) +
        "): their outward normals are nowhere opposed (within "
        "60 degrees), so the zones can never touch; check the "
        "boundary ids");

    const QGauss<1> gauss(parameters.n_gauss);
    contact_points.clear();
    report                 = ContactSearchReport();
    report.search_distance = search_distance;
    report.expression_gap  = static_cast<bool>(gap_function);
    // Per point, the shapes of both bodies there: computed from the face's
    // cell at once on a serial or shared mesh, by the owners of a
    // distributed one at the end.
    std::vector<PointShape> shapes_1, shapes_2;
    zone_1.clear();
    // Gap evaluation = nodes: f_n on each face of S_1 is the polynomial of
    // body 1's degree through its values at the face's nodes (the
    // Gauss-Lobatto points: the vertices for degree 1, and the midpoint for
    // 2), so that a gap the trace can follow is met exactly.
    std::vector<Point<1>>                        nodes;
    std::vector<Polynomials::Polynomial<double>> lagrange; // of the nodes
    std::vector<double>                          node_f;   // f_n there
    if (gap_function && parameters.gap_evaluation == GapEvaluation::nodes)
    {
      nodes    = QGaussLobatto<1>(body_1.get_fe().degree + 1).get_points();
      lagrange = Polynomials::generate_complete_Lagrange_basis(nodes);
    }

    for (const auto &face : faces_1)
    {
      zone_1.push_back({{face.a, face.b}});
      const Tensor<1, 2> t      = face.b - face.a;
      const double       length = t.norm();
      node_f.clear();
      for (const auto &s : nodes)
        node_f.push_back(gap_function->value(face.a + s[0] * t));
      // The face is split where the normal lines through the vertices of
      // S_2 within reach cross it: there the partner face changes, and so
      // does the polynomial of u_2n (ContactSearch).
      std::vector<double> breaks = {0., 1.};
      for (const auto &v : search_2.segments().end_points_over(face.a, face.b))
      {
        if (std::abs((v - face.a) * face.normal) > search_distance)
          continue;
        const double s = (v - face.a) * t / (length * length);
        if (s > 1e-10 && s < 1. - 1e-10)
          breaks.push_back(s);
      }
      std::sort(breaks.begin(), breaks.end());
      breaks.erase(std::unique(breaks.begin(),
                               breaks.end(),
                               [](double x, double y)
                               { return std::abs(x - y) < 1e-10; }),
                   breaks.end());

      std::vector<Point<2>> xs;
      for (unsigned int piece = 0; piece + 1 < breaks.size(); ++piece)
        for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double s =
            breaks[piece] +
            gauss.point(q)[0] * (breaks[piece + 1] - breaks[piece]);
          ContactPoint p;
          p.x = face.a + s * t;
          p.JxW =
            gauss.weight(q) * (breaks[piece + 1] - breaks[piece]) * length;
          p.normal = face.normal;
          p.face   = zone_1.size() - 1;
          ++report.n_examined;

          // A point without a partner on S_2 cannot touch it: it carries no
          // pressure and has no gap.
          const auto partner = search_2.facing_point(p.x, p.normal);
          if (!partner)
            continue;
          p.projection = partner->point;
          if (!gap_function)
            p.gap = partner->gap;
          else if (nodes.empty())
            p.gap = gap_function->value(p.x);
          else
            for (unsigned int k = 0; k < nodes.size(); ++k)
              p.gap += lagrange[k].value(s) * node_f[k];
          if (!std::isfinite(p.gap))
            throw InputError(section + "Gap: " + gap_at(p) +
                             " of S_1; give an expression that is finite "
                             "on the whole zone");
          report.record(p.x, p.gap, partner->gap, length);
          if (!body_2.is_mesh_distributed())
            shapes_2.push_back(point_shapes_at(
              body_2, faces_2[partner->segment].cell, {p.projection})[0]);
          xs.push_back(p.x);
          contact_points.push_back(p);
        }
      if (!body_1.is_mesh_distributed() && !xs.empty())
        for (const auto &shape : point_shapes_at(body_1, face.cell, xs))
          shapes_1.push_back(shape);
    }

    arc_length = ZoneArcLength(zone_1);

    if (body_1.is_mesh_distributed() || body_2.is_mesh_distributed())
    {
      std::vector<Point<2>> xs, projections;
      for (const auto &p : contact_points)
      {
        xs.push_back(p.x);
        projections.push_back(p.projection);
      }
      if (body_1.is_mesh_distributed())
        shapes_1 = remote_point_shapes(body_1, xs, section + "Boundary id 1");
      if (body_2.is_mesh_distributed())
        shapes_2 =
          remote_point_shapes(body_2, projections, section + "Boundary id 2");
    }
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      auto &p    = contact_points[q];
      p.values_1 = shapes_1[q].values;
      couple(shapes_1[q],
             body_1.get_fe(),
             p.normal,
             p.dofs_1,
             p.a,
             p.load_dofs_1,
             p.load_1);
      // n_2 = -n_1 (small-gap assumption).
      couple(shapes_2[q],
             body_2.get_fe(),
             -p.normal,
             p.dofs_2,
             p.b,
             p.load_dofs_2,
             p.load_2);
      if (!has_friction())
        continue;
      // The tangent tau = n_1 turned by +90 degrees, tau_2 = -tau; the
      // same dofs and load dofs as the normal's.
      const Tensor<1, 2>                   tau({-p.normal[1], p.normal[0]});
      std::vector<types::global_dof_index> dofs, load_dofs;
      couple(
        shapes_1[q], body_1.get_fe(), tau, dofs, p.at, load_dofs, p.load_t1);
      couple(
        shapes_2[q], body_2.get_fe(), -tau, dofs, p.bt, load_dofs, p.load_t2);
      p.friction = friction_function->value(p.x);
      if (!std::isfinite(p.friction) || p.friction < 0)
      {
        std::ostringstream message;
        message << parameters.friction_entry() << ": " << p.friction << " at ("
                << p.x[0] << ", " << p.x[1]
                << ") of S_1; give an expression >= 0 and finite on the "
                   "whole zone";
        throw InputError(message.str());
      }
    }

    // Thickness of both bodies along the mean normal of S_1 (the x axis
    // if the normals cancel).
    Tensor<1, 2> mean;
    for (const auto &p : contact_points)
      mean += p.normal;
    mean = (mean.norm() > 0) ? mean / mean.norm() : Tensor<1, 2>({1., 0.});
    const auto extent_1 = body_1.get_mesh().extent_along(mean);
    const auto extent_2 = body_2.get_mesh().extent_along(mean);
    thickness_1         = parameters.thickness > 0 ? parameters.thickness
                                                   : extent_1.second - extent_1.first;
    thickness_2         = extent_2.second - extent_2.first;

    // An initial overlap deeper than both bodies together is no small-strain
    // contact problem (a gap given in other units, or a sign error).
    for (const auto &p : contact_points)
      if (p.gap < -(extent_1.second - extent_1.first + thickness_2))
        throw InputError(section + "Gap: " + gap_at(p) +
                         ", an overlap deeper than both bodies together; "
                         "check its sign and units");

    // theta = c H / E_1 (paper, section 6), or given.
    theta = (parameters.penalty_type == PenaltyType::relative)
              ? parameters.penalty * thickness_1 /
                  body_1.get_material().youngs_modulus
              : parameters.penalty;
    // The penalty relative to the body, c = theta E_1 / H_1: below 1e-12 the
    // penetration theta p is below round-off of the displacements and the
    // pressure g/theta is round-off amplified by 1e12 (no solver can tell
    // contact from separation).
    const double extent = extent_1.second - extent_1.first;
    const double c      = theta * body_1.get_material().youngs_modulus / extent;
    if (!(c >= 1e-12) || !std::isfinite(theta))
    {
      std::ostringstream s;
      s << section
        << (parameters.penalty_type == PenaltyType::relative &&
                parameters.thickness > 0
              ? "Thickness"
              : "Penalty")
        << ": theta = " << theta << " is " << c << " times H/E_1 of body '"
        << body_1.name() << "' (H = " << extent
        << "); a penalty below 1e-12 H/E_1 is lost in round-off: raise it, "
           "or use Formulation = exact";
      throw InputError(s.str());
    }
  }

  double
  ContactPair::default_search_distance(const double h_max) const
  {
    const auto diameter = [](const ElasticBody<2> &body)
    {
      const auto x = body.get_mesh().extent_along(Tensor<1, 2>({1., 0.}));
      const auto y = body.get_mesh().extent_along(Tensor<1, 2>({0., 1.}));
      return std::hypot(x.second - x.first, y.second - y.first);
    };
    return std::max(0.1 * std::min(diameter(body_1), diameter(body_2)),
                    2. * h_max);
  }

  std::vector<std::string>
  ContactPair::setup_warnings() const
  {
    std::vector<std::string> warnings;
    const std::string        pair = "contact pair " + parameters.name + ": ";
    std::ostringstream       s;
    s << std::setprecision(3);
    if (report.n_points == 0)
    {
      s << pair << "no point of the zone of '" << body_1.name()
        << "' (boundary id " << parameters.boundary_id_1
        << ") faces the zone of '" << body_2.name() << "' (boundary id "
        << parameters.boundary_id_2 << ") within the search distance "
        << report.search_distance
        << ": the zones face away from each other or lie farther apart, and "
           "the pair carries no force (raise Contact pair "
        << parameters.name
        << "/Search distance if a wider gap is meant to close)";
      warnings.push_back(s.str());
      return warnings;
    }
    if (report.min_gap <
        -ContactSearchReport::overlap_per_face * report.min_gap_face_length)
    {
      s << pair << "initial overlap: at x = " << coordinates(report.min_gap_at)
        << " the gap is " << report.min_gap << ", "
        << (gap_function ? "the Gap expression puts" : "the meshes put")
        << " body '" << body_1.name() << "' that deep inside body '"
        << body_2.name()
        << "' before any load, and the contact pushes them apart by as much "
           "(an interference fit if meant; otherwise check the meshes' "
           "positions"
        << (gap_function ? " and the Gap" : "") << ")";
      warnings.push_back(s.str());
      s.str("");
    }
    if (report.worst_excess > 0)
    {
      s << pair << "the Gap expression '" << parameters.gap_expression
        << "' gives " << report.worst_expression
        << " at x = " << coordinates(report.worst_excess_at)
        << ", where the meshes are " << report.worst_geometric
        << " apart along the normal (geometric gap): the expression lets the "
           "bodies touch across empty space; use Gap type = geometric, or a "
           "Gap that matches the meshes";
      warnings.push_back(s.str());
      s.str("");
    }
    // A law whose bound vanishes on the whole zone is frictionless: said,
    // not solved silently (a sweep over mu may mean it).
    if (has_friction() &&
        std::all_of(contact_points.begin(),
                    contact_points.end(),
                    [](const ContactPoint &p) { return p.friction == 0; }))
    {
      s << pair << parameters.friction_entry()
        << " is 0 on the whole zone: the contact is frictionless (Friction "
           "= none solves the same without tangential unknowns)";
      warnings.push_back(s.str());
    }
    return warnings;
  }

  void
  ContactPair::normal_displacements(const BodyVector    &u_1,
                                    const BodyVector    &u_2,
                                    std::vector<double> &u_1n,
                                    std::vector<double> &u_2n) const
  {
    u_1n.resize(contact_points.size());
    u_2n.resize(contact_points.size());
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto &p  = contact_points[q];
      double      v1 = 0, v2 = 0;
      for (unsigned int i = 0; i < p.a.size(); ++i)
        v1 += p.a[i] * u_1(p.dofs_1[i]);
      for (unsigned int i = 0; i < p.b.size(); ++i)
        v2 += p.b[i] * u_2(p.dofs_2[i]);
      u_1n[q] = v1;
      u_2n[q] = v2;
    }
  }

  std::vector<double>
  ContactPair::slips(const BodyVector &u_1, const BodyVector &u_2) const
  {
    std::vector<double> s(contact_points.size());
    if (!has_friction())
      return s;
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto &p = contact_points[q];
      for (unsigned int i = 0; i < p.at.size(); ++i)
        s[q] += p.at[i] * u_1(p.dofs_1[i]);
      for (unsigned int i = 0; i < p.bt.size(); ++i)
        s[q] += p.bt[i] * u_2(p.dofs_2[i]);
    }
    return s;
  }

  std::pair<Tensor<1, 2>, Tensor<1, 2>>
  ContactPair::add_friction_loads(const std::vector<double> &t,
                                  BodyVector                &load_1,
                                  BodyVector                &load_2) const
  {
    AssertDimension(t.size(), contact_points.size());
    Tensor<1, 2> force_1, force_2;
    if (!has_friction())
      return {force_1, force_2};
    const auto &fe_1 = body_1.get_fe();
    const auto &fe_2 = body_2.get_fe();
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      if (t[q] == 0.)
        continue;
      // The traction -t tau_a on body a, as sigma_n n_a for the normal.
      const auto  &p = contact_points[q];
      const double s = -t[q] * p.JxW;
      for (unsigned int i = 0; i < p.at.size(); ++i)
        force_1[fe_1.system_to_component_index(i).first] += s * p.at[i];
      for (unsigned int i = 0; i < p.bt.size(); ++i)
        force_2[fe_2.system_to_component_index(i).first] += s * p.bt[i];
      for (unsigned int i = 0; i < p.load_t1.size(); ++i)
        load_1(p.load_dofs_1[i]) += s * p.load_t1[i];
      for (unsigned int i = 0; i < p.load_t2.size(); ++i)
        load_2(p.load_dofs_2[i]) += s * p.load_t2[i];
    }
    return {force_1, force_2};
  }

  std::pair<Tensor<1, 2>, Tensor<1, 2>>
  ContactPair::add_contact_loads(const std::vector<double> &sigma_n,
                                 BodyVector                &load_1,
                                 BodyVector                &load_2) const
  {
    AssertDimension(sigma_n.size(), contact_points.size());
    const auto  &fe_1 = body_1.get_fe();
    const auto  &fe_2 = body_2.get_fe();
    Tensor<1, 2> force_1, force_2;
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      if (sigma_n[q] == 0.)
        continue;
      const auto  &p = contact_points[q];
      const double s = sigma_n[q] * p.JxW;
      for (unsigned int i = 0; i < p.a.size(); ++i)
        force_1[fe_1.system_to_component_index(i).first] += s * p.a[i];
      for (unsigned int i = 0; i < p.b.size(); ++i)
        force_2[fe_2.system_to_component_index(i).first] += s * p.b[i];
      // The constraints are resolved in the load coefficients.
      for (unsigned int i = 0; i < p.load_1.size(); ++i)
        load_1(p.load_dofs_1[i]) += s * p.load_1[i];
      for (unsigned int i = 0; i < p.load_2.size(); ++i)
        load_2(p.load_dofs_2[i]) += s * p.load_2[i];
    }
    return {force_1, force_2};
  }

  void
  ContactPair::add_unconstrained_contact_load(
    const std::vector<double> &sigma_n,
    const ElasticBody<2>      &body,
    BodyVector                &load) const
  {
    AssertDimension(sigma_n.size(), contact_points.size());
    Assert(&body == &body_1 || &body == &body_2, ExcInternalError());
    const bool on_body_1 = (&body == &body_1);
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto  &p            = contact_points[q];
      const double s            = sigma_n[q] * p.JxW;
      const auto  &dofs         = on_body_1 ? p.dofs_1 : p.dofs_2;
      const auto  &coefficients = on_body_1 ? p.a : p.b;
      for (unsigned int i = 0; i < dofs.size(); ++i)
        load(dofs[i]) += s * coefficients[i];
    }
  }

  void
  ContactPair::add_unconstrained_friction_load(const std::vector<double> &t,
                                               const ElasticBody<2>      &body,
                                               BodyVector &load) const
  {
    if (t.empty())
      return;
    AssertDimension(t.size(), contact_points.size());
    Assert(&body == &body_1 || &body == &body_2, ExcInternalError());
    const bool on_body_1 = (&body == &body_1);
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto  &p            = contact_points[q];
      const double s            = -t[q] * p.JxW;
      const auto  &dofs         = on_body_1 ? p.dofs_1 : p.dofs_2;
      const auto  &coefficients = on_body_1 ? p.at : p.bt;
      for (unsigned int i = 0; i < dofs.size(); ++i)
        load(dofs[i]) += s * coefficients[i];
    }
  }

  void
  ContactPair::add_traction_samples(const std::vector<double> &sigma_n,
                                    const ElasticBody<2>      &body,
                                    BoundaryTractionSamples   &samples,
                                    const std::vector<double> &t) const
  {
    AssertDimension(sigma_n.size(), contact_points.size());
    Assert(&body == &body_1 || &body == &body_2, ExcInternalError());
    const bool on_body_1 = (&body == &body_1);
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto &p = contact_points[q];
      samples.points.push_back(on_body_1 ? p.x : p.projection);
      samples.weights.push_back(p.JxW);
      Tensor<1, 2> traction = sigma_n[q] * p.normal;
      if (!t.empty())
        traction -= t[q] * Tensor<1, 2>({-p.normal[1], p.normal[0]});
      samples.traction.push_back(on_body_1 ? traction : -traction);
    }
  }
} // namespace ddcontact
