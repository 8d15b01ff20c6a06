#include <deal.II/base/mpi.h>

#include <ddcontact/interruption.h>
#include <ddcontact/output_file.h>

#include <atomic>
#include <csignal>
#include <deque>
#include <memory>

#include <fcntl.h>
#include <unistd.h>

namespace ddcontact
{
  using namespace dealii;

  namespace
  {
    volatile std::sig_atomic_t signal_received = 0;

    /** The record the first signal writes, prepared in full beforehand. */
    struct Record
    {
      std::string                filename, temporary;
      std::array<std::string, 2> texts;
    };

    // The handler reads the current record through a lock-free atomic;
    // the last few records stay alive in case a handler on another thread
    // still reads one that was just replaced.
    std::atomic<const Record *>         current_record{nullptr};
    std::deque<std::unique_ptr<Record>> kept_records;

    /** Write @p size bytes of @p data to @p fd; false on failure. */
    bool
    write_all(const int fd, const char *data, std::size_t size)
    {
      while (size > 0)
      {
        const auto n = ::write(fd, data, size);
        if (n <= 0)
          return false;
        data += n;
        size -= n;
      }
      return true;
    }

    /** Write the text of @p signal of @p record into its file (by the
     * temporary file and a rename); async-signal-safe. */
    void
    write_record(const Record *record, const int signal)
    {
      const std::string &text = record->texts[signal == SIGINT ? 0 : 1];
      const int          fd =
        ::open(record->temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd < 0)
        return;
      const bool written = write_all(fd, text.data(), text.size());
      if (::close(fd) == 0 && written &&
          ::rename(record->temporary.c_str(), record->filename.c_str()) == 0)
        run_manifest::record_file_from_signal_handler(record->filename.c_str());
      else
        ::unlink(record->temporary.c_str());
    }

    extern "C" void
    note_signal(const int signal)
    {
      signal_received = signal;
      // A second signal of either kind ends the process at once.
      std::signal(SIGINT, SIG_DFL);
      std::signal(SIGTERM, SIG_DFL);
      const Record *record = current_record.exchange(nullptr);
      if (record != nullptr)
        write_record(record, signal);
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

    void
    set_record(const std::string                &filename,
               const std::array<std::string, 2> &texts)
    {
      auto record       = std::make_unique<Record>();
      record->filename  = filename;
      record->temporary = filename + ".signal";
      record->texts     = texts;
      if (kept_records.empty() ||
          kept_records.back()->temporary != record->temporary)
        run_manifest::record_temporary(record->temporary);
      current_record.store(record.get());
      kept_records.push_back(std::move(record));
      // A signal that came before this record (while the run wrote its
      // "running" summary, say) has written the previous one, or none:
      // the new record is the true one, written now, so that a kill
      // before the run's next check leaves it and not "running".
      const int signal = signal_received;
      if (signal != 0)
        if (const Record *pending = current_record.exchange(nullptr))
          write_record(pending, signal);
      if (kept_records.size() > 3)
        kept_records.pop_front();
    }

    void
    clear_record()
    {
      current_record.store(nullptr);
    }
  } // namespace interruption

} // namespace ddcontact
