#ifndef ddcontact_iteration_errors_h
#define ddcontact_iteration_errors_h

#include <stdexcept>

namespace ddcontact
{
  /** An iteration diverged (its residual grew or stagnated) or stopped
   * short of its tolerance; the message says what to change. The
   * executable exits with code 4. */
  class DivergenceError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /** The iteration reached Contact solver/Max iterations while its
   * residual still fell: not diverged, only stopped too early (summary.json
   * `status` "not_converged"). Also exit code 4, so it is a
   * DivergenceError to every handler that does not tell the two apart. */
  class NotConvergedError : public DivergenceError
  {
  public:
    using DivergenceError::DivergenceError;
  };
  /** An adaptive run stopped with its estimate above Adaptation/Target
   * error (summary.json `status` "target_not_reached"); the message gives
   * the estimate and what stopped the refinement. Exit code 5. */
  class TargetNotReachedError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace ddcontact

#endif
