#ifndef ddcontact_body_distribution_h
#define ddcontact_body_distribution_h

#include <deal.II/base/mpi.h>

#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/parallel_parameters.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The DD's natural parallelism over MPI processes: the body problems of
   * one iteration (20) are independent, so each body is solved by its own
   * processes, and the solutions are then shared: broadcast (whole, or
   * only the traces), so that every process holds every body's iterate, or,
   * for a body with distributed vectors (ElasticBody::distribute_vectors()),
   * as ghosts imported from their owners. Everything else (contact pressures
   * (20), relaxation (21), Anderson, estimation and refinement) is cheap and
   * runs identically on every process on identical data, which keeps the
   * iteration equal to the serial one for any number of processes.
   *
   * Two layouts, chosen by "Parallel/Body owners"
   * (ParallelParameters::process_groups):
   * - one process per body (at most as many processes as bodies): the
   *   owner assembles, factorizes and solves the whole body; "auto"
   *   balances the dofs (largest body first onto the least loaded
   *   process) and balances again after every refinement;
   * - process groups: every body on a group of processes (disjoint groups
   *   sized in proportion to the dofs with "auto", all processes with
   *   "all", or a list). The body's mesh is partitioned between its group
   *   (ElasticBody::set_process_group), which assembles a distributed
   *   matrix and solves it together; the groups are fixed for the run and
   *   the partition within a group follows every refinement. Bodies whose
   *   groups overlap are solved one after the other.
   * With one process everything is owned locally and nothing is sent.
   */
  class BodyDistribution
  {
  public:
    BodyDistribution(const std::vector<ElasticBody<2> *> &bodies,
                     const ParallelParameters            &parameters,
                     const MPI_Comm                       communicator);

    BodyDistribution(const BodyDistribution &) = delete;
    BodyDistribution &
    operator=(const BodyDistribution &) = delete;

    /** Choose the owners (or, the first time, the process groups) from
     * the bodies' current sizes and tell every body whether it is solved
     * here (the newly owned ones assemble and factorize). Returns true if
     * an owner changed. */
    bool
    distribute();

    /** Whether body @p b is solved on this process (alone or with the
     * rest of its group). */
    bool
    owns(unsigned int b) const
    {
      return std::find(groups[b].begin(), groups[b].end(), this_process) !=
             groups[b].end();
    }

    /** The process that sends body @p b's solution to the others: the
     * first of its group. */
    unsigned int
    owner_of(unsigned int b) const
    {
      return groups[b][0];
    }

    /** All processes of the run. */
    MPI_Comm
    get_communicator() const
    {
      return communicator;
    }

    /** Whether the meshes are partitioned over process groups. */
    bool
    uses_process_groups() const
    {
      return process_groups;
    }

    /**
     * Run @p solve(b) for every body b owned here, concurrently (one task
     * per body), then send the results @p per_body[b] from the owners to
     * all processes. If a solve throws on any process, every process
     * throws an InputError with that message: none is left waiting.
     */
    void
    solve_and_share(const std::function<void(unsigned int)> &solve,
                    std::vector<BodyVector>                 &per_body) const;

    /**
     * The same, but the other processes receive only the values of
     * @p per_body[b] at the dofs @p traces[b] (its zero elsewhere), as its
     * owner lists them: what an operator that reads the iterate on the
     * contact zones needs (dd-newton), O(interface) bytes per body
     * instead of O(volume). The owners keep their whole vectors.
     */
    void
    solve_and_share_traces(
      const std::function<void(unsigned int)>                 &solve,
      std::vector<BodyVector>                                 &per_body,
      const std::vector<std::vector<types::global_dof_index>> &traces) const;

    /** Solve every body problem on its owner (a scene without contact)
     * and hand the solutions to all processes. */
    void
    solve_bodies();

    /** Send every body's vector from its owner to all processes. */
    void
    share(std::vector<BodyVector> &per_body) const;

    /** Send one vector of body @p b from its owner to all processes. */
    void
    share(unsigned int b, BodyVector &v) const;

    /** Run @p work(b) for every body (or every body owned here) as
     * concurrent tasks; an exception on any process is thrown on all. */
    void
    for_each_body(const std::function<void(unsigned int)> &work,
                  bool                                     owned_only) const;

    /** Throw the first error message of any process on every process
     * (@p message empty: no error here). */
    void
    agree_on_errors(const std::string &message) const;

    /** Whether this process writes files and prints. */
    bool
    is_root() const
    {
      return this_process == 0;
    }

    unsigned int
    n_processes() const
    {
      return n_procs;
    }

    /** Wall seconds this process spent in its own body solves, and in
     * the exchange after them (waiting for the slowest process, then the
     * broadcasts), summed over all calls of solve_and_share(). */
    double
    solve_seconds() const
    {
      return seconds_solving;
    }

    double
    exchange_seconds() const
    {
      return seconds_exchanging;
    }

    /** The dofs this process owns: its part of every body partitioned
     * over its process group, and every body it solves alone. Its copies of
     * the bodies solved elsewhere are not counted. */
    types::global_dof_index
    owned_dofs() const;

    /** The entries of the bodies' solution vectors this process stores:
     * every dof of a whole vector, the owned dofs and ghosts of a
     * distributed one (ElasticBody::distribute_vectors()). */
    std::uint64_t
    vector_entries() const;

    /** The constraint lines (Dirichlet dofs and hanging nodes) of the
     * bodies this process stores: all of a body's on a serial or shared
     * mesh, those of the stored entries with distributed vectors
     * (ElasticBody::share_constraints()). */
    std::uint64_t
    constraint_lines() const;

    /** Bytes of body vectors this process has sent by share() and
     * solve_and_share_traces() over the run (a broadcast counted as one
     * message per receiving process). */
    std::uint64_t
    bytes_sent() const
    {
      return bytes_shared;
    }

    /** "omega1: 0, omega2: 1-2": the processes of every body, for the
     * screen and summary. */
    std::string
    describe() const;

  private:
    /** A distributed vector @p v of body @p b: the ghosts are imported
     * from their owners instead of a broadcast (on every process of the
     * body's mesh, also those outside its group). */
    void
    import_ghosts(unsigned int b, BodyVector &v) const;

    /** Send the values of @p v at @p dofs (with the dofs) from the owner of
     * body @p b to all processes; the others' @p v is zero elsewhere. */
    void
    share_trace(unsigned int                                b,
                BodyVector                                 &v,
                const std::vector<types::global_dof_index> &dofs) const;

    std::vector<ElasticBody<2> *>          bodies;
    const ParallelParameters               parameters;
    const MPI_Comm                         communicator;
    const unsigned int                     this_process, n_procs;
    const bool                             process_groups;
    std::vector<std::vector<unsigned int>> groups;
    bool                                   groups_chosen      = false;
    mutable double                         seconds_solving    = 0;
    mutable double                         seconds_exchanging = 0;
    mutable std::uint64_t                  bytes_shared       = 0;
  };
} // namespace ddcontact

#endif
