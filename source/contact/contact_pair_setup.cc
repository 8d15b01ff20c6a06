#include <algorithm>
#include <array>
#include <cmath>
#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/contact_search.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

// ContactPair::setup(): the contact points on the common refinement of the
// two zones, and the searches it runs.
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

    /** "the gap is f at x = (x1, x2)", for messages. */
    std::string
    gap_at(const ContactPoint &p)
    {
      std::ostringstream s;
      s << std::setprecision(6) << "the gap is " << p.gap
        << " at x = " << point_coordinates(p.x);
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
          p.x  = face.a + s * t;
          p.ds = gauss.weight(q) * (breaks[piece + 1] - breaks[piece]) * length;
          p.JxW    = p.ds * section_measure(body_1.get_geometry(), p.x);
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
          // After the report: an interference is meant to overlap.
          p.gap -= parameters.interference;
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
        throw InputError(
          section + (parameters.interference > 0 ? "Interference" : "Gap") +
          ": " + gap_at(p) +
          (parameters.interference > 0 ? " with the Interference" : "") +
          ", an overlap deeper than both bodies together; check its sign "
          "and units");

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

} // namespace ddcontact
