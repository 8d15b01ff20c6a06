#include <deal.II/base/mpi.h>
#include <deal.II/base/thread_management.h>

#include <ddcontact/tasks.h>

#include <exception>
#include <numeric>
#include <vector>

namespace ddcontact
{
  void
  run_tasks(const unsigned int                       n,
            const std::function<void(unsigned int)> &work,
            const bool                               in_turn)
  {
    std::vector<std::exception_ptr> errors(n);
    const auto                      run = [&](const unsigned int i)
    {
      try
      {
        work(i);
      }
      catch (...)
      {
        errors[i] = std::current_exception();
      }
    };
    if (in_turn)
      for (unsigned int i = 0; i < n; ++i)
        run(i);
    else
    {
      dealii::Threads::TaskGroup<void> tasks;
      for (unsigned int i = 0; i < n; ++i)
        tasks += dealii::Threads::new_task([&run, i]() { run(i); });
      tasks.join_all();
    }
    for (const auto &e : errors)
      if (e)
        std::rethrow_exception(e);
  }

  double
  ordered_dot(const dealii::Vector<double> &x, const dealii::Vector<double> &y)
  {
    AssertDimension(x.size(), y.size());
    return std::inner_product(x.begin(), x.end(), y.begin(), 0.);
  }

  double
  ordered_sum(const double own, const MPI_Comm comm)
  {
    if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
      return own;
    const auto all = dealii::Utilities::MPI::all_gather(comm, own);
    return std::accumulate(all.begin(), all.end(), 0.);
  }

  double
  ordered_dot(const dealii::LinearAlgebra::distributed::Vector<double> &x,
              const dealii::LinearAlgebra::distributed::Vector<double> &y)
  {
    AssertDimension(x.locally_owned_size(), y.locally_owned_size());
    return ordered_sum(
      std::inner_product(
        x.begin(), x.begin() + x.locally_owned_size(), y.begin(), 0.),
      x.get_mpi_communicator());
  }
} // namespace ddcontact
