#ifndef ddcontact_kelly_estimator_h
#define ddcontact_kelly_estimator_h

#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <ddcontact/adaptivity/error_estimator.h>
#include <ddcontact/body/geometry.h>
#include <ddcontact/body/material_law.h>

namespace ddcontact
{
  /**
   * Kelly's indicator computed face by face for any cell type: the formula
   * of deal.II's KellyErrorEstimator with its default strategy
   * (cell_diameter_over_24), no coefficient and all components,
   * @f[
   *   \eta_K^2 = \frac{h_K}{24} \sum_{F \subset \partial K}
   *              \int_F |[\nabla u_h\, n]|^2,
   * @f]
   * with h_K = cell->diameter(), the sum over the interior faces of K
   * (boundary faces contribute nothing: no Neumann data) and a face of K
   * with a finer neighbour contributing its sub-faces. deal.II 9.4's class
   * aborts on a triangle with a refined neighbour (QProjector has no
   * sub-faces for simplices); here every face is integrated from its finer
   * side, with @p face_quadrature mapped to that (smaller) face, and the
   * other side's gradient is evaluated at the same real points, so the
   * result equals deal.II's wherever that one runs (tests/kelly_triangles).
   *
   * Only the locally owned cells get their value (others stay zero), so
   * that on a shared mesh the MPI sum of the processes' vectors is the
   * whole indicator. @p eta is resized to the number of active cells.
   */
  void
  face_jump_indicators(const Mapping<2>    &mapping,
                       const DoFHandler<2> &dof_handler,
                       const Quadrature<1> &face_quadrature,
                       const BodyVector    &solution,
                       Vector<double>      &eta);

  /**
   * The flux across a face at one point, from the gradients of the
   * components: each component's normal derivative (Kelly's), or with a
   * @p material the traction sigma(u_h) n / (2 mu) of Hooke's law (2),
   * elasticity's own flux, scaled to the units of a strain.
   */
  Tensor<1, 2>
  face_flux(const std::vector<Tensor<1, 2>> &gradient,
            const Tensor<1, 2>              &normal,
            const ElasticConstants          *material);

  /**
   * The face integrals of face_jump_indicators() per active cell, before
   * the factor h_K/24: the sum over the interior (sub-)faces F of K of
   * int_F |[face_flux()]|^2, with or without a @p material, over the
   * section's measure (dS = 2 pi r ds for an axisymmetric @p geometry; the
   * hoop strain u_r / r is continuous and has no jump). @p jumps is resized
   * to the number of active cells; only faces with a locally owned side are
   * integrated.
   */
  void
  face_jump_integrals(const Mapping<2>       &mapping,
                      const DoFHandler<2>    &dof_handler,
                      const Quadrature<1>    &face_quadrature,
                      const BodyVector       &solution,
                      const ElasticConstants *material,
                      const Geometry          geometry,
                      Vector<double>         &jumps);

  /**
   * eta_K = sqrt(h_K / 24 * @p integrals(K)) on the locally owned cells,
   * zero on the others: Kelly's weight (strategy cell_diameter_over_24),
   * with h_K = cell->diameter().
   */
  void
  kelly_weighted_indicators(const DoFHandler<2>  &dof_handler,
                            const Vector<double> &integrals,
                            Vector<double>       &eta);

  /**
   * Kelly's indicator: the jump of the normal derivative of the FEM
   * displacement across the faces of each cell, the baseline against which
   * the FEM-BEM estimator is measured. Quadrilateral bodies use deal.II's
   * KellyErrorEstimator, triangle bodies (locally refined, with hanging
   * nodes) face_jump_indicators(), the same formula. It has the units of
   * the displacement gradient times a length, so threshold marking does
   * not apply.
   */
  class KellyEstimator : public ErrorEstimator
  {
  public:
    explicit KellyEstimator(const ElasticBody<2> &body);

    void
    estimate(const BodyVector              &u_fem,
             const BoundaryTractionSamples &contact) override;

    const Vector<double> &
    indicators() const override
    {
      return eta;
    }

    bool
    comparable_with_delta() const override
    {
      return false;
    }

  private:
    const ElasticBody<2> &body;
    Vector<double>        eta;
  };
} // namespace ddcontact

#endif
