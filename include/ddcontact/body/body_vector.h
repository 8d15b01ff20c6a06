#ifndef ddcontact_body_vector_h
#define ddcontact_body_vector_h

#include <deal.II/lac/la_parallel_vector.h>

#include <algorithm>

namespace ddcontact
{
  /**
   * A vector of one body's dofs: a displacement, a load, a trace. On a
   * serial mesh, and wherever a body is held whole, it has every dof; a
   * body whose vectors are distributed (ElasticBody::reinit_vector()) keeps
   * only the dofs this process owns plus ghosts: its locally relevant dofs
   * and the dofs of the contact points (ContactProblem::trace_dofs()), so
   * that every process can evaluate the contact zones. Indices are always
   * the global dof numbers.
   */
  using BodyVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /**
   * Whether @p v holds this process's part of a vector partitioned
   * between processes (ElasticBody::distribute_vectors()) rather than a
   * vector of its own. Every process holding a vector of one layout gets
   * the same answer, so it may choose between collective operations;
   * whether this process's part is the whole vector may not (the process
   * that owns the single cell of a body owns every dof, the others none).
   */
  inline bool
  is_partitioned(const BodyVector &v)
  {
    return dealii::Utilities::MPI::n_mpi_processes(v.get_mpi_communicator()) >
           1;
  }

  /**
   * @p to = @p from on this process alone: the same layout, and the ghost
   * entries copied as they are, ghosted or not. BodyVector's assignment
   * imports the ghosts again, which is collective (a hang in code that
   * only the printing process runs), and its copy constructor drops them.
   */
  inline void
  copy_stored(const BodyVector &from, BodyVector &to)
  {
    to.reinit(from, true);
    const auto &layout = *from.get_partitioner();
    std::copy(from.begin(),
              from.begin() + layout.locally_owned_size() +
                layout.n_ghost_indices(),
              to.begin());
    to.set_ghost_state(from.has_ghost_elements());
  }
} // namespace ddcontact

#endif
