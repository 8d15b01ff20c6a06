#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <ddcontact/body/boundary_data_checks.h>
#include <ddcontact/body/material_laws.h>
#include <ddcontact/output_file.h>
#include <ddcontact/parameters.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <tuple>

// The scene's parameters: SceneParameters::declare() and parse(), and the
// listings of ParameterReader (--print-parameters, parameters.prm).
namespace ddcontact
{
  using parsing::n_world_processes;
  using parsing::split;

  namespace
  {
    /** The entries of the top level of the file. */
    void
    declare_scene_entries(ParameterHandler &prm)
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
      prm.declare_entry(
        "Geometry",
        "plane strain",
        selection_pattern<Geometry>(),
        "plane strain: the mesh is a slice of unit thickness, forces per unit "
        "thickness; axisymmetric: the mesh is a meridian section (x = r >= 0, "
        "y = z the axis), every force, reaction and energy a total over the "
        "ring (2 pi r); doc/axisymmetric.md.");
      prm.declare_entry("Contact pairs",
                        "",
                        Patterns::Anything(),
                        "Names of the contact pairs (comma separated); each "
                        "needs a subsection 'Contact pair <name>'.");
    }

    /** The subsection Output: the report points and the files. */
    void
    declare_output(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        // A Map that may name a body twice; the names are checked against
        // Bodies when the scene is parsed.
        prm.declare_entry(
          "Points",
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
    }

    /** The parameters of the body called @p name among @p bodies. */
    const BodyParameters &
    find_body(const std::vector<BodyParameters> &bodies,
              const std::string                 &name)
    {
      return *std::find_if(bodies.begin(),
                           bodies.end(),
                           [&](const BodyParameters &b)
                           { return b.name == name; });
    }

    /** The subsections of the bodies listed in Bodies, with their boundary
     * conditions. */
    void
    parse_bodies(ParameterHandler &prm, SceneParameters &scene)
    {
      scene.bodies.clear();
      for (const auto &name : scene.body_names)
      {
        if (std::count(scene.body_names.begin(), scene.body_names.end(), name) >
            1)
          throw InputError("Bodies: '" + name + "' is listed twice");
        BodyParameters body;
        body.name = name;
        prm.enter_subsection("Body " + name);
        body.parse(prm);
        prm.leave_subsection();
        body.geometry = scene.geometry;
        // The boundary conditions are parsed here too, with the parser the
        // body uses, so that a scene read without error is fully checked.
        make_boundary_conditions(body, scene.constants);
        scene.bodies.push_back(body);
      }
    }

    /** The bodies named in Adaptation/Bodies exist and can be adapted with
     * the estimator. */
    void
    check_adaptation_bodies(const SceneParameters &scene)
    {
      for (const auto &b : scene.adaptation.bodies)
      {
        const auto it =
          std::find(scene.body_names.begin(), scene.body_names.end(), b);
        if (it == scene.body_names.end())
          throw InputError("Adaptation/Bodies: '" + b +
                           "' is not one of the Bodies");
        // The BEM's basis is the trace of the FEM basis (26): linear or
        // quadratic boundary elements (degree 3 is refused with the Degree).
        if (scene.adaptation.enabled() &&
            scene.adaptation.mode != AdaptationMode::uniform &&
            is_fem_bem(scene.adaptation.estimator) &&
            find_body(scene.bodies, b).degree > 2)
          throw InputError(
            "Adaptation/Estimator: " + to_string(scene.adaptation.estimator) +
            " builds a BEM with linear or quadratic elements, but body '" + b +
            "' has Element/Degree = " +
            std::to_string(find_body(scene.bodies, b).degree) +
            "; use Estimator = kelly or residual, or Degree = 1 or 2");
      }
    }

    /** The subsections of the contact pairs, each checked against its
     * bodies. */
    void
    parse_contact_pairs(ParameterHandler &prm, SceneParameters &scene)
    {
      scene.contact_pairs.clear();
      for (const auto &name : split(prm.get("Contact pairs"), ','))
      {
        ContactPairParameters pair;
        pair.name = name;
        prm.enter_subsection("Contact pair " + name);
        pair.parse(prm);
        prm.leave_subsection();
        for (const auto &b : {pair.body_1, pair.body_2})
          if (std::find(scene.body_names.begin(), scene.body_names.end(), b) ==
              scene.body_names.end())
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
          const auto &body = find_body(scene.bodies, body_name);
          if (!make_boundary_conditions(body, scene.constants)
                 .contact.count(id))
            throw InputError(
              "Contact pair " + name + "/" + entry + ": " + std::to_string(id) +
              " is not among the Contact "
              "ids of body '" +
              body_name + "' ('" + body.contact_ids + "'); add it there");
        }
        scene.contact_pairs.push_back(pair);
      }
    }

