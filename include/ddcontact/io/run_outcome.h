#ifndef ddcontact_run_outcome_h
#define ddcontact_run_outcome_h

#include <string>

namespace ddcontact
{
  /**
   * How a run ended, as the driver (Simulation) decides it from what the
   * contact solver and the adaptive strategy returned; summary.json's
   * `status` writes it (status_name()), the exit code follows the error
   * the driver throws for it (doc/running.md, "Exit codes").
   */
  enum class RunOutcome
  {
    running,            // still under way (the summary of a step)
    completed,          // no contact iteration to converge
    converged,          // the contact iteration met its tolerance
    stalled,            // the Uzawa loop missed its tolerance (exit 4)
    target_not_reached, // above Adaptation/Target error (exit 5)
    not_converged,      // the iteration limit stopped a falling residual
    diverged,           // the iteration failed (exit 4)
    interrupted         // SIGINT or SIGTERM (exit 6)
  };

  /** The name summary.json's `status` gives @p outcome. */
  std::string
  status_name(RunOutcome outcome);

  /** Whether the contact iteration converged in @p outcome, so that the
   * penetration it left is judged (also stalled: the solver converged,
   * the Uzawa loop around it did not). */
  bool
  contact_converged(RunOutcome outcome);
} // namespace ddcontact

#endif
