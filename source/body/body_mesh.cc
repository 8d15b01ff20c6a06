#include <deal.II/distributed/p4est_wrappers.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <ddcontact/body/body_mesh.h>
#include <ddcontact/body/circular_boundaries.h>
#include <ddcontact/interruption.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <thread>

namespace ddcontact
{
  template <int dim>
  void
  BodyMesh<dim>::make(const BoundaryConditions<dim> &conditions,
                      const std::string             &work_directory)
  {
    made_with = &conditions;
    made_in   = work_directory;
    tria->clear();
    if (parameters.mesh_type == MeshType::rectangle)
      make_rectangle();
    else
    {
      read_file(work_directory);
      // Circular boundaries of the file stay round under refinement: the
      // new vertices are moved onto their circles after every refinement,
      // wherever it is done.
      circles.find(*tria);
      if (!circles.empty() && !snapping.connected())
        snapping = tria->signals.post_refinement.connect(
          [this]() { circles.snap(*tria); });
    }

    const bool simplex_mesh = tria->all_reference_cells_are_simplex();
    const bool quad_mesh    = tria->all_reference_cells_are_hyper_cube();
    if (is_simplex() && !simplex_mesh)
      throw InputError(parameters.section() +
                       "/Element/Cell type: 'triangle', but the mesh '" +
                       parameters.mesh_file + "' holds other cells");
    if (!is_simplex() && !quad_mesh)
      throw InputError(parameters.section() +
                       "/Element/Cell type: 'quadrilateral', but the mesh '" +
                       parameters.mesh_file +
                       "' holds other cells (recombine it in Gmsh, or choose "
                       "triangle)");

    // A file too large for this machine is blamed on itself, not on
    // Initial refinement = 0.
    if (parameters.mesh_type == MeshType::file)
      check_size(tria->n_global_active_cells(),
                 parameters.section() + "/Mesh/File ('" + file_name + "')");
    if (parameters.initial_refinement > 0)
      check_size(tria->n_global_active_cells() *
                   std::pow(4., parameters.initial_refinement),
                 parameters.section() + "/Mesh/Initial refinement");
    tria->refine_global(parameters.initial_refinement);

    if (!parameters.refinement_box.empty() && parameters.box_refinement > 0)
      refine_box();
    check_boundary_ids(conditions);
    if (parameters.mesh_type == MeshType::file)
      check_pieces(conditions);
  }

  template <int dim>
  void
  BodyMesh<dim>::make_rectangle()
  {
    check_size(double(parameters.subdivisions[0]) * parameters.subdivisions[1],
               parameters.section() + "/Mesh/Subdivisions");
    if (is_simplex())
      GridGenerator::subdivided_hyper_rectangle_with_simplices(
        *tria,
        parameters.subdivisions,
        parameters.corner_1,
        parameters.corner_2);
    else
      GridGenerator::subdivided_hyper_rectangle(*tria,
                                                parameters.subdivisions,
                                                parameters.corner_1,
                                                parameters.corner_2);
    // Ids 0 left, 1 right, 2 bottom, 3 top (deal.II 9.4 cannot colorize
    // the simplex variant, so both are labelled here).
    const double tolerance =
      1e-10 * parameters.corner_1.distance(parameters.corner_2);
    for (const auto &face : tria->active_face_iterators())
      if (face->at_boundary())
      {
        const auto c = face->center();
        if (std::abs(c[0] - parameters.corner_1[0]) < tolerance)
          face->set_boundary_id(0);
        else if (std::abs(c[0] - parameters.corner_2[0]) < tolerance)
          face->set_boundary_id(1);
        else if (std::abs(c[1] - parameters.corner_1[1]) < tolerance)
          face->set_boundary_id(2);
        else
          face->set_boundary_id(3);
      }
  }

