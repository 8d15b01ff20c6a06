#include <deal.II/base/mpi.h>

#include <ddcontact/io/json.h>
#include <ddcontact/io/run_record.h>
#include <ddcontact/output_file.h>
#include <ddcontact/parameter_tools.h>
#include <ddcontact/version.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <signal.h>
#include <sstream>
#include <unistd.h>

namespace ddcontact
{
  namespace
  {
    namespace fs = std::filesystem;

    const std::string lock_name = ".ddcontact.lock";

    /** @p text with the characters that mean something in a regular
     * expression escaped. */
    std::string
    literal(const std::string &text)
    {
      static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
      return std::regex_replace(text, special, R"(\$&)");
    }

    /** The names that @p scene's run may write into its directory (the
     * writers: OutputWriter, ContactZoneWriter, RunReport, the parameter
     * dump @p dump and the signal's record), with their temporary
     * names. */
    std::regex
    output_names(const SceneParameters &scene, const std::string &dump)
    {
      std::string bodies, pairs;
      for (const auto &name : scene.body_names)
        bodies += (bodies.empty() ? "" : "|") + literal(name);
      for (const auto &pair : scene.contact_pairs)
        pairs += (pairs.empty() ? "" : "|") + literal(pair.name);
      const std::string step = R"(-\d{4,})";
      std::string       any =
        "summary\\.json|history\\.csv|statistics\\.csv|solution\\.pvd|"
        "force_displacement\\.csv|" +
        literal(dump) + "|bodies" + step + "\\.pvtu";
      if (!bodies.empty())
        any += "|(" + bodies + ")" + step + R"((\.\d+)?\.vtu|cells_()" +
               bodies + ")" + step + "\\.csv";
      if (!pairs.empty())
        any += "|contact_(" + pairs + R"()((_step\d{4,}|_\d{4,})?\.csv|)" +
               step + R"(\.vtu|\.pvd))";
      return std::regex("(" + any + ")(\\.partial)?|summary\\.json\\.signal");
    }

    /** The process id in a lock file, or 0 (empty or unreadable). */
    long
    lock_owner(const std::string &lock_file)
    {
      std::ifstream in(lock_file);
      long          pid = 0;
      in >> pid;
      return pid;
    }

    /** Whether @p pid is a running ddcontact (a process id that the
     * system gave to another program since is not). */
    bool
    runs_ddcontact(const long pid)
    {
      if (kill(pid, 0) != 0 && errno == ESRCH)
        return false;
      std::ifstream command("/proc/" + std::to_string(pid) + "/cmdline");
      std::string   text;
      if (!command || !std::getline(command, text, '\0'))
        return true; // no /proc: trust the id
      return text.find("ddcontact") != std::string::npos;
    }

    /** Up to three names of @p names, and how many more. */
    std::string
    some_of(const std::vector<std::string> &names)
    {
      std::string text;
      for (unsigned int i = 0; i < names.size() && i < 3; ++i)
        text += (i > 0 ? ", " : "") + names[i];
      if (names.size() > 3)
        text += " and " + std::to_string(names.size() - 3) + " more";
      return text;
    }

    /** Sort the regular files in @p directory (the lock and the manifest
     * aside) into @p ours, the earlier run's files (those its manifest
     * lists and that are as it left them), and @p foreign, everything else
     * (sorted): someone else's, as are the @p input_files, whoever wrote
     * them. */
    void
    sort_earlier_files(const std::string              &directory,
                       const std::vector<std::string> &input_files,
                       std::vector<std::string>       &ours,
                       std::vector<std::string>       &foreign)
    {
      std::set<fs::path> inputs;
      for (const auto &file : input_files)
      {
        std::error_code error;
        inputs.insert(fs::weakly_canonical(file, error));
      }
      const auto      earlier = run_manifest::read(directory);
      std::error_code error;
      for (const auto &entry : fs::directory_iterator(directory, error))
      {
        const std::string name = entry.path().filename().string();
        std::error_code   e;
        if (!entry.is_regular_file(e) || name == lock_name ||
            name == run_manifest::file_name ||
            name.rfind(lock_name + ".", 0) == 0)
          continue;
        const auto listed = earlier.files.find(name);
        const bool unchanged =
          listed != earlier.files.end() &&
          listed->second.count(run_manifest::stamp(entry.path())) > 0;
        const bool input = inputs.count(fs::weakly_canonical(entry, e)) > 0;
        if (!input && (unchanged || earlier.temporaries.count(name) > 0))
          ours.push_back(name);
        else
          foreign.push_back(name);
      }
      std::sort(foreign.begin(), foreign.end());
    }
  } // namespace

