#ifndef ddcontact_parallel_parameters_h
#define ddcontact_parallel_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <ddcontact/body/body_parameters.h>
#include <ddcontact/parameter_tools.h>

#include <map>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** Parallel/Body owners: chosen from the bodies' sizes ("auto"), every
   * body on all processes ("all"), or the groups of a list. */
  enum class BodyOwners
  {
    automatic,
    all,
    list
  };

  /** Parallel/Mesh: how the mesh of a body that several processes solve
   * is split (ParallelParameters::distributed_mesh()). */
  enum class MeshPartition
  {
    automatic,
    shared,
    distributed
  };

  /** The kind of triangulation a body gets (BodyMesh): whole on the
   * process that solves it (serial), every cell on every process and
   * partitioned between the body's group (shared), or a p4est forest of
   * which each process keeps its own cells (distributed). */
  enum class MeshKind
  {
    serial,
    shared,
    distributed
  };

  DDCONTACT_DECLARE_SELECTION(BodyOwners)
  DDCONTACT_DECLARE_SELECTION(MeshPartition)

  /**
   * Runs on several MPI processes, in the subsection "Parallel": which
   * processes solve which body (BodyDistribution).
   */
  struct ParallelParameters
  {
    /** "auto", "all" or a list (the groups below). */
    BodyOwners mode = BodyOwners::automatic;
    /** With mode list: the processes (world ranks, ascending) that solve
     * every body. */
    std::map<std::string, std::vector<unsigned int>> body_groups;
    /** "auto", "shared" or "distributed": how the mesh of a body that
     * several processes solve is split (see distributed_mesh()). */
    MeshPartition mesh = MeshPartition::automatic;

    /**
     * Whether the bodies' meshes are partitioned over process groups
     * (p4est or parallel::shared::Triangulation, a distributed
     * matrix and solver on every group with more than one process): with
     * "all", with a list in which a body has several processes, and with
     * "auto" when there are more processes than bodies. Otherwise every
     * body is solved whole on one process (or there is one process).
     */
    bool
    process_groups(unsigned int n_processes, unsigned int n_bodies) const;

    /**
     * Whether @p body gets a parallel::distributed::Triangulation (p4est):
     * each process then keeps only its own cells and a ghost layer, so
     * the mesh memory shrinks with the processes, and the processes
     * outside the body's group keep none of them
     * (BodyMesh::set_process_group()). That needs a body of
     * quadrilaterals (deal.II 9.4's p4est holds no triangles) on process
     * groups (process_groups()). "auto" takes it wherever it is possible,
     * "shared" never.
     */
    bool
    distributed_mesh(const BodyParameters &body,
                     unsigned int          n_processes) const;

    /** The kind of mesh of @p body on @p n_processes processes solving
     * @p n_bodies bodies: the one place that decides it, from
     * process_groups() and distributed_mesh(). */
    MeshKind
    mesh_kind(const BodyParameters &body,
              unsigned int          n_processes,
              unsigned int          n_bodies) const;

    static void
    declare(ParameterHandler &prm);

    /** Checks the names against @p body_names and the processes against
     * the size of MPI_COMM_WORLD. */
    void
    parse(ParameterHandler &prm, const std::vector<std::string> &body_names);
  };
} // namespace ddcontact

#endif
