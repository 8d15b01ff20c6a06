#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_CrsMatrix.h>

#include <ddcontact/body/body_linear_solver.h>
#include <ddcontact/interruption.h>

#include <algorithm>
#include <functional>
#include <map>
#include <type_traits>

namespace ddcontact
{
  namespace
  {
    /** The values of @p v from global index @p first on, in memory. */
    const double *
    values_from(const BodyVector &v, const types::global_dof_index first)
    {
      return v.begin() + v.get_partitioner()->global_to_local(first);
    }

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
      compress()
      {
        matrix.compress(VectorOperation::add);
        load.compress(VectorOperation::add);
      }

      /** Every process of the group holds at least its own rows of the
       * @p extra load (all of them, or its part of a distributed
       * BodyVector): it takes those. */
      void
      right_hand_side(const BodyVector &extra,
                      const bool        with_load,
                      VectorType       &rhs,
                      VectorType       &x) const
      {
        if (with_load)
          rhs = load;
        else
          rhs.reinit(load);
        x.reinit(load);
        if (extra.size() > 0 && owned.n_elements() > 0)
          std::transform(rhs.begin(),
                         rhs.end(),
                         values_from(extra, *owned.begin()),
                         rhs.begin(),
                         std::plus<double>());
      }

      /** The solution in @p u: gathered whole on every process of the
       * group, or, into a distributed BodyVector (reinit by the body with
       * the same owned rows), this process's rows. Collective over the
       * group in the first case only: the choice is made from the layout
       * of @p u, the same on every process of the group, never from
       * whether this process owns every row (the one process that owns
       * the single cell of a body would gather while the others copied,
       * and the group would wait forever). */
      void
      to_whole(const VectorType &x, BodyVector &u) const
      {
        if (is_partitioned(u))
        {
          AssertDimension(u.size(), n_dofs);
          AssertDimension(u.locally_owned_size(), x.locally_owned_size());
          std::copy(x.begin(), x.end(), u.begin());
          return;
        }
        u.reinit(n_dofs);
        const int ierr = MPI_Allgatherv(x.begin(),
                                        x.locally_owned_size(),
                                        MPI_DOUBLE,
                                        u.begin(),
                                        range_sizes.data(),
                                        range_starts.data(),
                                        MPI_DOUBLE,
                                        communicator);
        AssertThrowMPI(ierr);
      }

      MPI_Comm                       communicator;
      IndexSet                       owned;
      types::global_dof_index        n_dofs = 0;
      std::vector<int>               range_starts, range_sizes;
      TrilinosWrappers::SparseMatrix matrix;
      VectorType                     load;
    };

