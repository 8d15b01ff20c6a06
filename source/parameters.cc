#include <deal.II/base/utilities.h>

#include <ddcontact/body/boundary_data_checks.h>
#include <ddcontact/output_file.h>
#include <ddcontact/parameter_messages.h>
#include <ddcontact/parameters.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <tuple>

namespace ddcontact
{
  using parameter_messages::follow_sections;
  using parameter_messages::joined;
  using parameter_messages::split_keyword;
  using parameter_messages::unknown_subsection;
  using parsing::edit_distance;
  using parsing::message_of;
  using parsing::n_world_processes;
  using parsing::split;

  namespace
  {
    /**
     * A parameter file with its `include` lines replaced by the included
     * files, the one text that deal.II parses, and where each of its lines
     * came from: deal.II's line numbers count the lines of this text, the
     * messages name the file the user wrote and the line in it.
     */
    struct ExpandedText
    {
      std::string text;

      /** A file read: its name as found (next to the including file, else
       * from the working directory), and the file and line of the include
       * that read it (includer -1: the parameter file itself). */
      struct File
      {
        std::string  name;
        int          includer;
        unsigned int include_line;
      };
      std::vector<File> files;

      /** Line @p first of the text (counted from 1) is line @p line of
       * files[file], and the lines after it follow up to the next run. */
      struct Run
      {
        unsigned int first;
        unsigned int file;
        unsigned int line;
      };
      std::vector<Run> runs;
      unsigned int     n_lines = 0;

      /** "common.prm, line 12 (included from scene.prm, line 1)" for line
       * @p n of the text; the parameter file's name for a line outside. */
      std::string
      location(const unsigned int n) const
      {
        if (n == 0 || n > n_lines || runs.empty())
          return files.front().name;
        const auto  run  = std::prev(std::upper_bound(
          runs.begin(),
          runs.end(),
          n,
          [](const unsigned int m, const Run &r) { return m < r.first; }));
        const File &file = files[run->file];
        std::string where =
          file.name + ", line " + std::to_string(run->line + (n - run->first));
        if (file.includer >= 0)
          where += " (included from " + files[file.includer].name + ", line " +
                   std::to_string(file.include_line) + ")";
        return where;
      }

      /** Line @p n of the text (empty outside). */
      std::string
      line(const unsigned int n) const
      {
        std::istringstream lines(text);
        std::string        line;
        for (unsigned int i = 0; i < n; ++i)
          if (!std::getline(lines, line))
            return "";
        return line;
      }
    };

    /** The subsections open before line @p n of @p text ("Body a/Mesh"):
     * deal.II names only the entry whose value does not match its pattern,
     * and our own checks name the section too. */
    std::string
    section_at_line(const std::string &text, const unsigned int n)
    {
      std::istringstream       lines(text);
      std::string              line;
      std::vector<std::string> path;
      for (unsigned int i = 1; i < n && std::getline(lines, line); ++i)
        follow_sections(path, split_keyword(line));
      return joined(path);
    }

    /**
     * For an entry @p entry that is not declared in the subsection
     * @p section (a path) and was one of the retired top-level subsection
     * "Domain decomposition" (issue 32): if @p section is "Contact solver" or
     * below, where the entry is now ("Contact solver/Gamma: this entry is now
     * 'Contact solver/Domain decomposition/Gamma'"), so that an old name
     * written in the new subsection gets its new path and not deal.II's
     * "not declared". Empty otherwise.
     */
    std::string
    moved_entry_in_contact_solver(const std::string &section,
                                  const std::string &entry)
    {
      if (section != "Contact solver" &&
          section.rfind("Contact solver/", 0) != 0)
        return "";
      // moved_solver_entry() words its answer for the old subsection:
      // "Domain decomposition/<entry> is now <place>" (<place> may be
      // "A (or B)"), or "... is retired: ..."; an entry it does not know
      // gets neither.
      const std::string old   = "Domain decomposition/" + entry + " ";
      const std::string moved = moved_solver_entry(entry);
      if (moved.rfind(old, 0) != 0)
        return "";
      std::string       rest   = moved.substr(old.size());
      const std::string is_now = "is now ";
      if (rest.rfind(is_now, 0) == 0)
      {
        const std::string place = rest.substr(is_now.size());
        const auto        other = place.find(" (or ");
        rest                    = is_now +
               ((other != std::string::npos && place.back() == ')')
                  ? "'" + place.substr(0, other) + "' (or '" +
                      place.substr(other + 5, place.size() - other - 6) + "')"
                  : "'" + place + "'");
      }
      return section + "/" + entry + ": this entry " + rest;
    }