    /** One formulation for all pairs, passed on to the contact solver with
     * the first frictional pair, and what friction asks of the loading. */
    void
    set_contact_formulation(SceneParameters &scene)
    {
      // One formulation for all pairs: the solvers treat the pairs alike.
      for (const auto &pair : scene.contact_pairs)
        if (pair.formulation != scene.contact_pairs.front().formulation)
          throw InputError(
            "Contact pair " + pair.name +
            "/Formulation: " + selection_name(pair.formulation) +
            ", but pair " + scene.contact_pairs.front().name + " is " +
            selection_name(scene.contact_pairs.front().formulation) +
            "; all pairs of a scene take the same formulation");
      const auto frictional =
        std::find_if(scene.contact_pairs.begin(),
                     scene.contact_pairs.end(),
                     [](const ContactPairParameters &pair)
                     { return pair.friction != FrictionLaw::none; });
      scene.contact_solver.set_formulation(
        scene.contact_pairs.empty() ||
          scene.contact_pairs.front().formulation == ContactFormulation::exact,
        frictional == scene.contact_pairs.end() ? std::string()
                                                : frictional->name);
      // Going back to the start of a load step (Steps = auto, Check path)
      // needs the meshes of that start; an adaptive loop refines them
      // (without friction auto takes one step and Check path has no effect).
      if ((scene.loading.automatic || scene.loading.check_path) &&
          frictional != scene.contact_pairs.end() &&
          scene.adaptation.mode != AdaptationMode::none)
        throw InputError(
          std::string("Loading/") +
          (scene.loading.automatic ? "Steps = auto" : "Check path = true") +
          " needs Adaptation/Mode = none: a load step solved again from its "
          "start needs the start's meshes, which the adaptive loop refines; "
          "with adaptation give a fixed number of Steps");
      // A step's estimated path error holds the solves' own error, of the
      // order of their Tolerance: a Path tolerance below it splits every
      // step to the floor of Max splits (2^30 steps: a run that never
      // ends) and says nothing about the path.
      const double floor = 10 * scene.contact_solver.tolerance;
      if ((scene.loading.automatic || scene.loading.check_path) &&
          frictional != scene.contact_pairs.end() &&
          scene.loading.path_tolerance < floor)
      {
        std::ostringstream s;
        s << "Loading/Path tolerance = " << scene.loading.path_tolerance
          << " is below what the solves resolve (10 x Contact "
             "solver/Tolerance = "
          << floor
          << "): every step would be split down to 2^-(Loading/Max splits); "
             "raise the Path tolerance or lower the Tolerance";
        throw InputError(s.str());
      }
    }

