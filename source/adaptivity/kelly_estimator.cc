#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/error_estimator.h>

#include <ddcontact/adaptivity/kelly_estimator.h>
#include <ddcontact/body/section_kinematics.h>

#include <cmath>

namespace ddcontact
{
  namespace
  {
    using Gradients = std::vector<std::vector<Tensor<1, 2>>>;

    /** The gradients of @p solution on the active @p cell at the real
     * points @p points of its face @p face. On a conforming face (@p
     * conforming) @p face_values on that face gives them: its quadrature
     * points are the same set, possibly in the opposite order (two
     * triangles may see their common line in opposite directions), so they
     * are matched by their coordinates, never by index. On the coarse side
     * of a hanging face (or if no match) the points are mapped back to @p
     * cell's reference cell. */
    void
    gradients_at(const DoFHandler<2>::active_cell_iterator &cell,
                 const unsigned int                         face,
                 const bool                                 conforming,
                 const std::vector<Point<2>>               &points,
                 const Mapping<2>                          &mapping,
                 const BodyVector                          &solution,
                 FEFaceValues<2>                           &face_values,
                 Gradients                                 &scratch,
                 Gradients                                 &gradients)
    {
      const unsigned int n       = points.size();
      bool               matched = conforming;
      if (conforming)
      {
        face_values.reinit(cell, face);
        face_values.get_function_gradients(solution, scratch);
        const double tolerance = 1e-10 * cell->face(face)->diameter();
        for (unsigned int q = 0; q < n && matched; ++q)
        {
          matched = false;
          for (unsigned int r = 0; r < n && !matched; ++r)
            if (points[q].distance(face_values.quadrature_point(r)) < tolerance)
            {
              gradients[q] = scratch[r];
              matched      = true;
            }
        }
      }
      if (matched)
        return;
      std::vector<Point<2>> unit(n);
      for (unsigned int q = 0; q < n; ++q)
        unit[q] = mapping.transform_real_to_unit_cell(cell, points[q]);
      FEValues<2> values(
        mapping, cell->get_fe(), Quadrature<2>(unit), update_gradients);
      values.reinit(cell);
      values.get_function_gradients(solution, gradients);
    }
  } // namespace

  Tensor<1, 2>
  face_flux(const std::vector<Tensor<1, 2>> &gradient,
            const Tensor<1, 2>              &normal,
            const ElasticConstants          *material)
  {
    Tensor<1, 2> f;
    if (material == nullptr)
    {
      for (unsigned int c = 0; c < gradient.size(); ++c)
        f[c] = gradient[c] * normal;
      return f;
    }
    SymmetricTensor<2, 2> strain;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        strain[i][j] = 0.5 * (gradient[i][j] + gradient[j][i]);
    // sigma n / (2 mu) of the elastic tangent (the in-plane part; the hoop
    // strain's lambda u_r / r is continuous and leaves the jumps).
    const SymmetricTensor<2, 3> sigma =
      material->tangent().apply(SectionKinematics::embed(strain, 0.));
    return SectionKinematics::in_plane(sigma) * normal / (2. * material->mu());
  }

  void
  face_jump_integrals(const Mapping<2>       &mapping,
                      const DoFHandler<2>    &dof_handler,
                      const Quadrature<1>    &face_quadrature,
                      const BodyVector       &solution,
                      const ElasticConstants *material,
                      const Geometry          geometry,
                      Vector<double>         &jumps)
  {
    const auto        &fe           = dof_handler.get_fe();
    const unsigned int n_components = fe.n_components();
    Assert(n_components <= 2, ExcNotImplemented());
    Assert(material == nullptr || n_components == 2, ExcNotImplemented());
    const unsigned int n_q = face_quadrature.size();
    FEFaceValues<2>    fine(mapping,
                         fe,
                         face_quadrature,
                         update_gradients | update_normal_vectors |
                           update_quadrature_points | update_JxW_values);
    FEFaceValues<2>    other(mapping,
                          fe,
                          face_quadrature,
                          update_gradients | update_quadrature_points);
    Gradients          grad(n_q, std::vector<Tensor<1, 2>>(n_components));
    Gradients          grad_other(grad), scratch(grad);

    // The squared jumps integrated over the faces of each cell. Every
    // interior face, or sub-face of a coarse cell's face, is integrated
    // once from its finer side (between equals, from the lower index), on
    // exactly the points deal.II's FESubfaceValues would use.
    jumps.reinit(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
      {
        if (cell->at_boundary(f))
          continue;
        const auto neighbor = cell->neighbor(f);
        if (neighbor->has_children())
          continue; // its children visit this face
        const bool coarser = cell->neighbor_is_coarser(f);
        if (!coarser &&
            neighbor->active_cell_index() < cell->active_cell_index())
          continue; // visited from the neighbour
        if (!cell->is_locally_owned() && !neighbor->is_locally_owned())
          continue;
        fine.reinit(cell, f);
        fine.get_function_gradients(solution, grad);
        gradients_at(neighbor,
                     coarser ? 0 : cell->neighbor_of_neighbor(f),
                     !coarser,
                     fine.get_quadrature_points(),
                     mapping,
                     solution,
                     other,
                     scratch,
                     grad_other);
        double integral = 0;
        for (unsigned int q = 0; q < n_q; ++q)
        {
          const Tensor<1, 2> &n = fine.normal_vector(q);
          integral += (face_flux(grad[q], n, material) -
                       face_flux(grad_other[q], n, material))
                        .norm_square() *
                      fine.JxW(q) *
                      section_measure(geometry, fine.quadrature_point(q));
        }
        jumps(cell->active_cell_index()) += integral;
        jumps(neighbor->active_cell_index()) += integral;
      }
  }

  void
  face_jump_indicators(const Mapping<2>    &mapping,
                       const DoFHandler<2> &dof_handler,
                       const Quadrature<1> &face_quadrature,
                       const BodyVector    &solution,
                       Vector<double>      &eta)
  {
    Vector<double> jumps;
    face_jump_integrals(mapping,
                        dof_handler,
                        face_quadrature,
                        solution,
                        nullptr,
                        Geometry::plane_strain,
                        jumps);
    kelly_weighted_indicators(dof_handler, jumps, eta);
  }

  void
  kelly_weighted_indicators(const DoFHandler<2>  &dof_handler,
                            const Vector<double> &integrals,
                            Vector<double>       &eta)
  {
    eta.reinit(integrals.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        eta(cell->active_cell_index()) = std::sqrt(
          cell->diameter() / 24. * integrals(cell->active_cell_index()));
  }

  KellyEstimator::KellyEstimator(const ElasticBody<2> &body)
    : body(body)
  {
  }

  void
  KellyEstimator::estimate(const BodyVector &u_fem,
                           const BoundaryTractionSamples &)
  {
    const QGauss<1> quadrature(body.get_fe().degree + 1);
    if (body.is_simplex())
      face_jump_indicators(
        body.get_mapping(), body.get_dof_handler(), quadrature, u_fem, eta);
    else
    {
      Vector<float> kelly(body.get_triangulation().n_active_cells());
      KellyErrorEstimator<2>::estimate(body.get_mapping(),
                                       body.get_dof_handler(),
                                       quadrature,
                                       {},
                                       u_fem,
                                       kelly);
      eta = kelly;
    }
    combine_process_values(body, eta);
  }
} // namespace ddcontact