    /** The top-level subsection "Domain decomposition" held every solver's
     * entries; they moved into "Contact solver". Its first entry is refused
     * with its new place, so that an old file fails in one line that says
     * what to write. */
    void
    refuse_retired_sections(const ExpandedText &input)
    {
      std::istringstream       lines(input.text);
      std::string              line;
      std::vector<std::string> path;
      for (unsigned int n = 1; std::getline(lines, line); ++n)
      {
        const auto split            = split_keyword(line);
        const auto &[keyword, rest] = split;
        const bool retired =
          path.size() == 1 && path[0] == "Domain decomposition";
        if (retired && (keyword == "set" || keyword == "end"))
          throw InputError("parameter file " + input.location(n) + ": " +
                           moved_solver_entry(
                             keyword == "set"
                               ? Utilities::trim(rest.substr(0, rest.find('=')))
                               : ""));
        follow_sections(path, split);
      }
    }

    /**
     * deal.II's message @p message about the text @p input, which it names
     * "<input string>", made one line that names the file and line the user
     * wrote ("parameter file common.prm, line 12 (included from scene.prm,
     * line 1), in subsection 'Body a': ..."). A subsection that @p prm does
     * not declare and an old solver entry in "Contact solver" get their own
     * words.
     */
    std::string
    file_error(std::string             message,
               const ExpandedText     &input,
               const ParameterHandler &prm)
    {
      const std::string input_string = " <input string>";
      const auto        l            = message.find("Line <");
      if (message.find("unequal numbers of 'subsection' and 'end'") !=
          std::string::npos)
      {
        const auto [n, what] =
          parameter_messages::unbalanced_sections(input.text, prm);
        return "parameter file " + input.location(n) + ": " + what;
      }
      if (l == std::string::npos)
      {
        for (auto at = message.find(input_string); at != std::string::npos;
             at      = message.find(input_string))
          message.erase(at, input_string.size());
        return "parameter file '" + input.files.front().name + "': " + message;
      }
      const auto         close = message.find('>', l);
      const unsigned int n =
        std::atoi(message.substr(l + 6, close - l - 6).c_str());
      // After "Line <n>": " of file <input string>: ...", or, for a
      // subsection nobody declared, " of file <input string: There is no
      // such subsection to be entered: A.B".
      const std::string of_file = " of file <input string";
      std::string       rest    = message.substr(close + 1);
      if (rest.rfind(of_file, 0) == 0)
        rest.erase(0, of_file.size());
      const auto start = rest.find_first_not_of(">: ");
      rest             = (start == std::string::npos) ? "" : rest.substr(start);

      const std::string where         = "parameter file " + input.location(n);
      const std::string section       = section_at_line(input.text, n);
      const auto [keyword, arguments] = split_keyword(input.line(n));
      if (keyword == "subsection" &&
          rest.find("no such subsection") != std::string::npos)
        return where + ": " + unknown_subsection(section, arguments, prm);
      if (keyword == "end" &&
          rest.find("no subsection to leave") != std::string::npos)
        return where + ": an 'end' without its 'subsection' (one too many)";
      if (keyword == "set" && rest.find("No entry with name") == 0)
      {
        const std::string entry =
          Utilities::trim(arguments.substr(0, arguments.find('=')));
        const std::string moved = moved_entry_in_contact_solver(section, entry);
        return where + ": " +
               (moved.empty()
                  ? parameter_messages::unknown_entry(section, entry, prm)
                  : moved);
      }
      std::string entry, value, pattern;
      if (keyword == "set" &&
          parameter_messages::split_value_message(rest, entry, value, pattern))
        return where + ": " +
               parameter_messages::bad_value(section, entry, value, pattern);
      return where +
             (section.empty() ? "" : ", in subsection '" + section + "'") +
             ": " + rest;
    }

