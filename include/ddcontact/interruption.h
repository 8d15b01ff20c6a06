#ifndef ddcontact_interruption_h
#define ddcontact_interruption_h

#include <array>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

namespace ddcontact
{
  /** The exit codes of the executable (doc/running.md, doc/reliability.md). */
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

  /** An allocation failed in a step that names itself (reading a mesh
   * file, say): main() prints the message, exit code 8. Any other
   * std::bad_alloc gets main()'s general out-of-memory line. */
  class OutOfMemoryError : public std::bad_alloc
  {
  public:
    explicit OutOfMemoryError(std::string message)
      : message(std::move(message))
    {
    }

    const char *
    what() const noexcept override
    {
      return message.c_str();
    }

  private:
    std::string message;
  };

  /**
   * SIGINT and SIGTERM end a run cleanly: the handler notes the signal and
   * writes the run's record at once (set_record()); the run checks at the
   * end of every contact iteration and adaptation step and then writes its
   * fuller record. A second signal ends the process at once, with the
   * record already true: mpirun kills its processes about 2 s after it
   * forwards a signal, which may be before the current step ends.
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

    /** What the first signal writes on this process, before anything
     * else: @p texts[0] (SIGINT) or @p texts[1] (SIGTERM) into
     * @p filename, by a temporary file `<filename>.signal` and a rename,
     * listed in the run's manifest (run_manifest). Replaces the record
     * set before; the handler only uses async-signal-safe calls. */
    void
    set_record(const std::string                &filename,
               const std::array<std::string, 2> &texts);

    /** No record any more (the run writes its final one). */
    void
    clear_record();
  } // namespace interruption

} // namespace ddcontact

#endif
