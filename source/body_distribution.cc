#include <ddcontact/body_distribution.h>

#include <deal.II/base/thread_management.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <numeric>
#include <sstream>

namespace ddcontact
{
  BodyDistribution::BodyDistribution(
    const std::vector<ElasticBody<2> *> &bodies,
    const ParallelParameters            &parameters,
    const MPI_Comm                       communicator)
    : bodies(bodies)
    , parameters(parameters)
    , communicator(communicator)
    , this_process(Utilities::MPI::this_mpi_process(communicator))
    , n_procs(Utilities::MPI::n_mpi_processes(communicator))
    , owner(bodies.size(), 0)
  {
  }

  bool
  BodyDistribution::distribute()
  {
    const std::vector<unsigned int> previous = owner;
    if (parameters.body_owners.empty())
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
        owner[b] = p;
        load[p] += bodies[b]->n_dofs();
      }
    }
    else
      for (unsigned int b = 0; b < bodies.size(); ++b)
        owner[b] = parameters.body_owners.at(bodies[b]->name());
    // Assembly and factorization of the bodies are independent.
    for_each_body([&](const unsigned int b)
                  { bodies[b]->set_solved_here(owns(b)); },
                  false);
    return owner != previous;
  }

  void
  BodyDistribution::for_each_body(const std::function<void(unsigned int)> &work,
                                  const bool owned_only) const
  {
    std::vector<std::string> errors(bodies.size());
    Threads::TaskGroup<void> tasks;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!owned_only || owns(b))
        tasks += Threads::new_task(
          [&, b]()
          {
            try
            {
              work(b);
            }
            catch (const std::exception &e)
            {
              errors[b] = e.what();
            }
          });
    tasks.join_all();
    std::string first_error;
    for (const auto &e : errors)
      if (first_error.empty())
        first_error = e;
    agree_on_errors(first_error);
  }

  void
  BodyDistribution::agree_on_errors(const std::string &message) const
  {
    if (n_procs == 1)
    {
      if (!message.empty())
        throw InputError(message);
      return;
    }
    // Collective: every process calls this once at the same point (after
    // every set of body solves). The messages are gathered only when some
    // process failed: the usual case costs one integer reduction.
    if (Utilities::MPI::max(static_cast<int>(!message.empty()),
                            communicator) == 0)
      return;
    for (const auto &m : Utilities::MPI::all_gather(communicator, message))
      if (!m.empty())
        throw InputError(m);
  }

  void
  BodyDistribution::solve_and_share(
    const std::function<void(unsigned int)> &solve,
    std::vector<Vector<double>>             &per_body) const
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
  BodyDistribution::share(const unsigned int b, Vector<double> &v) const
  {
    if (n_procs == 1)
      return;
    // Every process knows the body's size from its own copy of the mesh.
    if (!owns(b))
      v.reinit(bodies[b]->n_dofs());
    AssertDimension(v.size(), bodies[b]->n_dofs());
    Utilities::MPI::broadcast(v.data(), v.size(), owner[b], communicator);
  }

  void
  BodyDistribution::share(std::vector<Vector<double>> &per_body) const
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
      s << (b ? ", " : "") << bodies[b]->name() << ": " << owner[b];
    return s.str();
  }
} // namespace ddcontact
