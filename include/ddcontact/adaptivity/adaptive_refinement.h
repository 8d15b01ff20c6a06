#ifndef ddcontact_adaptive_refinement_h
#define ddcontact_adaptive_refinement_h

#include <deal.II/lac/vector.h>

#include <ddcontact/adaptivity/adaptation_parameters.h>
#include <ddcontact/adaptivity/error_estimator.h>
#include <ddcontact/adaptivity/fem_bem_estimator.h>
#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/elastic_body.h>

#include <map>
#include <memory>
#include <string>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The element diameters of Definitions 1-2 of doc/method.md: for a
   * triangle, D_e and d_e are the diameters of its circumscribed and
   * inscribed circles; for a quadrilateral, the largest D and the smallest
   * d over the four triangles formed by three of its vertices. K_e =
   * D_e/d_e is the regularity of the element. One value per active cell.
   */
  struct ElementDiameters
  {
    Vector<double> D, d, K;
  };

  ElementDiameters
  element_diameters(const Triangulation<2> &triangulation);

  /**
   * The adaptation step of one adapted body (sections 4-5 of the paper
   * README): estimate the error of the FEM solution of the current body
   * problem (20), mark cells, refine them and transfer the current iterate.
   * A body is only given this object if it is adapted, and the BEM (inside
   * FemBemEstimator) only exists for the FEM-BEM estimators: a scene that
   * adapts with Kelly or uniformly never builds one.
   *
   * The adapted mesh stays one-irregular (at most one hanging node per
   * face, the paper's fix for spurious refinement): deal.II 9.4's
   * prepare_coarsening_and_refinement() adds the flags that keep it so on
   * quadrilateral and triangle meshes alike (no smoothing flag needed; a
   * random refinement of triangle meshes never left it, and
   * tests/triangle_adaptivity checks it). Triangles adapt with every
   * estimator (Kelly through face_jump_indicators()).
   */
  class AdaptiveRefinement
  {
  public:
    AdaptiveRefinement(ElasticBody<2>             &body,
                       const AdaptationParameters &parameters);

    const ElasticBody<2> &
    get_body() const
    {
      return body;
    }

    ElasticBody<2> &
    get_body()
    {
      return body;
    }

    /** Compute eta for @p u_fem, the FEM solution of the body problem
     * loaded by @p contact. */
    void
    estimate(const BodyVector &u_fem, const BoundaryTractionSamples &contact);

    /**
     * Flag the cells to refine by the threshold delta of (27), except
     * cells at Max level, and nothing when the refined mesh would exceed
     * Max cells. Returns the number of flagged cells.
     */
    unsigned int
    mark_above_delta();

    /** Flag the cells whose error contribution is at least @p threshold
     * (fraction and Doerfler marking of all adapted bodies together,
     * joint_marking_threshold()), with the caps of mark_above_delta(). */
    unsigned int
    mark_above(double threshold);

    /** The cells' error contributions of the last estimate, zero on the
     * cells at Max level: fraction and Doerfler marking rank only cells
     * that can be refined, so that cells kept at Max level (corners,
     * contact edges) do not use up the fraction and stall the refinement
     * elsewhere. */
    const Vector<double> &
    error_contributions() const
    {
      return refinable_contributions;
    }

    /** Flag every cell (uniform refinement). */
    unsigned int
    mark_all();

    /** Refine the flagged cells and transfer the body's current iterate;
     * rebuilds the body's system and factorization. */
    void
    refine();

    /** eta per active cell of the last estimate. */
    const Vector<double> &
    indicators() const
    {
      return eta;
    }

    /** The largest eta and the sum of eta over all cells of the last
     * estimate (all processes' cells of a distributed mesh). */
    double
    eta_max() const
    {
      return eta_maximum;
    }

    double
    eta_sum() const
    {
      return eta_total;
    }

    /** Cells that the last marking flagged but Max level (threshold
     * marking) or Max cells kept unrefined. */
    unsigned int
    n_capped() const
    {
      return capped;
    }

    /** The FEM-BEM estimator, or nullptr (Kelly, uniform). */
    const FemBemEstimator *
    fem_bem() const
    {
      return dynamic_cast<const FemBemEstimator *>(estimator.get());
    }

    /** eta, D_e, d_e, K_e of the current mesh for the VTU output (eta
     * only if it belongs to this mesh). */
    std::map<std::string, Vector<double>>
    cell_data() const;

  private:
    /** Clear the refine flags of cells at Max level, and all flags if the
     * refinement would exceed Max cells; returns the cells still marked
     * (over all processes) and counts the others in `capped`. */
    unsigned int
    apply_caps();

    ElasticBody<2>            &body;
    const AdaptationParameters parameters;
    // Null with uniform refinement.
    std::unique_ptr<ErrorEstimator> estimator;
    Vector<double>                  eta;
    Vector<double>                  refinable_contributions;
    double                          eta_maximum = 0, eta_total = 0;
    unsigned int                    capped = 0;
  };
  /**
   * The relative energy-norm error of all bodies adapted with a FEM-BEM
   * estimator, (sum ||sigma_B - sigma_F||_E^2 / sum ||sigma_B||_E^2)^(1/2):
   * the global estimate that Adaptation/Target error is compared with.
   * Negative if no body has a FEM-BEM estimate (Kelly, uniform).
   */
  double
  relative_energy_error_estimate(
    const std::vector<std::unique_ptr<AdaptiveRefinement>> &adaptations);

} // namespace ddcontact

#endif
