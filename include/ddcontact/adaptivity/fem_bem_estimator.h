#ifndef ddcontact_fem_bem_estimator_h
#define ddcontact_fem_bem_estimator_h

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/adaptivity/adaptation_parameters.h>
#include <ddcontact/adaptivity/error_estimator.h>
#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/elastic_body.h>

#include <boost/signals2/connection.hpp>

#include <memory>
#include <string>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The FEM-BEM error estimator of section 4 of doc/method.md, (22)-(27),
   * for one body: the body problem (20) of the current DD iteration is
   * solved a second time by the BEM on the boundary mesh of the FEM mesh
   * (25)-(26), with the same data (Dirichlet (5), tractions (6) and the
   * penalty contact traction), and the BEM stresses sigma_B, a priori more
   * accurate (23), are compared cell by cell with the FEM stresses
   * sigma_F, (24). With ||z||_W = sqrt(int_W sum_ij z_ij^2):
   *
   *  printed (27):  eta(e) = (||sigma_B - sigma_F||_e / |e|)
   *                          / (||sigma_B||_Omega / |Omega|);
   *  scaled:        eta(e) = (||sigma_B - sigma_F||_e / sqrt|e|)
   *                          / (||sigma_B||_Omega / sqrt|Omega|),
   *
   * the scaled one being the element's RMS stress error relative to the
   * body's RMS stress. The printed form grows like 1/h_e times the local
   * error: where the stress error is first order (Q1) it does not decrease
   * under refinement, so a fixed threshold delta need never be met; the
   * scaled form decreases like the local error.
   *
   * The BEM is set up (boundary mesh, assembly, LU) once per mesh: the
   * estimator watches its body's triangulation and rebuilds it after any
   * change.
   */
  class FemBemEstimator : public ErrorEstimator
  {
  public:
    /** @p variant is EstimatorType::fem_bem (printed) or
     * EstimatorType::fem_bem_scaled (scaled). */
    FemBemEstimator(const ElasticBody<2> &body, EstimatorType variant);

    ~FemBemEstimator() override;

    /**
     * Estimate the error of @p u_fem, the FEM solution of the body problem
     * loaded by @p contact on the body's contact ids (and by its own
     * boundary data). Fills indicators() and the global norms.
     */
    void
    estimate(const BodyVector              &u_fem,
             const BoundaryTractionSamples &contact) override;

    /** eta per active cell (printed or scaled, by the variant). */
    const Vector<double> &
    indicators() const override
    {
      return eta;
    }

    /** Both forms are relative to the body's stress: dimensionless. */
    bool
    comparable_with_delta() const override
    {
      return true;
    }

    /** ||sigma_B - sigma_F||_E,e, the energy norm on the cell: what it
     * adds to the global energy-norm error (in the same units on every
     * body, whatever its material). */
    const Vector<double> &
    error_contributions() const override
    {
      return local_energy_error;
    }

    /** ||sigma_B - sigma_F||_e per active cell. */
    const Vector<double> &
    local_errors() const
    {
      return local_error;
    }

    /** ||sigma_B - sigma_F||_Omega, the global estimate of (24). */
    double
    global_error() const
    {
      return error_norm;
    }

    /** ||sigma_B - sigma_F||_E = (int (sigma_B - sigma_F) : C^{-1}
     * (sigma_B - sigma_F))^(1/2), the energy norm of the stress error. */
    double
    energy_norm_error() const
    {
      return energy_error;
    }

    /** ||sigma_B||_E, the energy norm of the reference stress. */
    double
    energy_norm_of_stress() const
    {
      return energy_norm;
    }

    /** ||sigma_B||_Omega. */
    double
    stress_norm() const
    {
      return bem_stress_norm;
    }

    /** The BEM unknowns (for the total count M of Fig. 10). */
    unsigned int
    bem_unknowns() const
    {
      return bem.n_unknowns();
    }

    const BoundaryElementSolver &
    get_bem() const
    {
      return bem;
    }

    /** Seconds spent in BEM setup (assembly + LU), BEM solves, interior
     * stresses and the comparison, summed over all calls. */
    struct Timings
    {
      double bem_setup = 0, bem_solve = 0, bem_interior = 0, compare = 0;
    };

    const Timings &
    timings() const
    {
      return time;
    }

  private:
    /** The stresses of one body at the quadrature points of its cells. */
    using CellStresses = std::vector<std::vector<SymmetricTensor<2, 2>>>;

    /**
     * (24), (27): the cell norms of sigma_B - sigma_F (local_error, and in
     * the energy norm local_energy_error), their global norms and those of
     * sigma_B, with the FEM's cell quadrature, on the cells this process
     * computes (summed over a distributed mesh's processes). @p area gets
     * every cell's area; returns the body's.
     */
    double
    compare(const CellStresses &sigma_B,
            const CellStresses &sigma_F,
            Vector<double>     &area);

    const ElasticBody<2>       &body;
    const bool                  scaled;
    BoundaryElementSolver       bem;
    bool                        bem_is_current = false;
    boost::signals2::connection mesh_changed;

    Vector<double> eta, local_error, local_energy_error;
    double         error_norm = 0, bem_stress_norm = 0;
    double         energy_error = 0, energy_norm = 0;
    Timings        time;
  };
} // namespace ddcontact

#endif
