#ifndef ddcontact_fatal_error_h
#define ddcontact_fatal_error_h

#include <mpi.h>

#include <exception>
#include <string>
#include <utility>

namespace ddcontact
{
  /**
   * The end of a run that failed: the exit code of the error (exit_codes,
   * doc/running.md "Exit codes") and its message, printed once.
   *
   * Under MPI an error may be met by every process (a parameter file, a
   * contact iteration that stopped: the decision follows a reduction) or
   * by one alone (its mesh file, its memory, a value only it was given).
   * report() tells them apart without a collective on the run's own
   * communicators, where the other processes may wait in another call:
   * on a communicator of its own, it starts a non-blocking barrier. If
   * every process arrives within a few seconds, the messages are gathered
   * and process 0 prints each distinct one once (naming the processes
   * when they differ), and all return the same code. Otherwise the process
   * prints its message with its number and ends every process by
   * MPI_Abort with its code, which mpirun returns.
   */
  class FatalError
  {
  public:
    /** Call after MPI_Init, on every process (collective: duplicates
     * MPI_COMM_WORLD). */
    FatalError();

    ~FatalError();

    FatalError(const FatalError &) = delete;
    FatalError &
    operator=(const FatalError &) = delete;

    /** The exit code and the one-line message of @p error. */
    static std::pair<int, std::string>
    classify(const std::exception_ptr &error);

    /** Print @p error once and return its exit code on this process (or
     * do not return: see the class). */
    int
    report(const std::exception_ptr &error) const;

    /** How long a process waits for the others to meet an error too. */
    static constexpr double seconds_to_wait = 5.;

  private:
    MPI_Comm     communicator = MPI_COMM_NULL;
    unsigned int rank         = 0;
    unsigned int n_processes  = 1;
  };
} // namespace ddcontact

#endif
