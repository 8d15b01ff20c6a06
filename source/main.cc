// ddcontact: frictionless contact of linear elastic bodies in plane strain,
// by penalty and parallel Neumann domain decomposition. This file only reads
// the command line; everything else is in the library.

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <ddcontact/fatal_error.h>
#include <ddcontact/interruption.h>
#include <ddcontact/io/run_record.h>
#include <ddcontact/output_file.h>
#include <ddcontact/parameters.h>
#include <ddcontact/simulation.h>
#include <ddcontact/version.h>

#include <filesystem>
#include <iostream>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "Usage: ddcontact [options] FILE.prm\n"
           "  --output DIR               write results to DIR (overrides "
           "'Output directory')\n"
           "  --set \"Section/Entry=value\" override one entry of FILE.prm "
           "(repeatable)\n"
           "  --print-parameters         print all entries with their "
           "documentation\n"
           "                             (of FILE.prm if given, else the "
           "defaults)\n"
           "  --version                  the git revision and deal.II "
           "version\n"
           "  --help                     this text\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace ddcontact;
  // MPI lives until main returns: an error is reported while every process
  // can still be reached (FatalError).
  Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, numbers::invalid_unsigned_int);
  const FatalError fatal_error;
  // Under mpirun every process holds every body and solves the ones it
  // owns (BodyDistribution); the first process alone prints.
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
  {
    // SIGINT and SIGTERM end the run at the end of its current step.
    interruption::install_handlers();

    std::string              parameter_file, output_directory;
    std::vector<std::string> overrides;
    bool                     print_parameters = false, output_given = false;
    for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h")
      {
        if (root)
          print_usage(std::cout);
        return 0;
      }
      else if (arg == "--version")
      {
        if (root)
          std::cout << version_banner() << std::endl;
        return 0;
      }
      else if (arg == "--print-parameters")
        print_parameters = true;
      else if (arg == "--output" || arg == "--set")
      {
        if (i + 1 == argc)
          throw InputError(arg + " needs a value");
        if (arg == "--output")
        {
          output_directory = argv[++i];
          output_given     = true;
        }
        else
          overrides.emplace_back(argv[++i]);
      }
      else if (arg.rfind("--", 0) == 0)
        throw InputError("unknown option '" + arg + "' (see --help)");
      else if (parameter_file.empty())
        parameter_file = arg;
      else
        throw InputError("more than one parameter file given ('" +
                         parameter_file + "', '" + arg + "')");
    }

    if (print_parameters && parameter_file.empty())
    {
      if (root)
        ParameterReader::print_defaults(std::cout);
      return 0;
    }
    if (parameter_file.empty())
    {
      if (root)
        print_usage(std::cerr);
      return 2;
    }

    if (output_given)
      overrides.push_back("Output directory=" + output_directory);
    const ParameterReader reader(parameter_file, overrides);
    if (print_parameters)
    {
      if (root)
        reader.print(std::cout);
      return 0;
    }

    const auto &scene = reader.scene();
    if (scene.n_threads > 0)
      MultithreadInfo::set_thread_limit(scene.n_threads);
    // One line naming the directory, not the library's text with errno.
    std::error_code error;
    std::filesystem::create_directories(scene.output_directory, error);
    if (error || !std::filesystem::is_directory(scene.output_directory))
      throw InputError("Output directory: cannot create '" +
                       scene.output_directory + "' (" + error.message() + ")");
    // The lock, the removal of an earlier run's results and the "running"
    // summary come before anything else is written there.
    const RunRecord record(scene.output_directory, scene.scene_name);
    if (root)
      reader.write_used(scene.output_directory + "/parameters.prm");

    Simulation simulation(scene, std::cout);
    simulation.run();
  }
  catch (...)
  {
    return fatal_error.report(std::current_exception());
  }
  return 0;
}
