#ifndef ddcontact_boundary_element_solver_h
#define ddcontact_boundary_element_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/bem/boundary_mesh.h>
#include <ddcontact/bem/collocation_system.h>
#include <ddcontact/bem/kelvin_solution.h>
#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/material_law.h>

#include <array>
#include <memory>
#include <mutex>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Direct boundary element method for 2D plane-strain elastostatics on
   * the boundary of one FEM body, the reference solution of the FEM-BEM
   * estimator (22)-(27):
   *  - one straight element per active boundary face (25), one node per
   *    boundary vertex, linear shape functions = the trace of the Q1 (or
   *    P1) basis (26); for a body of degree 2 quadratic shape functions with
   *    one more node at each face midpoint = the trace of the Q2 (or P2)
   *    basis, which keeps the BEM a priori more accurate than the FEM, as
   *    (22)-(23) require; in 2D no hanging node lies on the boundary of a
   *    body;
   *  - Kelvin fundamental solution, nodal collocation, element-end
   *    tractions (they may jump at corners and at Dirichlet/Neumann
   *    junctions), one extra collocation row where the same displacement
   *    component is prescribed on both sides of a corner;
   *  - lengths scaled by the body's diameter and tractions by mu before
   *    assembly (the degenerate scale of the log kernel);
   *  - the dense collocation system solved by a CollocationSystem: LU for
   *    small systems, GMRES preconditioned by a hierarchical (HODLR)
   *    factorization for large ones; set up once per boundary mesh by setup()
   * (refinement that leaves the boundary alone keeps it), reused by solve() for
   * any contact load;
   *  - interior stresses by the Somigliana stress identity with adaptive
   *    subdivision near the boundary, in parallel over points.
   * Boundary data are those of the body: Dirichlet (5) by id and component,
   * Neumann tractions (6) by id, ids not listed are traction free, and the
   * contact ids carry the traction given to solve().
   *
   * The boundary mesh, its unknowns and the boundary solution are a
   * BoundaryMesh, the element integrals are in BoundaryIntegration, and
   * the hierarchical evaluation at many points is FarFieldStresses; this
   * class assembles the collocation system, factorizes and solves it.
   */
  class BoundaryElementSolver
  {
  public:
    BoundaryElementSolver(const ElasticConstants      &material,
                          const BoundaryConditions<2> &boundary_conditions);

    /** Build the boundary mesh from the active boundary faces of the mesh
     * of @p dof_handler, assemble the system and prepare its solver. Call
     * again after every mesh change; if the boundary mesh did not change,
     * the system and its factorization are kept. */
    void
    setup(const DoFHandler<2> &dof_handler, const Mapping<2> &mapping);

    /** Solve for the unknown boundary displacements and tractions with the
     * body's own data plus @p contact on the contact ids. */
    void
    solve(const BoundaryTractionSamples &contact = {});

    /** Interior stresses (Somigliana identity) at arbitrary points inside
     * the body, physical units. */
    std::vector<SymmetricTensor<2, 2>>
    stress_at_points(const std::vector<Point<2>> &points) const;

    /**
     * The same on every process of @p communicator (each holding the same
     * body and boundary solution), with the work shared and the result
     * independent of the number of processes: where every point is
     * integrated on its own, each process takes a contiguous share and the
     * shares are summed exactly (zeros elsewhere); the @p hierarchical
     * evaluation (see hierarchical()), whose boxes depend on the whole
     * set, runs whole on every process (its cost is about linear).
     */
    std::vector<SymmetricTensor<2, 2>>
    stress_at_points(const std::vector<Point<2>> &points,
                     const MPI_Comm               communicator,
                     bool                         hierarchical) const;

    /** Whether an evaluation at @p n_points points (of the whole mesh, on
     * any number of processes) uses the hierarchical evaluation. */
    bool
    hierarchical(std::size_t n_points) const;

    /** sigma_B at the quadrature points of every active cell, indexed
     * [active_cell_index][q], ready for the estimator (27). With a
     * communicator of several processes (each holding the same body and
     * boundary solution) every process evaluates a contiguous share of the
     * cells and all receive all values. On a distributed mesh (p4est) each
     * process evaluates its own cells only. */
    std::vector<std::vector<SymmetricTensor<2, 2>>>
    stress_at_quadrature_points(
      const DoFHandler<2> &dof_handler,
      const Mapping<2>    &mapping,
      const Quadrature<2> &quadrature,
      const MPI_Comm       communicator = MPI_COMM_SELF) const;

    /**
     * sigma_B at the quadrature points of every active cell as the
     * estimator needs it, at a fraction of the cost: the Somigliana
     * identity is evaluated at the support points of the body's scalar
     * element (Q_p or P_p; shared by neighbouring cells, about 1/(p+1)^2 of
     * the quadrature points per cell for p = 1) and interpolated to the
     * quadrature points, except in the cells that touch the boundary,
     * where the identity is singular at the support points and is
     * evaluated at the quadrature points themselves. The interpolation
     * error is O(h^(p+1)), an order above the FEM stress error O(h^p) that
     * the estimator measures. A mesh that every process of
     * @p communicator holds whole (not distributed); the points are shared
     * as stress_at_points() shares them, and the result does not depend on
     * the number of processes.
     */
    std::vector<std::vector<SymmetricTensor<2, 2>>>
    interpolated_stress_at_quadrature_points(
      const DoFHandler<2> &dof_handler,
      const Mapping<2>    &mapping,
      const Quadrature<2> &quadrature,
      const MPI_Comm       communicator = MPI_COMM_SELF) const;

    /** Number of points at which the last interior evaluation computed
     * the Somigliana identity. */
    std::size_t
    n_interior_points() const
    {
      return interior_points;
    }

    unsigned int
    n_nodes() const;

    unsigned int
    n_elements() const;

    /** Size of the dense system (the BEM unknowns of Fig. 10), without the
     * rigid-mode multipliers of a floating body. */
    unsigned int
    n_unknowns() const;

    /** Boundary solution: position and displacement of node i. */
    Point<2>
    node_position(unsigned int i) const;

    Tensor<1, 2>
    node_displacement(unsigned int i) const;

    /** Wall seconds of the last setup (assembly, LU) and of the interior
     * evaluations summed since setup. */
    struct Timings
    {
      double assembly      = 0;
      double factorization = 0;
      double solve         = 0;
      double interior      = 0;
      // GMRES iterations of the last solve (0 with the dense LU).
      unsigned int iterations = 0;
    };

    const Timings &
    timings() const;

    /**
     * Evaluate the interior stresses of many points by a hierarchy of
     * boxes: elements well separated from a box act on it through a
     * Chebyshev interpolant of their (smooth) field, accurate to about
     * 1e-8 of it; only the nearby elements are integrated at every point
     * (default true; false integrates every element at every point).
     */
    void
    set_far_field_interpolation(const bool enabled)
    {
      use_far_field_interpolation = enabled;
    }

    /** How to solve the collocation system (default: automatic, by size);
     * takes effect at the next setup(). */
    void
    set_solver_method(const CollocationSystem::Method new_method)
    {
      method = new_method;
      current_signature.clear();
    }

    /** How many times setup() assembled and factorized the system (it
     * does not when the boundary mesh is unchanged). */
    unsigned int
    n_system_setups() const
    {
      return system_setups;
    }

    const CollocationSystem &
    get_collocation_system() const
    {
      return system;
    }

    /** Whether the last setup() chose the dense LU (else GMRES). */
    bool
    uses_dense_lu() const
    {
      return system.uses_dense_lu();
    }

    /** @name Further access, for tests and diagnostics. */
    /** @{ */

    /** Boundary solution: traction at end @p end (0 = start, 1 = end in the
     * direction of travel, body on the left; 2 = midpoint for degree 2) of
     * element @p e, physical units. Tractions are stored per element end
     * (doc/bem-method.md §2.2). */
    Tensor<1, 2>
    element_traction(unsigned int e, unsigned int end) const;

    /** The two vertex nodes of element @p e, ordered so that the body lies
     * on the left of the element (outer boundaries counter-clockwise). */
    std::array<unsigned int, 2>
    element_nodes(unsigned int e) const;

    /** The midpoint node of element @p e (degree 2; invalid for degree 1).
     */
    unsigned int
    element_midpoint_node(unsigned int e) const;

    /** Polynomial degree of the boundary elements, that of the body's FE. */
    unsigned int
    degree() const;

    types::boundary_id
    element_boundary_id(unsigned int e) const;

    /** The FEM degrees of freedom (x, y) at node @p i: the BEM nodal
     * displacement is the trace of the FEM field there (26). */
    std::array<types::global_dof_index, 2>
    node_dof_indices(unsigned int i) const;

    /** Interior displacements (Somigliana identity), physical units. */
    std::vector<Tensor<1, 2>>
    displacement_at_points(const std::vector<Point<2>> &points) const;

    /**
     * The 2x2 diagonal block of the BIE at node @p i as produced by the
     * rigid-body trick (free term c_ij plus the Cauchy principal value on
     * the two adjacent elements, dimensionless; doc/bem-method.md §2.1, §2.3).
     */
    Tensor<2, 2>
    diagonal_block(unsigned int i) const;

    /** Number of extra (off-node) collocation rows at corners with the same
     * displacement component prescribed on both sides (doc/bem-method.md §2.7).
     */
    unsigned int
    n_extra_collocation_rows() const;

    /** Number of rigid-body modes the system was bordered with (3 for a
     * floating body, 0 when the Dirichlet data fix the body; §5.1). */
    unsigned int
    n_rigid_modes() const;

    /** Length scale L_ref (bounding-box diagonal of the boundary) used to
     * nondimensionalise the system (doc/bem-method.md §3.3). */
    double
    length_scale() const;

    /** @} */

  private:
    /** The stresses at @p points, by the hierarchical evaluation or point
     * by point; the hierarchical one builds its boxes from the points of
     * all processes of @p communicator (a collective call there). */
    std::vector<SymmetricTensor<2, 2>>
    evaluate_stress(const std::vector<Point<2>> &points,
                    bool                         hierarchical,
                    MPI_Comm communicator = MPI_COMM_SELF) const;

    void
    assemble_system(FullMatrix<double> &system_matrix);

    std::vector<double>
    boundary_signature() const;

    /** Positions along the boundary of the rows' collocation points and of
     * the columns' unknowns, for the hierarchical solver. */
    std::array<std::vector<double>, 2>
    boundary_order_keys() const;

    void
    project_contact_traction(const BoundaryTractionSamples &contact,
                             Vector<double> &contact_values) const;

    const ElasticConstants      material;
    const BoundaryConditions<2> boundary_conditions;
    // Kernels with mu = 1: tractions and stresses are scaled by mu.
    const KelvinSolution kelvin;

    BoundaryMesh mesh;
    // The 2x2 diagonal block of the BIE at every node, for diagnostics.
    std::vector<Tensor<2, 2>> diagonal_blocks;

    CollocationSystem         system;
    CollocationSystem::Method method = CollocationSystem::Method::automatic;
    // The boundary mesh the system was assembled for (element ends and
    // ids), to recognise an unchanged boundary after refinement.
    std::vector<double> current_signature;
    unsigned int        system_setups = 0;
    // Right-hand side of the body's own Dirichlet and Neumann data, and
    // the G columns of the contact element ends, whose data change with
    // every call of solve().
    Vector<double>     body_rhs;
    FullMatrix<double> contact_matrix;
    bool               is_solved                   = false;
    bool               use_far_field_interpolation = true;
    // Above this many points the hierarchical evaluation pays.
    static constexpr std::size_t far_field_points = 1000;

    // Interior evaluations may run concurrently (const); the mutex sits
    // behind a pointer so that the solver stays movable.
    mutable Timings             timing_data;
    mutable std::size_t         interior_points = 0;
    std::unique_ptr<std::mutex> timing_mutex = std::make_unique<std::mutex>();
  };
} // namespace ddcontact

#endif
