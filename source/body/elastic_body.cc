#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/meshworker/copy_data.h>
#include <deal.II/meshworker/mesh_loop.h>
#include <deal.II/meshworker/scratch_data.h>

#include <deal.II/numerics/solution_transfer.h>
#include <deal.II/numerics/vector_tools.h>

#include <ddcontact/body/elastic_body.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>
#include <type_traits>

namespace ddcontact
{
  template <int dim>
  ElasticBody<dim>::ElasticBody(const BodyParameters &parameters,
                                const Constants      &constants,
                                const MPI_Comm        mesh_communicator,
                                const bool            distributed_mesh)
    : parameters(parameters)
    , material(parameters.material)
    , boundary_conditions(make_boundary_conditions(parameters, constants))
    , mesh_distributed(distributed_mesh)
    , group_communicator(MPI_COMM_NULL)
  {
    // Mesh smoothing keeps adapted quadrilateral meshes graded; deal.II 9.4
    // refines triangles only globally and without smoothing.
    const auto smoothing =
      parameters.cell_type == CellType::triangle
        ? Triangulation<dim>::none
        : Triangulation<dim>::limit_level_difference_at_vertices;
    AssertThrow(!mesh_distributed || parameters.cell_type != CellType::triangle,
                ExcMessage("p4est meshes hold quadrilaterals only"));
    if (mesh_distributed)
      // p4est partitions the cells between all processes of the
      // communicator (z-order of the forest) and again after every
      // refinement.
      triangulation =
        std::make_unique<parallel::distributed::Triangulation<dim>>(
          mesh_communicator, smoothing);
    else if (Utilities::MPI::n_mpi_processes(mesh_communicator) > 1)
    {
      // Every process keeps every cell (no artificial cells); the
      // subdomain ids say which process of the group assembles a cell.
      auto shared = std::make_unique<parallel::shared::Triangulation<dim>>(
        mesh_communicator,
        smoothing,
        false,
        parallel::shared::Triangulation<dim>::partition_custom_signal);
      shared->signals.create.connect([this]() { partition_between_group(); });
      shared->signals.post_refinement.connect([this]()
                                              { partition_between_group(); });
      triangulation = std::move(shared);
    }
    else
      triangulation = std::make_unique<Triangulation<dim>>(smoothing);

    static_assert(dim == 2, "ddcontact bodies are two-dimensional");
    const unsigned int p = parameters.degree;
    if (is_simplex())
    {
      fe      = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(p), dim);
      mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
      cell_quadrature = std::make_unique<QGaussSimplex<dim>>(p + 1);
    }
    else
    {
      fe              = std::make_unique<FESystem<dim>>(FE_Q<dim>(p), dim);
      mapping         = std::make_unique<MappingQ<dim>>(1);
      cell_quadrature = std::make_unique<QGauss<dim>>(p + 1);
      if (parameters.volumetric_integration == VolumetricIntegration::reduced)
        volumetric_quadrature = std::make_unique<QGauss<dim>>(p);
    }
    face_quadrature = std::make_unique<QGauss<dim - 1>>(p + 1);
  }

  namespace
  {
    /** Whether every entry of @p v is finite (Vector::l2_norm() asserts
     * that in Debug builds instead of answering). */
    bool
    finite(const Vector<double> &v)
    {
      return std::all_of(
        v.begin(), v.end(), [](const double x) { return std::isfinite(x); });
    }

    /** Seconds gmsh may take for one .geo: DDCONTACT_GMSH_TIMEOUT, or 120. */
    double
    gmsh_time_limit()
    {
      const char *value = std::getenv("DDCONTACT_GMSH_TIMEOUT");
      if (value == nullptr)
        return 120.;
      char        *end     = nullptr;
      const double seconds = std::strtod(value, &end);
      if (end == value || *end != '\0' || !(seconds > 0) ||
          !std::isfinite(seconds))
        throw InputError(std::string("DDCONTACT_GMSH_TIMEOUT: '") + value +
                         "' is not a positive number of seconds");
      return seconds;
    }

    /**
     * Run @p arguments (the program first, found on PATH) with its output
     * and errors in @p log, without a shell, so that no character of a
     * file name is ever interpreted. Returns the exit status, -1 if the
     * program could not be started or ended by a signal, -2 if it ran
     * longer than @p seconds (then it is killed).
     */
    int
    run_without_shell(const std::vector<std::string> &arguments,
                      const std::string              &log,
                      const double                    seconds)
    {
      std::vector<char *> argv;
      for (const auto &a : arguments)
        argv.push_back(const_cast<char *>(a.c_str()));
      argv.push_back(nullptr);

      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      posix_spawn_file_actions_addopen(
        &actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      posix_spawn_file_actions_adddup2(&actions, 1, 2);
      pid_t     pid = 0;
      const int failed =
        posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
      posix_spawn_file_actions_destroy(&actions);
      if (failed != 0)
        return -1;

      const auto start  = std::chrono::steady_clock::now();
      int        status = 0;
      while (waitpid(pid, &status, WNOHANG) == 0)
      {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                          start)
              .count() > seconds)
        {
          kill(pid, SIGKILL);
          waitpid(pid, &status, 0);
          return -2;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    /** What this process may allocate, in bytes: MemAvailable of
     * /proc/meminfo (without swapping), or less under an address-space
     * limit (ulimit -v; half of it, since the libraries reserve address
     * space they never touch); 0 if neither can be read. */
    double
    available_memory()
    {
      double        available = 0;
      std::ifstream meminfo("/proc/meminfo");
      std::string   key;
      double        kb = 0;
      while (meminfo >> key >> kb)
      {
        if (key == "MemAvailable:")
        {
          available = kb * 1024.;
          break;
        }
        meminfo.ignore(256, '\n');
      }
      rlimit limit;
      if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      {
        const double allowed = 0.5 * static_cast<double>(limit.rlim_cur);
        available = (available > 0) ? std::min(available, allowed) : allowed;
      }
      return available;
    }
  } // namespace

  template <int dim>
  void
  ElasticBody<dim>::check_dirichlet_values() const
  {
    // The prescribed displacements at the vertices and midpoints of the
    // Dirichlet faces (where interpolation evaluates them for degree 1
    // and 2): a NaN would enter the constraints and every solution.
    Vector<double> value(dim);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
          {
            const auto it =
              boundary_conditions.dirichlet.find(cell->face(f)->boundary_id());
            if (it == boundary_conditions.dirichlet.end())
              continue;
            for (const auto &x : {cell->face(f)->vertex(0),
                                  cell->face(f)->vertex(1),
                                  cell->face(f)->center()})
            {
              it->second.displacement->vector_value(x, value);
              if (!finite(value))
              {
                std::ostringstream s;
                s << parameters.section()
                  << "/Boundary conditions/Dirichlet: the displacement on "
                     "boundary id "
                  << it->first << " is not finite at (" << x[0] << ", " << x[1]
                  << "); give expressions finite on the whole "
                  << "boundary";
                throw InputError(s.str());
              }
            }
          }
  }

  template <int dim>
  void
  ElasticBody<dim>::throw_non_finite_load() const
  {
    // Which expression, and where: the body force at the cells'
    // quadrature points, then the tractions on their Neumann faces.
    const auto where = [](const Point<dim> &x)
    {
      std::ostringstream s;
      s << std::setprecision(6) << " at (" << x[0] << ", " << x[1] << ")";
      return s.str();
    };
    const std::string section = parameters.section() + "/Boundary conditions/";
    Vector<double>    value(dim);
    FEValues<dim>     fe_values(
      *mapping, *fe, *cell_quadrature, update_quadrature_points);
    FEFaceValues<dim> fe_face(
      *mapping, *fe, *face_quadrature, update_quadrature_points);
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (!computes(cell))
        continue;
      if (boundary_conditions.body_force)
      {
        fe_values.reinit(cell);
        for (const auto &x : fe_values.get_quadrature_points())
        {
          boundary_conditions.body_force->vector_value(x, value);
          if (!finite(value))
            throw InputError(section + "Body force: not finite" + where(x) +
                             "; give expressions finite in the whole body");
        }
      }
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
        {
          const auto it =
            boundary_conditions.neumann.find(cell->face(f)->boundary_id());
          if (it == boundary_conditions.neumann.end())
            continue;
          fe_face.reinit(cell, f);
          for (const auto &x : fe_face.get_quadrature_points())
          {
            it->second->vector_value(x, value);
            if (!finite(value))
              throw InputError(section +
                               "Neumann: the traction on boundary "
                               "id " +
                               std::to_string(it->first) + " is not finite" +
                               where(x) +
                               "; give expressions finite on the whole "
                               "boundary");
          }
        }
    }
    throw InputError(section + "the load vector is not finite");
  }

  template <int dim>
  void
  ElasticBody<dim>::check_mesh_size(const double       n_cells,
                                    const std::string &entry) const
  {
    // Unknowns per cell: 2 components times p^2 nodes per quadrilateral,
    // about half that per triangle. A body needs about 4 kB per unknown
    // with the direct solver (measured in Release: 556 MB at 1.3e5 and
    // 1780 MB at 5.3e5 unknowns, the factorization growing faster than
    // the unknowns).
    const double p       = parameters.degree;
    const double n_dofs  = n_cells * (is_simplex() ? 1. : 2.) * p * p;
    const double bytes   = 4096. * n_dofs;
    const double memory  = available_memory();
    const bool   too_big = n_cells > 1e9 || (memory > 0 && bytes > memory);
    if (!too_big)
      return;
    std::ostringstream s;
    s << std::setprecision(3) << parameters.section() << "/" << entry
      << ": the mesh would have about " << n_cells << " cells and " << n_dofs
      << " unknowns, needing about " << bytes / 1e9
      << " GB (4 kB per unknown), but " << memory / 1e9
      << " GB are available; lower it";
    throw InputError(s.str());
  }

  template <int dim>
  void
  ElasticBody<dim>::read_mesh_file(const std::string &work_directory)
  {
    const std::string what = parameters.section() + "/Mesh/File";
    std::string       file = parameters.mesh_file;
    if (!std::ifstream(file))
      throw InputError(what + ": mesh file '" + file +
                       "' does not exist or cannot be read");

    const auto ends_with = [&](const std::string &suffix)
    {
      return file.size() >= suffix.size() &&
             file.compare(file.size() - suffix.size(), suffix.size(), suffix) ==
               0;
    };

    if (ends_with(".geo"))
    {
      // Mesh the geometry with the gmsh binary, in the legacy ASCII format
      // that GridIn reads without the Gmsh API.
      // Under mpirun every process meshes (gmsh is deterministic) into a
      // file of its own.
      const std::string rank =
        Utilities::MPI::job_supports_mpi() &&
            Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1
          ? "." +
              std::to_string(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD))
          : "";
      const std::string msh =
        work_directory + "/" + parameters.name + rank + ".msh";
      const std::string log =
        work_directory + "/" + parameters.name + rank + ".gmsh.log";
      read_bounded_file(file, 16u << 20, what); // size and kind only
      const double timeout = gmsh_time_limit();
      const int    status  = run_without_shell(
        {"gmsh", "-2", "-format", "msh22", "-v", "2", "-o", msh, file},
        log,
        timeout);
      if (status == -2)
        throw InputError(what + ": gmsh did not finish meshing '" + file +
                         "' within " + Utilities::to_string(timeout) +
                         " s (an endless loop in the .geo?); stopped it "
                         "(the limit is DDCONTACT_GMSH_TIMEOUT)");
      if (status != 0)
        throw InputError(what + ": gmsh could not mesh '" + file + "' (see " +
                         log + ")");
      file = msh;
    }
    else if (!ends_with(".msh"))
      throw InputError(what + ": '" + file +
                       "' is neither a Gmsh .msh nor a .geo file");

    // A mesh of 512 MiB has millions of cells: beyond what a body here
    // can factorize; refuse before reading it (and anything not a file).
    std::istringstream in(read_bounded_file(file, 512u << 20, what));
    GridIn<dim>        grid_in;
    grid_in.attach_triangulation(*triangulation);
    try
    {
      grid_in.read_msh(in);
    }
    catch (const std::exception &e)
    {
      throw InputError(what + ": cannot read '" + file + "' as a Gmsh mesh");
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::make_mesh(const std::string &work_directory)
  {
    triangulation->clear();
    if (parameters.mesh_type == MeshType::rectangle)
    {
      check_mesh_size(double(parameters.subdivisions[0]) *
                        parameters.subdivisions[1],
                      "Mesh/Subdivisions");
      if (is_simplex())
        GridGenerator::subdivided_hyper_rectangle_with_simplices(
          *triangulation,
          parameters.subdivisions,
          parameters.corner_1,
          parameters.corner_2);
      else
        GridGenerator::subdivided_hyper_rectangle(*triangulation,
                                                  parameters.subdivisions,
                                                  parameters.corner_1,
                                                  parameters.corner_2);
      // Ids 0 left, 1 right, 2 bottom, 3 top (deal.II 9.4 cannot colorize
      // the simplex variant, so both are labelled here).
      const double tolerance =
        1e-10 * parameters.corner_1.distance(parameters.corner_2);
      for (const auto &face : triangulation->active_face_iterators())
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
    else
      read_mesh_file(work_directory);

    const bool simplex_mesh = triangulation->all_reference_cells_are_simplex();
    const bool quad_mesh = triangulation->all_reference_cells_are_hyper_cube();
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

    check_mesh_size(triangulation->n_global_active_cells() *
                      std::pow(4., parameters.initial_refinement),
                    "Mesh/Initial refinement");
    triangulation->refine_global(parameters.initial_refinement);

    if (!parameters.refinement_box.empty() && parameters.box_refinement > 0)
    {
      if (is_simplex())
        throw InputError(parameters.section() +
                         "/Mesh/Refinement box: local refinement needs "
                         "quadrilaterals (deal.II 9.4 refines triangles "
                         "only globally)");
      const auto      &c = parameters.refinement_box;
      const Point<dim> lo(c[0], c[1]);
      const Point<dim> hi(c[2], c[3]);
      if (parameters.mesh_type == MeshType::rectangle)
      {
        // Before any cell is made: at step k the cells of size h_k that
        // touch the box (clipped to the body) are refined, each into four.
        double cells = triangulation->n_global_active_cells();
        for (unsigned int k = 0; k < parameters.box_refinement; ++k)
        {
          double flagged = 1;
          for (unsigned int d = 0; d < 2; ++d)
          {
            const double n_across =
              parameters.subdivisions[d] *
              std::pow(2., parameters.initial_refinement + k);
            const double length =
              parameters.corner_2[d] - parameters.corner_1[d];
            const double width = std::min(hi[d], parameters.corner_2[d]) -
                                 std::max(lo[d], parameters.corner_1[d]);
            flagged *=
              std::min(n_across, std::max(0., width) / length * n_across + 2);
          }
          cells += 3 * flagged;
        }
        check_mesh_size(cells, "Mesh/Box refinement");
      }
      for (unsigned int k = 0; k < parameters.box_refinement; ++k)
      {
        unsigned int n_flagged = 0;
        for (const auto &cell : triangulation->active_cell_iterators())
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
        check_mesh_size(triangulation->n_global_active_cells() +
                          3. * Utilities::MPI::sum(
                                 n_flagged, triangulation->get_communicator()),
                        "Mesh/Box refinement");
        triangulation->execute_coarsening_and_refinement();
      }
    }
    check_boundary_ids();
  }

  template <int dim>
  void
  ElasticBody<dim>::check_boundary_ids() const
  {
    const auto ids = triangulation->get_boundary_ids();
    const auto check =
      [&](const types::boundary_id id, const std::string &entry)
    {
      if (std::find(ids.begin(), ids.end(), id) == ids.end())
      {
        std::string list;
        for (const auto i : ids)
          list += (list.empty() ? "" : ", ") + std::to_string(i);
        throw InputError(parameters.section() + "/Boundary conditions/" +
                         entry + ": boundary id " + std::to_string(id) +
                         " does not exist in the mesh (its ids: " + list + ")");
      }
    };
    for (const auto &[id, d] : boundary_conditions.dirichlet)
      check(id, "Dirichlet");
    for (const auto &[id, f] : boundary_conditions.neumann)
      check(id, "Neumann");
    for (const auto id : boundary_conditions.contact)
      check(id, "Contact ids");
  }

  template <int dim>
  ElasticBody<dim>::~ElasticBody()
  {
    // The distributed solver objects use the group's communicator: release
    // them (collectively, every process destroys the bodies in the same
    // order) before the communicator.
    distributed_direct.reset();
    amg_preconditioner.clear();
    distributed_matrix.clear();
    distributed_load.clear();
    if (group_communicator != MPI_COMM_NULL)
      MPI_Comm_free(&group_communicator);
  }

  template <int dim>
  void
  ElasticBody<dim>::partition_between_group()
  {
    const unsigned int k = process_group.size();
    if (k == 1)
      for (const auto &cell : triangulation->active_cell_iterators())
        cell->set_subdomain_id(process_group[0]);
    else
    {
      if (is_simplex())
      {
        // Equal shares of the active cells in their order.
        const unsigned int n = triangulation->n_active_cells();
        for (const auto &cell : triangulation->active_cell_iterators())
          cell->set_subdomain_id(
            static_cast<std::size_t>(cell->active_cell_index()) * k / n);
      }
      else
        GridTools::partition_triangulation_zorder(k, *triangulation);
      for (const auto &cell : triangulation->active_cell_iterators())
        cell->set_subdomain_id(process_group[cell->subdomain_id()]);
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::set_process_group(const std::vector<unsigned int> &ranks,
                                      const MPI_Comm                   group)
  {
    AssertThrow(!ranks.empty(), ExcInternalError());
    const bool partitioned =
      dynamic_cast<parallel::shared::Triangulation<dim> *>(
        triangulation.get()) != nullptr;
    AssertThrow(
      ranks.size() == 1 || partitioned || mesh_distributed,
      ExcMessage("a body on several processes needs a partitioned mesh"));
    // p4est splits the forest between all processes of the mesh's
    // communicator, which must be the group.
    AssertThrow(!mesh_distributed ||
                  ranks.size() == Utilities::MPI::n_mpi_processes(
                                    triangulation->get_communicator()),
                ExcMessage("a distributed mesh is solved by all processes"));
    const bool changed = ranks != process_group;
    process_group      = ranks;
    if (group_communicator != MPI_COMM_NULL)
      MPI_Comm_free(&group_communicator);
    group_communicator = group;
    if (changed && mesh_distributed)
      setup_system();
    else if (changed && partitioned)
    {
      // No cell is flagged: the refinement step only fires the
      // post-refinement signal, which partitions between the new group.
      triangulation->execute_coarsening_and_refinement();
      setup_system();
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::gather_in_group(const TrilinosWrappers::MPI::Vector &owned,
                                    Vector<double> &whole) const
  {
    // Every process of the group owns one contiguous range, stored in
    // order in the Trilinos vector (group_ranges, from setup_matrix()).
    whole.reinit(dof_handler.n_dofs());
    const int ierr = MPI_Allgatherv(owned.begin(),
                                    owned.locally_owned_size(),
                                    MPI_DOUBLE,
                                    whole.data(),
                                    group_range_sizes.data(),
                                    group_range_starts.data(),
                                    MPI_DOUBLE,
                                    group_communicator);
    AssertThrowMPI(ierr);
  }

  namespace
  {
    /** One constraint u_i = sum_k w_k u_{m_k} + b_i, as sent between
     * processes. */
    struct ConstraintLine
    {
      types::global_dof_index              index;
      std::vector<types::global_dof_index> masters;
      std::vector<double>                  weights;
      double                               inhomogeneity;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &index &masters &weights &inhomogeneity;
      }
    };
  } // namespace

  template <int dim>
  void
  ElasticBody<dim>::complete_constraints()
  {
    // Every dof's constraint as the process owning the dof computed it,
    // on every process, in one closed object: the DD keeps the whole
    // iterate on every process and distributes the constraints in it
    // (relaxation (21), the transfer after refinement), which must give
    // the same numbers everywhere. These are the Dirichlet dofs of (5)
    // and the hanging nodes: few next to the iterate.
    std::vector<ConstraintLine> owned_lines;
    const IndexSet             &owned = dof_handler.locally_owned_dofs();
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
      {
        ConstraintLine l{line.index, {}, {}, line.inhomogeneity};
        for (const auto &[master, weight] : line.entries)
        {
          l.masters.push_back(master);
          l.weights.push_back(weight);
        }
        owned_lines.push_back(l);
      }
    // (reinit() also drops the restriction to the locally relevant dofs.)
    constraints.reinit();
    for (const auto &from_process : Utilities::MPI::all_gather(
           triangulation->get_communicator(), owned_lines))
      for (const auto &l : from_process)
      {
        constraints.add_line(l.index);
        for (unsigned int k = 0; k < l.masters.size(); ++k)
          constraints.add_entry(l.index, l.masters[k], l.weights[k]);
        constraints.set_inhomogeneity(l.index, l.inhomogeneity);
      }
    constraints.close();
  }

  template <int dim>
  void
  ElasticBody<dim>::setup_system()
  {
    dof_handler.reinit(*triangulation);
    dof_handler.distribute_dofs(*fe);

    // Hanging nodes first, then the Dirichlet data (5); merged in one
    // object so that a Dirichlet node that is also hanging is handled. A
    // distributed mesh computes the constraints of its locally relevant
    // dofs (below, they are completed).
    constraints.clear();
    if (mesh_distributed)
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      constraints.reinit(relevant);
    }
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    check_dirichlet_values();
    for (const auto &[id, d] : boundary_conditions.dirichlet)
      VectorTools::interpolate_boundary_values(
        *mapping, dof_handler, id, *d.displacement, constraints, d.mask);
    constraints.close();
    if (mesh_distributed)
      complete_constraints();

    load_vector.reinit(dof_handler.n_dofs());
    solution.reinit(dof_handler.n_dofs());
    if (solved_here)
      setup_matrix();
    is_factorized = false;
  }

  template <int dim>
  void
  ElasticBody<dim>::setup_matrix()
  {
    // The old factorization and preconditioner refer to the old matrix
    // (and MUMPS frees its factors collectively): release them first.
    distributed_direct.reset();
    amg_preconditioner.clear();
    if (is_solved_distributed())
    {
      // The rows of this process's dofs, with the columns its cells
      // couple them to; entries of other rows are sent to their owners.
      const IndexSet &owned = dof_handler.locally_owned_dofs();
      // A partitioned DoFHandler numbers the dofs subdomain by subdomain;
      // solve() and gather_in_group() rely on one range per process.
      AssertThrow(owned.is_contiguous(), ExcInternalError());
      group_range_starts = Utilities::MPI::all_gather(
        group_communicator,
        static_cast<int>(owned.n_elements() ? *owned.begin() : 0));
      group_range_sizes = Utilities::MPI::all_gather(
        group_communicator, static_cast<int>(owned.n_elements()));
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      TrilinosWrappers::SparsityPattern sp(
        owned, owned, relevant, group_communicator);
      DoFTools::make_sparsity_pattern(dof_handler, sp, constraints, false);
      sp.compress();
      distributed_matrix.reinit(sp);
      distributed_load.reinit(owned, group_communicator);
      stiffness_matrix.clear();
      sparsity_pattern.reinit(0, 0, 0);
    }
    else
    {
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      sparsity_pattern.copy_from(dsp);
      stiffness_matrix.reinit(sparsity_pattern);
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::assemble_system()
  {
    const bool distributed = is_solved_distributed();
    if (distributed)
    {
      distributed_matrix = 0;
      distributed_load   = 0;
    }
    else
    {
      stiffness_matrix = 0;
      load_vector      = 0;
    }

    using Iterator = typename DoFHandler<dim>::active_cell_iterator;
    const FEValuesExtractors::Vector displacement(0);
    const double                     lambda = material.lambda();
    const double                     mu     = material.mu();
    // With reduced volumetric integration the lambda term is added below,
    // on its own quadrature.
    const double lambda_full = reduced_volumetric_integration() ? 0. : lambda;

    // a_a(u, v) of (11) and the body-force part of l_a(v).
    const auto cell_worker = [&](const Iterator                &cell,
                                 MeshWorker::ScratchData<dim>  &scratch,
                                 MeshWorker::CopyData<1, 1, 1> &copy)
    {
      const auto        &fe_values     = scratch.reinit(cell);
      const unsigned int dofs_per_cell = fe_values.dofs_per_cell;
      copy.reinit(dofs_per_cell);
      cell->get_dof_indices(copy.local_dof_indices[0]);
      auto &cell_matrix = copy.matrices[0];
      auto &cell_rhs    = copy.vectors[0];

      std::vector<Vector<double>> force(fe_values.n_quadrature_points,
                                        Vector<double>(dim));
      if (boundary_conditions.body_force)
        boundary_conditions.body_force->vector_value_list(
          fe_values.get_quadrature_points(), force);

      std::vector<SymmetricTensor<2, dim>> eps(dofs_per_cell);
      std::vector<double>                  div(dofs_per_cell);
      for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          eps[i] = fe_values[displacement].symmetric_gradient(i, q);
          div[i] = trace(eps[i]);
        }
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            cell_matrix(i, j) +=
              (lambda_full * div[i] * div[j] + 2. * mu * (eps[i] * eps[j])) *
              JxW;
          if (boundary_conditions.body_force)
          {
            const unsigned int c = fe->system_to_component_index(i).first;
            cell_rhs(i) += fe_values.shape_value(i, q) * force[q](c) * JxW;
          }
        }
      }
    };

    // The traction part of l_a(v), (12), on Gamma_p.
    const auto boundary_worker = [&](const Iterator                &cell,
                                     const unsigned int             face_no,
                                     MeshWorker::ScratchData<dim>  &scratch,
                                     MeshWorker::CopyData<1, 1, 1> &copy)
    {
      const auto it =
        boundary_conditions.neumann.find(cell->face(face_no)->boundary_id());
      if (it == boundary_conditions.neumann.end())
        return;
      const auto                 &fe_face = scratch.reinit(cell, face_no);
      std::vector<Vector<double>> traction(fe_face.n_quadrature_points,
                                           Vector<double>(dim));
      it->second->vector_value_list(fe_face.get_quadrature_points(), traction);
      auto &cell_rhs = copy.vectors[0];
      for (const unsigned int q : fe_face.quadrature_point_indices())
        for (unsigned int i = 0; i < fe_face.dofs_per_cell; ++i)
        {
          const unsigned int c = fe->system_to_component_index(i).first;
          cell_rhs(i) +=
            fe_face.shape_value(i, q) * traction[q](c) * fe_face.JxW(q);
        }
    };

    // On a partitioned mesh mesh_loop visits only this process's cells.
    // A load expression that is not finite somewhere (sqrt(x) at x < 0) is
    // found here, in the serial part (a worker thread must not throw), and
    // named after the loop.
    bool       non_finite_load = false;
    const auto copier          = [&](const MeshWorker::CopyData<1, 1, 1> &copy)
    {
      for (const double v : copy.vectors[0])
        non_finite_load = non_finite_load || !std::isfinite(v);
      if (non_finite_load)
        return;
      if (distributed)
        constraints.distribute_local_to_global(copy.matrices[0],
                                               copy.vectors[0],
                                               copy.local_dof_indices[0],
                                               distributed_matrix,
                                               distributed_load);
      else
        constraints.distribute_local_to_global(copy.matrices[0],
                                               copy.vectors[0],
                                               copy.local_dof_indices[0],
                                               stiffness_matrix,
                                               load_vector);
    };

    MeshWorker::ScratchData<dim> scratch(
      *mapping,
      *fe,
      *cell_quadrature,
      update_values | update_gradients | update_quadrature_points |
        update_JxW_values,
      *face_quadrature,
      update_values | update_quadrature_points | update_JxW_values);
    MeshWorker::CopyData<1, 1, 1> copy;
    MeshWorker::mesh_loop(dof_handler.active_cell_iterators(),
                          cell_worker,
                          copier,
                          scratch,
                          copy,
                          MeshWorker::assemble_own_cells |
                            MeshWorker::assemble_boundary_faces,
                          boundary_worker);

    if (non_finite_load)
      throw_non_finite_load();
    if (reduced_volumetric_integration())
      assemble_reduced_volumetric_term(copier);
    if (distributed)
    {
      distributed_matrix.compress(VectorOperation::add);
      distributed_load.compress(VectorOperation::add);
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::assemble_reduced_volumetric_term(
    const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &copier)
  {
    using Iterator = typename DoFHandler<dim>::active_cell_iterator;
    const FEValuesExtractors::Vector displacement(0);
    const double                     lambda = material.lambda();

    // Selective reduced integration: lambda div u div v on one Gauss point
    // per cell. For nu -> 1/2 (lambda/mu -> infinity) the full rule forces
    // div u = 0 at all four points of a Q1 cell, which only a few fields
    // satisfy (locking); one point leaves one constraint per cell, as many
    // as a pressure constant per cell. The deviatoric-shear part keeps the
    // full rule, so no hourglass mode appears. The copier adds the
    // Dirichlet inhomogeneities of this part to the load vector.
    const auto volumetric_worker = [&](const Iterator                &cell,
                                       MeshWorker::ScratchData<dim>  &scratch,
                                       MeshWorker::CopyData<1, 1, 1> &copy)
    {
      const auto        &fe_values     = scratch.reinit(cell);
      const unsigned int dofs_per_cell = fe_values.dofs_per_cell;
      copy.reinit(dofs_per_cell);
      cell->get_dof_indices(copy.local_dof_indices[0]);
      std::vector<double> div(dofs_per_cell);
      for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          div[i] = fe_values[displacement].divergence(i, q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            copy.matrices[0](i, j) +=
              lambda * div[i] * div[j] * fe_values.JxW(q);
      }
    };
    MeshWorker::ScratchData<dim>  volumetric_scratch(*mapping,
                                                    *fe,
                                                    *volumetric_quadrature,
                                                    update_gradients |
                                                      update_JxW_values);
    MeshWorker::CopyData<1, 1, 1> copy;
    MeshWorker::mesh_loop(dof_handler.active_cell_iterators(),
                          volumetric_worker,
                          copier,
                          volumetric_scratch,
                          copy,
                          MeshWorker::assemble_own_cells);
  }

  template <int dim>
  std::vector<double>
  ElasticBody<dim>::reduced_dilatation(const Vector<double> &u) const
  {
    if (!reduced_volumetric_integration())
      return {};
    std::vector<double> dilatation(triangulation->n_active_cells());
    FEValues<dim>       fe_values(
      *mapping, *fe, *volumetric_quadrature, update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<double>              div(volumetric_quadrature->size());
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (!computes(cell))
        continue;
      fe_values.reinit(cell);
      fe_values[displacement].get_function_divergences(u, div);
      dilatation[cell->active_cell_index()] = div[0];
    }
    return dilatation;
  }

  template <int dim>
  void
  ElasticBody<dim>::factorize()
  {
    const bool distributed = is_solved_distributed();
    if (parameters.solver == BodySolverType::direct)
    {
      if (distributed)
      {
        // MUMPS through Amesos: factorized once per mesh over the group.
        distributed_direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          direct_control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         "Amesos_Mumps"));
        distributed_direct->initialize(distributed_matrix);
      }
      else
        try
        {
          direct_solver.initialize(stiffness_matrix);
        }
        catch (const std::exception &)
        {
          // UMFPACK reports a singular or overflowing matrix by an
          // exception with a stack trace; the user needs the body.
          throw InputError(parameters.section() +
                           ": the stiffness matrix cannot be factorized "
                           "(singular, or its entries overflow); check "
                           "Material/Young's modulus and the Dirichlet "
                           "conditions");
        }
    }
    else
    {
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = (parameters.degree > 1);
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      DoFTools::extract_constant_modes(
        dof_handler, ComponentMask(dim, true), data.constant_modes);
      if (distributed)
        amg_preconditioner.initialize(distributed_matrix, data);
      else
      {
        trilinos_matrix.reinit(stiffness_matrix);
        amg_preconditioner.initialize(trilinos_matrix, data);
      }
    }
    is_factorized = true;
  }

  template <int dim>
  void
  ElasticBody<dim>::setup_and_factorize()
  {
    setup_system();
    if (solved_here)
    {
      assemble_system();
      factorize();
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::refine_and_transfer()
  {
    triangulation->prepare_coarsening_and_refinement();
    if (mesh_distributed)
    {
      // p4est refines the owned cells, repartitions, and moves the
      // transferred values with the cells; the interpolation needs the
      // ghost values of the old mesh.
      AssertThrow(is_solved_distributed(), ExcInternalError());
      const MPI_Comm comm = triangulation->get_communicator();
      IndexSet       relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      TrilinosWrappers::MPI::Vector owned(dof_handler.locally_owned_dofs(),
                                          comm),
        ghosted(dof_handler.locally_owned_dofs(), relevant, comm);
      for (const auto i : dof_handler.locally_owned_dofs())
        owned(i) = solution(i);
      owned.compress(VectorOperation::insert);
      ghosted = owned;
      parallel::distributed::SolutionTransfer<dim,
                                              TrilinosWrappers::MPI::Vector>
        transfer(dof_handler);
      transfer.prepare_for_coarsening_and_refinement(ghosted);
      triangulation->execute_coarsening_and_refinement();

      setup_system();
      TrilinosWrappers::MPI::Vector moved(dof_handler.locally_owned_dofs(),
                                          comm);
      transfer.interpolate(moved);
      gather_in_group(moved, solution);
    }
    else
    {
      SolutionTransfer<dim, Vector<double>> transfer(dof_handler);
      const Vector<double>                  old_solution = solution;
      transfer.prepare_for_coarsening_and_refinement(old_solution);
      triangulation->execute_coarsening_and_refinement();

      setup_system();
      transfer.interpolate(old_solution, solution);
    }
    // New hanging nodes and the Dirichlet data (5) on new boundary vertices.
    constraints.distribute(solution);
    if (solved_here)
    {
      assemble_system();
      factorize();
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::set_solved_here(const bool here)
  {
    solved_here = here;
    if (solved_here && !is_factorized)
    {
      setup_matrix();
      assemble_system();
      factorize();
    }
    else if (!solved_here && is_factorized)
    {
      // (UMFPACK keeps its factors until the next initialize: it has no
      // public clear().)
      trilinos_matrix.clear();
      amg_preconditioner.clear();
      distributed_direct.reset();
      distributed_matrix.clear();
      is_factorized = false;
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::solve(const Vector<double> &load, Vector<double> &u) const
  {
    Assert(is_factorized, ExcMessage("factorize() must be called first"));
    if (load.size() > 0)
      AssertDimension(load.size(), dof_handler.n_dofs());
    // CG with the AMG preconditioner, on the serial or the distributed
    // matrix and vectors.
    const auto solve_cg = [&](const auto &matrix, auto &x, const auto &rhs)
    {
      SolverControl control(parameters.solver_max_iterations,
                            parameters.solver_tolerance * rhs.l2_norm());
      SolverCG<std::remove_const_t<std::remove_reference_t<decltype(rhs)>>> cg(
        control);
      try
      {
        cg.solve(matrix, x, rhs, amg_preconditioner);
      }
      catch (const SolverControl::NoConvergence &e)
      {
        throw InputError(
          parameters.section() + "/Solver: cg-amg did not converge in " +
          std::to_string(e.last_step) + " iterations (residual " +
          std::to_string(e.last_residual) +
          "); raise Max iterations or use Type = direct");
      }
    };
    if (is_solved_distributed())
    {
      // Every process of the group holds the whole load: it takes the
      // rows it owns, and the group gathers the whole displacement.
      TrilinosWrappers::MPI::Vector rhs(distributed_load), x;
      x.reinit(distributed_load);
      if (load.size() > 0)
      {
        // The owned entries are one contiguous range (see
        // gather_in_group()), stored in order.
        const IndexSet &owned = dof_handler.locally_owned_dofs();
        if (owned.n_elements() > 0)
          std::transform(rhs.begin(),
                         rhs.end(),
                         load.begin() + *owned.begin(),
                         rhs.begin(),
                         std::plus<double>());
      }
      if (parameters.solver == BodySolverType::direct)
        distributed_direct->solve(x, rhs);
      else
        solve_cg(distributed_matrix, x, rhs);
      gather_in_group(x, u);
    }
    else
    {
      Vector<double> rhs(load_vector);
      if (load.size() > 0)
        rhs += load;
      u.reinit(dof_handler.n_dofs());
      if (parameters.solver == BodySolverType::direct)
        direct_solver.vmult(u, rhs);
      else
        solve_cg(trilinos_matrix, u, rhs);
    }
    constraints.distribute(u);
    for (const double v : u)
      if (!std::isfinite(v))
        throw InputError(parameters.section() +
                         ": the body problem gave a non-finite displacement; "
                         "check the Dirichlet conditions and the material");
  }

  template <int dim>
  void
  ElasticBody<dim>::solve()
  {
    solve(Vector<double>(), solution);
  }

  template <int dim>
  std::vector<std::vector<SymmetricTensor<2, dim>>>
  ElasticBody<dim>::stress_at_quadrature_points(const Vector<double> &u) const
  {
    std::vector<std::vector<SymmetricTensor<2, dim>>> stress(
      triangulation->n_active_cells());
    FEValues<dim> fe_values(*mapping, *fe, *cell_quadrature, update_gradients);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(cell_quadrature->size());
    const std::vector<double> dilatation = reduced_volumetric_integration()
                                             ? reduced_dilatation(u)
                                             : std::vector<double>();
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (!computes(cell))
        continue;
      fe_values.reinit(cell);
      fe_values[displacement].get_function_symmetric_gradients(u, strain);
      auto &s = stress[cell->active_cell_index()];
      s.resize(strain.size());
      for (unsigned int q = 0; q < strain.size(); ++q)
        s[q] =
          stress_from_strain(strain[q], dilatation, cell->active_cell_index());
    }
    return stress;
  }

  template <int dim>
  double
  ElasticBody<dim>::strain_energy(const Vector<double> &u) const
  {
    FEValues<dim> fe_values(
      *mapping, *fe, *cell_quadrature, update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(cell_quadrature->size());
    double                               energy = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (!computes(cell))
        continue;
      fe_values.reinit(cell);
      fe_values[displacement].get_function_symmetric_gradients(u, strain);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        energy += 0.5 *
                  (reduced_volumetric_integration()
                     ? 2. * material.mu() * (strain[q] * strain[q])
                     : material.stress(strain[q]) * strain[q]) *
                  fe_values.JxW(q);
    }
    if (reduced_volumetric_integration())
    {
      // The volumetric part on its own (one-point) rule, as assembled.
      const auto    dilatation = reduced_dilatation(u);
      FEValues<dim> fe_reduced(
        *mapping, *fe, *volumetric_quadrature, update_JxW_values);
      for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!computes(cell))
          continue;
        fe_reduced.reinit(cell);
        const double d = dilatation[cell->active_cell_index()];
        for (const unsigned int q : fe_reduced.quadrature_point_indices())
          energy += 0.5 * material.lambda() * d * d * fe_reduced.JxW(q);
      }
    }
    return mesh_distributed
             ? Utilities::MPI::sum(energy, triangulation->get_communicator())
             : energy;
  }

  template <int dim>
  PointValues<dim>
  ElasticBody<dim>::point_values(const Point<dim>     &x,
                                 const Vector<double> &u) const
  {
    const auto outside = [&]()
    {
      std::ostringstream s;
      s << "Output/Points: the point (" << x << ") does not lie in body '"
        << parameters.name << "'";
      return InputError(s.str());
    };
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    // Displacement and stress at the unit point @p xi of @p cell.
    const auto evaluate = [&](const CellIterator &cell, const Point<dim> &xi)
    {
      const Quadrature<dim> at_point(std::vector<Point<dim>>{xi});
      FEValues<dim>         fe_values(
        *mapping, *fe, at_point, update_values | update_gradients);
      fe_values.reinit(cell);
      const FEValuesExtractors::Vector     displacement(0);
      std::vector<Tensor<1, dim>>          value(1);
      std::vector<SymmetricTensor<2, dim>> strain(1);
      fe_values[displacement].get_function_values(u, value);
      fe_values[displacement].get_function_symmetric_gradients(u, strain);

      PointValues<dim> result;
      result.x            = x;
      result.displacement = value[0];
      result.stress       = material.stress(strain[0]);
      if (reduced_volumetric_integration())
      {
        // The dilatation of the cell's reduced point, as in the assembly.
        FEValues<dim> fe_reduced(
          *mapping, *fe, *volumetric_quadrature, update_gradients);
        std::vector<double> div(1);
        fe_reduced.reinit(cell);
        fe_reduced[displacement].get_function_divergences(u, div);
        result.stress += material.lambda() * (div[0] - trace(strain[0])) *
                         unit_symmetric_tensor<dim>();
      }
      return result;
    };

    PointValues<dim> result;
    if (mesh_distributed)
    {
      // The process owning the cell around x evaluates and sends
      // (collective over the mesh's processes, which all ask for x).
      static_assert(dim == 2, "five values: u and the plane stress");
      using Values = std::array<double, 5>;
      Utilities::MPI::RemotePointEvaluation<dim> remote(1e-6, true);
      remote.reinit({x}, *triangulation, *mapping);
      if (!remote.all_points_found())
        throw outside();
      std::vector<Values> found, buffer;
      remote.template evaluate_and_process<Values>(
        found,
        buffer,
        [&](const ArrayView<Values> &values, const auto &cell_data)
        {
          for (unsigned int c = 0; c < cell_data.cells.size(); ++c)
          {
            const CellIterator cell(&*triangulation,
                                    cell_data.cells[c].first,
                                    cell_data.cells[c].second,
                                    &dof_handler);
            for (unsigned int k = cell_data.reference_point_ptrs[c];
                 k < cell_data.reference_point_ptrs[c + 1];
                 ++k)
            {
              const auto v =
                evaluate(cell, cell_data.reference_point_values[k]);
              values[k] = {{v.displacement[0],
                            v.displacement[1],
                            v.stress[0][0],
                            v.stress[1][1],
                            v.stress[0][1]}};
            }
          }
        });
      const Values &v     = found.at(0);
      result.x            = x;
      result.displacement = Tensor<1, dim>({v[0], v[1]});
      result.stress[0][0] = v[2];
      result.stress[1][1] = v[3];
      result.stress[0][1] = v[4];
    }
    else
    {
      // The cache version reports a point outside the mesh by an invalid
      // iterator instead of an assertion.
      const GridTools::Cache<dim> cache(*triangulation, *mapping);
      const auto found = GridTools::find_active_cell_around_point(cache, x);
      if (found.first.state() != IteratorState::valid)
        throw outside();
      result = evaluate(CellIterator(&*triangulation,
                                     found.first->level(),
                                     found.first->index(),
                                     &dof_handler),
                        found.second);
    }
    result.von_mises = material.von_mises(result.stress);
    return result;
  }

  template <int dim>
  double
  ElasticBody<dim>::min_cell_diameter() const
  {
    double h = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation->active_cell_iterators())
      if (computes(cell))
        h = std::min(h, cell->diameter(*mapping));
    return mesh_distributed
             ? Utilities::MPI::min(h, triangulation->get_communicator())
             : h;
  }

  template <int dim>
  std::pair<double, double>
  ElasticBody<dim>::extent_along(const Tensor<1, dim> &direction) const
  {
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const auto &cell : triangulation->active_cell_iterators())
      if (computes(cell))
        for (const unsigned int v : cell->vertex_indices())
        {
          lo = std::min(lo, cell->vertex(v) * direction);
          hi = std::max(hi, cell->vertex(v) * direction);
        }
    if (mesh_distributed)
    {
      lo = Utilities::MPI::min(lo, triangulation->get_communicator());
      hi = Utilities::MPI::max(hi, triangulation->get_communicator());
    }
    return {lo, hi};
  }

  template class ElasticBody<2>;
} // namespace ddcontact
