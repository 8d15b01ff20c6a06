#ifndef ddcontact_elastic_body_h
#define ddcontact_elastic_body_h

#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <deal.II/meshworker/copy_data.h>

#include <ddcontact/body/body_linear_solver.h>
#include <ddcontact/body/body_mesh.h>
#include <ddcontact/body/body_parameters.h>
#include <ddcontact/body/body_stresses.h>
#include <ddcontact/body/body_vector.h>
#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/geometry.h>
#include <ddcontact/body/material_law.h>
#include <ddcontact/body/parallel_parameters.h>
#include <ddcontact/body/quadrature_point_history.h>
#include <ddcontact/body/rigid_body_modes.h>
#include <ddcontact/body/section_kinematics.h>
#include <ddcontact/parameter_tools.h>

#include <functional>
#include <memory>
#include <string>

namespace ddcontact
{
  using namespace dealii;

  /** The residual norms of ElasticBody::solve_nonlinear(), one per
   * assembly (the last one converged; a step halved by the backtracking
   * adds one). */
  struct BodyNewtonReport
  {
    std::vector<double> residuals;
    /** What the residuals are measured against: the norm of the load l_a +
     * load, or if larger of the forces of the start, K_T u on the free
     * dofs (a body driven by its Dirichlet values, or unloaded). */
    double load_norm = 0;

    unsigned int
    n_steps() const
    {
      return residuals.empty() ? 0 : residuals.size() - 1;
    }
  };

  /**
   * One linear elastic body Omega_a in plane strain: its finite element
   * space on its mesh (BodyMesh: quadrilaterals with hanging nodes, or
   * triangles), its constraints (hanging nodes merged with the Dirichlet
   * data (5)), and the assembly of the bilinear form a_a of (11) and the
   * load l_a of (12) into its linear solver (BodyLinearSolver), which is
   * factorized once per mesh: the domain decomposition solves the body
   * problem (20) hundreds of times with a new contact load. solve() is
   * const and may be called for several bodies at once from different
   * threads. Stresses, energy and point values of a displacement are
   * computed by BodyStresses (stresses()).
   *
   * On a mesh shared or distributed between processes (see BodyMesh) the
   * processes of the body's group assemble their cells into a matrix
   * distributed over the group and solve it together. The body's vectors
   * (BodyVector, reinit_vector()) are whole on every process, so that the
   * DD loop (20)-(21) is the same for every kind of mesh, unless a p4est
   * body's are distributed (distribute_vectors(): owned dofs plus ghosts,
   * for every solver and estimator). On a p4est mesh every process holds
   * the constraints of the entries it stores, each from the dof's owner
   * (share_constraints()).
   */
  template <int dim>
  class ElasticBody
  {
  public:
    /** @p mesh_kind: see BodyMesh and ParallelParameters::mesh_kind(). */
    ElasticBody(const BodyParameters &parameters,
                const Constants      &constants,
                const MeshKind        mesh_kind = MeshKind::serial);

    ElasticBody(const ElasticBody &) = delete;
    ElasticBody &
    operator=(const ElasticBody &) = delete;

    /** Create the initial mesh (BodyMesh::make(); a .geo file is meshed
     * into @p work_directory). */
    void
    make_mesh(const std::string &work_directory = ".");

    /** Distribute dofs, build constraints and, where the body is solved,
     * the sparsity pattern. Call again after the mesh has been refined. */
    void
    setup_system();

    /** Assemble the stiffness matrix and the load vector of body force and
     * Neumann tractions (12), with the Dirichlet data condensed. */
    void
    assemble_system();

    /** Factorize (direct) or build the AMG preconditioner (cg-amg). */
    void
    factorize();

    /** The load parameter t of the boundary data (Loading/Steps): the
     * Dirichlet values and the loads of @p t, assembled and factorized
     * where the body is solved (the matrix is the same; the constraints'
     * inhomogeneities enter the load through the assembly). Collective
     * over the body's group, as assemble_system(). */
    void
    set_load_time(double t);

    /** setup_system(), assemble_system() and factorize() in a row. */
    void
    setup_and_factorize();

    /**
     * Refine (and coarsen) the cells flagged on the triangulation, carry
     * the body's current solution over to the new mesh (SolutionTransfer, or
     * RefinementTransfer on triangles; the transferred field is made
     * conforming again by the new constraints), and rebuild the system and its
     * factorization: the adaptive step of Fig. 2 transfers the current iterate
     * to the new mesh.
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
     * their communicator (MPI_COMM_NULL on the other processes; the mesh
     * takes it over and frees it). Needs a mesh on MPI_COMM_WORLD;
     * repartitions the cells between the group (collective over the world)
     * and distributes the dofs again. Call set_solved_here() after.
     */
    void
    set_process_group(const std::vector<unsigned int> &ranks,
                      const MPI_Comm                   group_communicator);

