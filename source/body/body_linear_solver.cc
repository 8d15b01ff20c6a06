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
#include <ddcontact/body/body_systems.h>
#include <ddcontact/interruption.h>

#include <algorithm>
#include <functional>
#include <map>
#include <type_traits>

namespace ddcontact
{
  namespace
  {
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
      zero_load() override
      {
        system.load = 0;
      }

      void
      add_load(const AffineConstraints<double>            &constraints,
               const FullMatrix<double>                   &cell_matrix,
               const Vector<double>                       &cell_load,
               const std::vector<types::global_dof_index> &dof_indices) override
      {
        constraints.distribute_local_to_global(
          cell_load, dof_indices, system.load, cell_matrix);
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
          return factorize_group_with_springs(system, springs);
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
