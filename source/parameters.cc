#include <deal.II/base/utilities.h>

#include <ddcontact/output_file.h>
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
  using parsing::message_of;
  using parsing::n_world_processes;
  using parsing::split;

  namespace
  {
    /** The keyword of a parameter-file line (lower case: "subsection",
     * "set", "end", ...) and the rest of the line, comments removed. */
    std::pair<std::string, std::string>
    split_keyword(const std::string &line)
    {
      const std::string text = Utilities::trim(line.substr(0, line.find('#')));
      std::string       keyword = text.substr(0, text.find(' '));
      std::transform(keyword.begin(),
                     keyword.end(),
                     keyword.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      return {keyword, Utilities::trim(text.substr(keyword.size()))};
    }

    /** Follow one line (split_keyword()) through the subsections: @p path
     * gains the subsection the line opens and loses the one it ends. */
    void
    follow_sections(std::vector<std::string>                  &path,
                    const std::pair<std::string, std::string> &line)
    {
      if (line.first == "subsection")
        path.push_back(line.second);
      else if (line.first == "end" && line.second.empty() && !path.empty())
        path.pop_back();
    }

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
      std::string section;
      for (const auto &p : path)
        section += (section.empty() ? "" : "/") + p;
      return section;
    }

    /** The top-level subsection "Domain decomposition" held every solver's
     * entries; they moved into "Contact solver". Its first entry is refused
     * with its new place, so that an old file fails in one line that says
     * what to write. */
    void
    refuse_retired_sections(const std::string &text)
    {
      std::istringstream       lines(text);
      std::string              line;
      std::vector<std::string> path;
      for (unsigned int n = 1; std::getline(lines, line); ++n)
      {
        const auto split            = split_keyword(line);
        const auto &[keyword, rest] = split;
        const bool retired =
          path.size() == 1 && path[0] == "Domain decomposition";
        if (retired && (keyword == "set" || keyword == "end"))
          throw InputError("line " + std::to_string(n) + ": " +
                           moved_solver_entry(
                             keyword == "set"
                               ? Utilities::trim(rest.substr(0, rest.find('=')))
                               : ""));
        follow_sections(path, split);
      }
    }

    /** deal.II names the parsed text "<input string>"; the message names
     * the file already, so "Line <n> of file <input string>" becomes
     * "line n" (of the file @p text, with its includes expanded), and the
     * subsection of that line is added. */
    std::string
    without_input_string(std::string message, const std::string &text)
    {
      // deal.II 9.4 on a subsection nobody declared: "Line <n> of file
      // <input string: There is no such subsection to be entered: A.B".
      const std::string unknown = "There is no such subsection to be entered: ";
      const auto        u       = message.find(unknown);
      const auto        l       = message.find("Line <");
      if (u != std::string::npos && l != std::string::npos)
      {
        std::string path = Utilities::trim(message.substr(u + unknown.size()));
        std::replace(path.begin(), path.end(), '.', '/');
        const std::string number =
          message.substr(l + 6, message.find('>', l) - l - 6);
        return "line " + number + ": there is no subsection '" + path +
               "' (misspelled? a body or contact pair also needs its name "
               "in Bodies or Contact pairs)";
      }
      const std::string tag  = " of file <input string>";
      const auto        at   = message.find(tag);
      const auto        line = message.find("Line <");
      if (at != std::string::npos)
        message.erase(at, tag.size());
      if (line != std::string::npos)
      {
        message.replace(line, 6, "line ");
        const auto close = message.find('>', line);
        if (close != std::string::npos)
        {
          message.erase(close, 1);
          const std::string section = section_at_line(
            text,
            std::atoi(message.substr(line + 5, close - line - 5).c_str()));
          if (!section.empty())
            message.insert(close, ", in subsection '" + section + "'");
        }
      }
      return message;
    }

    /** A parameter file with its `include` lines replaced by the included
     * files (found next to the including file, else from the working
     * directory), so that deal.II parses one bounded text. Cycles and
     * depths beyond 16 are refused, and the whole text is capped at 16 MiB:
     * a file that includes itself overflowed the stack, and `include
     * /dev/zero` read until memory ran out. */
    std::string
    expand_includes(const std::string        &filename,
                    std::vector<std::string> &chain,
                    std::size_t              &total)
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

      const auto        slash = filename.find_last_of('/');
      const std::string directory =
        (slash == std::string::npos) ? "" : filename.substr(0, slash + 1);
      std::istringstream lines(text);
      std::string        line, expanded;
      while (std::getline(lines, line))
      {
        const std::string trimmed = Utilities::trim(line);
        if (trimmed.rfind("include", 0) == 0 && trimmed.size() > 7 &&
            std::isspace(static_cast<unsigned char>(trimmed[7])))
        {
          std::string included = Utilities::trim(trimmed.substr(7));
          if (!included.empty() && included[0] != '/' &&
              std::filesystem::exists(directory + included))
            included = directory + included;
          expanded += expand_includes(included, chain, total);
        }
        else
          expanded += line + "\n";
      }
      chain.pop_back();
      return expanded;
    }

    /** The parameter text of @p filename with its includes. */
    std::string
    read_parameter_text(const std::string &filename)
    {
      std::vector<std::string> chain;
      std::size_t              total = 0;
      return expand_includes(filename, chain, total);
    }
  } // namespace

  void
  SceneParameters::declare(ParameterHandler               &prm,
                           const std::vector<std::string> &bodies,
                           const std::vector<std::string> &pairs)
  {
    prm.declare_entry("Scene name",
                      "scene",
                      Patterns::Anything(),
                      "Name of the scene, written to summary.json.");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::Anything(),
                      "Where VTU/PVD, CSV and summary.json go (created if "
                      "missing; overridden by --output).");
    prm.declare_entry("Bodies",
                      "",
                      Patterns::Anything(),
                      "Names of the bodies (comma separated); each needs a "
                      "subsection 'Body <name>'.");
    // The names are checked by parse_constants() (not x, y, not empty).
    prm.declare_entry("Constants",
                      "",
                      Patterns::Map(Patterns::Anything(),
                                    Patterns::Double(),
                                    0,
                                    Patterns::Map::max_int_value,
                                    ",",
                                    "="),
                      "Named constants for all expressions, 'r0=1e-3, "
                      "Delta=1.366e-3'.");
    prm.declare_entry("Threads",
                      "0",
                      Patterns::Integer(0),
                      "Number of threads (0: one per core).");
    prm.declare_entry("Contact pairs",
                      "",
                      Patterns::Anything(),
                      "Names of the contact pairs (comma separated); each "
                      "needs a subsection 'Contact pair <name>'.");

    prm.enter_subsection("Contact solver");
    ContactSolverParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Adaptation");
    AdaptationParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Loading");
    prm.declare_entry(
      "Steps",
      "1",
      Patterns::Integer(1, 100000),
      "Quasi-static load steps: the Dirichlet, Neumann and body-force "
      "expressions may use the load parameter t, which runs through k / "
      "Steps, k = 1, ..., Steps (t = 1 with one step). Each step is solved "
      "from the last (warm start); with friction the slip and the "
      "tangential traction carry over from step to step (doc/friction.md). "
      "Every step writes its output (bodies-<step>.vtu in the PVD time "
      "series, contact_<pair>_step<k>.csv).");
    prm.leave_subsection();

    prm.enter_subsection("Parallel");
    ParallelParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      // A Map that may name a body twice; the names are checked against
      // Bodies when the scene is parsed.
      prm.declare_entry("Points",
                        "",
                        Patterns::Map(Patterns::Anything(),
                                      Patterns::List(Patterns::Double(), 2, 2),
                                      0,
                                      Patterns::Map::max_int_value,
                                      ";",
                                      ":"),
                        "Points where displacement and stress are reported: "
                        "'body: x1, x2; body: x1, x2'.");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write VTU/PVD files for ParaView: the bodies "
                        "(solution.pvd) and every contact zone "
                        "(contact_<pair>.pvd); doc/output.md.");
      prm.declare_entry("Smoothed stresses",
                        "true",
                        Patterns::Bool(),
                        "Also write the L2 projection of the stresses onto "
                        "each body's finite element space "
                        "(sigma_11_smoothed, ..., von_mises_smoothed) next "
                        "to the per-cell stresses; not on distributed "
                        "(p4est) meshes.");
      prm.declare_entry("Verbosity",
                        "normal",
                        Patterns::Selection("normal|full"),
                        "normal: a DD line for the first five iterations, "
                        "then about ten per decade, and the last; full: a "
                        "line for every DD iteration (history.csv holds "
                        "every iteration either way).");
    }
    prm.leave_subsection();

    for (const auto &name : bodies)
    {
      prm.enter_subsection("Body " + name);
      BodyParameters::declare(prm);
      prm.leave_subsection();
    }
    for (const auto &name : pairs)
    {
      prm.enter_subsection("Contact pair " + name);
      ContactPairParameters::declare(prm);
      prm.leave_subsection();
    }
  }

  void
  SceneParameters::parse(ParameterHandler &prm)
  {
    scene_name       = prm.get("Scene name");
    output_directory = Utilities::trim(prm.get("Output directory"));
    if (output_directory.empty())
      throw InputError("Output directory: empty; name the directory for the "
                       "results (or give --output DIR)");
    body_names = split(prm.get("Bodies"), ',');
    constants  = parse_constants(prm.get("Constants"), "Constants");
    n_threads  = prm.get_integer("Threads");
    if (body_names.empty())
      throw InputError("Bodies: no body is listed");

    bodies.clear();
    for (const auto &name : body_names)
    {
      if (std::count(body_names.begin(), body_names.end(), name) > 1)
        throw InputError("Bodies: '" + name + "' is listed twice");
      BodyParameters body;
      body.name = name;
      prm.enter_subsection("Body " + name);
      body.parse(prm);
      prm.leave_subsection();
      // The boundary conditions are parsed here too, with the parser the
      // body uses, so that a scene read without error is fully checked.
      make_boundary_conditions(body, constants);
      bodies.push_back(body);
    }
    const auto body_parameters =
      [this](const std::string &name) -> const BodyParameters &
    {
      return *std::find_if(bodies.begin(),
                           bodies.end(),
                           [&](const BodyParameters &b)
                           { return b.name == name; });
    };

    prm.enter_subsection("Contact solver");
    contact_solver.parse(prm);
    prm.leave_subsection();

    prm.enter_subsection("Adaptation");
    adaptation.parse(prm);
    prm.leave_subsection();
    prm.enter_subsection("Loading");
    load_steps = prm.get_integer("Steps");
    prm.leave_subsection();
    // The combined algorithm (Fig. 2) interleaves single DD steps with the
    // refinement; the monolithic solver has no such steps.
    if (adaptation.mode == AdaptationMode::combined &&
        contact_solver.solver == ContactSolverType::monolithic)
      throw InputError("Adaptation/Mode: combined needs Contact "
                       "solver/Solver = dd-newton or dd; use Mode = "
                       "nested with the monolithic solver");
    prm.enter_subsection("Parallel");
    parallel.parse(prm, body_names);
    prm.leave_subsection();
    // An explicit request for p4est meshes that a quadrilateral body cannot
    // have is an error, not a silent fallback (triangles are always shared).
    if (parallel.mesh == MeshPartition::distributed &&
        n_world_processes() > 1 &&
        !parallel.process_groups(n_world_processes(), bodies.size()))
      throw InputError(
        "Parallel/Mesh: distributed, but every body is solved whole on one "
        "process (Body owners = auto with at most as many processes as "
        "bodies, or a list of single processes), so no mesh is split; use "
        "more processes, Body owners = all, or Mesh = auto");
    if (contact_solver.solver == ContactSolverType::monolithic &&
        n_world_processes() > 1)
      throw InputError("Contact solver/Solver: monolithic runs on one "
                       "process; use Solver = dd-newton or dd under mpirun");

    for (const auto &b : adaptation.bodies)
    {
      const auto it = std::find(body_names.begin(), body_names.end(), b);
      if (it == body_names.end())
        throw InputError("Adaptation/Bodies: '" + b +
                         "' is not one of the Bodies");
      // The BEM's basis is the trace of the FEM basis (26): linear or
      // quadratic boundary elements (degree 3 is refused with the Degree).
      if (adaptation.enabled() && adaptation.mode != AdaptationMode::uniform &&
          is_fem_bem(adaptation.estimator) && body_parameters(b).degree > 2)
        throw InputError(
          "Adaptation/Estimator: " + to_string(adaptation.estimator) +
          " builds a BEM with linear or quadratic elements, but body '" + b +
          "' has Element/Degree = " +
          std::to_string(body_parameters(b).degree) +
          "; use Estimator = kelly or residual, or Degree = 1 or 2");
    }

    contact_pairs.clear();
    for (const auto &name : split(prm.get("Contact pairs"), ','))
    {
      ContactPairParameters pair;
      pair.name = name;
      prm.enter_subsection("Contact pair " + name);
      pair.parse(prm);
      prm.leave_subsection();
      for (const auto &b : {pair.body_1, pair.body_2})
        if (std::find(body_names.begin(), body_names.end(), b) ==
            body_names.end())
          throw InputError("Contact pair " + name + ": body '" + b +
                           "' is not one of the Bodies");
      // A zone that is not among its body's Contact ids would get no
      // contact load: the run would end with zero force and no word.
      for (const auto &[entry, body_name, id] :
           {std::make_tuple(
              std::string("Boundary id 1"), pair.body_1, pair.boundary_id_1),
            std::make_tuple(
              std::string("Boundary id 2"), pair.body_2, pair.boundary_id_2)})
      {
        const auto &body = body_parameters(body_name);
        if (!make_boundary_conditions(body, constants).contact.count(id))
          throw InputError(
            "Contact pair " + name + "/" + entry + ": " + std::to_string(id) +
            " is not among the Contact "
            "ids of body '" +
            body_name + "' ('" + body.contact_ids + "'); add it there");
      }
      contact_pairs.push_back(pair);
    }
    // One formulation for all pairs: the solvers treat the pairs alike.
    for (const auto &pair : contact_pairs)
      if (pair.formulation != contact_pairs.front().formulation)
        throw InputError("Contact pair " + pair.name +
                         "/Formulation: " + selection_name(pair.formulation) +
                         ", but pair " + contact_pairs.front().name + " is " +
                         selection_name(contact_pairs.front().formulation) +
                         "; all pairs of a scene take the same formulation");
    const auto frictional =
      std::find_if(contact_pairs.begin(),
                   contact_pairs.end(),
                   [](const ContactPairParameters &pair)
                   { return pair.friction != FrictionLaw::none; });
    contact_solver.set_formulation(
      contact_pairs.empty() ||
        contact_pairs.front().formulation == ContactFormulation::exact,
      frictional == contact_pairs.end() ? std::string() : frictional->name);

    prm.enter_subsection("Output");
    {
      write_vtu                            = prm.get_bool("Write vtu");
      smoothed_stresses                    = prm.get_bool("Smoothed stresses");
      contact_solver.print_every_iteration = (prm.get("Verbosity") == "full");
      points.clear();
      for (const auto &item : split(prm.get("Points"), ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw InputError("Output/Points: '" + item +
                           "' is not 'body: x1, x2'");
        ReportPoint p;
        p.body = Utilities::trim(item.substr(0, colon));
        p.x    = parse_point(item.substr(colon + 1), "Output/Points");
        if (std::find(body_names.begin(), body_names.end(), p.body) ==
            body_names.end())
          throw InputError("Output/Points: '" + p.body +
                           "' is not one of the Bodies");
        points.push_back(p);
      }
    }
    prm.leave_subsection();
  }

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
        throw InputError("--set '" + assignment + "': " + message_of(e));
      }
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.leave_subsection();
    }
  } // namespace

  ParameterReader::ParameterReader(const std::string              &filename,
                                   const std::vector<std::string> &overrides)
  {
    const std::string text = read_parameter_text(filename);

    // First pass: only the list of bodies matters; everything else in the
    // file is skipped.
    std::vector<std::string> body_names, pair_names;
    {
      ParameterHandler prescan;
      prescan.declare_entry("Bodies", "", Patterns::Anything());
      prescan.declare_entry("Contact pairs", "", Patterns::Anything());
      try
      {
        prescan.parse_input_from_string(text, "", true);
      }
      catch (const std::exception &e)
      {
        throw InputError("parameter file '" + filename +
                         "': " + without_input_string(message_of(e), text));
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

    // Second pass: strict.
    SceneParameters::declare(prm, body_names, pair_names);
    try
    {
      refuse_retired_sections(text);
      prm.parse_input_from_string(text, "", false);
    }
    catch (const std::exception &e)
    {
      throw InputError("parameter file '" + filename +
                       "': " + without_input_string(message_of(e), text));
    }
    for (const auto &o : overrides)
      apply_override(prm, o);

    // A listed body or pair needs its subsection (in the file, or in an
    // override of one of its entries): without it every entry would take
    // its default, and the first complaint would name some default.
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

  namespace
  {
    /** The units every listing of the entries starts with. */
    void
    print_units(std::ostream &out)
    {
      out << "# Units: any consistent system. Entries marked [length] and "
             "[stress] are in its\n"
          << "# length and stress units; forces and energies are per unit "
             "thickness (plane\n"
          << "# strain). Each shipped scene states its units in its header "
             "(most use cm and\n"
          << "# MPa; doc/method.md, section 8).\n";
    }
  } // namespace

  void
  ParameterReader::print(std::ostream &out) const
  {
    print_units(out);
    prm.print_parameters(out, ParameterHandler::PRM);
  }

  void
  ParameterReader::write_used(const std::string &filename) const
  {
    OutputFile out(filename);
    prm.print_parameters(out.stream(), ParameterHandler::ShortPRM);
    out.commit();
  }

  void
  ParameterReader::print_defaults(std::ostream &out)
  {
    ParameterHandler prm;
    SceneParameters::declare(prm, {"<name>"}, {"<name>"});
    print_units(out);
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace ddcontact
