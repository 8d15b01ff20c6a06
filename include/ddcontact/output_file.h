#ifndef ddcontact_output_file_h
#define ddcontact_output_file_h

#include <fstream>
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
   * which the next run into the directory removes (RunRecord).
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
} // namespace ddcontact

#endif
