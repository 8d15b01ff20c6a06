#ifndef ddcontact_neumann_dd_solver_h
#define ddcontact_neumann_dd_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body_distribution.h>
#include <ddcontact/contact_pair.h>
#include <ddcontact/elastic_body.h>
#include <ddcontact/parameters.h>

#include <deque>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** The iteration diverged; the message says what to change. */
  class DivergenceError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /** What one DD iteration measured (one row of history.csv). */
  struct IterationRecord
  {
    unsigned int iteration       = 0;
    double       increment       = 0; // the paper's test, max over bodies
    double       residual        = 0; // ||u~_n - u_n|| / ||u~_n|| on S
    double       gamma           = 0;
    double       force           = 0; // |contact force on body 1|, all pairs
    double       active_length   = 0;
    double       max_penetration = 0;
    double       time            = 0;
  };

  /** Contact results of one pair, from the current iterate. */
  struct ContactState
  {
    std::vector<double> u_1n, u_2n, sigma_n; // at every contact point
    Tensor<1, 2>        force_1, force_2;
    double              max_pressure   = 0;
    double              contact_length = 0;
    double half_width      = 0; // half the extent of the active set along S
    double max_penetration = 0;
  };

  /**
   * The parallel Neumann domain decomposition (20)-(21): every iteration
   * loads each body by the penalty pressure of the previous iterate,
   *   sigma_n^k = (1/theta) min(0, f_n - u_1n^k - u_2n^k)        (20),
   * solves all body problems at once (one task per body, each reusing its
   * factorization), and relaxes, u^{k+1} = gamma u~^{k+1} + (1-gamma) u^k
   * (21), or with a dynamic gamma (Aitken) or Anderson acceleration.
   * Optionally an outer augmented-Lagrangian (Uzawa) loop adds a multiplier
   * lambda to the pressure, sigma_n = min(0, lambda + g/theta), so that the
   * penetration goes to zero without shrinking theta.
   */
  class NeumannDDSolver
  {
  public:
    /** The body problems are solved where @p distribution says (every
     * body on this process when it has one process). */
    NeumannDDSolver(const DDParameters                  &parameters,
                    const std::vector<ElasticBody<2> *> &bodies,
                    const std::vector<ContactPair *>    &pairs,
                    const BodyDistribution              &distribution,
                    ConditionalOStream                  &pcout);

    /** Initial guess (zero or Winkler); resets the history. Call after the
     * bodies and pairs have been set up. */
    void
    initialize();

    /** One iteration (20)-(21); returns true when the stopping test holds.
     * Throws DivergenceError. */
    bool
    step();

    /** Iterate until converged (with Uzawa updates if requested); returns
     * the number of DD iterations. Throws DivergenceError, or a
     * std::runtime_error when the maximum is reached. */
    unsigned int
    run();

    /** Contact state of pair @p p for the current iterate. */
    ContactState
    contact_state(unsigned int p) const;

    /** Called after every iteration with its number (e.g. to write the
     * contact profiles of every iterate, the paper's Fig. 9). */
    void
    set_iteration_callback(const std::function<void(unsigned int)> &callback)
    {
      iteration_callback = callback;
    }

    const std::vector<IterationRecord> &
    history() const
    {
      return records;
    }

    /** Uzawa updates over the whole run (all meshes). */
    unsigned int
    n_uzawa_updates() const
    {
      return uzawa_updates;
    }

    /**
     * The augmented Lagrangian's outer step, after the iteration on the
     * current multipliers has converged: if the penetration is still above
     * the tolerance and not yet at the limit of non-matching meshes (no
     * longer shrinking, after falling tenfold), set lambda <- sigma_n (the
     * converged pressure) and start a new phase of the DD (returns true);
     * otherwise leave lambda as it is, so that the iterate and the
     * reported pressure stay consistent (returns false). Always false
     * without "Augmented Lagrangian". Also drives the monolithic solver's
     * Uzawa loop.
     */
    bool
    start_uzawa_phase();

    /** Empty when the augmented Lagrangian is off, met its tolerance on
     * the current iterate, or stopped at the limit of non-matching meshes
     * (see start_uzawa_phase()); otherwise the one-line message that says how
     * far it is off and what to change (the run must not say
     * "converged"). */
    std::string
    augmented_lagrangian_shortfall() const;

    /** The Uzawa multipliers lambda of every pair, at its contact points
     * (zero without the augmented Lagrangian). */
    const std::vector<std::vector<double>> &
    get_multipliers() const
    {
      return multipliers;
    }

    /**
     * Estimate the stability limit gamma* of the fixed relaxation (21) by
     * power iteration on the linearised DD operator with every contact
     * point active (costs about 30 solves of each body).
     */
    double
    estimate_gamma_limit() const;

    /**
     * The FEM solution u~^{k+1} of the body problem (20) of @p body in the
     * last step, before the relaxation (21): the FEM side of the FEM-BEM
     * estimator, which must solve the same boundary value problem as the
     * BEM.
     */
    const Vector<double> &
    last_body_solution(const ElasticBody<2> &body) const;

    /** The contact traction that loaded @p body in the last step (20). */
    BoundaryTractionSamples
    last_contact_traction(const ElasticBody<2> &body) const;

    /** Take the bodies' current solutions as the last body solutions,
     * loaded by their own contact pressure: after a solver that converged
     * without DD steps (the monolithic one), the converged u solves (20)
     * with that load, so the estimator sees the same problem. */
    void
    adopt_current_iterate();

    /** Re-create internal vectors after a mesh change (the bodies keep
     * their transferred solutions and the pairs have been set up again).
     * The multipliers move to the new contact points (each takes the value
     * of the nearest old point), and the Uzawa loop starts afresh on the
     * new mesh. */
    void
    reinit_after_refinement();

  private:
    /** Penalty pressure of pair p from the displacements u. */
    std::vector<double>
    pressure(unsigned int p, const std::vector<Vector<double>> &u) const;

    /** The bodies' current solutions u^k. */
    std::vector<Vector<double>>
    current_iterate() const;

    /** The largest penetration u_1n + u_2n - f_n over all pairs, and its
     * ratio to the largest approach |u_1n| + |u_2n| (the measure of the
     * AL tolerance). */
    std::pair<double, double>
    penetration() const;

    /** Throw, naming the cause, if the pressure last_sigma_n[p] computed
     * from @p u is not finite: a DivergenceError if @p u is not finite, an
     * InputError naming the penalty if g/theta overflowed. */
    void
    check_finite_pressure(unsigned int                       p,
                          const std::vector<Vector<double>> &u,
                          unsigned int                       iteration) const;

    /** The smallest residual of the current Uzawa phase and its
     * iteration. */
    std::pair<double, unsigned int>
    best_of_phase() const;

    /** Solve every body b with the extra load loads[b] (empty: none), each
     * on its process, concurrently; every process receives all u[b]. */
    void
    solve_all(const std::vector<Vector<double>> &loads,
              std::vector<Vector<double>>       &u) const;

    /** Solve all bodies with the contact loads of the normal stresses
     * sigma_n (one vector per pair). */
    void
    solve_bodies(const std::vector<std::vector<double>> &sigma_n,
                 std::vector<Vector<double>>            &u_tilde) const;

    /** Normal displacements on S of all pairs, both sides, body by body. */
    std::vector<std::vector<double>>
    normal_displacements_by_body(const std::vector<Vector<double>> &u) const;

    void
    relax(const std::vector<Vector<double>> &u_tilde);

    /** The current contact points of every pair, to transfer the
     * multipliers after refinement. */
    void
    record_multiplier_points();

    /** The message of a DivergenceError: what diverged, and which
     * parameter to change (Gamma, the penalty c, or eps_residual), judged
     * from the estimated gamma*. */
    std::string
    divergence_message(const IterationRecord &record,
                       double                 best,
                       unsigned int           best_k) const;

    unsigned int
    body_index(const ElasticBody<2> &body) const;

    const DDParameters            parameters;
    std::vector<ElasticBody<2> *> bodies;
    std::vector<ContactPair *>    pairs;
    const BodyDistribution       &distribution;
    ConditionalOStream           &pcout;

    std::vector<std::vector<double>>   multipliers; // Uzawa lambda per pair
    std::vector<std::vector<Point<2>>> multiplier_points; // where they live
    std::vector<IterationRecord>       records;
    // The last step's loads sigma_n^k (per pair) and solutions u~^{k+1}.
    std::vector<std::vector<double>> last_sigma_n;
    std::vector<Vector<double>>      last_u_tilde;
    unsigned int                     uzawa_updates      = 0; // whole run
    unsigned int                     mesh_uzawa_updates = 0; // this mesh
    double                           last_penetration   = 0;
    double first_penetration = 0; // at the first Uzawa check of this mesh
    bool   mesh_limited = false;  // the last check stopped at the mesh limit
    unsigned int phase_start = 0; // first record of this Uzawa phase
    double       gamma       = 0;
    Timer        timer;
    std::function<void(unsigned int)> iteration_callback;

    // Aitken: the previous residual; Anderson: histories of residual and
    // map-value differences.
    Vector<double>             previous_residual, previous_g;
    std::deque<Vector<double>> delta_f, delta_g;
  };
} // namespace ddcontact

#endif