    /**
     * The stiffness of a GroupSystem plus springs, MUMPS over the group:
     * the rows of each process are its own rows of K with the couplings of
     * the springs added (each process adds the entries of its own rows, so
     * nothing is sent), and the solution is gathered whole.
     */
    class GroupSpringFactorization : public SpringFactorization
    {
    public:
      GroupSpringFactorization(const GroupSystem             &system,
                               const std::vector<DofSprings> &springs)
        : system(system)
      {
        // Row by row: K's entries of each owned row with the springs'
        // entries of that row merged in, inserted in one call per row
        // (entry by entry, the copy of 8.9e4 dofs took 20 s; 0.08 s so).
        const auto             &owned = system.owned;
        const Epetra_CrsMatrix &K     = system.matrix.trilinos_matrix();
        std::map<types::global_dof_index,
                 std::map<types::global_dof_index, double>>
          extra;
        for (const auto &s : springs)
          for (unsigned int a = 0; a < s.dofs.size(); ++a)
            if (owned.is_element(s.dofs[a]))
              for (unsigned int b = 0; b < s.dofs.size(); ++b)
                extra[s.dofs[a]][s.dofs[b]] += s.stiffness * s.c[a] * s.c[b];
        std::vector<std::vector<types::global_dof_index>> columns(
          owned.n_elements());
        std::vector<std::vector<double>>  values(owned.n_elements());
        TrilinosWrappers::SparsityPattern sp(owned, system.communicator);
        unsigned int                      r = 0;
        for (const auto i : owned)
        {
          // Epetra's view of the row (deal.II's row iterator copies the
          // row again for every entry).
          std::map<types::global_dof_index, double> row;
          int                                       length      = 0;
          double                                   *row_values  = nullptr;
          int                                      *row_columns = nullptr;
          K.ExtractMyRowView(K.RowMap().LID(static_cast<int>(i)),
                             length,
                             row_values,
                             row_columns);
          for (int k = 0; k < length; ++k)
            row[K.ColMap().GID(row_columns[k])] += row_values[k];
          if (const auto e = extra.find(i); e != extra.end())
            for (const auto &[j, v] : e->second)
              row[j] += v;
          for (const auto &[j, v] : row)
          {
            columns[r].push_back(j);
            values[r].push_back(v);
          }
          sp.add_entries(i, columns[r].begin(), columns[r].end(), true);
          ++r;
        }
        sp.compress();
        matrix.reinit(sp);
        r = 0;
        for (const auto i : owned)
        {
          matrix.set(i, columns[r], values[r], false);
          ++r;
        }
        matrix.compress(VectorOperation::insert);
        direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         "Amesos_Mumps"));
        direct->initialize(matrix);
      }

      void
      solve(const BodyVector &rhs, BodyVector &v) const override
      {
        GroupSystem::VectorType b, x;
        system.right_hand_side(rhs, false, b, x);
        direct->solve(x, b);
        system.to_whole(x, v);
      }

    private:
      const GroupSystem                                      &system;
      TrilinosWrappers::SparseMatrix                          matrix;
      mutable SolverControl                                   control;
      mutable std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
    };

    /** What every implementation shares: the system it assembles into. */
    template <int dim, class System>
    class SystemSolver : public BodyLinearSolver<dim>
    {
    public:
      SystemSolver(const BodyParameters &parameters, System system)
        : parameters(parameters)
        , system(std::move(system))
      {
      }

      /** The factorization or preconditioner of the old matrix is released
       * before the new matrix is made. */
      void
      reinit(const DoFHandler<dim>           &dof_handler,
             const AffineConstraints<double> &constraints) override
      {
        release();
        system.reinit(dof_handler, constraints);
      }

      void
      zero() override
      {
        system.matrix = 0;
        system.load   = 0;
      }

      void
      add(const AffineConstraints<double>            &constraints,
          const FullMatrix<double>                   &cell_matrix,
          const Vector<double>                       &cell_load,
          const std::vector<types::global_dof_index> &dof_indices) override
      {
        constraints.distribute_local_to_global(
          cell_matrix, cell_load, dof_indices, system.matrix, system.load);
      }

      void
      compress() override
      {
        system.compress();
      }

      const SparseMatrix<double> &
      matrix() const override
      {
        if constexpr (std::is_same_v<System, SerialSystem>)
          return system.matrix;
        else
          return BodyLinearSolver<dim>::matrix();
      }

      const Vector<double> &
      load_vector() const override
      {
        if constexpr (std::is_same_v<System, SerialSystem>)
          return system.load;
        else
          return BodyLinearSolver<dim>::load_vector();
      }

      std::unique_ptr<SpringFactorization>
      factorize_with_springs(
        const std::vector<DofSprings> &springs) const override
      {
        if constexpr (std::is_same_v<System, GroupSystem>)
          return std::make_unique<GroupSpringFactorization>(system, springs);
        else
          return BodyLinearSolver<dim>::factorize_with_springs(springs);
      }

    protected:
      virtual void
      release()
      {
      }

      /** A factorization failed with @p error: out of memory (a
       * std::bad_alloc, or UMFPACK's status -1) is named as such (exit 8),
       * never as a singular matrix; anything else is a singular matrix. */
      [[noreturn]] void
      throw_factorization_error(const std::exception_ptr &error) const
      {
        bool out_of_memory = false;
        try
        {
          std::rethrow_exception(error);
        }
        catch (const std::bad_alloc &)
        {
          out_of_memory = true;
        }
        catch (const std::exception &e)
        {
          out_of_memory =
            std::string(e.what()).find("error status -1") != std::string::npos;
        }
        if (out_of_memory)
          throw OutOfMemoryError(
            parameters.section() +
            ": out of memory while factorizing the stiffness matrix of " +
            std::to_string(system.load.size()) +
            " unknowns; refine less (Mesh/Initial refinement, Adaptation/Max "
            "cells), use Solver/Type = cg-amg, or run on more processes");
        // UMFPACK reports a singular or overflowing matrix by an exception
        // with a stack trace; the user needs the body.
        throw InputError(parameters.section() +
                         ": the stiffness matrix cannot be factorized "
                         "(singular, or its entries overflow); check "
                         "Material/Young's modulus and the Dirichlet "
                         "conditions");
      }

      const BodyParameters &parameters;
      System                system;
    };

    /** UMFPACK on one process. */
    template <int dim>
    class SerialDirectSolver : public SystemSolver<dim, SerialSystem>
    {
    public:
      using SystemSolver<dim, SerialSystem>::SystemSolver;

      void
      factorize(const DoFHandler<dim> &) override
      {
        try
        {
          direct.initialize(this->system.matrix);
        }
        catch (const std::exception &)
        {
          this->throw_factorization_error(std::current_exception());
        }
      }

      void
      solve(const BodyVector &load,
            BodyVector       &u,
            const bool        with_load) const override
      {
        Vector<double> rhs, x;
        this->system.right_hand_side(load, with_load, rhs, x);
        direct.vmult(x, rhs);
        this->system.to_whole(x, u);
      }

    private:
      SparseDirectUMFPACK direct;
    };

    /** MUMPS (through Amesos) over the process group. */
    template <int dim>
    class GroupDirectSolver : public SystemSolver<dim, GroupSystem>
    {
    public:
      using SystemSolver<dim, GroupSystem>::SystemSolver;

      /** MUMPS frees its factors collectively over the group. */
      void
      release() override
      {
        direct.reset();
      }

      void
      factorize(const DoFHandler<dim> &) override
      {
        direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         "Amesos_Mumps"));
        try
        {
          direct->initialize(this->system.matrix);
        }
        catch (const std::bad_alloc &)
        {
          this->throw_factorization_error(std::current_exception());
        }
      }

      void
      solve(const BodyVector &load,
            BodyVector       &u,
            const bool        with_load) const override
      {
        GroupSystem::VectorType rhs, x;
        this->system.right_hand_side(load, with_load, rhs, x);
        direct->solve(x, rhs);
        this->system.to_whole(x, u);
      }

    private:
      mutable SolverControl                                   control;
      mutable std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
    };

    /** CG preconditioned by ML's algebraic multigrid, on either system. */
    template <int dim, class System>
    class CgAmgSolver : public SystemSolver<dim, System>
    {
    public:
      using SystemSolver<dim, System>::SystemSolver;

      void
      release() override
      {
        amg.clear();
      }

      void
      factorize(const DoFHandler<dim> &dof_handler) override
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = (this->parameters.degree > 1);
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        DoFTools::extract_constant_modes(
          dof_handler, ComponentMask(dim, true), data.constant_modes);
        if constexpr (std::is_same_v<System, SerialSystem>)
          copy.reinit(this->system.matrix);
        amg.initialize(trilinos_matrix(), data);
      }

      void
      solve(const BodyVector &load,
            BodyVector       &u,
            const bool        with_load) const override
      {
        typename System::VectorType rhs, x;
        this->system.right_hand_side(load, with_load, rhs, x);
        SolverControl control(this->parameters.solver_max_iterations,
                              this->parameters.solver_tolerance *
                                rhs.l2_norm());
        SolverCG<typename System::VectorType> cg(control);
        try
        {
          cg.solve(trilinos_matrix(), x, rhs, amg);
        }
        catch (const SolverControl::NoConvergence &e)
        {
          throw InputError(this->parameters.section() +
                           "/Solver: cg-amg did not converge in " +
                           std::to_string(e.last_step) +
                           " iterations (residual " +
                           std::to_string(e.last_residual) +
                           "); raise Max iterations or use Type = direct");
        }
        this->system.to_whole(x, u);
      }

    private:
      /** The matrix ML works on: the distributed one as it is, a serial
       * one's copy (its SparseMatrix stays for the monolithic solver). */
      const TrilinosWrappers::SparseMatrix &
      trilinos_matrix() const
      {
        if constexpr (std::is_same_v<System, SerialSystem>)
          return copy;
        else
          return this->system.matrix;
      }

      TrilinosWrappers::SparseMatrix    copy;
      TrilinosWrappers::PreconditionAMG amg;
    };
  } // namespace

  template <int dim>
  const SparseMatrix<double> &
  BodyLinearSolver<dim>::matrix() const
  {
    AssertThrow(false,
                ExcMessage("the matrix of a body solved by a process group "
                           "is distributed"));
    static const SparseMatrix<double> none;
    return none;
  }

  template <int dim>
  const Vector<double> &
  BodyLinearSolver<dim>::load_vector() const
  {
    AssertThrow(false,
                ExcMessage("the load of a body solved by a process group is "
                           "distributed"));
    static const Vector<double> none;
    return none;
  }

  template <int dim>
  std::unique_ptr<SpringFactorization>
  BodyLinearSolver<dim>::factorize_with_springs(
    const std::vector<DofSprings> &) const
  {
    AssertThrow(false,
                ExcMessage("a body solved on one process factorizes its "
                           "springs with its own copy of matrix()"));
    return nullptr;
  }

  template <int dim>
  std::unique_ptr<BodyLinearSolver<dim>>
  BodyLinearSolver<dim>::create(const BodyParameters &parameters,
                                const MPI_Comm        group_communicator,
                                const unsigned int    group_size)
  {
    const bool group = group_size > 1;
    switch (parameters.solver)
    {
      case BodySolverType::direct:
        if (group)
          return std::make_unique<GroupDirectSolver<dim>>(
            parameters, GroupSystem(group_communicator));
        return std::make_unique<SerialDirectSolver<dim>>(parameters,
                                                         SerialSystem());
      case BodySolverType::cg_amg:
        if (group)
          return std::make_unique<CgAmgSolver<dim, GroupSystem>>(
            parameters, GroupSystem(group_communicator));
        return std::make_unique<CgAmgSolver<dim, SerialSystem>>(parameters,
                                                                SerialSystem());
    }
    AssertThrow(false, ExcInternalError());
    return nullptr;
  }

  template class BodyLinearSolver<2>;
} // namespace ddcontact
