#ifndef ddcontact_residual_estimator_h
#define ddcontact_residual_estimator_h

#include <ddcontact/adaptivity/error_estimator.h>

namespace ddcontact
{
  /**
   * The explicit residual estimator of linear elasticity
   * (Adaptation/Estimator = residual): Kelly's face jumps taken in
   * elasticity's own flux, the traction, with the Neumann data and the
   * cell residual,
   * @f[
   *   \eta_K^2 = \frac{h_K}{24} \Big( h_K \int_K \Big|\frac{f +
   *      \mathrm{div}\,\sigma(u_h)}{2\mu}\Big|^2
   *    + \sum_{F \not\subset \Gamma} \int_F
   *      \Big|\frac{[\sigma(u_h) n]}{2\mu}\Big|^2
   *    + \sum_{F \subset \Gamma_p \cup S \cup \Gamma_0}
   *      \int_F \Big|\frac{g - \sigma(u_h) n}{2\mu}\Big|^2 \Big),
   * @f]
   * Kelly's weight h_K/24 on every term, so that without data and for
   * linear elements it is KellyEstimator's in the traction. It bounds the
   * energy error from above and below (Verfuerth); the face terms dominate
   * for linear elements, the cell term is needed from degree 2 on.
   *
   * g is the prescribed traction (6) on Gamma_p, zero on the traction-free
   * boundary Gamma_0 and, on the contact zone S, the whole contact traction
   * of the iterate (p n and, with friction, t tau): the contact zone's
   * error, which Kelly's gradient jumps see only through the cells next to
   * it, enters directly. The contact traction is known at sample points
   * only (BoundaryTractionSamples): it enters face by face as its L2
   * projection on the polynomials of the element's degree, from the
   * moments sum_q w_q g_q L_j(x_q) of the samples on the face, the moments
   * that load the FEM problem (20).
   *
   * In an axisymmetric body (Geometry = axisymmetric) sigma holds the hoop
   * strain u_r / r, div sigma its terms in (r, z), and every integral is
   * over the ring (2 pi r; doc/axisymmetric.md).
   *
   * Its units are those of Kelly's (a strain times a length), so threshold
   * marking does not apply.
   */
  class ResidualEstimator : public ErrorEstimator
  {
  public:
    explicit ResidualEstimator(const ElasticBody<2> &body);

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
    /** Adds int_K |(f + div sigma(u_h)) / (2 mu)|^2 h_K per cell. */
    void
    add_cell_residuals(const BodyVector &u_fem,
                       Vector<double>   &integrals) const;

    /** Adds int_F |(g - sigma(u_h) n) / (2 mu)|^2 over the boundary faces
     * with traction data, in the components that no Dirichlet condition
     * prescribes. */
    void
    add_boundary_residuals(const BodyVector              &u_fem,
                           const BoundaryTractionSamples &contact,
                           Vector<double>                &integrals) const;

    const ElasticBody<2> &body;
    Vector<double>        eta;
  };
} // namespace ddcontact

#endif
