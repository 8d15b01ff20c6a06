#ifndef ddcontact_kelly_estimator_h
#define ddcontact_kelly_estimator_h

#include <ddcontact/adaptivity/error_estimator.h>

namespace ddcontact
{
  /**
   * Kelly's indicator: the jump of the normal derivative of the FEM
   * displacement across the faces of each cell (deal.II's
   * KellyErrorEstimator), the baseline against which the FEM-BEM
   * estimator is measured. It has the units of the displacement gradient
   * times a length, so threshold marking does not apply.
   */
  class KellyEstimator : public ErrorEstimator
  {
  public:
    explicit KellyEstimator(const ElasticBody<2> &body);

    void
    estimate(const Vector<double>          &u_fem,
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