    /** Read @p filename into @p input, its includes expanded (found next
     * to the including file, else from the working directory), @p
     * includer the file (index in input.files) and @p include_line the
     * line that includes it. Cycles and depths beyond 16 are refused, and
     * the whole text is capped at 16 MiB: a file that includes itself
     * overflowed the stack, and `include /dev/zero` read until memory ran
     * out. */
    void
    expand_includes(const std::string        &filename,
                    const int                 includer,
                    const unsigned int        include_line,
                    std::vector<std::string> &chain,
                    std::size_t              &total,
                    ExpandedText             &input)
    {
      constexpr std::size_t max_bytes = 16u << 20;
      const std::string     canonical =
        std::filesystem::weakly_canonical(filename).string();
      if (std::find(chain.begin(), chain.end(), canonical) != chain.end())
        throw InputError("parameter file '" + filename +
                         "' includes itself (through '" + chain.back() + "')");
      if (chain.size() >= 16)
        throw InputError("parameter file '" + filename +
                         "': includes nested deeper than 16 files");
      const std::string text =
        read_bounded_file(filename,
                          max_bytes,
                          chain.empty() ? "parameter file" : "included file");
      total += text.size();
      if (total > max_bytes)
        throw InputError("parameter file '" + filename +
                         "': with its includes more than 16 MiB");
      chain.push_back(canonical);
      const unsigned int file = input.files.size();
      input.files.push_back({filename, includer, include_line});

      const auto        slash = filename.find_last_of('/');
      const std::string directory =
        (slash == std::string::npos) ? "" : filename.substr(0, slash + 1);
      std::istringstream lines(text);
      std::string        line;
      bool               in_run = false;
      for (unsigned int n = 1; std::getline(lines, line); ++n)
      {
        const std::string trimmed = Utilities::trim(line);
        if (trimmed.rfind("include", 0) == 0 && trimmed.size() > 7 &&
            std::isspace(static_cast<unsigned char>(trimmed[7])))
        {
          std::string included = Utilities::trim(trimmed.substr(7));
          if (!included.empty() && included[0] != '/' &&
              std::filesystem::exists(directory + included))
            included = directory + included;
          expand_includes(included, file, n, chain, total, input);
          in_run = false;
        }
        else
        {
          if (!in_run)
            input.runs.push_back({input.n_lines + 1, file, n});
          in_run = true;
          input.text += line + "\n";
          ++input.n_lines;
        }
      }
      chain.pop_back();
    }

    /** The parameter text of @p filename with its includes. */
    ExpandedText
    read_parameter_text(const std::string &filename)
    {
      std::vector<std::string> chain;
      std::size_t              total = 0;
      ExpandedText             input;
      expand_includes(filename, -1, 0, chain, total, input);
      return input;
    }
  } // namespace

  namespace
  {
    /** Apply one "Section/Sub/Entry=value" override to prm. */
    void
    apply_override(ParameterHandler &prm, const std::string &assignment)
    {
      const auto eq = assignment.find('=');
      if (eq == std::string::npos)
        throw InputError("--set '" + assignment +
                         "': expected \"Section/Entry=value\"");
      const auto path =
        Utilities::split_string_list(assignment.substr(0, eq), '/');
      const std::string entry = assignment.substr(0, eq);
      if (path.empty() || entry.front() == '/' || entry.back() == '/' ||
          std::any_of(path.begin(),
                      path.end(),
                      [](const std::string &p) { return p.empty(); }))
        throw InputError("--set '" + assignment +
                         "': the entry path has an empty part; expected "
                         "\"Section/Entry=value\"");
      if (path.size() == 2 && path[0] == "Domain decomposition")
        throw InputError("--set '" + assignment +
                         "': " + moved_solver_entry(path[1]));
      const auto value = Utilities::trim(assignment.substr(eq + 1));
      // deal.II's enter_subsection() makes a subsection nobody declared,
      // and set() then calls a misspelled subsection an undeclared entry.
      std::string section;
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
      {
        if (!prm.subsection_path_exists(
              std::vector<std::string>(path.begin(), path.begin() + i + 1)))
          throw InputError("--set '" + assignment +
                           "': " + unknown_subsection(section, path[i], prm));
        section += (section.empty() ? "" : "/") + path[i];
      }
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.enter_subsection(path[i]);
      try
      {
        prm.set(path.back(), value);
      }
      catch (const std::exception &e)
      {
        for (unsigned int i = 0; i + 1 < path.size(); ++i)
          prm.leave_subsection();
        const bool undeclared =
          dynamic_cast<const ParameterHandler::ExcEntryUndeclared *>(&e) !=
          nullptr;
        const std::string moved =
          undeclared ? moved_entry_in_contact_solver(section, path.back()) : "";
        std::string       entry, bad, pattern;
        const std::string message = message_of(e);
        const std::string why =
          !moved.empty() ? moved
          : undeclared
            ? parameter_messages::unknown_entry(section, path.back(), prm)
          : parameter_messages::split_value_message(
              message, entry, bad, pattern)
            ? parameter_messages::bad_value(
                section, path.back(), value, pattern)
            : message;
        throw InputError("--set '" + assignment + "': " + why);
      }
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.leave_subsection();
    }

