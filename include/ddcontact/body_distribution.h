#ifndef ddcontact_body_distribution_h
#define ddcontact_body_distribution_h

#include <deal.II/base/mpi.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/elastic_body.h>
#include <ddcontact/parameters.h>

#include <functional>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The DD's natural parallelism over MPI processes: the body problems of
   * one iteration (20) are independent, so each body is solved on the
   * process that owns it, and the solutions are then broadcast, so that
   * every process holds every body's iterate. Everything else (contact
   * pressures (20), relaxation (21), Anderson, output decisions) is cheap
   * and runs identically on every process on identical data, which keeps
   * the iteration bit-for-bit equal to the serial one for any number of
   * processes.
   *
   * Only the owner assembles and factorizes a body; the others keep its
   * mesh, DoFHandler and constraints (for the contact maps and the
   * transfer after refinement). Owners are chosen by the parameter
   * "Parallel/Body owners": "auto" balances the bodies' dofs over the
   * processes (largest body first onto the least loaded process, again
   * after every refinement), or an explicit list "omega1: 0, omega2: 1".
   * With more processes than bodies the extra processes only follow along:
   * splitting one body over a process group needs distributed meshes.
   * With one process everything is owned locally and nothing is sent.
   */
  class BodyDistribution
  {
  public:
    BodyDistribution(const std::vector<ElasticBody<2> *> &bodies,
                     const ParallelParameters            &parameters,
                     const MPI_Comm                       communicator);

    /** Choose the owners from the bodies' current sizes and tell every
     * body whether it is solved here (the newly owned ones assemble and
     * factorize, concurrently). Returns true if an owner changed. */
    bool
    distribute();

    /** Whether body @p b is solved on this process. */
    bool
    owns(unsigned int b) const
    {
      return owner[b] == this_process;
    }

    unsigned int
    owner_of(unsigned int b) const
    {
      return owner[b];
    }

    /**
     * Run @p solve(b) for every body b owned here, concurrently (one task
     * per body), then send the results @p per_body[b] from the owners to
     * all processes. If a solve throws on any process, every process
     * throws an InputError with that message: none is left waiting.
     */
    void
    solve_and_share(const std::function<void(unsigned int)> &solve,
                    std::vector<Vector<double>>             &per_body) const;

    /** Send every body's vector from its owner to all processes. */
    void
    share(std::vector<Vector<double>> &per_body) const;

    /** Send one vector of body @p b from its owner to all processes. */
    void
    share(unsigned int b, Vector<double> &v) const;

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

    /** "omega1: 0, omega2: 1": the owners, for the screen and summary. */
    std::string
    describe() const;

  private:
    std::vector<ElasticBody<2> *> bodies;
    const ParallelParameters      parameters;
    const MPI_Comm                communicator;
    const unsigned int            this_process, n_procs;
    std::vector<unsigned int>     owner;
    mutable double                seconds_solving    = 0;
    mutable double                seconds_exchanging = 0;
  };
} // namespace ddcontact

#endif
