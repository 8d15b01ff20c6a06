#ifndef ddcontact_elastic_body_h
#define ddcontact_elastic_body_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <deal.II/meshworker/copy_data.h>

#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/material.h>
#include <ddcontact/parameters.h>

#include <functional>
#include <memory>
#include <string>

namespace ddcontact
{
  using namespace dealii;

  /** Displacement and stress of a body at one point. */
  template <int dim>
  struct PointValues
  {
    Point<dim>              x;
    Tensor<1, dim>          displacement;
    SymmetricTensor<2, dim> stress;
    double                  von_mises = 0.;
  };

  /**
   * One linear elastic body Omega_a in plane strain: its triangulation
   * (quadrilaterals with hanging nodes, or triangles), its finite element
   * space, its constraints (hanging nodes merged with the Dirichlet data
   * (5)), and the stiffness of the bilinear form a_a of (11).
   *
   * The domain decomposition solves the body problem (20) hundreds of
   * times with the same matrix and a new contact load, so the matrix is
   * factorized once per mesh (factorize()) and solve() only does the
   * forward and backward substitution. solve() is const and may be called
   * for several bodies at once from different threads.
   *
   * Under mpirun with process groups (ParallelParameters::process_groups)
   * the triangulation is a parallel::shared::Triangulation on
   * MPI_COMM_WORLD: every process keeps the whole mesh and the whole
   * iterate (the contact maps, the BEM and the refinement stay replicated),
   * but the cells are partitioned between the processes of the body's
   * group, which assemble their cells into a Trilinos matrix distributed
   * over the group and solve it together (Amesos MUMPS or CG with AMG).
   * The partition follows every refinement (repartitioning in the
   * post-refinement signal).
   *
   * A quadrilateral body solved by every process may instead have a
   * parallel::distributed::Triangulation (p4est; "Parallel/Mesh"): each
   * process then keeps only its own cells and a ghost layer (but all
   * constraints, which are few: complete_constraints()), and whatever is
   * computed cell by cell (energy, stresses, point values) is computed on the
   * owned cells and summed over the processes. The iterate stays whole on
   * every process, so that the DD loop (20)-(21) is the same for every
   * kind of mesh; the contact pairs find their points in the owned cells
   * with RemotePointEvaluation (ContactPair::setup()).
   */
  template <int dim>
  class ElasticBody
  {
  public:
    /** @p mesh_communicator: MPI_COMM_SELF for a serial triangulation, or
     * MPI_COMM_WORLD for a mesh partitioned over process groups. */
    ElasticBody(const BodyParameters &parameters,
                const Constants      &constants,
                const MPI_Comm        mesh_communicator = MPI_COMM_SELF,
                const bool            distributed_mesh  = false);

    ~ElasticBody();

    ElasticBody(const ElasticBody &) = delete;
    ElasticBody &
    operator=(const ElasticBody &) = delete;

    /**
     * Create the initial mesh (rectangle or Gmsh file; a .geo file is
     * meshed into @p work_directory) and check that every boundary id
     * named in the boundary conditions exists.
     */
    void
    make_mesh(const std::string &work_directory = ".");

    /** Distribute dofs, build constraints and the sparsity pattern. Call
     * again after the mesh has been refined. */
    void
    setup_system();

    /** Assemble the stiffness matrix and the load vector of body force and
     * Neumann tractions (12), with the Dirichlet data condensed. */
    void
    assemble_system();

    /** Factorize (direct) or build the AMG preconditioner (cg-amg). */
    void
    factorize();

    /** setup_system(), assemble_system() and factorize() in a row. */
    void
    setup_and_factorize();

    /**
     * Refine (and coarsen) the cells flagged on the triangulation, carry
     * the body's current solution over to the new mesh (SolutionTransfer;
     * the transferred field is made conforming again by the new
     * constraints), and rebuild the system and its factorization. The
     * adaptive driver calls this after marking (section 5 of the paper
     * README: "transfer the current iterate to the new mesh").
     */
    void
    refine_and_transfer();

    /**
     * Whether this process solves the body (see BodyDistribution): only
     * then are the system assembled and factorized; elsewhere the body
     * keeps its mesh, dofs and constraints. Switching it on assembles and
     * factorizes, switching it off frees the matrix and factorization.
     */
    void
    set_solved_here(bool solved_here);

    bool
    is_solved_here() const
    {
      return solved_here;
    }

