#ifndef ddcontact_body_mesh_h
#define ddcontact_body_mesh_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <ddcontact/body/body_parameters.h>
#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/circular_boundaries.h>
#include <ddcontact/body/parallel_parameters.h>
#include <ddcontact/parameter_tools.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealii::parallel::distributed
{
  template <int dim, int spacedim>
  class Triangulation;
} // namespace dealii::parallel::distributed

namespace ddcontact
{
  using namespace dealii;

  /**
   * The mesh of one body Omega_a: the kind of triangulation, its initial
   * cells (a subdivided rectangle or a Gmsh file; a .geo is meshed by the
   * gmsh program), the checks of its size and boundary ids, and its
   * partition between the processes that solve the body.
   *
   * Three kinds of triangulation, decided here and nowhere else:
   *  - serial (MPI_COMM_SELF): every process that holds the body holds it
   *    whole;
   *  - shared (parallel::shared::Triangulation on a communicator of several
   *    processes): every process keeps every cell, and the subdomain ids
   *    say which process of the body's group assembles which cell; the
   *    partition follows every refinement (post-refinement signal);
   *  - distributed (parallel::distributed::Triangulation, p4est,
   *    quadrilaterals only): each process keeps its own cells and a ghost
   *    layer, and p4est repartitions after every refinement.
   */
  template <int dim>
  class BodyMesh
  {
  public:
    /** A serial mesh lives on MPI_COMM_SELF, the other kinds on
     * MPI_COMM_WORLD. */
    BodyMesh(const BodyParameters &parameters, const MeshKind kind);

    ~BodyMesh();

    BodyMesh(const BodyMesh &) = delete;
    BodyMesh &
    operator=(const BodyMesh &) = delete;

    /**
     * Create the initial mesh: the rectangle with boundary ids 0 left,
     * 1 right, 2 bottom, 3 top, or the Gmsh file (a .geo is meshed into
     * @p work_directory); then the initial and the box refinement. Each
     * step is refused, naming its entry, if the mesh would not fit into
     * the available memory, before its cells are made. A Gmsh mesh is
     * validated as read: no cell of zero or negative area, no coincident
     * but separate vertices (merged if Mesh/Merge coincident vertices),
     * and, when it has several separate pieces, every piece held in x
     * and y by a Dirichlet condition. Finally every boundary id named in
     * @p conditions must exist in the mesh.
     */
    void
    make(const BoundaryConditions<dim> &conditions,
         const std::string             &work_directory);

    /**
     * The processes (world ranks, ascending) that solve the body and their
     * communicator (MPI_COMM_NULL on the others; the mesh takes it over and
     * frees it). A shared mesh is partitioned between the ranks again;
     * returns whether the group changed.
     *
     * A p4est mesh stays on all processes (every one of them can then
     * evaluate the body at contact points and import its traces), but its
     * cells go to the group alone: p4est cuts the forest's z-order into
     * consecutive pieces for the ranks of the mesh's communicator in turn,
     * so the mesh moves onto a communicator that the group leads (made
     * again there, once, when the group is not its first ranks), and cell
     * weights (group_weight()) leave the other processes no cell, now and
     * after every refinement. The ElasticBody reinitializes its dofs on
     * the new mesh, then calls release_previous_mesh().
     */
    bool
    set_process_group(const std::vector<unsigned int> &ranks,
                      const MPI_Comm                   group_communicator);

    /** Free the mesh replaced by set_process_group() (its DoFHandler has
     * moved to the new one). */
    void
    release_previous_mesh();

    const std::vector<unsigned int> &
    process_group() const
    {
      return group;
    }

    MPI_Comm
    group_communicator() const
    {
      return group_comm;
    }

    Triangulation<dim> &
    triangulation()
    {
      return *tria;
    }

    const Triangulation<dim> &
    triangulation() const
    {
      return *tria;
    }

    /** The mapping from the reference cells (linear). */
    const Mapping<dim> &
    mapping() const
    {
      return *cell_mapping;
    }

    bool
    is_simplex() const;

    /** Whether the mesh is a p4est forest. */
    bool
    is_distributed() const
    {
      return distributed;
    }

    /** Whether the mesh is a shared triangulation partitioned between
     * processes. */
    bool
    is_shared() const;

    /** Whether this process computes the cell's contributions to cell
     * sums and per-cell fields: every cell on a serial or shared mesh, the
     * owned cells on a distributed one. */
    template <typename CellIterator>
    bool
    computes(const CellIterator &cell) const
    {
      return !distributed || cell->is_locally_owned();
    }

    /** @p value summed over the processes of a distributed mesh (the
     * value itself on the other kinds). */
    double
    sum(const double value) const;

    /** The smallest cell diameter (all processes' cells). */
    double
    min_cell_diameter() const;

    /** The smallest and largest value of x . @p direction over the
     * vertices of the mesh (all processes' cells). */
    std::pair<double, double>
    extent_along(const Tensor<1, dim> &direction) const;

