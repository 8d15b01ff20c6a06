#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ddcontact/body/body_mesh.h>
#include <ddcontact/body/circular_boundaries.h>
#include <ddcontact/interruption.h>
#include <deal.II/distributed/p4est_wrappers.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <signal.h>
#include <spawn.h>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

// BodyMesh: reading a mesh file (Gmsh .geo or .msh), and the size checks
// against the memory.
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

    /** Mesh the geometry @p geo with the gmsh binary into
     * @p work_directory, in the legacy ASCII format that GridIn reads
     * without the Gmsh API; return the name of the .msh file. Under mpirun
     * every process meshes (gmsh is deterministic) into a file of its own.
     */
    std::string
    mesh_with_gmsh(const std::string &geo,
                   const std::string &work_directory,
                   const std::string &body_name,
                   const std::string &what)
    {
      const std::string rank =
        Utilities::MPI::job_supports_mpi() &&
            Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1
          ? "." +
              std::to_string(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD))
          : "";
      const std::string msh = work_directory + "/" + body_name + rank + ".msh";
      const std::string log =
        work_directory + "/" + body_name + rank + ".gmsh.log";
      read_bounded_file(geo, 16u << 20, what); // size and kind only
      const double timeout = gmsh_time_limit();
      const int    status  = run_without_shell(
        {"gmsh", "-2", "-format", "msh22", "-v", "2", "-o", msh, geo},
        log,
        timeout);
      if (status == -2)
        throw InputError(what + ": gmsh did not finish meshing '" + geo +
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
        throw InputError(what + ": gmsh could not mesh '" + geo + "'" +
                         (last.empty() ? "" : " (gmsh: " + last + ")"));
      }
      return msh;
    }

    /** Refuse a mesh file @p file (named @p file_name in the input) that
     * would not fit into memory, before reading it. Reading takes about 7
     * times the file's size: the text and its stream, GridIn's vertices and
     * cells, the triangulation (measured, in Release and Debug: an 87 MB
     * file of 10^6 quadrilaterals raised the peak memory by 570 MB). */
    void
    check_memory_for_reading(const std::string &file,
                             const std::string &file_name,
                             const std::string &what)
    {
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
      file   = mesh_with_gmsh(file, work_directory, parameters.name, what);
      source = what + " (the mesh gmsh made of '" + file_name + "')";
    }
    else if (!ends_with(".msh"))
      throw InputError(what + ": '" + file +
                       "' is neither a Gmsh .msh nor a .geo file");

    check_memory_for_reading(file, file_name, what);

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

  // The members defined here (BodyMesh<2> itself is instantiated in
  // body_mesh.cc).
  template void
  BodyMesh<2>::check_refinement_size(const std::string &) const;
  template void
  BodyMesh<2>::check_size(double, const std::string &, double) const;
  template void
  BodyMesh<2>::read_file(const std::string &);
} // namespace ddcontact
