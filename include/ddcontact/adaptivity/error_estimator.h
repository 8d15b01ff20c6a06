#ifndef ddcontact_error_estimator_h
#define ddcontact_error_estimator_h

#include <deal.II/lac/vector.h>

#include <ddcontact/adaptivity/adaptation_parameters.h>
#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/elastic_body.h>

#include <memory>

namespace ddcontact
{
  using namespace dealii;

  /**
   * An error indicator eta per active cell of one body, computed from the
   * FEM solution of the body problem (20) of the current DD iteration
   * (section 4). Implementations: FemBemEstimator ((24), (27) and its
   * scaled form) and KellyEstimator (the gradient-jump baseline). A new
   * estimator is one class derived from this one plus its line in
   * create().
   *
   * On a distributed mesh eta holds the values of this process's own
   * cells and zero elsewhere; on a serial or shared mesh every cell's.
   */
  class ErrorEstimator
  {
  public:
    /** The estimator Adaptation/Estimator names, for @p body. */
    static std::unique_ptr<ErrorEstimator>
    create(const EstimatorType type, const ElasticBody<2> &body);

    virtual ~ErrorEstimator() = default;

    /** Compute eta for @p u_fem, the FEM solution of the body problem
     * loaded by @p contact on the body's contact ids. */
    virtual void
    estimate(const BodyVector              &u_fem,
             const BoundaryTractionSamples &contact) = 0;

    /** eta per active cell of the last estimate. */
    virtual const Vector<double> &
    indicators() const = 0;

    /** Each cell's share of the global error, for fraction and Doerfler
     * marking: they must rank cells by what refining them removes from the
     * error, not by an error density such as (27), which favours small
     * cells. The indicators themselves by default. */
    virtual const Vector<double> &
    error_contributions() const
    {
      return indicators();
    }

    /** Whether eta is dimensionless, so that threshold marking may compare
     * it with the delta of (27). */
    virtual bool
    comparable_with_delta() const = 0;
  };

  /**
   * Turns @p eta, computed by every process on its locally owned cells
   * only, into the convention of ErrorEstimator: on a serial or shared
   * mesh every cell's value (the sum over the processes), on a
   * distributed one the owned cells' values and zero elsewhere.
   */
  void
  combine_process_values(const ElasticBody<2> &body, Vector<double> &eta);
} // namespace ddcontact

#endif
