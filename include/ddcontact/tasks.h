#ifndef ddcontact_tasks_h
#define ddcontact_tasks_h

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
} // namespace ddcontact

#endif
