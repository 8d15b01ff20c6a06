#include <deal.II/base/mpi.h>

#include <ddcontact/io/json.h>
#include <ddcontact/io/run_record.h>
#include <ddcontact/output_file.h>
#include <ddcontact/parameter_tools.h>
#include <ddcontact/version.h>

#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <signal.h>
#include <unistd.h>

namespace ddcontact
{
  namespace
  {
    /** Whether @p name is a file that a run writes into its directory. */
    bool
    is_result_file(const std::string &name)
    {
      const auto ends_with = [&](const std::string &tail)
      {
        return name.size() >= tail.size() &&
               name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
      };
      return name == "summary.json" || name == "history.csv" ||
             name == "statistics.csv" || name == "parameters.prm" ||
             (name.rfind("contact_", 0) == 0 && ends_with(".csv")) ||
             (name.rfind("cells_", 0) == 0 && ends_with(".csv")) ||
             ends_with(".vtu") || ends_with(".pvtu") || ends_with(".pvd") ||
             ends_with(".partial");
    }

    /** The process id in a lock file, or 0. */
    long
    lock_owner(const std::string &lock_file)
    {
      std::ifstream in(lock_file);
      long          pid = 0;
      in >> pid;
      return pid;
    }
  } // namespace

  RunRecord::RunRecord(const std::string &directory, const std::string &scene)
    : lock_file(directory + "/.ddcontact.lock")
  {
    std::string refusal;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      // O_EXCL in effect: the first run to create the file holds it.
      for (int attempt = 0; attempt < 2 && !holds_lock; ++attempt)
      {
        if (std::FILE *f = std::fopen(lock_file.c_str(), "wx"))
        {
          std::fprintf(f, "%ld\n", static_cast<long>(getpid()));
          holds_lock = (std::fclose(f) == 0);
          if (!holds_lock)
            refusal = "W" + std::string("cannot write '") + lock_file + "'";
          break;
        }
        const long owner = lock_owner(lock_file);
        if (owner > 0 && kill(owner, 0) != 0 && errno == ESRCH)
          std::filesystem::remove(lock_file); // left by a run that died
        else if (std::filesystem::exists(lock_file))
        {
          refusal = "IOutput directory: '" + directory +
                    "' is in use by another run (process " +
                    std::to_string(owner) +
                    ", lock file .ddcontact.lock); wait for it to end or "
                    "choose another --output";
          break;
        }
        else
        {
          refusal = "Wcannot write in the output directory '" + directory +
                    "' (read-only?)";
          break;
        }
      }
      if (holds_lock)
      {
        std::error_code error;
        for (const auto &entry :
             std::filesystem::directory_iterator(directory, error))
          if (entry.is_regular_file() &&
              is_result_file(entry.path().filename().string()))
            std::filesystem::remove(entry.path(), error);
        try
        {
          write_json_file(Json{{"scene", scene},
                               {"code_revision", git_revision()},
                               {"status", "running"},
                               {"warnings", Json::array()}},
                          directory + "/summary.json");
        }
        catch (const std::exception &e)
        {
          refusal = std::string("W") + e.what();
        }
      }
    }
    if (!refusal.empty() && holds_lock)
    {
      std::filesystem::remove(lock_file);
      holds_lock = false;
    }
    // Every process ends alike: I an input error, W a write failure.
    refusal = Utilities::MPI::broadcast(MPI_COMM_WORLD, refusal, 0);
    if (refusal.empty())
      return;
    if (refusal[0] == 'W')
      throw WriteError(refusal.substr(1));
    throw InputError(refusal.substr(1));
  }

  RunRecord::~RunRecord()
  {
    if (holds_lock)
      std::filesystem::remove(lock_file);
  }
} // namespace ddcontact
