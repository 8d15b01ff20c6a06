#ifndef ddcontact_run_record_h
#define ddcontact_run_record_h

#include <stdexcept>
#include <string>

namespace ddcontact
{
  /** The exit codes of the executable (README, doc/reliability.md). */
  namespace exit_codes
  {
    constexpr int success            = 0;
    constexpr int bad_input          = 1;
    constexpr int internal_error     = 3;
    constexpr int iteration_failed   = 4;
    constexpr int target_not_reached = 5;
    constexpr int interrupted        = 6;
    constexpr int write_failed       = 7;
    constexpr int out_of_memory      = 8;
  } // namespace exit_codes

  /** SIGINT or SIGTERM arrived: the run stopped at the end of its current
   * step (summary.json `status` "interrupted", exit code 6). */
  class InterruptedError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * SIGINT and SIGTERM end a run cleanly: the handler only notes the
   * signal (a second one ends the process at once), and the run checks at
   * the end of every contact iteration and adaptation step.
   */
  namespace interruption
  {
    /** Install the handlers of SIGINT and SIGTERM. */
    void
    install_handlers();

    /** Throw InterruptedError if any process received a signal
     * (collective over MPI_COMM_WORLD, so that every process stops at the
     * same step); @p where says what was interrupted. */
    void
    check(const std::string &where);
  } // namespace interruption

  /**
   * The record of a run in its output directory, taken before anything is
   * written there (collective; process 0 acts):
   * - a lock (`.ddcontact.lock`, holding the process id) so that a second
   *   run into the same directory is refused in one line; a lock left by a
   *   process that no longer runs is taken over;
   * - every result file of an earlier run is removed (summary.json, the
   *   CSV, VTU, PVTU and PVD files, leftover `.partial` files), so that no
   *   stale result sits beside the new parameters;
   * - summary.json says `"status": "running"` until the run writes its own.
   * The lock is released when the record is destroyed.
   */
  class RunRecord
  {
  public:
    RunRecord(const std::string &directory, const std::string &scene);
    ~RunRecord();

    RunRecord(const RunRecord &) = delete;
    RunRecord &
    operator=(const RunRecord &) = delete;

  private:
    std::string lock_file;
    bool        holds_lock = false;
  };
} // namespace ddcontact

#endif
