#include <ddcontact/body/body_distribution.h>
#include <ddcontact/interruption.h>
#include <ddcontact/iteration_errors.h>
#include <ddcontact/tasks.h>

#include <deal.II/base/thread_management.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <numeric>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    // Leads the message of an out-of-memory error between processes.
    const std::string out_of_memory_mark = "\x01";
    // A body's Newton loop that did not converge or diverged (a nonlinear
    // law): the contact solver may damp its step and solve again.
    const std::string not_converged_mark = "\x02";
    const std::string divergence_mark    = "\x03";
  } // namespace

  BodyDistribution::BodyDistribution(
    const std::vector<ElasticBody<2> *> &bodies,
    const ParallelParameters            &parameters,
    const MPI_Comm                       communicator)
    : bodies(bodies)
    , parameters(parameters)
    , communicator(communicator)
    , this_process(Utilities::MPI::this_mpi_process(communicator))
    , n_procs(Utilities::MPI::n_mpi_processes(communicator))
    , process_groups(parameters.process_groups(n_procs, bodies.size()))
    , groups(bodies.size(), std::vector<unsigned int>{0})
  {
  }

  namespace
  {
    /** The ranks first, ..., first + n - 1. */
    std::vector<unsigned int>
    ranks(const unsigned int first, const unsigned int n)
    {
      std::vector<unsigned int> r(n);
      std::iota(r.begin(), r.end(), first);
      return r;
    }
  } // namespace

  bool
  BodyDistribution::distribute()
  {
    const auto previous = groups;
    if (process_groups)
    {
      // Chosen once: a body's mesh is partitioned between its group, and
      // refinement repartitions within the group.
      if (groups_chosen)
        return false;
      groups_chosen = true;
      if (parameters.mode == BodyOwners::all)
        for (auto &g : groups)
          g = ranks(0, n_procs);
      else if (parameters.mode == BodyOwners::list)
        for (unsigned int b = 0; b < bodies.size(); ++b)
          groups[b] = parameters.body_groups.at(bodies[b]->name());
      else
      {
        // One process per body, then each further process to the body
        // with the most dofs per process; consecutive ranks per body.
        std::vector<unsigned int> size(bodies.size(), 1);
        for (unsigned int p = bodies.size(); p < n_procs; ++p)
        {
          unsigned int best = 0;
          for (unsigned int b = 1; b < bodies.size(); ++b)
            if (static_cast<double>(bodies[b]->n_dofs()) / size[b] >
                static_cast<double>(bodies[best]->n_dofs()) / size[best])
              best = b;
          ++size[best];
        }
        unsigned int first = 0;
        for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          groups[b] = ranks(first, size[b]);
          first += size[b];
        }
      }
      // Collective over the world, in the same body order everywhere.
      // The bodies keep (and free) their groups' communicators.
      for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        MPI_Comm  group;
        const int ierr = MPI_Comm_split(
          communicator, owns(b) ? 0 : MPI_UNDEFINED, this_process, &group);
        AssertThrowMPI(ierr);
        bodies[b]->set_process_group(groups[b], group);
      }
    }
    else if (parameters.mode == BodyOwners::list)
      for (unsigned int b = 0; b < bodies.size(); ++b)
        groups[b] = parameters.body_groups.at(bodies[b]->name());
    else
    {
      // Largest body first onto the least loaded process: the time of one
      // DD iteration is that of the slowest process. Ties go to the lower
      // rank, and every process computes the same from the same meshes.
      std::vector<unsigned int> order(bodies.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int a, const unsigned int b)
                       { return bodies[a]->n_dofs() > bodies[b]->n_dofs(); });
      std::vector<double> load(n_procs, 0.);
      for (const unsigned int b : order)
      {
        const unsigned int p =
          std::min_element(load.begin(), load.end()) - load.begin();
        groups[b] = {p};
        load[p] += bodies[b]->n_dofs();
      }
    }
    // Assembly and factorization of the bodies are independent.
    for_each_body([&](const unsigned int b)
                  { bodies[b]->set_solved_here(owns(b)); },
                  false);
    return groups != previous;
  }

  void
  BodyDistribution::for_each_body(const std::function<void(unsigned int)> &work,
                                  const bool owned_only) const
  {
    std::vector<std::string> errors(bodies.size());
    const auto               run = [&](const unsigned int b)
    {
      try
      {
        work(b);
      }
      // An allocation that failed stays out of memory (exit 8) on every
      // process: its message is marked for agree_on_errors().
      catch (const OutOfMemoryError &e)
      {
        errors[b] = out_of_memory_mark + e.what();
      }
      catch (const std::bad_alloc &)
      {
        errors[b] = out_of_memory_mark + std::string("out of memory in a body "
                                                     "problem; refine less or "
                                                     "run on more processes");
      }
      catch (const NotConvergedError &e)
      {
        errors[b] = not_converged_mark + e.what();
      }
      catch (const DivergenceError &e)
      {
        errors[b] = divergence_mark + e.what();
      }
      catch (const std::exception &e)
      {
        errors[b] = e.what();
      }
    };
    // With process groups the work may be collective over a body's group
    // or the world: every process takes the bodies in the same order, one
    // at a time.
    run_tasks(
      bodies.size(),
      [&](const unsigned int b)
      {
        if (!owned_only || owns(b))
          run(b);
      },
      process_groups);
    std::string first_error;
    for (const auto &e : errors)
      if (first_error.empty())
        first_error = e;
    agree_on_errors(first_error);
  }

  namespace
  {
    /** InputError, or the error of the mark the message carries
     * (OutOfMemoryError, NotConvergedError, DivergenceError). */
    [[noreturn]] void
    throw_error(const std::string &message)
    {
      if (message.rfind(out_of_memory_mark, 0) == 0)
        throw OutOfMemoryError(message.substr(out_of_memory_mark.size()));
      if (message.rfind(not_converged_mark, 0) == 0)
        throw NotConvergedError(message.substr(not_converged_mark.size()));
      if (message.rfind(divergence_mark, 0) == 0)
        throw DivergenceError(message.substr(divergence_mark.size()));
      throw InputError(message);
    }
  } // namespace

  void
  BodyDistribution::agree_on_errors(const std::string &message) const
  {
    if (n_procs == 1)
    {
      if (!message.empty())
        throw_error(message);
      return;
    }
    // Collective: every process calls this once at the same point (after
    // every set of body solves). The messages are gathered only when some
    // process failed: the usual case costs one integer reduction.
    if (Utilities::MPI::max(static_cast<int>(!message.empty()), communicator) ==
        0)
      return;
    for (const auto &m : Utilities::MPI::all_gather(communicator, message))
      if (!m.empty())
        throw_error(m);
  }

  void
  BodyDistribution::solve_and_share(
    const std::function<void(unsigned int)> &solve,
    std::vector<BodyVector>                 &per_body) const
  {
    AssertDimension(per_body.size(), bodies.size());
    Timer timer;
    for_each_body(solve, true);
    seconds_solving += timer.wall_time();
    timer.restart();
    share(per_body);
    seconds_exchanging += timer.wall_time();
  }

  void
  BodyDistribution::solve_and_share_traces(
    const std::function<void(unsigned int)>                 &solve,
    std::vector<BodyVector>                                 &per_body,
    const std::vector<std::vector<types::global_dof_index>> &traces) const
  {
    AssertDimension(per_body.size(), bodies.size());
    AssertDimension(traces.size(), bodies.size());
    Timer timer;
    for_each_body(solve, true);
    seconds_solving += timer.wall_time();
    timer.restart();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      share_trace(b, per_body[b], traces[b]);
    seconds_exchanging += timer.wall_time();
  }

  void
  BodyDistribution::share_trace(
    const unsigned int                          b,
    BodyVector                                 &v,
    const std::vector<types::global_dof_index> &dofs) const
  {
    if (n_procs == 1)
      return;
    if (bodies[b]->has_distributed_vectors())
    {
      import_ghosts(b, v);
      return;
    }
    // The owner's list with its values in one message: dofs (exact as
    // doubles below 2^53), then values.
    const bool          sender = this_process == owner_of(b);
    std::vector<double> message;
    if (sender)
    {
      AssertDimension(v.size(), bodies[b]->n_dofs());
      message.reserve(2 * dofs.size());
      for (const auto i : dofs)
        message.push_back(static_cast<double>(i));
      for (const auto i : dofs)
        message.push_back(v(i));
      bytes_shared += sizeof(double) * message.size() * (n_procs - 1);
    }
    message = Utilities::MPI::broadcast(communicator, message, owner_of(b));
    if (owns(b))
      return;
    bodies[b]->reinit_vector(v);
    const std::size_t n = message.size() / 2;
    for (std::size_t k = 0; k < n; ++k)
      v(static_cast<types::global_dof_index>(message[k])) = message[n + k];
  }

  void
  BodyDistribution::share(const unsigned int b, BodyVector &v) const
  {
    if (n_procs == 1)
      return;
    if (bodies[b]->has_distributed_vectors())
    {
      import_ghosts(b, v);
      return;
    }
    // Every process knows the body's size from its own copy of the mesh.
    if (!owns(b))
      bodies[b]->reinit_vector(v);
    AssertDimension(v.size(), bodies[b]->n_dofs());
    if (this_process == owner_of(b))
      bytes_shared += sizeof(double) * v.size() * (n_procs - 1);
    Utilities::MPI::broadcast(v.begin(), v.size(), owner_of(b), communicator);
  }

  void
  BodyDistribution::import_ghosts(const unsigned int b, BodyVector &v) const
  {
    if (bodies[b]->is_solved_by_part_of_mesh())
    {
      // Solved by the group alone: the others receive the traces (and a
      // vector of the body's layout, if they had none), and every
      // process of the mesh imports, collectively.
      if (!owns(b))
        bodies[b]->reinit_vector(v);
      v.update_ghost_values();
    }
    // The body's solve imported them already; a vector that was not
    // solved for (zero) imports them here. Every process takes the same
    // branch: the iteration is replicated.
    else if (!v.has_ghost_elements())
      v.update_ghost_values();
    bytes_shared += sizeof(double) * v.get_partitioner()->n_import_indices();
  }

  std::uint64_t
  BodyDistribution::vector_entries() const
  {
    std::uint64_t n = 0;
    for (const auto *body : bodies)
    {
      const auto &layout = *body->get_solution().get_partitioner();
      n += layout.locally_owned_size() + layout.n_ghost_indices();
    }
    return n;
  }

  std::uint64_t
  BodyDistribution::constraint_lines() const
  {
    std::uint64_t n = 0;
    for (const auto *body : bodies)
      n += body->get_constraints().n_constraints();
    return n;
  }

  types::global_dof_index
  BodyDistribution::owned_dofs() const
  {
    types::global_dof_index n = 0;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies[b]->is_solved_distributed())
        n += bodies[b]->get_dof_handler().locally_owned_dofs().n_elements();
      else if (this_process == owner_of(b))
        n += bodies[b]->n_dofs();
    return n;
  }

  void
  BodyDistribution::share(std::vector<BodyVector> &per_body) const
  {
    AssertDimension(per_body.size(), bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      share(b, per_body[b]);
  }

  std::string
  BodyDistribution::describe() const
  {
    std::ostringstream s;
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      s << (b ? ", " : "") << bodies[b]->name() << ": " << groups[b].front();
      if (groups[b].size() > 1)
        s << '-' << groups[b].back();
    }
    return s.str();
  }
  void
  BodyDistribution::solve_bodies()
  {
    std::vector<BodyVector> u(bodies.size());
    solve_and_share(
      [&](const unsigned int b)
      {
        // A nonlinear law: Newton from the last solution.
        if (bodies[b]->get_material_law().is_linear())
          bodies[b]->solve();
        else
          bodies[b]->solve_nonlinear(BodyVector(), bodies[b]->get_solution());
        u[b] = bodies[b]->get_solution();
      },
      u);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->get_solution() = u[b];
  }
} // namespace ddcontact
