#ifndef ddcontact_body_output_h
#define ddcontact_body_output_h

#include <deal.II/lac/vector.h>

#include <ddcontact/body/elastic_body.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Writes the bodies of a scene for ParaView: per step one VTU file per
   * body, a .pvtu that groups the bodies of that step, and a .pvd record
   * (solution.pvd) that lists all steps, so that ParaView opens the whole
   * run at once. Every body carries the displacement (vector), the stress
   * components sigma_11, sigma_22, sigma_12, sigma_33 = nu (sigma_11 +
   * sigma_22), the von Mises stress, the body id and the refinement level;
   * further cell fields (e.g. an error estimator) may be added per body;
   * bodies that lack a field get zeros so that all pieces match. With
   * smoothed stresses on (Output/Smoothed stresses), every body also
   * carries the continuous L2 projections of its stresses
   * (SmoothedStresses: sigma_11_smoothed, ..., von_mises_smoothed), unless
   * a body of the step lies on a distributed mesh, where the projection is
   * not available: then no body has them, so that all pieces match.
   *
   * A body whose mesh is partitioned between processes (process groups,
   * ElasticBody) is written in pieces: every process writes the cells it
   * owns (one VTU file per process, "omega1-0003.1.vtu"), and the step's
   * .pvtu lists all pieces. write_step() is then collective over
   * @p communicator; process 0 writes the whole serial bodies, the .pvtu
   * and the .pvd.
   */
  class OutputWriter
  {
  public:
    /** Cell fields by name, each of size n_active_cells. */
    using CellData = std::map<std::string, Vector<double>>;

    OutputWriter(const std::string &directory,
                 const MPI_Comm     communicator      = MPI_COMM_SELF,
                 const bool         smoothed_stresses = true);

    /** Write step @p step (labelled @p time in ParaView) for all bodies;
     * @p solutions[b] is the displacement of bodies[b]. */
    void
    write_step(unsigned int                               step,
               double                                     time,
               const std::vector<const ElasticBody<2> *> &bodies,
               const std::vector<const BodyVector *>     &solutions,
               const std::vector<CellData>               &cell_data = {});

  private:
    const std::string                           directory;
    const MPI_Comm                              communicator;
    const bool                                  smoothed_stresses;
    std::vector<std::pair<double, std::string>> records;
  };
} // namespace ddcontact

#endif