  template <int dim>
  void
  BodyMesh<dim>::refine_box()
  {
    const auto      &c = parameters.refinement_box;
    const Point<dim> lo(c[0], c[1]);
    const Point<dim> hi(c[2], c[3]);
    if (parameters.mesh_type == MeshType::rectangle)
    {
      // Before any cell is made: at step k the cells of size h_k that
      // touch the box (clipped to the body) are refined, each into four;
      // a square of the grid holds one quadrilateral or two triangles.
      double       cells = tria->n_global_active_cells();
      const double per_square =
        cells /
        (double(parameters.subdivisions[0]) * parameters.subdivisions[1] *
         std::pow(4., parameters.initial_refinement));
      for (unsigned int k = 0; k < parameters.box_refinement; ++k)
      {
        double flagged = 1;
        for (unsigned int d = 0; d < 2; ++d)
        {
          const double n_across =
            parameters.subdivisions[d] *
            std::pow(2., parameters.initial_refinement + k);
          const double length = parameters.corner_2[d] - parameters.corner_1[d];
          const double width  = std::min(hi[d], parameters.corner_2[d]) -
                               std::max(lo[d], parameters.corner_1[d]);
          flagged *=
            std::min(n_across, std::max(0., width) / length * n_across + 2);
        }
        cells += 3 * per_square * flagged;
      }
      check_size(cells, parameters.section() + "/Mesh/Box refinement");
    }
    for (unsigned int k = 0; k < parameters.box_refinement; ++k)
    {
      unsigned int n_flagged = 0;
      for (const auto &cell : tria->active_cell_iterators())
      {
        // p4est takes the flags of the owned cells.
        if (!computes(cell))
          continue;
        const auto box = cell->bounding_box();
        if (box.get_boundary_points().first[0] <= hi[0] &&
            box.get_boundary_points().second[0] >= lo[0] &&
            box.get_boundary_points().first[1] <= hi[1] &&
            box.get_boundary_points().second[1] >= lo[1])
        {
          cell->set_refine_flag();
          ++n_flagged;
        }
      }
      // Each flagged cell becomes four (the one-irregularity closure adds
      // a few more, within the factor of the estimate).
      check_size(tria->n_global_active_cells() +
                   3. *
                     Utilities::MPI::sum(n_flagged, tria->get_communicator()),
                 parameters.section() + "/Mesh/Box refinement");
      tria->execute_coarsening_and_refinement();
    }
  }

  template <int dim>
  BodyMesh<dim>::BodyMesh(const BodyParameters &parameters, const MeshKind kind)
    : parameters(parameters)
    , distributed(kind == MeshKind::distributed)
  {
    // Mesh smoothing keeps adapted quadrilateral meshes graded. Triangles
    // refine locally without it: deal.II 9.4's vertex-patch smoothing
    // (limit_level_difference_at_vertices, maximum_smoothing) reads a
    // fourth vertex and aborts on them, and the one-irregularity closure
    // of prepare_coarsening_and_refinement() needs no smoothing flag.
    const auto smoothing =
      is_simplex() ? Triangulation<dim>::none
                   : Triangulation<dim>::limit_level_difference_at_vertices;
    AssertThrow(!distributed || !is_simplex(),
                ExcMessage("p4est meshes hold quadrilaterals only"));
    switch (kind)
    {
      case MeshKind::distributed:
        // p4est partitions the cells between all processes (z-order of
        // the forest) and again after every refinement.
        tria = std::make_unique<parallel::distributed::Triangulation<dim>>(
          MPI_COMM_WORLD, smoothing);
        break;
      case MeshKind::shared:
      {
        // Every process keeps every cell (no artificial cells); the
        // subdomain ids say which process of the group assembles a cell.
        auto shared = std::make_unique<parallel::shared::Triangulation<dim>>(
          MPI_COMM_WORLD,
          smoothing,
          false,
          parallel::shared::Triangulation<dim>::partition_custom_signal);
        shared->signals.create.connect([this]() { partition_between_group(); });
        shared->signals.post_refinement.connect([this]()
                                                { partition_between_group(); });
        tria = std::move(shared);
        break;
      }
      case MeshKind::serial:
        tria = std::make_unique<Triangulation<dim>>(smoothing);
        break;
    }

    if (is_simplex())
      cell_mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
    else
      cell_mapping = std::make_unique<MappingQ<dim>>(1);
  }