    /** Whether this process solves the body together with others. */
    bool
    is_solved_distributed() const
    {
      return solved_here && mesh.process_group().size() > 1;
    }

    /**
     * Solve a_a(u, v) = l_a(v) + load(v) for all v: @p load is an
     * additional right-hand side (e.g. the contact traction of (20))
     * assembled with get_constraints().distribute_local_to_global() and
     * may be empty (size 0) for none. Constraints are distributed in @p u.
     */
    void
    solve(const BodyVector &load, BodyVector &u) const;

    /**
     * Solve a_a(u, v) = load(v) with homogeneous data: no body force or
     * traction of l_a, zero Dirichlet values (the hanging-node constraints
     * are distributed without inhomogeneities). The response of the body to
     * a contact load alone, for the interface operator of DDNewtonSolver.
     */
    void
    solve_homogeneous(const BodyVector &load, BodyVector &u) const;

    /**
     * The body problem of a nonlinear material law: internal force
     * F(u) = l_a + @p load, F(u)(v) = int sigma(eps(u)) : eps(v) dV, by
     * Newton's method from @p u (a warm start; its Dirichlet values are
     * set first), with the law's consistent tangent assembled and
     * factorized at every step. Stops when the residual is Solver/Newton
     * tolerance times the load's norm; the law's trial state
     * (get_material_state()) is then that of @p u, and the consistent
     * tangent at @p u is left factorized: solve_homogeneous() then gives
     * the linearized response to a load (dd-newton's interface operator at
     * this linearization). A linear law converges in one step to solve()'s
     * answer. One process per body (for now); throws NotConvergedError or
     * DivergenceError naming the body if the loop does not converge.
     */
    BodyNewtonReport
    solve_nonlinear(const BodyVector &load, BodyVector &u);

    /**
     * A nonlinear law's linearization at @p u, for a solver that assembles
     * the bodies itself (MonolithicContactSolver): the consistent tangent
     * K_T into the body's matrix (get_stiffness_matrix()) and the residual
     * l_a - F(u) into its load vector (get_load_vector()), both condensed
     * with the constraints without their inhomogeneities (u carries the
     * Dirichlet values); the law's state of @p u becomes the trial state.
     * The factorization is stale afterwards. One process per body.
     */
    void
    linearize_at(const BodyVector &u);

    /** Solve with no extra load into the body's own solution vector. */
    void
    solve();

    /** The stresses of @p u, a vector of this body's dofs. */
    BodyStresses<dim>
    stresses(const BodyVector &u) const
    {
      return BodyStresses<dim>(*this, u);
    }

    /** The stresses of the body's own solution. */
    BodyStresses<dim>
    stresses() const
    {
      return BodyStresses<dim>(*this, solution);
    }

    const BodyMesh<dim> &
    get_mesh() const
    {
      return mesh;
    }

    /**
     * The mesh may be changed (refined) through this reference, e.g. by
     * tests and by the adaptive driver; call setup_and_factorize() or
     * refine_and_transfer() after.
     */
    Triangulation<dim> &
    get_triangulation()
    {
      return mesh.triangulation();
    }

    const Triangulation<dim> &
    get_triangulation() const
    {
      return mesh.triangulation();
    }

    /** Whether the mesh is a p4est forest (BodyMesh). */
    bool
    is_mesh_distributed() const
    {
      return mesh.is_distributed();
    }

    /** Whether this process computes the cell's contributions to cell sums
     * and per-cell fields (BodyMesh::computes()). */
    template <typename CellIterator>
    bool
    computes(const CellIterator &cell) const
    {
      return mesh.computes(cell);
    }

    /** The number of active cells of the whole mesh. */
    unsigned int
    n_active_cells() const
    {
      return mesh.triangulation().n_global_active_cells();
    }