    /**
     * The processes (world ranks, ascending) that solve the body, and
     * their communicator (MPI_COMM_NULL on the other processes; the body
     * takes it over and frees it). Needs a
     * mesh on MPI_COMM_WORLD; repartitions the cells between the group
     * (collective over the world) and distributes the dofs again. Call
     * set_solved_here() after.
     */
    void
    set_process_group(const std::vector<unsigned int> &ranks,
                      const MPI_Comm                   group_communicator);

    /** Whether the mesh is a p4est forest: this process holds only its
     * own cells and a ghost layer (see the class documentation). */
    bool
    is_mesh_distributed() const
    {
      return mesh_distributed;
    }

    /** Whether this process computes the cell's contributions to cell
     * sums and per-cell fields: every cell on a serial or shared mesh, the
     * owned cells on a distributed one. */
    template <typename CellIterator>
    bool
    computes(const CellIterator &cell) const
    {
      return !mesh_distributed || cell->is_locally_owned();
    }

    /** The number of active cells of the whole mesh. */
    unsigned int
    n_active_cells() const
    {
      return triangulation->n_global_active_cells();
    }

    /** The smallest and largest value of x . @p direction over the
     * vertices of the mesh (all processes' cells). */
    std::pair<double, double>
    extent_along(const Tensor<1, dim> &direction) const;

    /** Whether this process solves the body together with others. */
    bool
    is_solved_distributed() const
    {
      return solved_here && process_group.size() > 1;
    }

    /**
     * Solve a_a(u, v) = l_a(v) + load(v) for all v: @p load is an
     * additional right-hand side (e.g. the contact traction of (20))
     * assembled with get_constraints().distribute_local_to_global() and
     * may be empty (size 0) for none. Constraints are distributed in @p u.
     */
    void
    solve(const Vector<double> &load, Vector<double> &u) const;

    /** Solve with no extra load into the body's own solution vector. */
    void
    solve();

    /**
     * The mesh may be changed (refined) through this reference, e.g. by
     * tests and by the adaptive driver; call setup_and_factorize() after.
     */
    Triangulation<dim> &
    get_triangulation()
    {
      return *triangulation;
    }

    const Triangulation<dim> &
    get_triangulation() const
    {
      return *triangulation;
    }

    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    const Mapping<dim> &
    get_mapping() const
    {
      return *mapping;
    }

    const FiniteElement<dim> &
    get_fe() const
    {
      return *fe;
    }

    const Quadrature<dim> &
    get_cell_quadrature() const
    {
      return *cell_quadrature;
    }

    const Quadrature<dim - 1> &
    get_face_quadrature() const
    {
      return *face_quadrature;
    }

    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

    const SparseMatrix<double> &
    get_stiffness_matrix() const
    {
      return stiffness_matrix;
    }

    /** The condensed load vector of body force and tractions (12). */
    const Vector<double> &
    get_load_vector() const
    {
      return load_vector;
    }

    const Material &
    get_material() const
    {
      return material;
    }

    const BoundaryConditions<dim> &
    get_boundary_conditions() const
    {
      return boundary_conditions;
    }

    const std::string &
    name() const
    {
      return parameters.name;
    }

    bool
    is_simplex() const
    {
      return parameters.cell_type == CellType::triangle;
    }

    Vector<double> &
    get_solution()
    {
      return solution;
    }

    const Vector<double> &
    get_solution() const
    {
      return solution;
    }

    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    /**
     * Whether the volumetric term lambda div u div v of a_a (11) is
     * integrated with one Gauss point per cell ("Element/Volumetric
     * integration = reduced", Q1 only): selective reduced integration, which
     * keeps Q1 free of volumetric locking as nu -> 1/2. The stress is then
     * sigma = lambda (div u)(x_c) I + 2 mu eps(u), with the dilatation taken
     * at the cell's reduced point x_c, consistently in stresses, energy and
     * point values.
     */
    bool
    reduced_volumetric_integration() const
    {
      return volumetric_quadrature != nullptr;
    }

    /** div u at the reduced point of every active cell with reduced
     * volumetric integration, indexed by active_cell_index; empty with
     * full integration. */
    std::vector<double>
    reduced_dilatation(const Vector<double> &u) const;

    /** The stress (2) from the strain at a point of the active cell @p c,
     * with the cell's reduced dilatation from reduced_dilatation() (none
     * if that is empty). */
    SymmetricTensor<2, dim>
    stress_from_strain(const SymmetricTensor<2, dim> &strain,
                       const std::vector<double>     &dilatation,
                       const unsigned int             c) const
    {
      auto s = material.stress(strain);
      if (!dilatation.empty())
        s += material.lambda() * (dilatation[c] - trace(strain)) *
             unit_symmetric_tensor<dim>();
      return s;
    }