    /** The boundary ids of a Gmsh mesh found to be circular arcs, which
     * refinement keeps round (CircularBoundaries), one line each. */
    std::vector<std::string>
    circular_boundaries() const
    {
      return circles.describe();
    }

    /** Before refining the flagged cells: refuse, naming @p step (e.g.
     * "adaptation step 3"), a refinement whose unknowns would not fit into
     * the memory available (the estimate of the mesh's making). */
    void
    check_refinement_size(const std::string &step) const;

    /** How many coincident vertices of the file were merged into others
     * (Mesh/Merge coincident vertices); 0 if none or not a file. */
    unsigned int
    n_merged_vertices() const
    {
      return n_merged;
    }

  private:
    void
    make_rectangle();

    void
    read_file(const std::string &work_directory);

    /** The refinement box: cells touching it are refined, Box refinement
     * times. */
    void
    refine_box();

    /** Refuse, naming @p entry (its whole path), a mesh of
     * @p n_cells cells whose unknowns would not fit into the memory this
     * machine has available: an InputError, or for the refinement of a
     * mesh of @p n_cells_now > 0 cells (which needs only the growth) an
     * OutOfMemoryError. */
    void
    check_size(double             n_cells,
               const std::string &entry,
               double             n_cells_now = 0) const;

    void
    check_boundary_ids(const BoundaryConditions<dim> &conditions) const;

    /** Refuse a coarse cell whose Jacobian is zero or negative at a
     * corner (a degenerate, folded or inverted cell), naming the file and
     * the corner, before it is blamed on the material. */
    void
    check_cell_areas() const;

    /** Vertices of different coarse cells closer than 1e-10 times the
     * smallest cell diameter: merged (Mesh/Merge coincident vertices),
     * or refused naming their count and one location. */
    void
    merge_coincident_vertices();

    /**
     * The connected pieces of the coarse mesh, cells joined through a
     * shared face (cells meeting at a vertex only are separate pieces:
     * a vertex holds a translation but no rotation). A mesh of one piece
     * is left to RigidBodyModes. Of several, each must be held by
     * Dirichlet conditions in x and y: a piece with no condition at all is
     * held by nothing, and a piece held only by contact (or in one
     * component) floats, while the rigid modes are those of one body.
     */
    void
    check_pieces(const BoundaryConditions<dim> &conditions) const;

    /** Subdomain ids of the cells: the group's ranks, the cells split in
     * z-order (quadrilaterals) or in the order of the active cells
     * (triangles). */
    void
    partition_between_group();

    /** The mesh as the p4est forest it is (distributed meshes only). */
    parallel::distributed::Triangulation<dim, dim> &
    forest() const;

    /** A p4est mesh on a communicator that @p ranks lead, with the cell
     * weights that keep every cell on them (set_process_group()). */
    void
    place_forest_on_group(const std::vector<unsigned int> &ranks);

    /**
     * The weight of the next quadrant p4est asks for when it partitions a
     * forest whose cells belong to the first k = group.size() of its P
     * ranks. With weights summing to P, p4est gives rank r the quadrants
     * whose preceding weights sum to r (the cut of rank r is r P / P).
     * The quadrants are cut into k consecutive chunks of equal counts: the
     * last quadrant of each chunk but the last weighs 1, the very last
     * quadrant P - k + 1, all others 0. Chunk j's quadrants are then
     * preceded by weight j, so they go to rank j, and ranks k to P - 1 get
     * none. deal.II asks once per local quadrant, in p4est's order; the
     * count of calls gives the quadrant's global index.
     */
    unsigned int
    group_weight();

    const BodyParameters               &parameters;
    CircularBoundaries                  circles;
    boost::signals2::connection         snapping; // circles.snap()
    const bool                          distributed;
    std::unique_ptr<Triangulation<dim>> tria;
    std::unique_ptr<const Mapping<dim>> cell_mapping;
    // The file named in messages: the .geo the user gave, not the .msh
    // gmsh made of it.
    std::string               file_name;
    unsigned int              n_merged = 0;
    std::vector<unsigned int> group{0};
    MPI_Comm                  group_comm = MPI_COMM_NULL;
    bool                      placed     = false; // set_process_group()

    // What make() was given, for making a p4est mesh again on its
    // group's communicator.
    const BoundaryConditions<dim> *made_with = nullptr;
    std::string                    made_in;
    // A p4est mesh's communicator when it is not the world's (owned, freed
    // after the mesh), and the mesh it replaced until the dofs moved.
    MPI_Comm                            mesh_comm = MPI_COMM_NULL;
    std::unique_ptr<Triangulation<dim>> previous_tria;
    MPI_Comm                            previous_comm = MPI_COMM_NULL;
    boost::signals2::connection         weighting; // group_weight()
    std::uint64_t                       weight_calls = 0;
  };
} // namespace ddcontact

#endif
