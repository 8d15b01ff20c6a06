#ifndef ddcontact_adaptation_parameters_h
#define ddcontact_adaptation_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <ddcontact/parameter_tools.h>

#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** Adaptation/Mode: none; combined: one DD step (20)-(21) and one
   * adaptation step per cycle (Fig. 2); nested: DD to convergence on each
   * mesh, then adapt; uniform: DD to convergence, then refine every
   * cell. */
  enum class AdaptationMode
  {
    none,
    combined,
    nested,
    uniform
  };

  /** Adaptation/Estimator: eta_FB of (27) as printed; the local RMS stress
   * error relative to the global RMS stress; Kelly's, the baseline; the
   * explicit residual estimator, with the Neumann and contact data. */
  enum class EstimatorType
  {
    fem_bem,
    fem_bem_scaled,
    kelly,
    residual
  };

  /** Whether @p type compares FEM with BEM stresses (and builds a BEM). */
  inline bool
  is_fem_bem(const EstimatorType type)
  {
    return type == EstimatorType::fem_bem ||
           type == EstimatorType::fem_bem_scaled;
  }

  /** What an error estimator can take, one row per EstimatorType
   * (adaptation_parameters.cc); SceneParameters refuses the rest. */
  struct EstimatorCapabilities
  {
    /** Axisymmetric sections (the BEM's Kelvin kernels are plane
     * strain's). */
    bool axisymmetric = false;
    /** Bodies of a nonlinear material law (the jumps and residuals of the
     * law's own stress). */
    bool nonlinear_laws = false;
  };

  const EstimatorCapabilities &
  capabilities_of(EstimatorType type);

  /** "kelly or residual": the estimators that have @p capability (empty
   * if none). */
  std::string
  estimators_with(bool EstimatorCapabilities::*capability);

  /** Adaptation/Marking: eta > delta as in (27), a fixed fraction, or
   * Doerfler's bulk criterion. */
  enum class MarkingType
  {
    threshold,
    fraction,
    doerfler
  };

  DDCONTACT_DECLARE_SELECTION(AdaptationMode)
  DDCONTACT_DECLARE_SELECTION(EstimatorType)
  DDCONTACT_DECLARE_SELECTION(MarkingType)

  /** The entry value of an option ("combined", "fem-bem-scaled", ...), as
   * summary.json and the messages write it. */
  std::string
  to_string(AdaptationMode value);
  std::string
  to_string(EstimatorType value);
  std::string
  to_string(MarkingType value);

  /**
   * h-adaptivity and the combined algorithm (sections 4-5 of the paper
   * README), in the subsection "Adaptation".
   */
  struct AdaptationParameters
  {
    AdaptationMode           mode = AdaptationMode::none;
    std::vector<std::string> bodies; // the adapted bodies
    EstimatorType            estimator        = EstimatorType::fem_bem;
    MarkingType              marking          = MarkingType::threshold;
    double                   delta            = 0.1; // threshold of (27)
    double                   fraction         = 0.3;
    unsigned int             max_cycles       = 50;
    unsigned int             max_level        = 10;
    unsigned int             max_cells        = 200000;
    bool                     write_every_mesh = true;
    // Stop when the relative energy-norm estimate is below this (0: no
    // target).
    double target_error = 0;

    /** With a Target error above the estimate, each cycle refines cells
     * that carry at least this share of the squared estimate (Doerfler),
     * whatever the marking rule flagged: a geometric reduction of the
     * error per cycle, so that the run ends within a few times the cost of
     * its final mesh. */
    static constexpr double min_refined_error_share = 0.2;

    bool
    enabled() const
    {
      return mode != AdaptationMode::none;
    }

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };
} // namespace ddcontact

#endif
