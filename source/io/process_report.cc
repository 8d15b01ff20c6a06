#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <ddcontact/io/process_report.h>

#include <array>

namespace ddcontact
{
  namespace
  {
    /** This process's peak resident memory (VmHWM), MB. */
    double
    peak_memory_mb()
    {
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      return memory.VmHWM / 1024.;
    }
  } // namespace

  Json
  processes_json(const BodyDistribution &distribution,
                 const unsigned int      n_steps)
  {
    const std::array<double, 5> mine = {
      {static_cast<double>(distribution.owned_dofs()),
       peak_memory_mb(),
       static_cast<double>(distribution.bytes_sent()),
       static_cast<double>(distribution.vector_entries()),
       static_cast<double>(distribution.constraint_lines())}};
    Json         processes = Json::array();
    unsigned int rank      = 0;
    for (const auto &p : Utilities::MPI::all_gather(MPI_COMM_WORLD, mine))
      processes.push_back(
        {{"rank", rank++},
         {"owned_dofs", static_cast<unsigned long long>(p[0])},
         {"peak_memory_mb", p[1]},
         {"bytes_sent", static_cast<unsigned long long>(p[2])},
         {"bytes_sent_per_step", n_steps > 0 ? p[2] / n_steps : 0.},
         {"vector_entries", static_cast<unsigned long long>(p[3])},
         {"constraint_lines", static_cast<unsigned long long>(p[4])}});
    return processes;
  }

  Json
  peak_memory_json()
  {
    const double peak_mb = peak_memory_mb();
    return {
      {"largest_process_mb", Utilities::MPI::max(peak_mb, MPI_COMM_WORLD)},
      {"all_processes_mb", Utilities::MPI::sum(peak_mb, MPI_COMM_WORLD)}};
  }
} // namespace ddcontact
