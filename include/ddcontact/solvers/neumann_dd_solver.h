#ifndef ddcontact_neumann_dd_solver_h
#define ddcontact_neumann_dd_solver_h

#include <ddcontact/solvers/contact_solver.h>
#include <ddcontact/solvers/relaxation.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

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
   * augmented Lagrangian's outer loop is the ContactSolver's UzawaLoop.
   * This class does the iterating: initial guess, steps, stopping and
   * divergence tests.
   */
  class NeumannDDSolver : public ContactSolver
  {
  public:
    /** The body problems are solved where the distribution says (every
     * body on this process when it has one process). */
    using ContactSolver::ContactSolver;

    /** Initial guess (zero or Winkler); resets the history and the
     * multipliers. Call after the bodies and pairs have been set up. */
    void
    initialize() override;

    /** One iteration (20)-(21); returns true when the stopping test holds.
     * Throws DivergenceError. */
    bool
    step() override;

    /**
     * Contact solver/Max iterations is reached: throw
     * NotConvergedError if the residual still falls (a new best within the
     * last iterations, and below where it stood then), saying by how much
     * and roughly how many more iterations would reach Tolerance;
     * otherwise (grown or stagnated) a DivergenceError with the advice of
     * divergence_message().
     */
    [[noreturn]] void
    stop_at_iteration_limit(const std::string &what) const override;

    /** The Uzawa update; on an update Aitken's dynamic gamma starts again
     * from the given one. */
    bool
    start_uzawa_phase() override;

    std::string
    name() const override
    {
      return "dd";
    }

    /** One set of body solves per iteration; no Newton or Krylov steps. */
    SolverCounts
    counts() const override;

  private:
    /** The relaxation's history is dropped and divergence is judged from
     * here on. */
    void
    start_phase() override;

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

    /** The smallest residual of the current phase and its iteration. */
    std::pair<double, unsigned int>
    best_of_phase() const;

    /** The message of a DivergenceError: what diverged (@p event, e.g.
     * "diverged at iteration 12"), and which parameter to change (Gamma,
     * the penalty c, or Tolerance), judged from the estimated gamma*. */
    std::string
    divergence_message(const std::string     &event,
                       const IterationRecord &record,
                       double                 best,
                       unsigned int           best_k) const;

    std::unique_ptr<Relaxation> relaxation = make_relaxation(parameters.dd);
  };
} // namespace ddcontact

#endif
