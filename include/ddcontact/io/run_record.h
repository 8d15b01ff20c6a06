#ifndef ddcontact_run_record_h
#define ddcontact_run_record_h

#include <ddcontact/interruption.h>
#include <ddcontact/parameters.h>

#include <string>
#include <vector>

namespace ddcontact
{
  /**
   * The record of a run in its output directory, taken once the scene is
   * set up and checked (so that a refused run changes nothing on disk),
   * before anything is written there (collective; process 0 acts):
   * - a lock (`.ddcontact.lock`, holding the process id) so that a second
   *   run into the same directory is refused in one line; a lock that
   *   names a process that no longer runs, or none, is taken over with one
   *   line;
   * - the files the earlier run there listed in its manifest
   *   (run_manifest) and left as it wrote them are removed, and nothing
   *   else: files of other programs, the input file, and files changed
   *   since, stay as they are (one line says so). If one of those has a
   *   name this run would write, the run is refused in one line;
   * - a new manifest, and summary.json saying `"status": "running"` until
   *   the run writes its own.
   * The lock is released when the record is destroyed.
   */
  class RunRecord
  {
  public:
    /** Claim the output directory of @p scene, read from @p input_files
     * (never removed or written). */
    RunRecord(const SceneParameters          &scene,
              const std::vector<std::string> &input_files);
    ~RunRecord();

    RunRecord(const RunRecord &) = delete;
    RunRecord &
    operator=(const RunRecord &) = delete;

    /** Where the parameters as used go: parameters.prm, or
     * parameters.used.prm where parameters.prm is not the run's own (the
     * input file itself, say). */
    const std::string &
    parameter_file() const
    {
      return parameter_dump;
    }

    /** After an error that ended the run: if summary.json still says
     * "running", it says @p status and @p message instead, keeping what
     * the run recorded of its completed steps (process 0; never throws). */
    void
    close_after_error(const std::string &status,
                      const std::string &message) const noexcept;

    /** The summary.json status of an exit code (exit_codes). */
    static std::string
    status_of_exit_code(int code);

  private:
    /** Take the lock of the directory (process 0); return the refusal
     * (starting with I or W) if the run may not, and add to @p note what
     * the console should hear. */
    std::string
    take_lock(std::string &note);

    /** Once the lock is held: remove the earlier run's files, open the new
     * manifest and the running summary.json (process 0); return the
     * refusal, as take_lock() does. */
    std::string
    clear_earlier_run(const SceneParameters          &scene,
                      const std::vector<std::string> &input_files,
                      std::string                    &note);

    std::string directory;
    std::string lock_file;
    std::string parameter_dump;
    bool        holds_lock = false;
  };
} // namespace ddcontact

#endif