    /** The subsection Output. */
    void
    parse_output(ParameterHandler &prm, SceneParameters &scene)
    {
      prm.enter_subsection("Output");
      {
        scene.write_vtu         = prm.get_bool("Write vtu");
        scene.smoothed_stresses = prm.get_bool("Smoothed stresses");
        scene.contact_solver.print_every_iteration =
          (prm.get("Verbosity") == "full");
        scene.points.clear();
        for (const auto &item : split(prm.get("Points"), ';'))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            throw InputError("Output/Points: '" + item +
                             "' is not 'body: x1, x2'");
          ReportPoint p;
          p.body = Utilities::trim(item.substr(0, colon));
          p.x    = parse_point(item.substr(colon + 1), "Output/Points");
          if (std::find(scene.body_names.begin(),
                        scene.body_names.end(),
                        p.body) == scene.body_names.end())
            throw InputError("Output/Points: '" + p.body +
                             "' is not one of the Bodies");
          scene.points.push_back(p);
        }
      }
      prm.leave_subsection();
    }
  } // namespace

  void
  SceneParameters::declare(ParameterHandler               &prm,
                           const std::vector<std::string> &bodies,
                           const std::vector<std::string> &pairs)
  {
    declare_scene_entries(prm);

    prm.enter_subsection("Contact solver");
    ContactSolverParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Adaptation");
    AdaptationParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Loading");
    LoadingParameters::declare(prm);
    prm.leave_subsection();

    prm.enter_subsection("Parallel");
    ParallelParameters::declare(prm);
    prm.leave_subsection();

    declare_output(prm);

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

  namespace
  {
    /** The bodies' material laws and the scene's geometry against what
     * the contact solver and the estimator can take (their tables). */
    void
    check_material_laws(const SceneParameters &scene)
    {
      const auto &solver     = capabilities_of(scene.contact_solver.solver);
      const auto &adaptation = scene.adaptation;
      const bool  estimates =
        adaptation.enabled() && adaptation.mode != AdaptationMode::uniform;
      const auto &estimator = capabilities_of(adaptation.estimator);
      // The BEM's kernels (Kelvin's solution) are those of plane strain;
      // an axisymmetric body would need ring-load kernels
      // (doc/axisymmetric.md).
      if (scene.geometry == Geometry::axisymmetric && estimates &&
          !estimator.axisymmetric)
        throw InputError(
          "Adaptation/Estimator: " + to_string(adaptation.estimator) +
          " is written for plane strain; with Geometry = axisymmetric use "
          "Estimator = " +
          estimators_with(&EstimatorCapabilities::axisymmetric) +
          " (or Mode = uniform)");
      for (const auto &body : scene.bodies)
      {
        const MaterialLawInfo &info = material_law_info(body.material_law);
        const std::string      law =
          body.section() + "/Material/Law = " + body.material_law;
        if (info.path_dependent && adaptation.enabled() &&
            n_world_processes() > 1)
          throw InputError(law + ": the law's state does not follow the "
                                 "refinement of meshes shared between "
                                 "processes yet; set Adaptation/Mode = none, "
                                 "or run on one process");
        if (info.linear)
          continue;
        // The body's Newton loop and its quadrature-point state live on the
        // process that owns the body; the reports do not gather the state
        // from there yet.
        if (n_world_processes() > 1)
          throw InputError(law + ": a nonlinear law runs on one process "
                                 "(for now); run without mpirun (the bodies "
                                 "are still solved concurrently, by threads)");
        const std::string solvers =
          solvers_with(&SolverCapabilities::nonlinear_laws);
        if (!solver.nonlinear_laws)
          throw InputError(
            law + ": Contact solver/Solver = " + scene.contact_solver.solver +
            " solves linear bodies only" +
            (solvers.empty() ? std::string(" (so far every solver)")
                             : "; use Solver = " + solvers));
        const std::string estimators =
          estimators_with(&EstimatorCapabilities::nonlinear_laws);
        if (estimates && !estimator.nonlinear_laws)
          throw InputError(
            law +
            ": Adaptation/Estimator = " + to_string(adaptation.estimator) +
            " estimates linear bodies only; use " +
            (estimators.empty() ? std::string("")
                                : "Estimator = " + estimators + " or ") +
            "Mode = uniform");
      }
    }
  } // namespace

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
    geometry   = parse_selection<Geometry>(prm.get("Geometry"));
    if (body_names.empty())
      throw InputError("Bodies: no body is listed");

    parse_bodies(prm, *this);

    prm.enter_subsection("Contact solver");
    contact_solver.parse(prm);
    prm.leave_subsection();

    prm.enter_subsection("Adaptation");
    adaptation.parse(prm);
    prm.leave_subsection();
    prm.enter_subsection("Loading");
    loading.parse(prm);
    prm.leave_subsection();
    // The bodies check their boundary data at every load time.
    set_checked_load_steps(loading.n_checked_load_times());
    // The combined algorithm (Fig. 2) interleaves single DD steps with the
    // refinement; a solver that solves whole has no such steps.
    const auto &can = capabilities_of(contact_solver.solver);
    if (adaptation.mode == AdaptationMode::combined && !can.single_steps)
      throw InputError("Adaptation/Mode: combined needs Contact "
                       "solver/Solver = " +
                       solvers_with(&SolverCapabilities::single_steps) +
                       "; use Mode = nested with the " + contact_solver.solver +
                       " solver");
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
    if (!can.several_processes && n_world_processes() > 1)
      throw InputError("Contact solver/Solver: " + contact_solver.solver +
                       " runs on one process; use Solver = " +
                       solvers_with(&SolverCapabilities::several_processes) +
                       " under mpirun");

    check_adaptation_bodies(*this);
    check_material_laws(*this);
    parse_contact_pairs(prm, *this);
    set_contact_formulation(*this);
    parse_output(prm, *this);
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
  ParameterReader::print(std::ostream &out, const bool json) const
  {
    // JSON (--print-parameters-json): with every entry's pattern, for
    // scripts/generate_parameters_doc.py.
    if (json)
    {
      prm.print_parameters(out, ParameterHandler::JSON);
      return;
    }
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
  ParameterReader::print_defaults(std::ostream &out, const bool json)
  {
    ParameterHandler prm;
    SceneParameters::declare(prm, {"<name>"}, {"<name>"});
    // JSON (--print-parameters-json): with every entry's pattern, for
    // scripts/generate_parameters_doc.py.
    if (json)
    {
      prm.print_parameters(out, ParameterHandler::JSON);
      return;
    }
    print_units(out);
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace ddcontact
