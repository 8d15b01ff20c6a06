#include <algorithm>
#include <array>
#include <cmath>
#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/contact_search.h>
#include <ddcontact/contact/point_shape.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>
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

    /** InputError naming @p entry when the zone has no face. */
    void
    require_faces(const std::vector<ZoneFace> &faces,
                  const ElasticBody<2>        &body,
                  const types::boundary_id     id,
                  const std::string           &entry)
    {
      if (faces.empty())
        throw InputError(entry + ": body '" + body.name() +
                         "' has no face with boundary id " +
                         std::to_string(id));
    }

    /** The longest face of either zone. */
    double
    longest_face(const std::vector<ZoneFace> &faces_1,
                 const std::vector<ZoneFace> &faces_2)
    {
      double h_max = 0;
      for (const auto *faces : {&faces_1, &faces_2})
        for (const auto &f : *faces)
          h_max = std::max(h_max, f.a.distance(f.b));
      return h_max;
    }

    /** The contact search on S_2 (doc/method.md, section 1.1): R-trees of
     * its faces and vertices, O(n log n) in all. */
    ContactSearch
    search_on(const std::vector<ZoneFace> &faces_2, const double distance)
    {
      std::vector<std::array<Point<2>, 2>> segments_2;
      std::vector<Tensor<1, 2>>            normals_2;
      for (const auto &f : faces_2)
      {
        segments_2.push_back({{f.a, f.b}});
        normals_2.push_back(f.normal);
      }
      return ContactSearch(segments_2, normals_2, distance);
    }

    /** The gap f_n at the points of one face of S_1: the search's gap
     * without a Gap expression, else the expression. With Gap evaluation
     * = nodes f_n on each face is the polynomial of body 1's degree
     * through its values at the face's nodes (the Gauss-Lobatto points:
     * the vertices for degree 1, and the midpoint for 2), so that a gap
     * the trace can follow is met exactly. */
    class FaceGap
    {
    public:
      FaceGap(const Function<2>           *expression,
              const ContactPairParameters &parameters,
              const unsigned int           degree)
        : expression(expression)
      {
        if (expression && parameters.gap_evaluation == GapEvaluation::nodes)
        {
          nodes    = QGaussLobatto<1>(degree + 1).get_points();
          lagrange = Polynomials::generate_complete_Lagrange_basis(nodes);
        }
      }

      /** The values at the nodes of @p face. */
      void
      start(const ZoneFace &face)
      {
        node_f.clear();
        for (const auto &s : nodes)
          node_f.push_back(
            expression->value(face.a + s[0] * (face.b - face.a)));
      }

      /** f_n at @p x, the point at @p s along the face, whose partner on
       * S_2 is @p search_gap away. */
      double
      at(const double s, const Point<2> &x, const double search_gap) const
      {
        if (!expression)
          return search_gap;
        if (nodes.empty())
          return expression->value(x);
        double gap = 0;
        for (unsigned int k = 0; k < nodes.size(); ++k)
          gap += lagrange[k].value(s) * node_f[k];
        return gap;
      }

    private:
      const Function<2>                           *expression;
      std::vector<Point<1>>                        nodes;
      std::vector<Polynomials::Polynomial<double>> lagrange; // of the nodes
      std::vector<double>                          node_f;   // f_n there
    };

    /** Where @p face is split, as parameters in [0, 1]: where the normal
     * lines through the vertices of S_2 within reach cross it; there the
     * partner face changes, and so does the polynomial of u_2n
     * (ContactSearch). */
    std::vector<double>
    face_breaks(const ZoneFace      &face,
                const ContactSearch &search_2,
                const double         search_distance)
    {
      const Tensor<1, 2>  t      = face.b - face.a;
      const double        length = t.norm();
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
      return breaks;
    }

    /**
     * The contact points of S_1, face by face, on the common refinement
     * of the two zones: every piece of a face between its breaks
     * (face_breaks()) gets its own Gauss rule, and a point keeps its
     * partner on S_2, its gap and (serial or shared meshes) the shapes of
     * both bodies there, computed from the face's cell at once.
     */
    class ZoneSampler
    {
    public:
      ZoneSampler(const ContactPairParameters &parameters,
                  const ElasticBody<2>        &body_1,
                  const ElasticBody<2>        &body_2,
                  const std::vector<ZoneFace> &faces_2,
                  const ContactSearch         &search_2,
                  const Function<2>           *gap_function)
        : parameters(parameters)
        , body_1(body_1)
        , body_2(body_2)
        , faces_2(faces_2)
        , search_2(search_2)
        , gauss(parameters.n_gauss)
        , gap(gap_function, parameters, body_1.get_fe().degree)
      {
        report.search_distance = search_2.distance();
        report.expression_gap  = gap_function != nullptr;
        report.interference    = parameters.interference;
      }

      /** Adds the points of @p face, the zone's face @p index. */
      void
      add_face(const ZoneFace &face, const unsigned int index);

      std::vector<ContactPoint> points;
      std::vector<PointShape>   shapes_1, shapes_2;
      ContactSearchReport       report;

    private:
      const ContactPairParameters &parameters;
      const ElasticBody<2>        &body_1, &body_2;
      const std::vector<ZoneFace> &faces_2;
      const ContactSearch         &search_2;
      const QGauss<1>              gauss;
      FaceGap                      gap;
    };

    void
    ZoneSampler::add_face(const ZoneFace &face, const unsigned int index)
    {
      const Tensor<1, 2> t      = face.b - face.a;
      const double       length = t.norm();
      gap.start(face);
      const auto breaks = face_breaks(face, search_2, search_2.distance());
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
          p.face   = index;
          ++report.n_examined;

          // A point without a partner on S_2 cannot touch it: it carries no
          // pressure and has no gap.
          const auto partner = search_2.facing_point(p.x, p.normal);
          if (!partner)
            continue;
          p.projection = partner->point;
          p.gap        = gap.at(s, p.x, partner->gap);
          if (!std::isfinite(p.gap))
            throw InputError("Contact pair " + parameters.name +
                             "/Gap: " + gap_at(p) +
                             " of S_1; give an expression that is finite "
                             "on the whole zone");
          report.record(p.x, p.gap, partner->gap, length);
          // After the report: an interference is meant to overlap.
          p.gap -= parameters.interference;
          if (!body_2.is_mesh_distributed())
            shapes_2.push_back(point_shapes_at(
              body_2, faces_2[partner->segment].cell, {p.projection})[0]);
          xs.push_back(p.x);
          points.push_back(p);
        }
      if (!body_1.is_mesh_distributed() && !xs.empty())
        for (const auto &shape : point_shapes_at(body_1, face.cell, xs))
          shapes_1.push_back(shape);
    }

  } // namespace

  void
  ContactPair::setup()
  {
    const std::string section = "Contact pair " + parameters.name + "/";
    const auto        faces_1 = zone_faces(body_1, parameters.boundary_id_1);
    const auto        faces_2 = zone_faces(body_2, parameters.boundary_id_2);
    require_faces(
      faces_1, body_1, parameters.boundary_id_1, section + "Boundary id 1");
    require_faces(
      faces_2, body_2, parameters.boundary_id_2, section + "Boundary id 2");
    if (has_friction())
      check_friction_on(faces_1, *friction_function, parameters, body_1.name());

    const ContactSearch search_2 =
      search_on(faces_2,
                parameters.search_distance > 0
                  ? parameters.search_distance
                  : default_search_distance(longest_face(faces_1, faces_2)));
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

    ZoneSampler sampler(
      parameters, body_1, body_2, faces_2, search_2, gap_function.get());
    zone_1.clear();
    for (const auto &face : faces_1)
    {
      zone_1.push_back({{face.a, face.b}});
      sampler.add_face(face, zone_1.size() - 1);
    }
    contact_points = std::move(sampler.points);
    report         = sampler.report;
    arc_length     = ZoneArcLength(zone_1);

    // On a distributed mesh the owners of the points' cells compute the
    // shapes, at the end.
    if (body_1.is_mesh_distributed() || body_2.is_mesh_distributed())
    {
      std::vector<Point<2>> xs, projections;
      for (const auto &p : contact_points)
      {
        xs.push_back(p.x);
        projections.push_back(p.projection);
      }
      if (body_1.is_mesh_distributed())
        sampler.shapes_1 =
          remote_point_shapes(body_1, xs, section + "Boundary id 1");
      if (body_2.is_mesh_distributed())
        sampler.shapes_2 =
          remote_point_shapes(body_2, projections, section + "Boundary id 2");
    }
    for (unsigned int q = 0; q < contact_points.size(); ++q)
      couple_point(contact_points[q],
                   sampler.shapes_1[q],
                   sampler.shapes_2[q],
                   body_1,
                   body_2,
                   has_friction() ? friction_function.get() : nullptr,
                   parameters.friction_entry());

    set_penalty();
  }

  void
  ContactPair::set_penalty()
  {
    const std::string section = "Contact pair " + parameters.name + "/";

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
                  body_1.get_elastic_constants().youngs_modulus
              : parameters.penalty;
    // The penalty relative to the body, c = theta E_1 / H_1: below 1e-12 the
    // penetration theta p is below round-off of the displacements and the
    // pressure g/theta is round-off amplified by 1e12 (no solver can tell
    // contact from separation).
    const double extent = extent_1.second - extent_1.first;
    const double c =
      theta * body_1.get_elastic_constants().youngs_modulus / extent;
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
