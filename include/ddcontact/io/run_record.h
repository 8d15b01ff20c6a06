#ifndef ddcontact_run_record_h
#define ddcontact_run_record_h

#include <ddcontact/interruption.h>

#include <string>

namespace ddcontact
{
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
