#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <ddcontact/contact_pair.h>

#include <algorithm>

namespace ddcontact
{
  namespace
  {
    /** A boundary face of a zone, as a straight segment (linear mapping). */
    struct ZoneFace
    {
      DoFHandler<2>::active_cell_iterator cell;
      unsigned int                        face_no;
      Point<2>                            a, b;
      Tensor<1, 2>                        normal; // outward
    };

    std::vector<ZoneFace>
    zone_faces(const ElasticBody<2> &body, const types::boundary_id id)
    {
      std::vector<ZoneFace> faces;
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
          {
            ZoneFace           z{cell,
                       f,
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
      return faces;
    }

    /** Values of the normal component of every shape function at points
     * of one cell given in real coordinates. */
    std::vector<std::vector<double>>
    normal_shape_values(const ElasticBody<2>                      &body,
                        const DoFHandler<2>::active_cell_iterator &cell,
                        const std::vector<Point<2>>               &points,
                        const Tensor<1, 2>                        &normal)
    {
      std::vector<Point<2>> unit_points(points.size());
      for (unsigned int i = 0; i < points.size(); ++i)
        unit_points[i] =
          body.get_mapping().transform_real_to_unit_cell(cell, points[i]);
      FEValues<2> fe_values(body.get_mapping(),
                            body.get_fe(),
                            Quadrature<2>(unit_points),
                            update_values);
      fe_values.reinit(cell);
      const auto                      &fe = body.get_fe();
      std::vector<std::vector<double>> values(
        points.size(), std::vector<double>(fe.dofs_per_cell));
      for (unsigned int q = 0; q < points.size(); ++q)
        for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          values[q][i]         = fe_values.shape_value(i, q) * normal[c];
        }
      return values;
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
    if (parameters.gap_type == "expression")
      gap_function = make_function(parameters.gap_expression,
                                   1,
                                   constants,
                                   "Contact pair " + parameters.name + "/Gap");
  }

  double
  ContactPair::thickness_of_body_1() const
  {
    if (parameters.thickness > 0)
      return parameters.thickness;
    // Extent of body 1 along the mean normal of S_1.
    Tensor<1, 2> mean;
    for (const auto &p : contact_points)
      mean += p.normal;
    if (mean.norm() == 0)
      return body_1.get_triangulation().begin_active()->diameter();
    mean /= mean.norm();
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const auto &v : body_1.get_triangulation().get_vertices())
    {
      lo = std::min(lo, v * mean);
      hi = std::max(hi, v * mean);
    }
    return hi - lo;
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

    // Vertices of S_2: their projections split the faces of S_1.
    std::vector<Point<2>> vertices_2;
    for (const auto &f : faces_2)
    {
      vertices_2.push_back(f.a);
      vertices_2.push_back(f.b);
    }

    const QGauss<1> gauss(parameters.n_gauss);
    contact_points.clear();
    for (const auto &face : faces_1)
    {
      const Tensor<1, 2>  t      = face.b - face.a;
      const double        length = t.norm();
      std::vector<double> breaks = {0., 1.};
      for (const auto &v : vertices_2)
      {
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

      std::vector<ContactPoint> face_points;
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
          face_points.push_back(p);
        }

      // Body 1: dofs and normal shape values of the face's cell.
      std::vector<Point<2>> xs;
      for (const auto &p : face_points)
        xs.push_back(p.x);
      const auto a = normal_shape_values(body_1, face.cell, xs, face.normal);
      std::vector<types::global_dof_index> dofs_1(
        body_1.get_fe().dofs_per_cell);
      face.cell->get_dof_indices(dofs_1);

      for (unsigned int q = 0; q < face_points.size(); ++q)
      {
        auto &p  = face_points[q];
        p.a      = a[q];
        p.dofs_1 = dofs_1;

        // Orthogonal projection P(x) on S_2: the closest point.
        double          best  = std::numeric_limits<double>::max();
        const ZoneFace *owner = nullptr;
        for (const auto &f : faces_2)
        {
          const Tensor<1, 2> d = f.b - f.a;
          const double       r =
            std::clamp((p.x - f.a) * d / d.norm_square(), 0., 1.);
          const Point<2> candidate = f.a + r * d;
          const double   distance  = candidate.distance(p.x);
          if (distance < best)
          {
            best         = distance;
            owner        = &f;
            p.projection = candidate;
          }
        }
        p.gap = gap_function ? gap_function->value(p.x)
                             : (p.projection - p.x) * p.normal;

        // n_2 = -n_1 (small-gap assumption).
        p.b = normal_shape_values(
          body_2, owner->cell, {p.projection}, -face.normal)[0];
        p.dofs_2.resize(body_2.get_fe().dofs_per_cell);
        owner->cell->get_dof_indices(p.dofs_2);
      }
      contact_points.insert(
        contact_points.end(), face_points.begin(), face_points.end());
    }

    // theta = c H / E_1 (paper, section 6), or given.
    theta = (parameters.penalty_type == "relative")
              ? parameters.penalty * thickness_of_body_1() /
                  body_1.get_material().youngs_modulus
              : parameters.penalty;
  }

  void
  ContactPair::normal_displacements(const Vector<double> &u_1,
                                    const Vector<double> &u_2,
                                    std::vector<double>  &u_1n,
                                    std::vector<double>  &u_2n) const
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

  std::pair<Tensor<1, 2>, Tensor<1, 2>>
  ContactPair::add_contact_loads(const std::vector<double> &sigma_n,
                                 Vector<double>            &load_1,
                                 Vector<double>            &load_2) const
  {
    AssertDimension(sigma_n.size(), contact_points.size());
    const auto    &fe_1 = body_1.get_fe();
    const auto    &fe_2 = body_2.get_fe();
    Tensor<1, 2>   force_1, force_2;
    Vector<double> local_1(fe_1.dofs_per_cell), local_2(fe_2.dofs_per_cell);
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      if (sigma_n[q] == 0.)
        continue;
      const auto  &p = contact_points[q];
      const double s = sigma_n[q] * p.JxW;
      for (unsigned int i = 0; i < p.a.size(); ++i)
      {
        local_1(i) = s * p.a[i];
        force_1[fe_1.system_to_component_index(i).first] += local_1(i);
      }
      for (unsigned int i = 0; i < p.b.size(); ++i)
      {
        local_2(i) = s * p.b[i];
        force_2[fe_2.system_to_component_index(i).first] += local_2(i);
      }
      body_1.get_constraints().distribute_local_to_global(
        local_1, p.dofs_1, load_1);
      body_2.get_constraints().distribute_local_to_global(
        local_2, p.dofs_2, load_2);
    }
    return {force_1, force_2};
  }

  void
  ContactPair::add_traction_samples(const std::vector<double> &sigma_n,
                                    const ElasticBody<2>      &body,
                                    BoundaryTractionSamples   &samples) const
  {
    AssertDimension(sigma_n.size(), contact_points.size());
    Assert(&body == &body_1 || &body == &body_2, ExcInternalError());
    const bool on_body_1 = (&body == &body_1);
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto &p = contact_points[q];
      samples.points.push_back(on_body_1 ? p.x : p.projection);
      samples.weights.push_back(p.JxW);
      samples.traction.push_back((on_body_1 ? sigma_n[q] : -sigma_n[q]) *
                                 p.normal);
    }
  }
} // namespace ddcontact
