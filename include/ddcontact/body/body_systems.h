#ifndef ddcontact_body_systems_h
#define ddcontact_body_systems_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ddcontact/body/body_linear_solver.h>
#include <ddcontact/body/body_vector.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <vector>

// Where the BodyLinearSolver implementations keep a body's matrix and
// load: on one process (SerialSystem) or over the body's process group
// (GroupSystem).
namespace ddcontact
{
  using namespace dealii;

  /** The values of @p v from global index @p first on, in memory. */
  const double *
  values_from(const BodyVector &v, types::global_dof_index first);

  /** Matrix and load of a body solved on this process alone. */
  struct SerialSystem
  {
    using VectorType = Vector<double>;

    template <int dim>
    void
    reinit(const DoFHandler<dim>           &dof_handler,
           const AffineConstraints<double> &constraints)
    {
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      sparsity.copy_from(dsp);
      matrix.reinit(sparsity);
      load.reinit(dof_handler.n_dofs());
    }

    void
    compress()
    {
    }

    /** l + @p extra (@p extra alone without @p with_load), and the
     * solution vector it is solved into. */
    void
    right_hand_side(const BodyVector &extra,
                    const bool        with_load,
                    VectorType       &rhs,
                    VectorType       &x) const
    {
      if (with_load)
        rhs = load;
      else
        rhs.reinit(load.size());
      if (extra.size() > 0)
        std::transform(rhs.begin(),
                       rhs.end(),
                       values_from(extra, 0),
                       rhs.begin(),
                       std::plus<double>());
      x.reinit(load.size());
    }

    /** The solution in @p u: whole, or into the owned rows of a
     * distributed BodyVector whose process owns every dof (a p4est body
     * on a group of one), which keeps its layout. */
    void
    to_whole(const VectorType &x, BodyVector &u) const
    {
      if (is_partitioned(u))
      {
        AssertDimension(u.locally_owned_size(), x.size());
      }
      else if (u.size() != x.size())
        u.reinit(x.size());
      std::copy(x.begin(), x.end(), u.begin());
    }

    SparsityPattern      sparsity;
    SparseMatrix<double> matrix;
    Vector<double>       load;
  };

  /**
   * Matrix and load distributed over the processes of the body's group:
   * each process assembles its own cells (subdomain) into the rows of
   * its dofs, one contiguous range per process (a partitioned DoFHandler
   * numbers the dofs subdomain by subdomain), and the solution is
   * gathered whole on every process of the group.
   */
  struct GroupSystem
  {
    using VectorType = TrilinosWrappers::MPI::Vector;

    explicit GroupSystem(const MPI_Comm communicator)
      : communicator(communicator)
    {
    }

    template <int dim>
    void
    reinit(const DoFHandler<dim>           &dof_handler,
           const AffineConstraints<double> &constraints)
    {
      // The rows of this process's dofs, with the columns its cells
      // couple them to; entries of other rows are sent to their owners.
      owned = dof_handler.locally_owned_dofs();
      AssertThrow(owned.is_contiguous(), ExcInternalError());
      n_dofs       = dof_handler.n_dofs();
      range_starts = Utilities::MPI::all_gather(
        communicator,
        static_cast<int>(owned.n_elements() ? *owned.begin() : 0));
      range_sizes = Utilities::MPI::all_gather(
        communicator, static_cast<int>(owned.n_elements()));
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      TrilinosWrappers::SparsityPattern sp(
        owned, owned, relevant, communicator);
      DoFTools::make_sparsity_pattern(dof_handler, sp, constraints, false);
      sp.compress();
      matrix.reinit(sp);
      load.reinit(owned, communicator);
    }

    void
    compress();

    /** Every process of the group holds at least its own rows of the
     * @p extra load (all of them, or its part of a distributed
     * BodyVector): it takes those. */
    void
    right_hand_side(const BodyVector &extra,
                    bool              with_load,
                    VectorType       &rhs,
                    VectorType       &x) const;

    /** The solution in @p u: gathered whole on every process of the
     * group, or, into a distributed BodyVector (reinit by the body with
     * the same owned rows), this process's rows. Collective over the
     * group in the first case only: the choice is made from the layout
     * of @p u, the same on every process of the group, never from
     * whether this process owns every row (the one process that owns
     * the single cell of a body would gather while the others copied,
     * and the group would wait forever). */
    void
    to_whole(const VectorType &x, BodyVector &u) const;

    MPI_Comm                       communicator;
    IndexSet                       owned;
    types::global_dof_index        n_dofs = 0;
    std::vector<int>               range_starts, range_sizes;
    TrilinosWrappers::SparseMatrix matrix;
    VectorType                     load;
  };

  /** The stiffness of @p system plus @p springs, MUMPS over the group:
   * the rows of each process are its own rows of K with the couplings of
   * the springs added (each process adds the entries of its own rows, so
   * nothing is sent), and the solution is gathered whole. */
  std::unique_ptr<SpringFactorization>
  factorize_group_with_springs(const GroupSystem             &system,
                               const std::vector<DofSprings> &springs);
} // namespace ddcontact

#endif