    /** Plane-strain stress sigma(u) (2) at every quadrature point of every
     * active cell, indexed [active_cell_index][q]. */
    std::vector<std::vector<SymmetricTensor<2, dim>>>
    stress_at_quadrature_points(const Vector<double> &u) const;

    /** Elastic energy 1/2 a_a(u, u) (11). */
    double
    strain_energy(const Vector<double> &u) const;

    /** Displacement, stress and von Mises stress at a point of the body;
     * throws InputError if the point lies outside the body. */
    PointValues<dim>
    point_values(const Point<dim> &x, const Vector<double> &u) const;

    /** Smallest cell diameter of the mesh. */
    double
    min_cell_diameter() const;

  private:
    void
    read_mesh_file(const std::string &work_directory);

    /** Refuse, naming @p entry of the body's section, a mesh of
     * @p n_cells cells whose unknowns would not fit into the memory this
     * machine has available (checked before the cells are made). */
    void
    check_mesh_size(double n_cells, const std::string &entry) const;

    /** Throw an InputError naming the load expression (Body force or
     * Neumann) that is not finite, and where (after assembly found a
     * non-finite load). */
    [[noreturn]] void
    throw_non_finite_load() const;

    /** Refuse Dirichlet expressions that are not finite on their faces. */
    void
    check_dirichlet_values() const;

    void
    check_boundary_ids() const;

    /** The lambda div u div v term of a_a (11) on one Gauss point per cell
     * (see reduced_volumetric_integration()), through @p copier. */
    void
    assemble_reduced_volumetric_term(
      const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &copier);

    /** The sparsity pattern and matrix (serial, or distributed over the
     * process group), where the body is solved. */
    void
    setup_matrix();

    /** On a distributed mesh: replace the constraints of the locally
     * relevant dofs by those of all dofs, each from its owner. */
    void
    complete_constraints();

    /** Subdomain ids of the cells: the process group's ranks, the cells
     * split in z-order (quadrilaterals) or in the order of the active
     * cells (triangles). Called after every change of the mesh. */
    void
    partition_between_group();

    /** The solution vector of the distributed solve, whole on every
     * process of the group. */
    void
    gather_in_group(const TrilinosWrappers::MPI::Vector &owned,
                    Vector<double>                      &whole) const;

    const BodyParameters          parameters;
    const Material                material;
    const BoundaryConditions<dim> boundary_conditions;

    std::unique_ptr<Triangulation<dim>>  triangulation;
    std::unique_ptr<FiniteElement<dim>>  fe;
    std::unique_ptr<Mapping<dim>>        mapping;
    std::unique_ptr<Quadrature<dim>>     cell_quadrature;
    std::unique_ptr<Quadrature<dim - 1>> face_quadrature;
    // One Gauss point for the volumetric term, or null (full integration).
    std::unique_ptr<Quadrature<dim>> volumetric_quadrature;
    DoFHandler<dim>                  dof_handler;

    AffineConstraints<double> constraints;
    SparsityPattern           sparsity_pattern;
    SparseMatrix<double>      stiffness_matrix;
    Vector<double>            load_vector;
    Vector<double>            solution;

    // Direct solver: factorized once per mesh.
    SparseDirectUMFPACK direct_solver;
    // Iterative alternative: CG with algebraic multigrid.
    TrilinosWrappers::SparseMatrix    trilinos_matrix;
    TrilinosWrappers::PreconditionAMG amg_preconditioner;
    bool                              is_factorized    = false;
    bool                              solved_here      = true;
    bool                              mesh_distributed = false;

    // Process groups: the world ranks solving this body, their
    // communicator, and the matrix, load and direct solver distributed over
    // them.
    std::vector<unsigned int>                               process_group{0};
    MPI_Comm                                                group_communicator;
    TrilinosWrappers::SparseMatrix                          distributed_matrix;
    TrilinosWrappers::MPI::Vector                           distributed_load;
    mutable SolverControl                                   direct_control;
    mutable std::unique_ptr<TrilinosWrappers::SolverDirect> distributed_direct;
    // First dof and number of dofs of every process of the group (its
    // ranges are contiguous), for gathering the solution.
    std::vector<int> group_range_starts, group_range_sizes;
  };
} // namespace ddcontact

#endif