  template <int dim>
  BodyMesh<dim>::~BodyMesh()
  {
    // The body's solver, which uses the group's communicator, is released
    // before the mesh (ElasticBody declares it after the mesh). The meshes
    // go before their communicators.
    weighting.disconnect();
    tria.reset();
    previous_tria.reset();
    for (MPI_Comm *comm : {&group_comm, &mesh_comm, &previous_comm})
      if (*comm != MPI_COMM_NULL)
        MPI_Comm_free(comm);
  }

  template <int dim>
  bool
  BodyMesh<dim>::is_simplex() const
  {
    return parameters.cell_type == CellType::triangle;
  }

  template <int dim>
  bool
  BodyMesh<dim>::is_shared() const
  {
    return dynamic_cast<const parallel::shared::Triangulation<dim> *>(
             tria.get()) != nullptr;
  }

  template <int dim>
  void
  BodyMesh<dim>::partition_between_group()
  {
    const unsigned int k = group.size();
    if (k == 1)
      for (const auto &cell : tria->active_cell_iterators())
        cell->set_subdomain_id(group[0]);
    else
    {
      if (is_simplex())
      {
        // Equal shares of the active cells in their order.
        const unsigned int n = tria->n_active_cells();
        for (const auto &cell : tria->active_cell_iterators())
          cell->set_subdomain_id(
            static_cast<std::size_t>(cell->active_cell_index()) * k / n);
      }
      else
        GridTools::partition_triangulation_zorder(k, *tria);
      for (const auto &cell : tria->active_cell_iterators())
        cell->set_subdomain_id(group[cell->subdomain_id()]);
    }
  }

  template <int dim>
  bool
  BodyMesh<dim>::set_process_group(const std::vector<unsigned int> &ranks,
                                   const MPI_Comm                   comm)
  {
    AssertThrow(!ranks.empty(), ExcInternalError());
    AssertThrow(
      ranks.size() == 1 || is_shared() || distributed,
      ExcMessage("a body on several processes needs a partitioned mesh"));
    // A p4est mesh is placed the first time even on the group {0} it
    // starts with: p4est spread its cells over every process.
    const bool changed = ranks != group || (distributed && !placed);
    group              = ranks;
    placed             = true;
    if (group_comm != MPI_COMM_NULL)
      MPI_Comm_free(&group_comm);
    group_comm = comm;
    if (changed && is_shared())
      // No cell is flagged: the refinement step only fires the
      // post-refinement signal, which partitions between the new group.
      tria->execute_coarsening_and_refinement();
    if (changed && distributed)
      place_forest_on_group(ranks);
    return changed;
  }

  template <int dim>
  void
  BodyMesh<dim>::place_forest_on_group(const std::vector<unsigned int> &ranks)
  {
    AssertThrow(made_with != nullptr, ExcInternalError());
    const MPI_Comm     comm = tria->get_communicator();
    const unsigned int n    = Utilities::MPI::n_mpi_processes(comm);
    AssertThrow(ranks.size() <= n, ExcInternalError());
    const unsigned int me = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const auto         position = std::find(ranks.begin(), ranks.end(), me);
    const bool         member   = position != ranks.end();
    // The world ranks in the order of the mesh's communicator.
    const auto order = Utilities::MPI::all_gather(comm, me);
    weighting.disconnect();
    if (!std::equal(ranks.begin(), ranks.end(), order.begin()))
    {
      // The group first, in its order, then the others: collective over
      // the world (every process holds every body's mesh object).
      const int key = member ? static_cast<int>(position - ranks.begin())
                             : static_cast<int>(ranks.size() + me);
      MPI_Comm  led;
      const int ierr = MPI_Comm_split(MPI_COMM_WORLD, 0, key, &led);
      AssertThrowMPI(ierr);
      // The old mesh lives until the DoFHandler has moved to the new one.
      previous_tria = std::move(tria);
      previous_comm = mesh_comm;
      mesh_comm     = led;
      snapping.disconnect();
      tria = std::make_unique<parallel::distributed::Triangulation<dim>>(
        mesh_comm, previous_tria->get_mesh_smoothing());
    }
    if (!previous_tria && ranks.size() == n)
      return; // p4est balances the cells over all processes
    if (ranks.size() < n)
      weighting = tria->signals.weight.connect(
        [this](const typename Triangulation<dim>::cell_iterator &,
               const typename Triangulation<dim>::CellStatus)
        { return group_weight(); });
    weight_calls = 0;
    if (previous_tria)
      make(*made_with, made_in);
    // The cells of the mesh as made, or as p4est spread them over every
    // process at creation, go to the group.
    forest().repartition();
    AssertThrow(member || forest().n_locally_owned_active_cells() == 0,
                ExcMessage("a process outside a body's group owns cells"));
  }

