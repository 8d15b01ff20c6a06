#include <ddcontact/io/run_outcome.h>

namespace ddcontact
{
  std::string
  status_name(const RunOutcome outcome)
  {
    switch (outcome)
    {
      case RunOutcome::running:
        return "running";
      case RunOutcome::completed:
        return "completed";
      case RunOutcome::converged:
        return "converged";
      case RunOutcome::stalled:
        return "stalled";
      case RunOutcome::target_not_reached:
        return "target_not_reached";
      case RunOutcome::not_converged:
        return "not_converged";
      case RunOutcome::diverged:
        return "diverged";
      case RunOutcome::interrupted:
        return "interrupted";
    }
    return "unknown";
  }

  bool
  contact_converged(const RunOutcome outcome)
  {
    return outcome == RunOutcome::converged || outcome == RunOutcome::stalled ||
           outcome == RunOutcome::target_not_reached;
  }
} // namespace ddcontact
