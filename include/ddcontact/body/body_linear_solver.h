#ifndef ddcontact_body_linear_solver_h
#define ddcontact_body_linear_solver_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_parameters.h>
#include <ddcontact/body/body_vector.h>
#include <ddcontact/parameter_tools.h>

#include <memory>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The linear system of one body problem (20), a_a(u, v) = l_a(v) +
   * contact load, and the solver that answers it for many loads: the
   * domain decomposition solves it hundreds of times with the same matrix,
   * so the matrix is factorized (or preconditioned) once per mesh and
   * solve() reuses it. solve() is const and may run for several bodies at
   * once in different threads.
   *
   * Three implementations, chosen once by Solver/Type and the body's
   * process group (create()):
   *  - direct on one process: the matrix in a SparseMatrix, UMFPACK;
   *  - direct over a process group: the matrix distributed over the group
   *    (Trilinos), MUMPS through Amesos;
   *  - cg-amg: CG with ML's algebraic multigrid, on one process or with the
   *    matrix distributed over the group.
   * Each owns its matrix and its load vector of body force and tractions
   * (12); the body assembles into them through add().
   */
  /** Springs s c c^T on the dofs of one contact unknown, added to a
   * body's stiffness (the Robin problems of RobinPreconditioner). */
  struct DofSprings
  {
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  c;
    double                               stiffness = 0;
  };

  /** A factorization of a body's stiffness plus springs, over the
   * processes of its group. */
  class SpringFactorization
  {
  public:
    virtual ~SpringFactorization() = default;

    /** v = (K + springs)^{-1} @p rhs: of @p rhs each process reads its
     * own rows; @p v whole on every process of the group, or this
     * process's rows of a distributed @p v (ElasticBody::reinit_vector());
     * collective over the group. */
    virtual void
    solve(const BodyVector &rhs, BodyVector &v) const = 0;
  };

  template <int dim>
  class BodyLinearSolver
  {
  public:
    /** The solver for @p parameters' Solver/Type, with the matrix on this
     * process (@p group_communicator MPI_COMM_SELF or a group of one) or
     * distributed over the group. */
    static std::unique_ptr<BodyLinearSolver<dim>>
    create(const BodyParameters &parameters,
           const MPI_Comm        group_communicator,
           const unsigned int    group_size);

    virtual ~BodyLinearSolver() = default;

    /** The sparsity pattern and a zero matrix for the dofs of
     * @p dof_handler coupled through @p constraints. */
    virtual void
    reinit(const DoFHandler<dim>           &dof_handler,
           const AffineConstraints<double> &constraints) = 0;

    /** Set matrix and load to zero before an assembly. */
    virtual void
    zero() = 0;

    /** Set the load alone to zero before assemble_load(): the matrix is
     * kept. */
    virtual void
    zero_load() = 0;

    /** Add one cell's load, condensed by @p constraints; @p cell_matrix
     * moves the Dirichlet inhomogeneities into it, as add() does. */
    virtual void
    add_load(const AffineConstraints<double>            &constraints,
             const FullMatrix<double>                   &cell_matrix,
             const Vector<double>                       &cell_load,
             const std::vector<types::global_dof_index> &dof_indices) = 0;

    /** Add one cell's matrix and load, condensed by @p constraints. */
    virtual void
    add(const AffineConstraints<double>            &constraints,
        const FullMatrix<double>                   &cell_matrix,
        const Vector<double>                       &cell_load,
        const std::vector<types::global_dof_index> &dof_indices) = 0;

    /** Exchange the entries added for other processes' rows. */
    virtual void
    compress()
    {
    }

    /** Factorize the assembled matrix, or build its preconditioner;
     * @p dof_handler gives the rigid-body modes to the AMG. Throws
     * InputError naming the body if the matrix cannot be factorized. */
    virtual void
    factorize(const DoFHandler<dim> &dof_handler) = 0;

    /** @p u = K^{-1} (l + @p load), whole on every process of the group;
     * @p load may be empty for none. Without @p with_load, K^{-1} @p load
     * (the body's own load l left out, for a homogeneous solve). The
     * constraints are not distributed (the body does that). */
    virtual void
    solve(const BodyVector &load,
          BodyVector       &u,
          bool              with_load = true) const = 0;

    /** The assembled matrix and load of a body solved on one process (the
     * monolithic solver builds its system from them); a body solved by a
     * process group has neither. */
    virtual const SparseMatrix<double> &
    matrix() const;

    virtual const Vector<double> &
    load_vector() const;

    /** The stiffness plus @p springs factorized by MUMPS over the process
     * group of a body solved by one (a serial body's preconditioner
     * factorizes its own copy of matrix()). Collective over the group. */
    virtual std::unique_ptr<SpringFactorization>
    factorize_with_springs(const std::vector<DofSprings> &springs) const;
  };
} // namespace ddcontact

#endif