  template <int dim>
  unsigned int
  BodyMesh<dim>::group_weight()
  {
    const auto         *forest = this->forest().get_p4est();
    const std::uint64_t N      = forest->global_num_quadrants;
    const std::uint64_t P      = forest->mpisize;
    const std::uint64_t k      = group.size();
    const std::uint64_t i =
      forest->global_first_quadrant[forest->mpirank] + weight_calls;
    if (++weight_calls ==
        static_cast<std::uint64_t>(forest->local_num_quadrants))
      weight_calls = 0;
    // Chunk j is [floor(j N / k), floor((j + 1) N / k)); the chunks j =
    // 1, ..., k - 1 that begin at i + 1 (several, if some are empty) are
    // those with ceil((i + 1) k / N) <= j <= ceil((i + 2) k / N) - 1.
    const auto ceil_div = [](const std::uint64_t a, const std::uint64_t b)
    { return (a + b - 1) / b; };
    const std::uint64_t lo =
      std::max<std::uint64_t>(ceil_div((i + 1) * k, N), 1);
    const std::uint64_t hi =
      std::min<std::uint64_t>(ceil_div((i + 2) * k, N), k) - 1;
    std::uint64_t weight = hi >= lo ? hi - lo + 1 : 0;
    if (i + 1 == N)
      weight += P - k + 1;
    return static_cast<unsigned int>(weight);
  }

  template <int dim>
  parallel::distributed::Triangulation<dim, dim> &
  BodyMesh<dim>::forest() const
  {
    return dynamic_cast<parallel::distributed::Triangulation<dim, dim> &>(
      *tria);
  }

  template <int dim>
  void
  BodyMesh<dim>::release_previous_mesh()
  {
    previous_tria.reset();
    if (previous_comm != MPI_COMM_NULL)
      MPI_Comm_free(&previous_comm);
  }

  template <int dim>
  double
  BodyMesh<dim>::sum(const double value) const
  {
    return distributed ? Utilities::MPI::sum(value, tria->get_communicator())
                       : value;
  }

  template <int dim>
  double
  BodyMesh<dim>::min_cell_diameter() const
  {
    double h = std::numeric_limits<double>::max();
    for (const auto &cell : tria->active_cell_iterators())
      if (computes(cell))
        h = std::min(h, cell->diameter(*cell_mapping));
    return distributed ? Utilities::MPI::min(h, tria->get_communicator()) : h;
  }

  template <int dim>
  std::pair<double, double>
  BodyMesh<dim>::extent_along(const Tensor<1, dim> &direction) const
  {
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const auto &cell : tria->active_cell_iterators())
      if (computes(cell))
        for (const unsigned int v : cell->vertex_indices())
        {
          lo = std::min(lo, cell->vertex(v) * direction);
          hi = std::max(hi, cell->vertex(v) * direction);
        }
    if (distributed)
    {
      lo = Utilities::MPI::min(lo, tria->get_communicator());
      hi = Utilities::MPI::max(hi, tria->get_communicator());
    }
    return {lo, hi};
  }

  template class BodyMesh<2>;
} // namespace ddcontact