    bool
    is_simplex() const
    {
      return mesh.is_simplex();
    }

    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    const Mapping<dim> &
    get_mapping() const
    {
      return mesh.mapping();
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

    /**
     * The one-point rule of the volumetric term lambda div u div v of a_a
     * (11) ("Element/Volumetric integration = reduced", Q1 only): selective
     * reduced integration, which keeps Q1 free of volumetric locking as
     * nu -> 1/2. Null with full integration.
     */
    const Quadrature<dim> *
    get_volumetric_quadrature() const
    {
      return volumetric_quadrature.get();
    }

    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

    /** The hanging-node constraints alone (no Dirichlet data), of all
     * dofs on every process: the conforming test functions of the reaction
     * forces (ReactionForces), which must not lose the share of a hanging
     * node on a Dirichlet boundary. */
    const AffineConstraints<double> &
    get_hanging_node_constraints() const
    {
      return hanging_node_constraints;
    }

    /**
     * r_i = a_a(u, phi_i) - l_a(phi_i) for every dof i, and the load
     * l_a(phi_i) alone, with the cell matrices and loads of
     * assemble_system() and no constraints applied: at a Dirichlet dof, r
     * is the force the support exerts (plus the share of a hanging node,
     * see get_hanging_node_constraints()). On a mesh partitioned between
     * processes, the sums of this process's cells only.
     */
    void
    unconstrained_residual(const BodyVector &u,
                           BodyVector       &r,
                           BodyVector       &load) const;

    /** The stiffness plus @p springs, factorized over the process group
     * of a body solved by one (is_solved_distributed()); collective. */
    std::unique_ptr<SpringFactorization>
    factorize_with_springs(const std::vector<DofSprings> &springs) const
    {
      return linear_solver->factorize_with_springs(springs);
    }

    /** The assembled stiffness matrix (on a body solved here by one
     * process). */
    const SparseMatrix<double> &
    get_stiffness_matrix() const
    {
      return linear_solver->matrix();
    }

    /** The condensed load vector of body force and tractions (12) (on a
     * body solved here by one process). */
    const Vector<double> &
    get_load_vector() const
    {
      return linear_solver->load_vector();
    }

    /** The rigid motions the Dirichlet conditions (5) leave free: none
     * for a held body; for a floating one (held only by contact) they are
     * clamped at a few components (RigidBodyModes::fixing_dofs()), which
     * makes the stiffness regular. */
    const RigidBodyModes<dim> &
    get_rigid_modes() const
    {
      return rigid_modes;
    }

    bool
    is_floating() const
    {
      return rigid_modes.size() > 0;
    }

    /** The work of the body's data (body force and tractions of (12)) on
     * every free rigid mode: the body is in equilibrium when the contact
     * load does the opposite work on each. */
    const std::vector<double> &
    get_mode_loads() const
    {
      return mode_loads;
    }

    /** The body's material law (Body X/Material/Law). */
    const MaterialLaw &
    get_material_law() const
    {
      return *law;
    }

    /** The elastic constants of the law, for the scales that need them
     * (penalty, Robin preconditioner, compliance, BEM). */
    const ElasticConstants &
    get_elastic_constants() const
    {
      return law->elastic_constants();
    }

    /** The law's quadrature-point state (empty for a law without one):
     * committed per load step (ContactSolver::start_load_step()), restored
     * for a second solve of a step, carried through refinement. */
    const QuadraturePointHistory<dim> &
    get_material_state() const
    {
      return material_state;
    }

    QuadraturePointHistory<dim> &
    get_material_state()
    {
      return material_state;
    }

    /** The strains of the body's section (plane strain or axisymmetric). */
    SectionKinematics
    get_kinematics() const;

    /** Plane strain, or an axisymmetric section (x = r, y = z). */
    Geometry
    get_geometry() const
    {
      return parameters.geometry;
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

    BodyVector &
    get_solution()
    {
      return solution;
    }

    const BodyVector &
    get_solution() const
    {
      return solution;
    }

    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    /** Make @p v a zero vector of this body's dofs, with the body's
     * layout (see BodyVector). */
    void
    reinit_vector(BodyVector &v) const
    {
      v.reinit(partitioner);
    }

    /**
     * On a distributed (p4est) mesh: from now on every vector of the body
     * holds only the dofs this process owns, plus as ghosts its locally
     * relevant dofs and @p traces (sorted; the dofs the contact
     * evaluations read, ContactProblem::trace_dofs()), instead of all
     * dofs. The solution keeps its values. Collective over the mesh's
     * processes. After a refinement (setup_system()) the vectors stay
     * distributed, with the locally relevant dofs as ghosts, until this is
     * called with the new traces.
     */
    void
    distribute_vectors(const std::vector<types::global_dof_index> &traces);

    /**
     * The constrained entries of @p u from its other entries (without the
     * inhomogeneities with @p homogeneous), on every dof @p u holds, with
     * the operations of AffineConstraints::distribute() in its order (the
     * same numbers on a whole vector). A distributed @p u must have its
     * ghosts imported; then no second exchange is needed: a ghost's
     * masters are on its cell, or are traces too (the load dofs of a
     * contact point). deal.II's distribute() treats every
     * LinearAlgebra::distributed::Vector as parallel and copies it whole
     * with an index set of its dofs at every call (the paper's DD calls it
     * every iteration).
     */
    void
    distribute_constraints(BodyVector &u, bool homogeneous = false) const;

    /** Whether the body's vectors hold only this process's part
     * (distribute_vectors()). */
    bool
    has_distributed_vectors() const
    {
      return distributed_vectors;
    }

    /** Whether the body is on a p4est mesh whose cells belong to a group
     * smaller than the mesh's processes (BodyMesh::set_process_group()):
     * the others hold its vectors' traces only, and import them after
     * every set of solves, collectively over the mesh's processes. */
    bool
    is_solved_by_part_of_mesh() const;

  private:
    /** The cell matrices of a_a (11) and the loads of l_a (12) of this
     * process's cells, each passed to @p copier (one thread at a time);
     * with @p load_only only the cells that carry a load or a Dirichlet
     * inhomogeneity (loaded_cell()), the others handed over without dofs.
     * With @p linearization the law's linearization at that displacement
     * instead: the consistent tangent matrices and the loads minus the
     * internal forces, l_a(phi_i) - F(u)(phi_i), and the law's new states
     * into @p new_states (by active cell index) if given. */
    void
    assemble_cells(
      const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &copier,
      bool                              load_only     = false,
      const BodyVector                 *linearization = nullptr,
      std::vector<std::vector<double>> *new_states    = nullptr) const;

    /** The lambda div u div v term of a_a (11) on one Gauss point per cell
     * (see get_volumetric_quadrature()), through @p copier; @p load_only
     * as in assemble_cells(). */
    void
    assemble_reduced_volumetric_term(
      const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &copier,
      bool load_only = false) const;

    /** Whether @p cell adds to the load vector: a body force, a Neumann
     * face, or a dof whose constraint is inhomogeneous (its matrix column
     * moves the Dirichlet values into the load). */
    bool
    loaded_cell(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /** The load vector alone, for a new load time on the same matrix
     * (set_load_time()): the cells of loaded_cell() only. */
    void
    assemble_load();

    /** assemble_system(), or with @p load_only assemble_load(); then the
     * loads' work on the rigid modes of a floating body, a non-finite load
     * named, the solver's entries exchanged. */
    void
    assemble(bool load_only);

    /** A new linear solver with its sparsity pattern, where the body is
     * solved. */
    void
    setup_matrix();

    /**
     * On a distributed mesh: replace the lines of @p to_complete by each
     * dof's line as the process owning the dof computed it, so that every
     * process computes a constrained entry it stores as its owner does.
     * With @p layout (distributed vectors) the lines of the entries a
     * process stores, its own dofs and @p layout's ghosts: each owner
     * sends the lines of its dofs that others import, O(partition
     * boundary + traces). Without, the lines of all dofs on every process
     * (whole vectors).
     */
    void
    share_constraints(AffineConstraints<double>         &to_complete,
                      const Utilities::MPI::Partitioner *layout) const;

    /** The states @p new_states (by active cell index, of assemble_cells())
     * become the trial states of the cells this process computes. */
    void
    set_trial_states(const std::vector<std::vector<double>> &new_states);

    /** The ghosts of a distributed @p u after a solve: imported over the
     * group that solves the body (group_layout), or over all the mesh's
     * processes when they are the group. The traces among the ghosts
     * that the group does not store are imported after the solves, by
     * BodyDistribution. */
    void
    import_group_ghosts(BodyVector &u) const;

    /** The hanging-node and Dirichlet constraints (5) and the fixed
     * components of the rigid modes, completed on a distributed mesh for
     * the stored entries. */
    void
    make_constraints();

    /** The free rigid modes (rigid_modes) and their fixed components,
     * added to the open @p constraints. */
    void
    setup_rigid_modes();

    const BodyParameters                     parameters;
    const std::shared_ptr<const MaterialLaw> law;
    QuadraturePointHistory<dim>              material_state;
    const BoundaryConditions<dim>            boundary_conditions;

    // The mesh first: the dofs and the solver (which uses the group's
    // communicator, freed by the mesh) are destroyed before it.
    BodyMesh<dim>                        mesh;
    std::unique_ptr<FiniteElement<dim>>  fe;
    std::unique_ptr<Quadrature<dim>>     cell_quadrature;
    std::unique_ptr<Quadrature<dim - 1>> face_quadrature;
    // One Gauss point for the volumetric term, or null (full integration).
    std::unique_ptr<Quadrature<dim>> volumetric_quadrature;
    DoFHandler<dim>                  dof_handler;

    AffineConstraints<double> constraints;
    AffineConstraints<double> hanging_node_constraints;
    BodyVector                solution;
    // The layout of the body's vectors (reinit_vector()).
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
    // The owned and locally relevant dofs over the group's communicator,
    // on a group smaller than the mesh's processes (import_group_ghosts()).
    std::shared_ptr<const Utilities::MPI::Partitioner> group_layout;
    bool                distributed_vectors = false;
    RigidBodyModes<dim> rigid_modes;
    std::vector<double> mode_loads;

    std::unique_ptr<BodyLinearSolver<dim>> linear_solver;
    bool                                   is_factorized = false;
    bool                                   solved_here   = true;
  };
} // namespace ddcontact

#endif
