#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <tuple>

namespace ddcontact
{
  namespace
  {
    /** deal.II's exception texts span several lines; we want one. */
    std::string
    one_line(const std::string &text)
    {
      std::string out;
      bool        space = false;
      for (const char c : text)
        if (c == '\n' || c == '\r' || c == '\t' || c == ' ')
          space = !out.empty();
        else
        {
          if (space)
            out += ' ';
          out += c;
          space = false;
        }
      return out;
    }

    std::string
    message_of(const std::exception &e)
    {
      if (const auto *dealii_exc = dynamic_cast<const ExceptionBase *>(&e))
      {
        std::ostringstream s;
        dealii_exc->print_info(s);
        return one_line(s.str());
      }
      return one_line(e.what());
    }

    /** deal.II names the parsed text "<input string>"; the message names
     * the file already, so "Line <n> of file <input string>" becomes
     * "line n" (of the file with its includes expanded). */
    std::string
    without_input_string(std::string message)
    {
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
          message.erase(close, 1);
      }
      return message;
    }

    /** The entry values of each option and their enum values: the one
     * table that parsing and printing share. */
    template <typename Enum>
    const std::vector<std::pair<std::string, Enum>> &
    selection_names();

#define DDCONTACT_SELECTION(Enum, ...)                               \
  template <>                                                        \
  const std::vector<std::pair<std::string, Enum>> &selection_names() \
  {                                                                  \
    static const std::vector<std::pair<std::string, Enum>> names = { \
      __VA_ARGS__};                                                  \
    return names;                                                    \
  }

    DDCONTACT_SELECTION(ContactSolverType,
                        {"dd", ContactSolverType::dd},
                        {"monolithic", ContactSolverType::monolithic})
    DDCONTACT_SELECTION(RelaxationType,
                        {"fixed", RelaxationType::fixed},
                        {"auto", RelaxationType::automatic},
                        {"aitken", RelaxationType::aitken},
                        {"anderson", RelaxationType::anderson})
    DDCONTACT_SELECTION(StoppingTest,
                        {"residual", StoppingTest::residual},
                        {"paper", StoppingTest::paper},
                        {"both", StoppingTest::both})
    DDCONTACT_SELECTION(InitialGuess,
                        {"zero", InitialGuess::zero},
                        {"winkler", InitialGuess::elastic_layer})
    DDCONTACT_SELECTION(AdaptationMode,
                        {"none", AdaptationMode::none},
                        {"combined", AdaptationMode::combined},
                        {"nested", AdaptationMode::nested},
                        {"uniform", AdaptationMode::uniform})
    DDCONTACT_SELECTION(EstimatorType,
                        {"fem-bem", EstimatorType::fem_bem},
                        {"fem-bem-scaled", EstimatorType::fem_bem_scaled},
                        {"kelly", EstimatorType::kelly})
    DDCONTACT_SELECTION(MarkingType,
                        {"threshold", MarkingType::threshold},
                        {"fraction", MarkingType::fraction},
                        {"doerfler", MarkingType::doerfler})
    DDCONTACT_SELECTION(GapType,
                        {"expression", GapType::expression},
                        {"geometric", GapType::geometric})
    DDCONTACT_SELECTION(PenaltyType,
                        {"relative", PenaltyType::relative},
                        {"absolute", PenaltyType::absolute})
    DDCONTACT_SELECTION(BodySolverType,
                        {"direct", BodySolverType::direct},
                        {"cg-amg", BodySolverType::cg_amg})
#undef DDCONTACT_SELECTION

    /** The enum value of an entry that a Patterns::Selection has checked
     * already. */
    template <typename Enum>
    Enum
    parse_selection(const std::string &value)
    {
      for (const auto &[name, e] : selection_names<Enum>())
        if (name == value)
          return e;
      AssertThrow(false, ExcMessage("unexpected selection '" + value + "'"));
      return Enum();
    }

    template <typename Enum>
    std::string
    selection_name(const Enum value)
    {
      for (const auto &[name, e] : selection_names<Enum>())
        if (e == value)
          return name;
      return "";
    }

    unsigned int
    n_world_processes()
    {
      // A program that never initialized MPI (a test) is one process.
      return Utilities::MPI::job_supports_mpi()
               ? Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
               : 1;
    }

    std::vector<std::string>
    split(const std::string &text, const char delimiter)
    {
      std::vector<std::string> parts;
      for (const auto &p : Utilities::split_string_list(text, delimiter))
        if (!p.empty())
          parts.push_back(p);
      return parts;
    }

    unsigned int
    parse_boundary_id(const std::string &text, const std::string &what)
    {
      try
      {
        const int id = Utilities::string_to_int(Utilities::trim(text));
        if (id < 0 || id >= 255)
          throw InputError("");
        return static_cast<unsigned int>(id);
      }
      catch (...)
      {
        throw InputError(what + ": '" + text +
                         "' is not a boundary id (a non-negative integer)");
      }
    }

