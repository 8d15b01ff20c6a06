#include <deal.II/base/mpi.h>

#include <ddcontact/interruption.h>

#include <csignal>

namespace ddcontact
{
  using namespace dealii;

  namespace
  {
    volatile std::sig_atomic_t signal_received = 0;

    extern "C" void
    note_signal(const int signal)
    {
      signal_received = signal;
      // A second signal ends the process at once.
      std::signal(signal, SIG_DFL);
    }

  } // namespace

  namespace interruption
  {
    void
    install_handlers()
    {
      std::signal(SIGINT, note_signal);
      std::signal(SIGTERM, note_signal);
    }

    void
    check(const std::string &where)
    {
      const int any =
        Utilities::MPI::max(static_cast<int>(signal_received), MPI_COMM_WORLD);
      if (any != 0)
        throw InterruptedError(
          std::string(any == SIGINT ? "SIGINT" : "SIGTERM") +
          " received: the run stopped after " + where);
    }
  } // namespace interruption

} // namespace ddcontact
