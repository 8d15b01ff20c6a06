#ifndef ddcontact_neumann_dd_solver_h
#define ddcontact_neumann_dd_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_distribution.h>
#include <ddcontact/contact/contact_problem.h>
#include <ddcontact/parameters.h>
#include <ddcontact/solvers/errors.h>
#include <ddcontact/solvers/relaxation.h>
#include <ddcontact/solvers/uzawa_loop.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

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

  /**
   * The parallel Neumann domain decomposition (20)-(21): every iteration
   * loads each body by the penalty pressure of the previous iterate,
   *   sigma_n^k = (1/theta) min(0, f_n - u_1n^k - u_2n^k)        (20),
   * solves all body problems at once (one task per body, each reusing its
   * factorization), and relaxes, u^{k+1} = gamma u~^{k+1} + (1-gamma) u^k
   * (21), or with a dynamic gamma (Aitken) or Anderson acceleration.
   *
   * The physics (bodies, pairs, the law (20) with its multipliers) is the
   * ContactProblem's; the relaxation strategy is a Relaxation; the
   * augmented Lagrangian's outer loop is a UzawaLoop. This class owns all
   * three and does the iterating: initial guess, steps, stopping and
   * divergence tests.
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

    /** Initial guess (zero or Winkler); resets the history and the
     * multipliers. Call after the bodies and pairs have been set up. */
    void
    initialize();

    /** One iteration (20)-(21); returns true when the stopping test holds.
     * Throws DivergenceError. */
    bool
    step();

    /** Iterate until converged (with Uzawa updates if requested); returns
     * the number of DD iterations. Throws DivergenceError, or
     * NotConvergedError at Max iterations with a falling residual. */
    unsigned int
    run();

    /**
     * Domain decomposition/Max iterations is reached: throw
     * NotConvergedError if the residual still falls (a new best within the
     * last iterations, and below where it stood then), saying by how much
     * and roughly how many more iterations would reach eps_residual;
     * otherwise (grown or stagnated) a DivergenceError with the advice of
     * divergence_message(). @p what names the loop in the message ("the
     * domain decomposition", "the combined algorithm").
     */
    [[noreturn]] void
    stop_at_iteration_limit(const std::string &what) const;

    /** Contact state of pair @p p for the current iterate. */
    ContactState
    contact_state(unsigned int p) const;

    /** The contact problem (bodies, pairs, laws) the solver iterates on;
     * other solvers of the same problem (the monolithic Newton solver)
     * share its laws and multipliers. */
    ContactProblem &
    get_problem()
    {
      return problem;
    }

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
      return uzawa.n_updates();
    }

    /**
     * The augmented Lagrangian's outer step (UzawaLoop::update()) after
     * the iteration on the current multipliers has converged; on an update
     * a new phase of the DD starts (relaxation history and divergence
     * judgement afresh). Also drives the monolithic solver's Uzawa loop.
     */
    bool
    start_uzawa_phase();

    /** See UzawaLoop::shortfall(). */
    std::string
    augmented_lagrangian_shortfall() const
    {
      return uzawa.shortfall(problem);
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
    /** Throw, naming the cause, if the pressure last_sigma_n[p] computed
     * from @p u is not finite: a DivergenceError if @p u is not finite, an
     * InputError naming the penalty if g/theta overflowed. */
    void
    check_finite_pressure(unsigned int                   p,
                          const ContactProblem::Iterate &u,
                          unsigned int                   iteration) const;

    /** u^{k+1} from u~^{k+1} and the current u^k by the relaxation (21),
     * stored in the bodies with their constraints. */
    void
    relax(const ContactProblem::Iterate &u_tilde);

    /** A new phase of the iteration: the relaxation's history is dropped
     * and divergence is judged from here on. */
    void
    start_phase();

    /** The smallest residual of the current phase and its iteration. */
    std::pair<double, unsigned int>
    best_of_phase() const;

    /** The message of a DivergenceError: what diverged (@p event, e.g.
     * "diverged at iteration 12"), and which parameter to change (Gamma,
     * the penalty c, or eps_residual), judged from the estimated gamma*. */
    std::string
    divergence_message(const std::string     &event,
                       const IterationRecord &record,
                       double                 best,
                       unsigned int           best_k) const;

    const DDParameters           parameters;
    ContactProblem               problem;
    std::unique_ptr<Relaxation>  relaxation;
    UzawaLoop                    uzawa;
    ConditionalOStream          &pcout;
    std::vector<IterationRecord> records;
    // The last step's loads sigma_n^k (per pair) and solutions u~^{k+1}.
    std::vector<std::vector<double>>  last_sigma_n;
    ContactProblem::Iterate           last_u_tilde;
    unsigned int                      phase_start = 0; // first record
    Timer                             timer;
    std::function<void(unsigned int)> iteration_callback;
  };
} // namespace ddcontact

#endif