    /** First pass over the parameter text of @p input: only the lists of
     * bodies and contact pairs (with their overrides) matter; everything
     * else in the file is skipped. */
    void
    read_listed_names(const ExpandedText             &input,
                      const std::vector<std::string> &overrides,
                      std::vector<std::string>       &body_names,
                      std::vector<std::string>       &pair_names)
    {
      ParameterHandler prescan;
      prescan.declare_entry("Bodies", "", Patterns::Anything());
      prescan.declare_entry("Contact pairs", "", Patterns::Anything());
      try
      {
        prescan.parse_input_from_string(input.text, "", true);
      }
      catch (const std::exception &e)
      {
        throw InputError(file_error(message_of(e), input, prescan));
      }
      for (const auto &o : overrides)
        if (o.rfind("Bodies", 0) == 0 || o.rfind("Contact pairs", 0) == 0)
          apply_override(prescan, o);
      body_names = split(prescan.get("Bodies"), ',');
      pair_names = split(prescan.get("Contact pairs"), ',');
      for (const auto &name : body_names)
        check_name(name, "Bodies");
      for (const auto &name : pair_names)
        check_name(name, "Contact pairs");
    }

    /** A listed body or pair needs its subsection (in the file @p text, or
     * in an override of one of its entries): without it every entry would
     * take its default, and the first complaint would name some default. */
    void
    check_listed_sections(const std::string              &text,
                          const std::vector<std::string> &overrides,
                          const std::vector<std::string> &body_names,
                          const std::vector<std::string> &pair_names)
    {
      std::set<std::string> sections;
      std::istringstream    lines(text);
      std::string           line;
      while (std::getline(lines, line))
      {
        std::istringstream words(line.substr(0, line.find('#')));
        std::string        keyword, word, name;
        words >> keyword;
        std::transform(keyword.begin(),
                       keyword.end(),
                       keyword.begin(),
                       [](const unsigned char c) { return std::tolower(c); });
        if (keyword != "subsection")
          continue;
        while (words >> word)
          name += (name.empty() ? "" : " ") + word;
        sections.insert(name);
      }
      const auto has_section = [&](const std::string &section)
      {
        return sections.count(section) > 0 ||
               std::any_of(overrides.begin(),
                           overrides.end(),
                           [&](const std::string &o)
                           { return o.rfind(section + "/", 0) == 0; });
      };
      using Listed =
        std::tuple<std::string, std::string, const std::vector<std::string> &>;
      for (const auto &[entry, prefix, names] :
           {Listed("Bodies", "Body ", body_names),
            Listed("Contact pairs", "Contact pair ", pair_names)})
        for (const auto &name : names)
          if (!has_section(prefix + name))
            throw InputError(entry + ": '" + name +
                             "' is listed, but the file has no subsection '" +
                             prefix + name + "'");
    }
  } // namespace

  ParameterReader::ParameterReader(const std::string              &filename,
                                   const std::vector<std::string> &overrides)
  {
    const ExpandedText input = read_parameter_text(filename);
    const std::string &text  = input.text;

    std::vector<std::string> body_names, pair_names;
    read_listed_names(input, overrides, body_names, pair_names);

    // Second pass: strict.
    SceneParameters::declare(prm, body_names, pair_names);
    refuse_retired_sections(input);
    try
    {
      prm.parse_input_from_string(text, "", false);
    }
    catch (const std::exception &e)
    {
      throw InputError(file_error(message_of(e), input, prm));
    }
    for (const auto &o : overrides)
      apply_override(prm, o);

    check_listed_sections(text, overrides, body_names, pair_names);

    try
    {
      scene_parameters.parse(prm);
    }
    catch (const InputError &)
    {
      throw;
    }
    catch (const std::exception &e)
    {
      throw InputError("parameter file '" + filename + "': " + message_of(e));
    }

    // Mesh files are found relative to the parameter file.
    const auto        slash = filename.find_last_of('/');
    const std::string directory =
      (slash == std::string::npos) ? "" : filename.substr(0, slash + 1);
    for (auto &body : scene_parameters.bodies)
      if (body.mesh_type == MeshType::file && !body.mesh_file.empty() &&
          body.mesh_file[0] != '/' && std::ifstream(directory + body.mesh_file))
        body.mesh_file = directory + body.mesh_file;
  }

} // namespace ddcontact
