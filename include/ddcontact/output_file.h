#ifndef ddcontact_output_file_h
#define ddcontact_output_file_h

#include <cstdint>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace ddcontact
{
  /** A result file could not be written (full disk, no permission): the
   * message names the file. The executable exits with code 7. */
  class WriteError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A result file written under a temporary name and renamed to its own
   * name only when it is complete and every write succeeded (commit()), so
   * that no reader ever finds a half file under the real name: a full disk,
   * a signal or a crash leaves the temporary `<name>.partial` at most,
   * which the next run into the directory removes (RunRecord): both names
   * are listed in the run's manifest (run_manifest).
   */
  class OutputFile
  {
  public:
    /** Open `<filename>.partial`; throws WriteError if it cannot. */
    explicit OutputFile(const std::string &filename);

    /** Removes the temporary file if commit() was not reached. */
    ~OutputFile();

    OutputFile(const OutputFile &) = delete;
    OutputFile &
    operator=(const OutputFile &) = delete;

    std::ostream &
    stream()
    {
      return out;
    }

    /** Call @p writer with the stream. A writer that gives up on a failed
     * stream (deal.II's DataOut throws ExcIO on a full disk) is reported
     * as commit() reports a failed write: a WriteError naming the file. */
    template <typename Writer>
    void
    write(const Writer &writer)
    {
      try
      {
        writer(out);
      }
      catch (...)
      {
        if (!out.fail())
          throw;
        commit(); // throws the WriteError
        throw WriteError("cannot write '" + filename + "'");
      }
    }

    /** Flush, check every write, close and rename to the file's name;
     * throws WriteError naming the file if anything failed. */
    void
    commit();

  private:
    std::string   filename;
    std::string   temporary;
    std::ofstream out;
    bool          committed = false;
  };

  /**
   * The list of the files a run wrote into its output directory
   * (`.ddcontact.manifest`), so that the next run there removes those and
   * nothing else (RunRecord). Once open(), every OutputFile in the
   * directory is listed twice: its temporary name before it is created
   * (`temp NAME`), and its size and modification time once it is complete
   * (`file SIZE MTIME_NS NAME`), before it is renamed. A file whose size or
   * time differs from every stamp listed for it was changed by someone
   * else since, and is not the run's any more. Every process appends its
   * own lines (O_APPEND, one write() a line).
   */
  namespace run_manifest
  {
    /** The manifest's name in the output directory. */
    inline const std::string file_name = ".ddcontact.manifest";

    /** List from now on the files of @p directory (after the manifest of
     * an earlier run there was acted on, and emptied by process 0). */
    void
    open(const std::string &directory);

    /** Stop listing (the end of the run). */
    void
    close();

    /** Whether @p path is in the open manifest's directory. */
    bool
    lists(const std::string &path);

    /** List @p temporary, the temporary file of a result (if lists()). */
    void
    record_temporary(const std::string &temporary);

    /** List @p path with its present size and time, as @p name (the name
     * it will have; the file's own by default) if lists(@p name). */
    void
    record_file(const std::string &path, const std::string &name = "");

    /** Async-signal-safe record_file() of @p path, for the signal
     * handler's record; does nothing unless open. */
    void
    record_file_from_signal_handler(const char *path);

    /** What a manifest lists: for each name, its stamps (size, time), and
     * the temporary files. */
    struct Contents
    {
      std::map<std::string, std::set<std::pair<std::uintmax_t, long long>>>
                            files;
      std::set<std::string> temporaries;
    };

    /** The manifest of @p directory (empty if there is none). */
    Contents
    read(const std::string &directory);

    /** The size and time of @p path ({0, -1} if it is not a regular
     * file). */
    std::pair<std::uintmax_t, long long>
    stamp(const std::string &path);
  } // namespace run_manifest
} // namespace ddcontact

#endif