  RunRecord::RunRecord(const SceneParameters          &scene,
                       const std::vector<std::string> &input_files)
    : directory(scene.output_directory)
    , lock_file(scene.output_directory + "/" + lock_name)
    , parameter_dump(scene.output_directory + "/parameters.prm")
  {
    // Messages to every process: I an input error, W a write failure, and
    // N a note for the console.
    std::string refusal, note;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      refusal = take_lock(note);
      if (holds_lock)
        refusal = clear_earlier_run(scene, input_files, note);
    }
    if (!refusal.empty() && holds_lock)
    {
      run_manifest::close();
      fs::remove(lock_file);
      holds_lock = false;
    }
    // Every process ends alike.
    refusal = Utilities::MPI::broadcast(MPI_COMM_WORLD, refusal, 0);
    if (!refusal.empty())
    {
      if (refusal[0] == 'W')
        throw WriteError(refusal.substr(1));
      throw InputError(refusal.substr(1));
    }
    parameter_dump =
      Utilities::MPI::broadcast(MPI_COMM_WORLD, parameter_dump, 0);
    std::cout << note << std::flush;
    run_manifest::open(directory);
  }

  std::string
  RunRecord::take_lock(std::string &note)
  {
    // The lock is a complete file linked into place: link() fails if
    // the name exists, and a full disk fails before the lock exists.
    std::string       refusal;
    const std::string mine = lock_file + "." + std::to_string(getpid());
    std::FILE        *f    = std::fopen(mine.c_str(), "w");
    const bool        made =
      f && std::fprintf(f, "%ld\n", static_cast<long>(getpid())) > 0;
    if (f == nullptr || std::fclose(f) != 0 || !made)
      refusal = "Wcannot write in the output directory '" + directory +
                "' (read-only, or the disk full?)";
    for (int attempt = 0; refusal.empty() && attempt < 2 && !holds_lock;
         ++attempt)
    {
      if (link(mine.c_str(), lock_file.c_str()) == 0)
      {
        holds_lock = true;
        break;
      }
      if (errno != EEXIST)
        refusal = "Wcannot write in the output directory '" + directory +
                  "' (" + std::strerror(errno) + ")";
      else if (const long owner = lock_owner(lock_file);
               owner > 0 && runs_ddcontact(owner))
        refusal = "IOutput directory: '" + directory +
                  "' is in use by another run (process " +
                  std::to_string(owner) +
                  ", lock file .ddcontact.lock); wait for it to end or "
                  "choose another --output";
      else
      {
        note += "Output directory: took over the lock file " + lock_name +
                (owner > 0 ? " of process " + std::to_string(owner) +
                               ", which no longer runs"
                           : ", which names no process (left by a run "
                             "that met a full disk?)") +
                "\n";
        fs::remove(lock_file);
      }
    }
    std::remove(mine.c_str());
    return refusal;
  }

  std::string
  RunRecord::clear_earlier_run(const SceneParameters          &scene,
                               const std::vector<std::string> &input_files,
                               std::string                    &note)
  {
    std::vector<std::string> ours, foreign;
    sort_earlier_files(directory, input_files, ours, foreign);
    const auto is_foreign = [&](const std::string &name)
    { return std::binary_search(foreign.begin(), foreign.end(), name); };
    if (is_foreign("parameters.prm"))
      parameter_dump = directory + "/parameters.used.prm";

    const std::regex writes =
      output_names(scene, fs::path(parameter_dump).filename().string());
    std::vector<std::string> in_the_way, left;
    for (const auto &name : foreign)
      (std::regex_match(name, writes) ? in_the_way : left).push_back(name);
    if (!in_the_way.empty())
      return "IOutput directory: '" + directory + "' holds " +
             std::to_string(in_the_way.size()) +
             " file(s) that this run would write but that no ddcontact run "
             "wrote there, or that changed since (" +
             some_of(in_the_way) +
             "); move them away or choose another --output";

    std::error_code error;
    for (const auto &name : ours)
      fs::remove(fs::path(directory) / name, error);
    fs::remove(fs::path(directory) / run_manifest::file_name, error);
    if (!left.empty())
      note += "Output directory: " + std::to_string(left.size()) +
              " file(s) there that this run did not write are left as "
              "they are (" +
              some_of(left) + ")\n";
    run_manifest::open(directory);
    try
    {
      write_json_file(Json{{"scene", scene.scene_name},
                           {"code_revision", git_revision()},
                           {"status", "running"},
                           {"warnings", Json::array()}},
                      directory + "/summary.json");
    }
    catch (const std::exception &e)
    {
      return std::string("W") + e.what();
    }
    return "";
  }

  RunRecord::~RunRecord()
  {
    run_manifest::close();
    if (holds_lock)
      std::filesystem::remove(lock_file);
  }

  void
  RunRecord::close_after_error(const std::string &status,
                               const std::string &message) const noexcept
  {
    if (!holds_lock)
      return;
    try
    {
      const std::string summary = directory + "/summary.json";
      Json              json;
      {
        std::ifstream in(summary);
        json = Json::parse(in, nullptr, false);
      }
      if (json.is_discarded() || !json.is_object())
        json = Json::object();
      if (json.value("status", std::string("running")) != "running")
        return;
      json["status"] = status;
      json["error"]  = message;
      write_json_file(json, summary);
    }
    catch (...)
    {
      // The error that ended the run is reported by the caller.
    }
  }

  std::string
  RunRecord::status_of_exit_code(const int code)
  {
    switch (code)
    {
      case exit_codes::success:
        return "completed";
      case exit_codes::bad_input:
        return "bad_input";
      case exit_codes::iteration_failed:
        return "diverged";
      case exit_codes::target_not_reached:
        return "target_not_reached";
      case exit_codes::interrupted:
        return "interrupted";
      case exit_codes::write_failed:
        return "write_failed";
      case exit_codes::out_of_memory:
        return "out_of_memory";
      default:
        return "internal_error";
    }
  }
} // namespace ddcontact
