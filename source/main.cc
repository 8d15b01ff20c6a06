// ddcontact: contact of linear elastic bodies in plane strain (doc/method.md).
// This file only reads the command line and claims the output directory;
// everything else is in the library.

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
#include <memory>

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
           "  --print-parameters-json    the same in JSON, with every entry's "
           "pattern\n"
           "  --version                  the git revision and deal.II "
           "version\n"
           "  --help                     this text\n";
  }

  /** What the command line asks for. */
  struct CommandLine
  {
    // --help or --version: print that and stop, whatever else is given.
    bool                     help = false, version = false;
    bool                     print_parameters = false, json = false;
    std::string              parameter_file;
    bool                     output_given = false;
    std::string              output_directory;
    std::vector<std::string> overrides;
  };

  /** Read the command line; an option in error throws, except after
   * --help or --version, which end the reading. */
  CommandLine
  parse_command_line(const int argc, char **argv)
  {
    using ddcontact::InputError;
    CommandLine command_line;
    for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h")
      {
        command_line.help = true;
        return command_line;
      }
      else if (arg == "--version")
      {
        command_line.version = true;
        return command_line;
      }
      else if (arg == "--print-parameters")
        command_line.print_parameters = true;
      else if (arg == "--print-parameters-json")
        command_line.print_parameters = command_line.json = true;
      else if (arg == "--output" || arg == "--set")
      {
        if (i + 1 == argc)
          throw InputError(arg + " needs a value");
        if (arg == "--output")
        {
          command_line.output_directory = argv[++i];
          command_line.output_given     = true;
        }
        else
          command_line.overrides.emplace_back(argv[++i]);
      }
      else if (arg.rfind("--", 0) == 0)
        throw InputError("unknown option '" + arg + "' (see --help)");
      else if (command_line.parameter_file.empty())
        command_line.parameter_file = arg;
      else
        throw InputError("more than one parameter file given ('" +
                         command_line.parameter_file + "', '" + arg + "')");
    }
    return command_line;
  }
  /** Print what the command line asks for without a parameter file (the
   * usage, the version, the default parameters) on the first process
   * (@p root) and return the exit code; -1 if it asks for more. */
  int
  print_without_reading(const CommandLine &command_line, const bool root)
  {
    if (command_line.help)
    {
      if (root)
        print_usage(std::cout);
      return 0;
    }
    if (command_line.version)
    {
      if (root)
        std::cout << ddcontact::version_banner() << std::endl;
      return 0;
    }
    if (command_line.print_parameters && command_line.parameter_file.empty())
    {
      if (root)
        ddcontact::ParameterReader::print_defaults(std::cout,
                                                   command_line.json);
      return 0;
    }
    if (command_line.parameter_file.empty())
    {
      if (root)
        print_usage(std::cerr);
      return 2;
    }
    return -1;
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
  // The claim on the output directory, once the scene is checked; it
  // outlives the run so that an error can still be recorded there.
  std::unique_ptr<RunRecord> record;
  try
  {
    // SIGINT and SIGTERM end the run at the end of its current step.
    interruption::install_handlers();

    const CommandLine command_line = parse_command_line(argc, argv);
    if (const int code = print_without_reading(command_line, root); code >= 0)
      return code;

    const std::string       &parameter_file = command_line.parameter_file;
    std::vector<std::string> overrides      = command_line.overrides;
    if (command_line.output_given)
      overrides.push_back("Output directory=" + command_line.output_directory);
    const ParameterReader reader(parameter_file, overrides);
    if (command_line.print_parameters)
    {
      if (root)
        reader.print(std::cout, command_line.json);
      return 0;
    }

    // --output DIR as written: the parameter reader trims an entry's
    // spaces, and 'RES ' went into RES, replacing the results there.
    SceneParameters scene = reader.scene();
    if (command_line.output_given)
      scene.output_directory = command_line.output_directory;
    if (scene.n_threads > 0)
      MultithreadInfo::set_thread_limit(scene.n_threads);
    std::error_code error;
    if (std::filesystem::exists(scene.output_directory, error) &&
        !std::filesystem::is_directory(scene.output_directory, error))
      throw InputError("Output directory: '" + scene.output_directory +
                       "' is a file, not a directory; name a directory "
                       "(--output DIR)");

    // Every entry, mesh and expression is checked before the output
    // directory is touched: a refused run changes nothing on disk.
    Simulation simulation(scene, std::cout);
    simulation.setup();

    // One line naming the directory, not the library's text with errno.
    std::filesystem::create_directories(scene.output_directory, error);
    if (error || !std::filesystem::is_directory(scene.output_directory))
      throw InputError("Output directory: cannot create '" +
                       scene.output_directory + "' (" + error.message() + ")");
    // The lock, the removal of the earlier run's own files and the
    // "running" summary come before anything else is written there.
    record = std::make_unique<RunRecord>(
      scene, std::vector<std::string>{parameter_file});
    if (root)
      reader.write_used(record->parameter_file());

    simulation.run();
  }
  catch (...)
  {
    const auto error = std::current_exception();
    if (record)
    {
      const auto [code, message] = FatalError::classify(error);
      record->close_after_error(RunRecord::status_of_exit_code(code), message);
    }
    return fatal_error.report(error);
  }
  return 0;
}
