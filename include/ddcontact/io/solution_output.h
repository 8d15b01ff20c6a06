#ifndef ddcontact_solution_output_h
#define ddcontact_solution_output_h

#include <ddcontact/io/contact_zone_writer.h>
#include <ddcontact/io/output_writer.h>
#include <ddcontact/io/run_report.h>
#include <ddcontact/parameters.h>

#include <memory>

namespace ddcontact
{
  /**
   * The ParaView output of a run (Output/Write vtu): each step writes every
   * body (OutputWriter, with the estimator's cell fields on the adapted
   * bodies) and every contact zone (ContactZoneWriter, with the Uzawa
   * multipliers when the augmented Lagrangian is on), each into its PVD
   * time series.
   */
  class SolutionOutput
  {
  public:
    /** Output of the scene @p parameters (kept by reference). */
    explicit SolutionOutput(const SceneParameters &parameters);

    /** Write step @p step of @p results; collective on partitioned meshes
     * (every process writes its cells), else done by process 0. */
    void
    write_step(const RunReport::Results &results, unsigned int step);

  private:
    const SceneParameters             &parameters;
    std::unique_ptr<OutputWriter>      body_writer;
    std::unique_ptr<ContactZoneWriter> zone_writer;
  };
} // namespace ddcontact

#endif
