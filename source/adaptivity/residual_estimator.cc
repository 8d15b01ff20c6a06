#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>

#include <ddcontact/adaptivity/kelly_estimator.h>
#include <ddcontact/adaptivity/residual_estimator.h>
#include <ddcontact/bem/boundary_integration.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace ddcontact
{
  namespace
  {
    using Gradients = std::vector<std::vector<Tensor<1, 2>>>;

    /** The contact faces of a body that this process knows (owned and
     * ghost cells), with the samples of the contact load nearest to each:
     * on body 1 of a pair they are Gauss points of its faces, on body 2
     * the projections of those, on pieces that S_2's vertices split
     * (ContactPair), so every sample lies inside one face. The nearest
     * face is found by looking at all of them (samples times faces: some
     * 1e7 distances at 5e5 unknowns, tens of milliseconds). */
    struct ContactFaces
    {
      std::vector<std::pair<DoFHandler<2>::active_cell_iterator, unsigned int>>
                                             faces;
      std::vector<std::vector<unsigned int>> samples; // per face

      ContactFaces(const ElasticBody<2>          &body,
                   const BoundaryTractionSamples &contact)
      {
        const auto &ids = body.get_boundary_conditions().contact;
        for (const auto &cell : body.get_dof_handler().active_cell_iterators())
          if (!cell->is_artificial())
            for (const unsigned int f : cell->face_indices())
              if (cell->at_boundary(f) &&
                  ids.count(cell->face(f)->boundary_id()) > 0)
                faces.emplace_back(cell, f);
        samples.resize(faces.size());
        for (unsigned int q = 0; q < contact.points.size(); ++q)
        {
          unsigned int nearest  = numbers::invalid_unsigned_int;
          double       distance = std::numeric_limits<double>::max();
          for (unsigned int i = 0; i < faces.size(); ++i)
          {
            const auto   face = faces[i].first->face(faces[i].second);
            const double d    = BoundaryIntegration::point_segment_distance(
              contact.points[q], face->vertex(0), face->vertex(1));
            if (d < distance)
            {
              distance = d;
              nearest  = i;
            }
          }
          // A sample of a face this process does not know (an artificial
          // cell of a distributed mesh) is far from every face it knows.
          if (nearest != numbers::invalid_unsigned_int &&
              distance <=
                0.25 *
                  faces[nearest].first->face(faces[nearest].second)->diameter())
            samples[nearest].push_back(q);
        }
      }
    };

    /** The coordinate in [0, 1] of @p x along the chord from @p a to @p b. */
    double
    chord_coordinate(const Point<2> &x, const Point<2> &a, const Point<2> &b)
    {
      const Tensor<1, 2> t = b - a;
      return (x - a) * t / t.norm_square();
    }

    /**
     * Adds to @p g, at the points @p x of the face from @p a to @p b, the
     * L2 projection (in the measure @p dS) of the contact load of the
     * @p samples on the polynomials @p legendre of the chord coordinate:
     * the face's moments sum_q w_q g_q L_j(x_q) of the samples, which load
     * the FEM problem (20), divided by the Gram matrix.
     */
    void
    add_projected_load(
      const Point<2>                                     &a,
      const Point<2>                                     &b,
      const std::vector<Point<2>>                        &x,
      const std::vector<double>                          &dS,
      const std::vector<unsigned int>                    &samples,
      const BoundaryTractionSamples                      &contact,
      const std::vector<Polynomials::Polynomial<double>> &legendre,
      std::vector<Tensor<1, 2>>                          &g)
    {
      const unsigned int n = legendre.size(), n_q = x.size();
      // L_j at the face's quadrature points.
      std::vector<std::vector<double>> L(n_q, std::vector<double>(n));
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int j = 0; j < n; ++j)
          L[q][j] = legendre[j].value(chord_coordinate(x[q], a, b));
      FullMatrix<double> gram(n, n);
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int k = 0; k < n; ++k)
            gram(j, k) += L[q][j] * L[q][k] * dS[q];
      gram.gauss_jordan();
      std::vector<Tensor<1, 2>> moments(n), coefficients(n);
      for (const unsigned int p : samples)
      {
        const double s = chord_coordinate(contact.points[p], a, b);
        for (unsigned int j = 0; j < n; ++j)
          moments[j] +=
            contact.weights[p] * legendre[j].value(s) * contact.traction[p];
      }
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int k = 0; k < n; ++k)
          coefficients[j] += gram(j, k) * moments[k];
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int j = 0; j < n; ++j)
          g[q] += L[q][j] * coefficients[j];
    }

    /**
     * int_F |(g - sigma(u_h) n) / (2 mu)|^2 dS over the face of @p values
     * in the components that @p prescribed leaves free, with u_h's
     * gradients @p grad and values @p u (the strain of @p kinematics, with
     * the hoop strain of an axisymmetric section), the stress of the
     * elastic @p material's tangent, and the measure @p dS.
     */
    double
    traction_residual(const FEFaceValues<2>             &values,
                      const Gradients                   &grad,
                      const std::vector<Vector<double>> &u,
                      const std::vector<Tensor<1, 2>>   &g,
                      const std::vector<double>         &dS,
                      const ComponentMask               &prescribed,
                      const ElasticConstants            &material,
                      const SectionKinematics           &kinematics)
    {
      const MaterialTangent tangent  = material.tangent();
      double                integral = 0;
      for (unsigned int q = 0; q < dS.size(); ++q)
      {
        if (dS[q] == 0)
          continue; // a face on the axis: no ring, no residual
        const Tensor<1, 2>   &n = values.normal_vector(q);
        SymmetricTensor<2, 2> in_plane;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = i; j < 2; ++j)
            in_plane[i][j] = 0.5 * (grad[q][i][j] + grad[q][j][i]);
        const double eps_33 = kinematics.out_of_plane_strain(
          values.quadrature_point(q), u[q](0), grad[q][0][0]);
        const SymmetricTensor<2, 2> sigma = SectionKinematics::in_plane(
          tangent.apply(SectionKinematics::embed(in_plane, eps_33)));
        const Tensor<1, 2> r = (g[q] - sigma * n) / (2. * material.mu());
        for (unsigned int c = 0; c < 2; ++c)
          if (!prescribed[c])
            integral += r[c] * r[c] * dS[q];
      }
      return integral;
    }
  } // namespace

  void
  ResidualEstimator::add_boundary_residuals(
    const BodyVector              &solution,
    const BoundaryTractionSamples &contact,
    Vector<double>                &integrals) const
  {
    const QGauss<1>             face_quadrature(body.get_fe().degree + 1);
    const auto                 &conditions = body.get_boundary_conditions();
    const ElasticConstants     &material   = body.get_elastic_constants();
    const SectionKinematics     kinematics = body.get_kinematics();
    const unsigned int          n_q        = face_quadrature.size();
    const unsigned int          degree     = body.get_fe().degree;
    FEFaceValues<2>             values(body.get_mapping(),
                           body.get_fe(),
                           face_quadrature,
                           update_values | update_gradients |
                             update_normal_vectors | update_quadrature_points |
                             update_JxW_values);
    Gradients                   grad(n_q, std::vector<Tensor<1, 2>>(2));
    std::vector<Vector<double>> u(n_q, Vector<double>(2));
    std::vector<Vector<double>> neumann(n_q, Vector<double>(2));
    std::vector<Tensor<1, 2>>   g(n_q);
    // The measure of the boundary: ds, or 2 pi r ds on the ring, the
    // measure of the contact samples' weights as well.
    std::vector<double> dS(n_q);

    // The contact load per face: its L2 projection on the Legendre
    // polynomials of degree <= the element's in the chord coordinate.
    const ContactFaces contact_faces(body, contact);
    const auto         legendre =
      Polynomials::Legendre::generate_complete_basis(degree);
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> face_index;
    for (unsigned int i = 0; i < contact_faces.faces.size(); ++i)
      face_index[{contact_faces.faces[i].first->active_cell_index(),
                  contact_faces.faces[i].second}] = i;

    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
        {
          if (!cell->at_boundary(f))
            continue;
          const types::boundary_id id = cell->face(f)->boundary_id();
          ComponentMask            prescribed(2, false);
          if (const auto d = conditions.dirichlet.find(id);
              d != conditions.dirichlet.end())
            prescribed = d->second.mask;
          if (prescribed.n_selected_components(2) == 2)
            continue;
          values.reinit(cell, f);
          values.get_function_gradients(solution, grad);
          values.get_function_values(solution, u);
          for (unsigned int q = 0; q < n_q; ++q)
            dS[q] =
              values.JxW(q) * kinematics.measure(values.quadrature_point(q));

          std::fill(g.begin(), g.end(), Tensor<1, 2>());
          if (const auto t = conditions.neumann.find(id);
              t != conditions.neumann.end())
          {
            t->second->vector_value_list(values.get_quadrature_points(),
                                         neumann);
            for (unsigned int q = 0; q < n_q; ++q)
              for (unsigned int c = 0; c < 2; ++c)
                g[q][c] = neumann[q](c);
          }
          if (const auto i = face_index.find({cell->active_cell_index(), f});
              i != face_index.end() &&
              !contact_faces.samples[i->second].empty())
          {
            const auto face = cell->face(f);
            add_projected_load(face->vertex(0),
                               face->vertex(1),
                               values.get_quadrature_points(),
                               dS,
                               contact_faces.samples[i->second],
                               contact,
                               legendre,
                               g);
          }

          const double integral = traction_residual(
            values, grad, u, g, dS, prescribed, material, kinematics);
          integrals(cell->active_cell_index()) += integral;
        }
  }

  ResidualEstimator::ResidualEstimator(const ElasticBody<2> &body)
    : body(body)
  {
  }

  void
  ResidualEstimator::add_cell_residuals(const BodyVector &solution,
                                        Vector<double>   &integrals) const
  {
    const ElasticConstants &material = body.get_elastic_constants();
    const auto             &force = body.get_boundary_conditions().body_force;
    const Geometry          geometry   = body.get_geometry();
    const SectionKinematics kinematics = body.get_kinematics();
    const double            lambda = material.lambda(), mu = material.mu();
    const auto             &quadrature = body.get_cell_quadrature();
    const unsigned int      n_q        = quadrature.size();
    FEValues<2>             values(body.get_mapping(),
                       body.get_fe(),
                       quadrature,
                       update_values | update_gradients | update_hessians |
                         update_quadrature_points | update_JxW_values);
    std::vector<std::vector<Tensor<2, 2>>> hessians(
      n_q, std::vector<Tensor<2, 2>>(2));
    Gradients                   grad(n_q, std::vector<Tensor<1, 2>>(2));
    std::vector<Vector<double>> u(n_q, Vector<double>(2));
    std::vector<Vector<double>> f(n_q, Vector<double>(2));
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
      {
        values.reinit(cell);
        values.get_function_hessians(solution, hessians);
        if (geometry == Geometry::axisymmetric)
        {
          values.get_function_values(solution, u);
          values.get_function_gradients(solution, grad);
        }
        if (force)
          force->vector_value_list(values.get_quadrature_points(), f);
        double integral = 0;
        for (unsigned int q = 0; q < n_q; ++q)
        {
          // div sigma(u) = lambda grad div u + mu (Laplace u + grad div u)
          // (Hooke's law (2), homogeneous body).
          const auto  &H          = hessians[q];
          const double grad_div_0 = H[0][0][0] + H[1][1][0];
          const double grad_div_1 = H[0][0][1] + H[1][1][1];
          Tensor<1, 2> r;
          r[0]              = (lambda + mu) * grad_div_0 + mu * trace(H[0]);
          r[1]              = (lambda + mu) * grad_div_1 + mu * trace(H[1]);
          const Point<2> &x = values.quadrature_point(q);
          if (geometry == Geometry::axisymmetric)
          {
            // The terms of the hoop strain u_r / r in (r, z): with a = u_r,
            // b = u_z, div sigma gains (lambda + 2 mu)(a_r / r - a / r^2)
            // and ((lambda + mu) a_z + mu b_r) / r, the remainder of
            // (sigma_rr - sigma_tt) / r and sigma_rz / r once sigma holds
            // lambda a / r. Quadrature points lie off the axis, r > 0.
            const auto  &G  = grad[q];
            const double rr = x[0];
            const double hoop =
              kinematics.out_of_plane_strain(x, u[q](0), G[0][0]);
            r[0] += (lambda + 2. * mu) * (G[0][0] - hoop) / rr;
            r[1] += ((lambda + mu) * G[0][1] + mu * G[1][0]) / rr;
          }
          if (force)
            for (unsigned int c = 0; c < 2; ++c)
              r[c] += f[q](c);
          integral += (r / (2. * mu)).norm_square() * values.JxW(q) *
                      kinematics.measure(x);
        }
        integrals(cell->active_cell_index()) += cell->diameter() * integral;
      }
  }

  void
  ResidualEstimator::estimate(const BodyVector              &u_fem,
                              const BoundaryTractionSamples &contact)
  {
    Vector<double> integrals;
    face_jump_integrals(body.get_mapping(),
                        body.get_dof_handler(),
                        QGauss<1>(body.get_fe().degree + 1),
                        u_fem,
                        &body.get_elastic_constants(),
                        body.get_geometry(),
                        integrals);
    add_boundary_residuals(u_fem, contact, integrals);
    add_cell_residuals(u_fem, integrals);
    kelly_weighted_indicators(body.get_dof_handler(), integrals, eta);
    combine_process_values(body, eta);
  }
} // namespace ddcontact