    double
    parse_double(const std::string &text, const std::string &what)
    {
      try
      {
        std::size_t  pos   = 0;
        const auto   t     = Utilities::trim(text);
        const double value = std::stod(t, &pos);
        if (pos != t.size() || !std::isfinite(value))
          throw InputError("");
        return value;
      }
      catch (...)
      {
        throw InputError(what + ": '" + text + "' is not a finite number");
      }
    }
  } // namespace

  std::string
  to_string(const RelaxationType value)
  {
    return selection_name(value);
  }

  std::string
  to_string(const AdaptationMode value)
  {
    return selection_name(value);
  }

  std::string
  to_string(const EstimatorType value)
  {
    return selection_name(value);
  }

  std::string
  to_string(const MarkingType value)
  {
    return selection_name(value);
  }

  void
  check_name(const std::string &name, const std::string &what)
  {
    // Names become file names (<body>-NNNN.vtu, contact_<pair>.csv) and
    // subsection names: a '/' or '..' would write elsewhere, and very long
    // names exceed the file system's limit.
    const bool safe =
      !name.empty() && name.size() <= 64 && name[0] != '.' &&
      std::all_of(name.begin(),
                  name.end(),
                  [](const char c)
                  {
                    return std::isalnum(static_cast<unsigned char>(c)) ||
                           c == '_' || c == '-' || c == '.';
                  });
    if (!safe)
      throw InputError(what + ": '" + name.substr(0, 80) +
                       (name.size() > 80 ? "...'" : "'") +
                       " is not a usable name (1 to 64 letters, digits, '_', "
                       "'-' or '.', not starting with '.')");
  }

  std::string
  read_bounded_file(const std::string &filename,
                    const std::size_t  max_bytes,
                    const std::string &what)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    // Devices, pipes and directories have no size to check in advance
    // (/dev/zero never ends): only regular files are read.
    if (!fs::is_regular_file(filename, error))
      throw InputError(what + " '" + filename + "' " +
                       (fs::exists(filename, error)
                          ? "is not a regular file"
                          : "does not exist or cannot be read"));
    const auto size = fs::file_size(filename, error);
    if (error || size > max_bytes)
      throw InputError(what + " '" + filename + "' has " +
                       std::to_string(size) + " bytes, more than the " +
                       std::to_string(max_bytes) + " bytes allowed");
    std::ifstream in(filename, std::ios::binary);
    if (!in)
      throw InputError(what + " '" + filename + "' cannot be read");
    std::string text(size, '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(in.gcount()));
    return text;
  }

  namespace
  {
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

  Point<2>
  parse_point(const std::string &text, const std::string &what)
  {
    const auto parts = Utilities::split_string_list(text, ',');
    if (parts.size() != 2)
      throw InputError(what + ": '" + text + "' is not a point 'x1, x2'");
    return Point<2>(parse_double(parts[0], what), parse_double(parts[1], what));
  }

  Constants
  parse_constants(const std::string &text, const std::string &what)
  {
    Constants constants;
    for (const auto &item : split(text, ','))
    {
      const auto eq = item.find('=');
      if (eq == std::string::npos)
        throw InputError(what + ": '" + item + "' is not 'name=value'");
      const std::string name = Utilities::trim(item.substr(0, eq));
      if (name.empty() || name == "x" || name == "y")
        throw InputError(what + ": '" + item + "' has no usable name");
      constants[name] = parse_double(item.substr(eq + 1), what);
    }
    return constants;
  }

  std::shared_ptr<Function<2>>
  make_function(const std::string &expression,
                const unsigned int n_components,
                const Constants   &constants,
                const std::string &what)
  {
    const auto parts = Utilities::split_string_list(expression, ';');
    if (parts.size() != n_components)
      throw InputError(what + ": '" + expression + "' must have " +
                       std::to_string(n_components) +
                       " expression(s) separated by ';'");
    auto function = std::make_shared<FunctionParser<2>>(n_components);
    // muparser compiles lazily: evaluate once so that a syntax error shows
    // up here, with the entry's name, and not in a worker thread. deal.II
    // prints muparser's diagnosis to std::cerr before it throws; capture it
    // for our one-line message instead.
    std::ostringstream diagnosis;
    auto *const        cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
    try
    {
      function->initialize("x,y", parts, constants);
      Vector<double> values(n_components);
      function->vector_value(Point<2>(0.123, 0.456), values);
    }
    catch (...)
    {
      std::cerr.rdbuf(cerr_buffer);
      std::string message = diagnosis.str();
      const auto  start   = message.find("Message:");
      message =
        (start == std::string::npos)
          ? ""
          : message.substr(start + 8, message.find('\n', start) - start - 8);
      throw InputError(what + ": cannot parse '" + expression + "'" +
                       (message.empty() ? "" : ": " + one_line(message)));
    }
    std::cerr.rdbuf(cerr_buffer);
    return function;
  }

  BoundaryConditions<2>
  make_boundary_conditions(const BodyParameters &body,
                           const Constants      &constants)
  {
    BoundaryConditions<2> bc;
    const std::string     section = body.section() + "/";

    for (const auto &item : split(body.dirichlet, '|'))
    {
      const std::string what = section + "Dirichlet";
      const auto        c1   = item.find(':');
      const auto c2 = (c1 == std::string::npos) ? c1 : item.find(':', c1 + 1);
      if (c2 == std::string::npos)
        throw InputError(what + ": '" + item +
                         "' is not 'id: components: expr_x; expr_y'");
      const auto id         = parse_boundary_id(item.substr(0, c1), what);
      const auto components = Utilities::trim(item.substr(c1 + 1, c2 - c1 - 1));
      if (components != "x" && components != "y" && components != "xy")
        throw InputError(what + ": components '" + components +
                         "' must be x, y or xy");
      if (bc.dirichlet.count(id))
        throw InputError(what + ": boundary id " + std::to_string(id) +
                         " appears twice");
      DirichletCondition<2> d;
      d.mask = ComponentMask(
        std::vector<bool>{components.find('x') != std::string::npos,
                          components.find('y') != std::string::npos});
      d.displacement   = make_function(item.substr(c2 + 1), 2, constants, what);
      bc.dirichlet[id] = d;
    }

    for (const auto &item : split(body.neumann, '|'))
    {
      const std::string what = section + "Neumann";
      const auto        c1   = item.find(':');
      if (c1 == std::string::npos)
        throw InputError(what + ": '" + item + "' is not 'id: expr_x; expr_y'");
      const auto id = parse_boundary_id(item.substr(0, c1), what);
      if (bc.neumann.count(id) || bc.dirichlet.count(id))
        throw InputError(what + ": boundary id " + std::to_string(id) +
                         " already has a boundary condition");
      bc.neumann[id] = make_function(item.substr(c1 + 1), 2, constants, what);
    }

    for (const auto &item : split(body.contact_ids, ','))
    {
      const std::string what = section + "Contact ids";
      const auto        id   = parse_boundary_id(item, what);
      if (bc.neumann.count(id) || bc.dirichlet.count(id))
        throw InputError(what + ": boundary id " + std::to_string(id) +
                         " already has a Dirichlet or Neumann condition");
      bc.contact.insert(id);
    }

    if (!Utilities::trim(body.body_force).empty())
      bc.body_force =
        make_function(body.body_force, 2, constants, section + "Body force");

    // A body without any prescribed displacement can move rigidly: its
    // stiffness matrix is singular and the body problem (20) has no
    // unique solution.
    if (bc.dirichlet.empty())
      throw InputError(section +
                       "Dirichlet: the body has no Dirichlet boundary, so its "
                       "stiffness is singular; prescribe a displacement on at "
                       "least one boundary id");
    bool has_x = false, has_y = false;
    for (const auto &[id, d] : bc.dirichlet)
    {
      has_x = has_x || d.mask[0];
      has_y = has_y || d.mask[1];
    }
    if (!(has_x && has_y))
      throw InputError(
        section + "Dirichlet: only the " + (has_x ? "x" : "y") +
        " component is prescribed anywhere, so the body can "
        "slide rigidly; prescribe the other component somewhere");
    return bc;
  }

  void
  BodyParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      prm.declare_entry(
        "Type",
        "rectangle",
        Patterns::Selection("rectangle|file"),
        "rectangle: a subdivided rectangle with boundary ids "
        "0 (left), 1 (right), 2 (bottom), 3 (top); file: a Gmsh "
        "mesh (.msh, or .geo meshed by the gmsh binary) whose "
        "physical curve tags become boundary ids.");
      prm.declare_entry(
        "Corner 1",
        "0, 0",
        Patterns::Anything(),
        "Lower left corner of the rectangle (x1, x2) [length].");
      prm.declare_entry(
        "Corner 2",
        "1, 1",
        Patterns::Anything(),
        "Upper right corner of the rectangle (x1, x2) [length].");
      prm.declare_entry("Subdivisions",
                        "1, 1",
                        Patterns::List(Patterns::Integer(1), 2, 2),
                        "Cells of the rectangle in x1 and x2.");
      prm.declare_entry("File",
                        "",
                        Patterns::Anything(),
                        "Gmsh file (.msh or .geo), relative to the parameter "
                        "file's directory or absolute.");
      prm.declare_entry("Initial refinement",
                        "0",
                        Patterns::Integer(0, 20),
                        "Number of global refinements of the initial mesh.");
      prm.declare_entry("Refinement box",
                        "",
                        Patterns::Anything(),
                        "'x0, y0, x1, y1': cells that touch this box are "
                        "refined Box refinement more times after the global "
                        "refinement (quadrilaterals; hanging nodes).");
      prm.declare_entry(
        "Box refinement",
        "0",
        Patterns::Integer(0, 20),
        "Number of refinements of the cells in Refinement box.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Element");
    {
      prm.declare_entry("Cell type",
                        "quadrilateral",
                        Patterns::Selection("quadrilateral|triangle"),
                        "quadrilateral: FE_Q with hanging-node constraints; "
                        "triangle: FE_SimplexP (a rectangle is split into "
                        "triangles; a Gmsh file must hold triangles).");
      prm.declare_entry("Degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Polynomial degree of the displacement (1 or 2).");
      prm.declare_entry(
        "Volumetric integration",
        "full",
        Patterns::Selection("full|reduced"),
        "full: the bilinear form a_a (11) with (p+1)^2 Gauss points; "
        "reduced: its volumetric part lambda div u div v with one Gauss "
        "point per cell (selective reduced integration, B-bar on "
        "parallelograms), which removes the volumetric locking of Q1 as "
        "nu -> 1/2. Quadrilaterals of degree 1 only (Q2 locks far less).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      prm.declare_entry(
        "Young's modulus", "2.1e5", Patterns::Double(), "E [stress], > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        Patterns::Double(),
                        "nu, in (-1, 0.5) (plane strain).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    {
      prm.declare_entry("Dirichlet",
                        "",
                        Patterns::Anything(),
                        "Prescribed displacements (5) (Gamma_u): 'id: "
                        "components: expr_x; expr_y | id: ...' with "
                        "components x, y or xy; expressions in x, y and the "
                        "scene's constants [length].");
      prm.declare_entry("Neumann",
                        "",
                        Patterns::Anything(),
                        "Prescribed tractions p (6) (Gamma_p): 'id: expr_x; "
                        "expr_y | ...' [stress]. Ids with no condition are "
                        "traction free.");
      prm.declare_entry("Contact ids",
                        "",
                        Patterns::Anything(),
                        "Boundary ids that form the possible contact zone S "
                        "(comma separated).");
      prm.declare_entry("Body force",
                        "",
                        Patterns::Anything(),
                        "Body force 'expr_x; expr_y' [force/volume]; empty "
                        "for none.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    {
      prm.declare_entry("Type",
                        "direct",
                        Patterns::Selection("direct|cg-amg"),
                        "direct: UMFPACK factorization, computed once per "
                        "mesh and reused for every right-hand side; cg-amg: "
                        "conjugate gradients with Trilinos ML AMG (large "
                        "meshes).");
      prm.declare_entry("Tolerance",
                        "1e-12",
                        Patterns::Double(0),
                        "Relative residual tolerance of cg-amg.");
      prm.declare_entry("Max iterations",
                        "10000",
                        Patterns::Integer(1),
                        "Iteration limit of cg-amg.");
    }
    prm.leave_subsection();
  }

  void
  BodyParameters::parse(ParameterHandler &prm)
  {
    const std::string section = this->section() + "/";
    prm.enter_subsection("Mesh");
    {
      mesh_type = prm.get("Type");
      corner_1  = parse_point(prm.get("Corner 1"), section + "Mesh/Corner 1");
      corner_2  = parse_point(prm.get("Corner 2"), section + "Mesh/Corner 2");
      const auto n = Utilities::string_to_int(
        Utilities::split_string_list(prm.get("Subdivisions")));
      subdivisions       = {static_cast<unsigned int>(n[0]),
                            static_cast<unsigned int>(n[1])};
      mesh_file          = prm.get("File");
      initial_refinement = prm.get_integer("Initial refinement");
      box_refinement     = prm.get_integer("Box refinement");
      // The cells these entries would make are checked against the
      // machine's memory when the mesh is built (ElasticBody::make_mesh).
      const std::string box = Utilities::trim(prm.get("Refinement box"));
      refinement_box.clear();
      for (const auto &c : Utilities::split_string_list(box))
        refinement_box.push_back(
          parse_double(c, section + "Mesh/Refinement box"));
      if (!box.empty() && refinement_box.size() != 4)
        throw InputError(section + "Mesh/Refinement box: '" + box +
                         "' is not 'x0, y0, x1, y1'");
      if (mesh_type == "rectangle" &&
          !(corner_1[0] < corner_2[0] && corner_1[1] < corner_2[1]))
        throw InputError(section +
                         "Mesh/Corner 2: must lie above and to the right of "
                         "Corner 1");
      if (mesh_type == "file" && Utilities::trim(mesh_file).empty())
        throw InputError(section + "Mesh/File: empty, but Mesh/Type = file");
    }
    prm.leave_subsection();

    prm.enter_subsection("Element");
    {
      cell_type              = prm.get("Cell type");
      degree                 = prm.get_integer("Degree");
      volumetric_integration = prm.get("Volumetric integration");
      if (volumetric_integration == "reduced" &&
          !(cell_type == "quadrilateral" && degree == 1))
        throw InputError(section +
                         "Element/Volumetric integration: reduced needs Cell "
                         "type = quadrilateral and Degree = 1 (for triangles "
                         "or degree 2 use full; near nu = 1/2 use Degree = "
                         "2)");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      material.youngs_modulus = prm.get_double("Young's modulus");
      material.poisson_ratio  = prm.get_double("Poisson's ratio");
      // Stiffness entries are E times O(1) factors summed over cells: at
      // 1e300 they overflow. Any unit system fits within 1e-30..1e30.
      if (!(material.youngs_modulus >= 1e-30 &&
            material.youngs_modulus <= 1e30))
        throw InputError(section + "Material/Young's modulus: E = " +
                         prm.get("Young's modulus") +
                         " must be positive and within 1e-30 .. 1e30");
      if (!(material.poisson_ratio > -1. && material.poisson_ratio < 0.5))
        throw InputError(section + "Material/Poisson's ratio: nu = " +
                         prm.get("Poisson's ratio") + " must lie in (-1, 0.5)");
      // Volumetric locking: with lambda/mu = 2 nu/(1 - 2 nu) >= 100 the
      // fully integrated linear elements (Q1, P1) can only represent nearly
      // divergence-free fields by moving almost nothing, and the answer is
      // silently far too stiff (the contact force of the paper's scene is
      // 30 % off at nu = 0.499, 200 % at 0.4999, on 4 cells across).
      const double nu = material.poisson_ratio;
      if (degree == 1 && volumetric_integration == "full" &&
          2. * nu / (1. - 2. * nu) >= 100.)
        throw InputError(
          section +
          "Material/Poisson's ratio: nu = " + prm.get("Poisson's ratio") +
          " makes linear elements lock (lambda/mu >= 100); set Element/"
          "Degree = 2" +
          (cell_type == "quadrilateral"
             ? " or Element/Volumetric integration = reduced"
             : ""));
    }
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    {
      dirichlet   = prm.get("Dirichlet");
      neumann     = prm.get("Neumann");
      contact_ids = prm.get("Contact ids");
      body_force  = prm.get("Body force");
    }
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    {
      solver                = parse_selection<BodySolverType>(prm.get("Type"));
      solver_tolerance      = prm.get_double("Tolerance");
      solver_max_iterations = prm.get_integer("Max iterations");
    }
    prm.leave_subsection();
  }

  void
  ContactPairParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Body 1",
                      "",
                      Patterns::Anything(),
                      "Body whose zone S_1 carries the contact integral.");
    prm.declare_entry("Boundary id 1",
                      "0",
                      Patterns::Integer(0, 254),
                      "Boundary id of S_1 on body 1.");
    prm.declare_entry("Body 2", "", Patterns::Anything(), "The opposite body.");
    prm.declare_entry("Boundary id 2",
                      "0",
                      Patterns::Integer(0, 254),
                      "Boundary id of S_2 on body 2.");
    prm.declare_entry("Gap type",
                      "expression",
                      Patterns::Selection("expression|geometric"),
                      "expression: f_n(x) given below (the paper's scene, "
                      "both zones on one line); geometric: f_n(x) = (P(x) - "
                      "x) . n_1, the distance to the orthogonal projection "
                      "P(x) of x on S_2 (curved surfaces).");
    prm.declare_entry("Gap",
                      "0",
                      Patterns::Anything(),
                      "Initial normal gap f_n(x) [length], an expression in "
                      "x, y and the constants (Gap type = expression).");
    prm.declare_entry("Penalty type",
                      "relative",
                      Patterns::Selection("relative|absolute"),
                      "relative: theta = c H / E_1 as in the paper; "
                      "absolute: theta = Penalty [length/stress].");
    prm.declare_entry("Penalty",
                      "0.05",
                      Patterns::Double(),
                      "c (relative) or theta (absolute) of the penalty (15); "
                      "> 0.");
    prm.declare_entry("Thickness",
                      "0",
                      Patterns::Double(0),
                      "H of theta = c H / E_1 [length]; 0: the extent of "
                      "body 1 along the contact normal.");
    prm.declare_entry("Gauss points",
                      "3",
                      Patterns::Integer(1, 10),
                      "Gauss points on each piece of the common refinement "
                      "of S_1 and S_2.");
  }

  void
  ContactPairParameters::parse(ParameterHandler &prm)
  {
    const std::string section = "Contact pair " + name + "/";
    body_1                    = Utilities::trim(prm.get("Body 1"));
    body_2                    = Utilities::trim(prm.get("Body 2"));
    boundary_id_1             = prm.get_integer("Boundary id 1");
    boundary_id_2             = prm.get_integer("Boundary id 2");
    gap_type                  = parse_selection<GapType>(prm.get("Gap type"));
    gap_expression            = prm.get("Gap");
    penalty_type = parse_selection<PenaltyType>(prm.get("Penalty type"));
    penalty      = prm.get_double("Penalty");
    thickness    = prm.get_double("Thickness");
    n_gauss      = prm.get_integer("Gauss points");
    if (!(penalty > 0.))
      throw InputError(section + "Penalty: " + prm.get("Penalty") +
                       " must be positive");
    if (body_1 == body_2)
      throw InputError(section + "Body 2: '" + body_2 +
                       "' is the same body as Body 1");
  }

  void
  DDParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Solver",
      "dd",
      Patterns::Selection("dd|monolithic"),
      "dd: the parallel Neumann domain decomposition (20)-(21); "
      "monolithic: semismooth Newton on the penalised problem "
      "(16) for all bodies at once (the reference).");
    prm.declare_entry("Relaxation",
                      "fixed",
                      Patterns::Selection("fixed|auto|aitken|anderson"),
                      "fixed: u^{k+1} = gamma u~ + (1-gamma) u^k (21); auto: "
                      "fixed with the optimal gamma estimated from the "
                      "contact-zone compliance; aitken: "
                      "dynamic gamma (Aitken's delta^2); anderson: Anderson "
                      "acceleration of the fixed-point map u^k -> u~^{k+1}.");
    prm.declare_entry("Gamma",
                      "0.02",
                      Patterns::Double(),
                      "Relaxation gamma of (21), in (0, 1]; the first gamma "
                      "of aitken and the mixing of anderson.");
    prm.declare_entry("Anderson depth",
                      "8",
                      Patterns::Integer(1, 50),
                      "Number of previous iterates anderson combines.");
    prm.declare_entry(
      "Stopping test",
      "residual",
      Patterns::Selection("residual|paper|both"),
      "residual: ||u~^{k+1}_n - u^k_n|| <= eps_r ||u~^{k+1}_n|| "
      "on S; paper: ||u^{k+1}_an - u^k_an|| <= eps_u "
      "||u^{k+1}_an|| for each body (weaker by a factor "
      "gamma); both: either.");
    prm.declare_entry("eps_u",
                      "1.5e-3",
                      Patterns::Double(0),
                      "Tolerance of the paper's increment test.");
    prm.declare_entry("eps_residual",
                      "1e-8",
                      Patterns::Double(0),
                      "Tolerance of the residual test.");
    prm.declare_entry("Max iterations",
                      "5000",
                      Patterns::Integer(1),
                      "Maximum number of DD iterations.");
    prm.declare_entry("Initial guess",
                      "winkler",
                      Patterns::Selection("zero|winkler"),
                      "zero, or the elastic-layer (Winkler) model: contact "
                      "pressure from the contact-free solution with springs "
                      "E'/H in series with the penalty (replaced by zero "
                      "when one DD step moves it ten times more than the "
                      "zero guess, e.g. a plate bending onto a base).");
    prm.declare_entry("Augmented Lagrangian",
                      "false",
                      Patterns::Bool(),
                      "Outer Uzawa update of the contact pressure, so that "
                      "the penetration of the penalty goes to zero.");
    prm.declare_entry("AL tolerance",
                      "1e-3",
                      Patterns::Double(0),
                      "Stop the Uzawa updates when max penetration <= this "
                      "times the largest normal displacement on S.");
    prm.declare_entry("AL max updates",
                      "30",
                      Patterns::Integer(1),
                      "Maximum number of Uzawa updates.");
    prm.declare_entry("Write every iteration",
                      "false",
                      Patterns::Bool(),
                      "Write contact_<pair>_<k>.csv at every iteration.");
    prm.declare_entry("Max Newton iterations",
                      "50",
                      Patterns::Integer(1),
                      "Iteration limit of the monolithic Newton solver.");
  }

  void
  DDParameters::parse(ParameterHandler &prm)
  {
    solver         = parse_selection<ContactSolverType>(prm.get("Solver"));
    relaxation     = parse_selection<RelaxationType>(prm.get("Relaxation"));
    gamma          = prm.get_double("Gamma");
    anderson_depth = prm.get_integer("Anderson depth");
    stopping       = parse_selection<StoppingTest>(prm.get("Stopping test"));
    eps_u          = prm.get_double("eps_u");
    eps_residual   = prm.get_double("eps_residual");
    max_iterations = prm.get_integer("Max iterations");
    initial_guess  = parse_selection<InitialGuess>(prm.get("Initial guess"));
    augmented_lagrangian  = prm.get_bool("Augmented Lagrangian");
    al_tolerance          = prm.get_double("AL tolerance");
    al_max_updates        = prm.get_integer("AL max updates");
    write_every_iteration = prm.get_bool("Write every iteration");
    n_newton              = prm.get_integer("Max Newton iterations");
    if (!(gamma > 0. && gamma <= 1.))
      throw InputError("Domain decomposition/Gamma: " + prm.get("Gamma") +
                       " must lie in (0, 1]");
  }

  void
  AdaptationParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Mode",
      "none",
      Patterns::Selection("none|combined|nested|uniform"),
      "none: the meshes stay as built; combined: the paper's algorithm "
      "(Fig. 2), one DD step (20)-(21) then one adaptation step per cycle, "
      "until the DD test holds and no cell is marked; nested: DD to "
      "convergence on each mesh, then one adaptation step; uniform: DD to "
      "convergence, then every cell of the adapted bodies is refined "
      "(Max cycles times).");
    prm.declare_entry("Bodies",
                      "",
                      Patterns::Anything(),
                      "The adapted bodies (comma separated); the paper "
                      "adapts Omega_2 only.");
    prm.declare_entry(
      "Estimator",
      "fem-bem",
      Patterns::Selection("fem-bem|fem-bem-scaled|kelly"),
      "fem-bem: eta_FB of (27) as printed, ||sigma_B - sigma_F||_e/|e| over "
      "||sigma_B||/|Omega|; fem-bem-scaled: the same with square roots of "
      "the areas (local RMS stress error over global RMS stress, which "
      "decreases with h); kelly: the Kelly gradient-jump estimator (no "
      "BEM).");
    prm.declare_entry("Marking",
                      "threshold",
                      Patterns::Selection("threshold|fraction|doerfler"),
                      "threshold: refine cells with eta > delta (the "
                      "paper); fraction: the Fraction of cells with the "
                      "largest eta; doerfler: the fewest cells whose "
                      "eta^2 sum to Fraction of the total.");
    prm.declare_entry("Delta",
                      "0.1",
                      Patterns::Double(0),
                      "Threshold delta of (27) (dimensionless).");
    prm.declare_entry("Fraction",
                      "0.3",
                      Patterns::Double(0, 1),
                      "Fraction for fraction and doerfler marking.");
    prm.declare_entry("Max cycles",
                      "50",
                      Patterns::Integer(0),
                      "combined: maximum number of adaptation steps; "
                      "nested and uniform: number of meshes after the "
                      "first.");
    prm.declare_entry("Max level",
                      "10",
                      Patterns::Integer(0, 30),
                      "Cells at this refinement level are not refined.");
    prm.declare_entry("Max cells",
                      "200000",
                      Patterns::Integer(1),
                      "No refinement beyond this many cells per body.");
    prm.declare_entry("Write every mesh",
                      "true",
                      Patterns::Bool(),
                      "Write VTU (with eta, D_e, d_e, K_e) and the mesh of "
                      "every adaptation step; otherwise first and last.");
  }

  void
  AdaptationParameters::parse(ParameterHandler &prm)
  {
    mode             = parse_selection<AdaptationMode>(prm.get("Mode"));
    bodies           = split(prm.get("Bodies"), ',');
    estimator        = parse_selection<EstimatorType>(prm.get("Estimator"));
    marking          = parse_selection<MarkingType>(prm.get("Marking"));
    delta            = prm.get_double("Delta");
    fraction         = prm.get_double("Fraction");
    max_cycles       = prm.get_integer("Max cycles");
    max_level        = prm.get_integer("Max level");
    max_cells        = prm.get_integer("Max cells");
    write_every_mesh = prm.get_bool("Write every mesh");
    if (enabled() && bodies.empty())
      throw InputError("Adaptation/Bodies: Mode = " + to_string(mode) +
                       " needs at least one adapted body");
  }

  void
  ParallelParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Body owners",
      "auto",
      Patterns::Anything(),
      "Under mpirun: the processes that solve each body's problem (20). "
      "'auto': with at most as many processes as bodies, each body on one "
      "process (balancing the dofs, again after every refinement); with more "
      "processes, every body on its own group of processes, the group sizes "
      "in proportion to the dofs. 'all': every body on all processes, one "
      "body after the other. Or a list 'name: 0, name: 1-3' for every body "
      "(a process or a range of processes). A body on several processes has "
      "its mesh partitioned between them and is solved by a distributed "
      "solver (Trilinos: Amesos MUMPS, or CG with ML AMG).");
    prm.declare_entry(
      "Mesh",
      "auto",
      Patterns::Selection("auto|shared|distributed"),
      "How the mesh of a body solved by several processes is split. "
      "'distributed': parallel::distributed::Triangulation (p4est), each "
      "process keeps only its cells and a ghost layer; for quadrilateral "
      "bodies solved by every process (Body owners = all). "
      "'shared': parallel::shared::Triangulation, every process keeps the "
      "whole mesh and assembles its part. 'auto': distributed where "
      "possible, shared elsewhere.");
  }

  bool
  ParallelParameters::distributed_mesh(const BodyParameters &body,
                                       const unsigned int    n_processes) const
  {
    if (n_processes <= 1 || mesh == "shared")
      return false;
    const bool on_every_process =
      mode == "all" ||
      (mode == "list" && body_groups.at(body.name).size() == n_processes);
    return on_every_process && body.cell_type == "quadrilateral";
  }

  bool
  ParallelParameters::process_groups(const unsigned int n_processes,
                                     const unsigned int n_bodies) const
  {
    if (n_processes <= 1)
      return false;
    if (mode == "all")
      return true;
    if (mode == "auto")
      return n_processes > n_bodies;
    for (const auto &[name, group] : body_groups)
      if (group.size() > 1)
        return true;
    return false;
  }

  void
  ParallelParameters::parse(ParameterHandler               &prm,
                            const std::vector<std::string> &body_names)
  {
    body_groups.clear();
    mesh                   = prm.get("Mesh");
    const std::string text = prm.get("Body owners");
    if (text == "auto" || text == "all")
    {
      mode = text;
      return;
    }
    mode                           = "list";
    const unsigned int n_processes = n_world_processes();
    const auto         rank        = [&](const std::string &entry,
                          const std::string &what) -> unsigned int
    {
      const double r = parse_double(entry, what);
      if (r < 0 || r != std::floor(r) || r >= n_processes)
        throw InputError(what + ": process " + entry +
                         " does not exist in a run on " +
                         std::to_string(n_processes) + " processes");
      return static_cast<unsigned int>(r);
    };
    for (const auto &item : split(text, ','))
    {
      const auto what  = "Parallel/Body owners: '" + item + "'";
      const auto parts = split(item, ':');
      if (parts.size() != 2)
        throw InputError(what + " is not 'body: process' or "
                                "'body: first-last'");
      if (std::find(body_names.begin(), body_names.end(), parts[0]) ==
          body_names.end())
        throw InputError(what + ": '" + parts[0] +
                         "' is not one of the Bodies");
      const auto         range = split(parts[1], '-');
      const unsigned int first = rank(range[0], what);
      const unsigned int last =
        range.size() == 2 ? rank(range[1], what) : first;
      if (range.size() > 2 || last < first)
        throw InputError(what + ": '" + parts[1] +
                         "' is not a process or a range first-last");
      auto &group = body_groups[parts[0]];
      group.clear();
      for (unsigned int r = first; r <= last; ++r)
        group.push_back(r);
    }
    for (const auto &name : body_names)
      if (body_groups.count(name) == 0)
        throw InputError("Parallel/Body owners: body '" + name +
                         "' is not listed");
  }

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
    prm.declare_entry("Constants",
                      "",
                      Patterns::Anything(),
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

    prm.enter_subsection("Domain decomposition");
    DDParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Adaptation");
    AdaptationParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Parallel");
    ParallelParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Points",
                        "",
                        Patterns::Anything(),
                        "Points where displacement and stress are reported: "
                        "'body: x1, x2; body: x1, x2'.");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write VTU/PVD files for ParaView.");
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

    prm.enter_subsection("Domain decomposition");
    dd.parse(prm);
    prm.leave_subsection();

    prm.enter_subsection("Adaptation");
    adaptation.parse(prm);
    prm.leave_subsection();
    // The combined algorithm (Fig. 2) interleaves single DD steps with the
    // refinement; the monolithic solver has no such steps.
    if (adaptation.mode == AdaptationMode::combined &&
        dd.solver == ContactSolverType::monolithic)
      throw InputError("Adaptation/Mode: combined needs Domain "
                       "decomposition/Solver = dd; use Mode = nested with the "
                       "monolithic solver");
    prm.enter_subsection("Parallel");
    parallel.parse(prm, body_names);
    prm.leave_subsection();
    // An explicit request for p4est meshes that a quadrilateral body cannot
    // have is an error, not a silent fallback (triangles are always shared).
    if (parallel.mesh == "distributed" && n_world_processes() > 1)
      for (const auto &body : bodies)
        if (body.cell_type == "quadrilateral" &&
            !parallel.distributed_mesh(body, n_world_processes()))
          throw InputError(
            "Parallel/Mesh: distributed, but body '" + body.name +
            "' is not solved by every process (distributed meshes need "
            "Body owners = all, or a list that gives the body every "
            "process); use Mesh = auto or shared");
    if (dd.solver == ContactSolverType::monolithic && n_world_processes() > 1)
      throw InputError("Domain decomposition/Solver: monolithic runs on one "
                       "process; use Solver = dd under mpirun");

    for (const auto &b : adaptation.bodies)
    {
      const auto it = std::find(body_names.begin(), body_names.end(), b);
      if (it == body_names.end())
        throw InputError("Adaptation/Bodies: '" + b +
                         "' is not one of the Bodies");
      // The BEM's basis is the trace of the FEM basis (26): linear only.
      if (adaptation.enabled() && adaptation.mode != AdaptationMode::uniform &&
          adaptation.estimator != EstimatorType::kelly &&
          body_parameters(b).degree != 1)
        throw InputError(
          "Adaptation/Estimator: " + to_string(adaptation.estimator) +
          " builds a BEM with linear elements, but body '" + b +
          "' has Element/Degree = " +
          std::to_string(body_parameters(b).degree) +
          "; use Estimator = kelly or Degree = 1");
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

    prm.enter_subsection("Output");
    {
      write_vtu                = prm.get_bool("Write vtu");
      dd.print_every_iteration = (prm.get("Verbosity") == "full");
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
                         "': " + without_input_string(message_of(e)));
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
      prm.parse_input_from_string(text, "", false);
    }
    catch (const std::exception &e)
    {
      throw InputError("parameter file '" + filename +
                       "': " + without_input_string(message_of(e)));
    }
    for (const auto &o : overrides)
      apply_override(prm, o);

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
      if (body.mesh_type == "file" && !body.mesh_file.empty() &&
          body.mesh_file[0] != '/' && std::ifstream(directory + body.mesh_file))
        body.mesh_file = directory + body.mesh_file;
  }

  void
  ParameterReader::print(std::ostream &out) const
  {
    prm.print_parameters(out, ParameterHandler::PRM);
  }

  void
  ParameterReader::write_used(const std::string &filename) const
  {
    std::ofstream out(filename);
    prm.print_parameters(out, ParameterHandler::ShortPRM);
  }

  void
  ParameterReader::print_defaults(std::ostream &out)
  {
    ParameterHandler prm;
    SceneParameters::declare(prm, {"<name>"}, {"<name>"});
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace ddcontact
