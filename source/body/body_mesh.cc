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
  namespace
  {
    /**
     * The cells of a Gmsh file in the 2.2 format (what gmsh writes for a
     * .geo here): refuse a file without 2D cells -- a .geo whose Physical
     * Curves have no Physical Surface makes one -- and second-order cells,
     * naming them, before GridIn fails without saying why.
     */
    void
    check_cell_types(const std::string &text,
                     const std::string &file,
                     const bool         from_geometry,
                     const std::string &what)
    {
      const auto at = text.find("$Elements");
      if (at == std::string::npos || text.find("$MeshFormat\n2") != 0)
        return; // another format: GridIn judges it
      std::istringstream in(text);
      in.seekg(at + 9);
      std::size_t n = 0;
      in >> n;
      unsigned int                                                  n_2d = 0;
      std::string                                                   line;
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> edge_group;
      std::getline(in, line);
      for (std::size_t i = 0; i < n && std::getline(in, line); ++i)
      {
        std::istringstream words(line);
        unsigned int       number = 0, type = 0;
        words >> number >> type;
        if (type == 9 || type == 10 || type == 16)
          throw InputError(what + ": '" + file + "' holds second-order " +
                           (type == 9 ? "triangles" : "quadrilaterals") +
                           ", which are not supported; mesh with first-order "
                           "cells (gmsh -order 1)");
        if (type == 2 || type == 3)
          ++n_2d;
        // A boundary edge in two physical groups: gmsh writes it once per
        // group, and each face would get one id or the other (a contact
        // curve also listed as Dirichlet lost three quarters of its points).
        unsigned int n_tags = 0, physical = 0, tag = 0, a = 0, b = 0;
        if (type == 1 && (words >> n_tags) && n_tags > 0 && (words >> physical))
        {
          for (unsigned int t = 1; t < n_tags; ++t)
            words >> tag;
          if (words >> a >> b)
          {
            const auto [it, inserted] =
              edge_group.emplace(std::minmax(a, b), physical);
            if (!inserted && it->second != physical)
              throw InputError(
                what + ": '" + file + "' puts the edge between its nodes " +
                std::to_string(a) + " and " + std::to_string(b) +
                " in the physical groups " + std::to_string(it->second) +
                " and " + std::to_string(physical) +
                "; give every curve one physical group (one boundary id)");
          }
        }
      }
      if (n_2d == 0)
        throw InputError(
          what + ": '" + file + "' gives no 2D cells" +
          (from_geometry
             ? ": it needs a Plane Surface, and with Physical Curves a "
               "Physical Surface too, or gmsh writes only the curves"
             : ""));
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
  BodyMesh<dim>::check_refinement_size(const std::string &step) const
  {
    // Each flagged cell becomes four, quadrilateral or triangle (the
    // closure of the one-irregularity adds a few, within the estimate's
    // factor); coarsening is left out, which errs on the safe side.
    double flagged = 0;
    for (const auto &cell : tria->active_cell_iterators())
      if (computes(cell) && cell->refine_flag_set())
        ++flagged;
    flagged = sum(flagged);
    if (flagged > 0)
      check_size(tria->n_global_active_cells() + 3. * flagged,
                 step + " of " + parameters.section() +
                   " would run out of memory (lower Adaptation/Max cells or "
                   "Max level)",
                 tria->n_global_active_cells());
  }

  template <int dim>
  void
  BodyMesh<dim>::check_size(const double       n_cells,
                            const std::string &entry,
                            const double       n_cells_now) const
  {
    // Unknowns per cell: 2 components times p^2 nodes per quadrilateral,
    // about half that per triangle. A body needs about 4 kB per unknown
    // with the direct solver (measured in Release: 556 MB at 1.3e5 and
    // 1780 MB at 5.3e5 unknowns, the factorization growing faster than
    // the unknowns).
    const double p      = parameters.degree;
    const double n_dofs = n_cells * (is_simplex() ? 1. : 2.) * p * p;
    // A refinement frees the old system before it builds the new one:
    // it needs the growth.
    const double bytes =
      4096. * n_dofs * (1. - std::min(1., n_cells_now / n_cells));
    const double memory  = available_memory();
    const bool   too_big = n_cells > 1e9 || (memory > 0 && bytes > memory);
    if (!too_big)
      return;
    std::ostringstream s;
    s << std::setprecision(3) << entry << ": the mesh would have about "
      << n_cells << " cells and " << n_dofs << " unknowns, needing about "
      << bytes / 1e9 << " GB more (4 kB per unknown), but " << memory / 1e9
      << " GB are available";
    if (n_cells_now > 0)
      throw OutOfMemoryError(s.str());
    throw InputError(s.str() + "; lower it");
  }

  template <int dim>
  void
  BodyMesh<dim>::read_file(const std::string &work_directory)
  {
    const std::string what = parameters.section() + "/Mesh/File";
    std::string       file = parameters.mesh_file;
    file_name              = file;
    n_merged               = 0;
    if (!std::ifstream(file))
      throw InputError(what + ": mesh file '" + file +
                       "' does not exist or cannot be read");

    const auto ends_with = [&](const std::string &suffix)
    {
      return file.size() >= suffix.size() &&
             file.compare(file.size() - suffix.size(), suffix.size(), suffix) ==
               0;
    };

    std::string source = what; // how read_bounded_file names the .msh
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
      {
        // The log is in the run's temporary directory, gone with the run:
        // its last error line goes into the message.
        std::ifstream in(log);
        std::string   line, last;
        while (std::getline(in, line))
          if (line.find("rror") != std::string::npos || last.empty())
            last = line;
        throw InputError(what + ": gmsh could not mesh '" + file + "'" +
                         (last.empty() ? "" : " (gmsh: " + last + ")"));
      }
      source = what + " (the mesh gmsh made of '" + file + "')";
      file   = msh;
    }
    else if (!ends_with(".msh"))
      throw InputError(what + ": '" + file +
                       "' is neither a Gmsh .msh nor a .geo file");

    // Reading takes about 7 times the file's size: the text and its
    // stream, GridIn's vertices and cells, the triangulation (measured, in
    // Release and Debug: an 87 MB file of 10^6 quadrilaterals raised the
    // peak memory by 570 MB). Refuse what would not fit before reading it.
    const double    read_cost = 7.;
    std::error_code error;
    const double    bytes  = std::filesystem::file_size(file, error);
    const double    memory = available_memory();
    if (!error && memory > 0 && read_cost * bytes > memory)
    {
      std::ostringstream s;
      s << std::setprecision(3) << what << ": reading '" << file_name << "' ("
        << bytes / 1e6 << " MB) needs about " << read_cost
        << " times its size, " << read_cost * bytes / 1e9 << " GB, but "
        << memory / 1e9 << " GB are available; use a coarser mesh";
      throw InputError(s.str());
    }

    try
    {
      // A mesh of 512 MiB has millions of cells: beyond what a body here
      // can factorize; refuse before reading it (and anything not a
      // file).
      std::string text = read_bounded_file(file, 512u << 20, source);
      check_cell_types(text, file_name, file != file_name, what);
      std::istringstream in(text);
      text = std::string(); // the stream holds its own copy
      GridIn<dim> grid_in;
      grid_in.attach_triangulation(*tria);
      try
      {
        grid_in.read_msh(in);
      }
      catch (const std::bad_alloc &)
      {
        throw;
      }
      catch (const std::exception &)
      {
        throw InputError(what + ": cannot read '" + file_name +
                         "' as a Gmsh mesh");
      }
    }
    catch (const std::bad_alloc &)
    {
      throw OutOfMemoryError(what + ": out of memory while reading '" +
                             file_name + "'; use a coarser mesh");
    }

    check_cell_areas();
    merge_coincident_vertices();
  }

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
