#ifndef ddcontact_tasks_h
#define ddcontact_tasks_h

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>

namespace ddcontact
{
  /**
   * Run work(i) for every i < n: as concurrent tasks, or one after the
   * other when @p in_turn (work that is collective over MPI processes must
   * come in the same order everywhere). All tasks finish before the first
   * exception (by index) is rethrown with its type: a task left running
   * while the caller unwinds would use objects that are being destroyed.
   */
  void
  run_tasks(unsigned int                             n,
            const std::function<void(unsigned int)> &work,
            bool                                     in_turn);

  /**
   * x . y summed in index order. deal.II's Vector::operator* and norms
   * split a long vector (from 16384 entries) into chunks by the number of
   * threads, which changes the round-off with the thread count; the
   * iterations (Anderson's least squares, the estimate of gamma*, the
   * choice of the initial guess) use this instead, so that their results do
   * not depend on Threads.
   */
  double
  ordered_dot(const dealii::Vector<double> &x, const dealii::Vector<double> &y);

  /** ||x||^2 summed in index order (see ordered_dot()). */
  inline double
  ordered_norm_sqr(const dealii::Vector<double> &x)
  {
    return ordered_dot(x, x);
  }

  /**
   * The sum of every process's @p own over @p comm, added in rank order:
   * the same bits on every process (an MPI_Allreduce may add in another
   * order on each, and replicated decisions taken from it could then
   * differ between processes). One MPI_Allgather of a double.
   */
  double
  ordered_sum(double own, MPI_Comm comm);

  /** x . y of two vectors of one body's layout: their own entries summed
   * in index order on every process, then over the processes of their
   * communicator (ordered_sum()). */
  double
  ordered_dot(const dealii::LinearAlgebra::distributed::Vector<double> &x,
              const dealii::LinearAlgebra::distributed::Vector<double> &y);

  /** ||x||^2 of a body's vector (ordered_dot()). */
  inline double
  ordered_norm_sqr(const dealii::LinearAlgebra::distributed::Vector<double> &x)
  {
    return ordered_dot(x, x);
  }
} // namespace ddcontact

#endif
