#ifndef ddcontact_process_report_h
#define ddcontact_process_report_h

#include <ddcontact/body/body_distribution.h>
#include <ddcontact/io/json.h>

namespace ddcontact
{
  /**
   * What every MPI process holds and sends, for summary.json: one entry per
   * process with the dofs it owns (BodyDistribution::owned_dofs()), its peak
   * resident memory (VmHWM) and the bytes of body solutions it has sent
   * (BodyDistribution::bytes_sent()), in total and per step of the contact
   * solver (@p n_steps: DD iterations, Newton steps or Newton solves).
   * Collective over MPI_COMM_WORLD.
   */
  Json
  processes_json(const BodyDistribution &distribution, unsigned int n_steps);

  /** The peak resident memory of the largest process and of all processes
   * together (MB). Collective over MPI_COMM_WORLD. */
  Json
  peak_memory_json();
} // namespace ddcontact

#endif
