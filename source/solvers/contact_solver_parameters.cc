#include <deal.II/base/utilities.h>

#include <ddcontact/solvers/contact_solver_parameters.h>

#include <map>

namespace ddcontact
{
  DDCONTACT_SELECTION(RelaxationType,
                      {"fixed", RelaxationType::fixed},
                      {"auto", RelaxationType::automatic},
                      {"aitken", RelaxationType::aitken},
                      {"anderson", RelaxationType::anderson})
  DDCONTACT_SELECTION(StoppingTest,
                      {"residual", StoppingTest::residual},
                      {"paper", StoppingTest::paper},
                      {"both", StoppingTest::both})
  DDCONTACT_SELECTION(CoulombLinearization,
                      {"fixed-point", CoulombLinearization::fixed_point},
                      {"newton", CoulombLinearization::newton})
  DDCONTACT_SELECTION(ContactPressure,
                      {"auto", ContactPressure::automatic},
                      {"points", ContactPressure::points},
                      {"nodes", ContactPressure::nodes})
  DDCONTACT_SELECTION(InitialGuess,
                      {"zero", InitialGuess::zero},
                      {"elastic-layer", InitialGuess::elastic_layer})

  std::string
  to_string(const RelaxationType value)
  {
    return selection_name(value);
  }

  void
  UzawaParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Tolerance",
                      "1e-3",
                      Patterns::Double(0),
                      "Stop the Uzawa updates of exact contact (Solver = dd "
                      "or monolithic) when the largest penetration is at "
                      "most this times the largest normal displacement on "
                      "S.");
    prm.declare_entry("Max updates",
                      "30",
                      Patterns::Integer(1),
                      "Maximum number of Uzawa updates.");
  }

  void
  UzawaParameters::parse(ParameterHandler &prm)
  {
    tolerance   = prm.get_double("Tolerance");
    max_updates = prm.get_integer("Max updates");
  }

  void
  DomainDecompositionParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Relaxation",
                      "fixed",
                      selection_pattern<RelaxationType>(),
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
      selection_pattern<StoppingTest>(),
      "residual: ||u~^{k+1}_n - u^k_n|| <= Tolerance ||u~^{k+1}_n|| on S "
      "(Contact solver/Tolerance); paper: ||u^{k+1}_an - u^k_an|| <= "
      "Increment tolerance ||u^{k+1}_an|| for each body (weaker by a "
      "factor gamma); both: either.");
    prm.declare_entry("Increment tolerance",
                      "1.5e-3",
                      Patterns::Double(0),
                      "eps_u of the paper's increment test (Stopping test = "
                      "paper or both).");
  }

  void
  DomainDecompositionParameters::parse(ParameterHandler &prm)
  {
    relaxation     = parse_selection<RelaxationType>(prm.get("Relaxation"));
    gamma          = prm.get_double("Gamma");
    anderson_depth = prm.get_integer("Anderson depth");
    stopping       = parse_selection<StoppingTest>(prm.get("Stopping test"));
    increment_tolerance = prm.get_double("Increment tolerance");
    if (!(gamma > 0. && gamma <= 1.))
      throw InputError("Contact solver/Domain decomposition/Gamma: " +
                       prm.get("Gamma") + " must lie in (0, 1]");
  }

  void
  DDNewtonParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Max Newton iterations",
                      "50",
                      Patterns::Integer(1),
                      "Iteration limit of the Newton steps on one mesh and "
                      "one penalty of the continuation.");
    prm.declare_entry(
      "Penalty continuation",
      "true",
      Patterns::Bool(),
      "From zero pressure on the nodes (exact contact, Contact "
      "pressure = nodes) where a zone overlaps on at least 100 nodes: find "
      "the active set along a path of softer penalties (theta + t "
      "H (1 - nu^2)/E of both bodies, t = 1, 1e-2, ...) before the pair's "
      "own theta or exact contact, so that the Newton steps do not grow as "
      "the mesh is refined.");
    prm.declare_entry(
      "Coulomb linearization",
      "newton",
      selection_pattern<CoulombLinearization>(),
      "newton: a slipping node's t = sigma mu p is coupled into the Newton "
      "step, which is then nonsymmetric and solved by GMRES; fixed-point: "
      "its traction is mu times its trial pressure at the start of the "
      "step, so that the step stays symmetric (CG), at more Newton steps "
      "where the bodies differ (Friction = coulomb only).");
  }

  void
  DDNewtonParameters::parse(ParameterHandler &prm)
  {
    max_newton_iterations = prm.get_integer("Max Newton iterations");
    penalty_continuation  = prm.get_bool("Penalty continuation");
    coulomb =
      parse_selection<CoulombLinearization>(prm.get("Coulomb linearization"));
  }

  void
  MonolithicParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Max Newton iterations",
                      "50",
                      Patterns::Integer(1),
                      "Iteration limit of one semismooth Newton solve of "
                      "(16).");
  }

  void
  MonolithicParameters::parse(ParameterHandler &prm)
  {
    max_newton_iterations = prm.get_integer("Max Newton iterations");
  }

  namespace
  {
    /** One subsection per solver: each reads only its own. */
    void
    declare_solver_subsections(ParameterHandler &prm)
    {
      prm.enter_subsection("Uzawa");
      UzawaParameters::declare(prm);
      prm.leave_subsection();
      prm.enter_subsection("Domain decomposition");
      DomainDecompositionParameters::declare(prm);
      prm.leave_subsection();
      prm.enter_subsection("DD-Newton");
      DDNewtonParameters::declare(prm);
      prm.leave_subsection();
      prm.enter_subsection("Monolithic");
      MonolithicParameters::declare(prm);
      prm.leave_subsection();
    }
  } // namespace

  void
  ContactSolverParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Solver",
                      ContactSolverParameters().solver,
                      contact_solver_pattern(),
                      contact_solver_documentation());
    prm.declare_entry("Max iterations",
                      "5000",
                      Patterns::Integer(1),
                      "Maximum number of steps of the solver over the run: "
                      "DD iterations (dd), Newton steps (dd-newton), Newton "
                      "solves (monolithic).");
    prm.declare_entry("Tolerance",
                      "1e-8",
                      Patterns::Double(0),
                      "Relative tolerance of the solver's residual test: "
                      "||u~^{k+1} - u^k|| on S (dd), ||Phi(p)||_W against "
                      "the initial overlap (dd-newton).");
    // "winkler", the old name of elastic-layer, is refused in parse() with
    // the new one.
    std::string guesses = "winkler";
    for (const auto &entry : selection_names<InitialGuess>())
      guesses += "|" + entry.first;
    prm.declare_entry("Initial guess",
                      "elastic-layer",
                      Patterns::Selection(guesses),
                      "zero, or the elastic-layer (Winkler) model: contact "
                      "pressure from the contact-free solution with springs "
                      "E'/H in series with the penalty (replaced by zero "
                      "when one DD step moves it ten times more than the "
                      "zero guess, e.g. a plate bending onto a base).");
    prm.declare_entry(
      "Contact pressure",
      "auto",
      Patterns::Selection("auto|points|nodes"),
      "The discrete contact pressure of Solver = dd-newton and monolithic "
      "with the penalty: 'points', a value at every contact point, the law "
      "(20) pointwise as the paper and the DD; 'nodes', one value per node "
      "of S_1 (piecewise linear), the law (20) for the gap averaged with the "
      "hat functions, whose Newton iteration converges for every penalty and "
      "whose pressure does not oscillate between the points. auto (the "
      "default): nodes wherever the solver takes them (dd-newton; monolithic "
      "with the penalty), points with dd and with monolithic exact contact. "
      "Exact contact with dd-newton always uses nodes.");
    prm.declare_entry(
      "Multiplier basis",
      "dual",
      Patterns::Selection("dual|standard"),
      "The functions that test the gap and the slip of a node of S_1 and "
      "spread its pressure and traction as a load, wherever the unknowns "
      "are on the nodes (exact contact; Contact pressure = nodes). 'dual' "
      "(the default): on every face of S_1 biorthogonal to the hat "
      "functions (the dual mortar basis), so that a node's weak gap and "
      "slip are its own, and a sticking node is not tied to its slipping "
      "neighbour through a mass matrix, which made the tangential traction "
      "oscillate before the stick edge (doc/friction.md 5.2). 'standard': "
      "the hat functions. The reported pressure and traction are the nodal "
      "values joined by the hat functions either way.");
    prm.declare_entry("Write every iteration",
                      "false",
                      Patterns::Bool(),
                      "Write contact_<pair>_<k>.csv at every iteration.");

    declare_solver_subsections(prm);
  }

  void
  ContactSolverParameters::parse(ParameterHandler &prm)
  {
    solver         = prm.get("Solver");
    max_iterations = prm.get_integer("Max iterations");
    tolerance      = prm.get_double("Tolerance");
    if (prm.get("Initial guess") == "winkler")
      throw InputError("Contact solver/Initial guess: 'winkler' is now "
                       "called 'elastic-layer'");
    initial_guess = parse_selection<InitialGuess>(prm.get("Initial guess"));
    contact_pressure =
      parse_selection<ContactPressure>(prm.get("Contact pressure"));
    dual_multipliers      = prm.get("Multiplier basis") == "dual";
    write_every_iteration = prm.get_bool("Write every iteration");

    prm.enter_subsection("Uzawa");
    uzawa.parse(prm);
    prm.leave_subsection();
    prm.enter_subsection("Domain decomposition");
    dd.parse(prm);
    prm.leave_subsection();
    prm.enter_subsection("DD-Newton");
    dd_newton.parse(prm);
    prm.leave_subsection();
    prm.enter_subsection("Monolithic");
    monolithic.parse(prm);
    prm.leave_subsection();
  }

  std::string
  moved_solver_entry(const std::string &entry)
  {
    // The entries of the former top-level subsection and where they are
    // now (issue 32: one subsection per solver, one naming convention).
    static const std::map<std::string, std::string> moved = {
      {"Solver", "Contact solver/Solver"},
      {"Max iterations", "Contact solver/Max iterations"},
      {"eps_residual", "Contact solver/Tolerance"},
      {"Initial guess", "Contact solver/Initial guess"},
      {"Contact pressure", "Contact solver/Contact pressure"},
      {"Write every iteration", "Contact solver/Write every iteration"},
      {"AL tolerance", "Contact solver/Uzawa/Tolerance"},
      {"AL max updates", "Contact solver/Uzawa/Max updates"},
      {"Relaxation", "Contact solver/Domain decomposition/Relaxation"},
      {"Gamma", "Contact solver/Domain decomposition/Gamma"},
      {"Anderson depth", "Contact solver/Domain decomposition/Anderson depth"},
      {"Stopping test", "Contact solver/Domain decomposition/Stopping test"},
      {"eps_u", "Contact solver/Domain decomposition/Increment tolerance"},
      {"Max Newton iterations",
       "Contact solver/DD-Newton/Max Newton iterations (or "
       "Contact solver/Monolithic/Max Newton iterations)"},
      {"Penalty continuation",
       "Contact solver/DD-Newton/Penalty continuation"}};
    if (entry == "Augmented Lagrangian")
      return "Domain decomposition/Augmented Lagrangian is retired: set "
             "Contact pair <name>/Formulation = exact (exact contact, the "
             "default) or penalty";
    const auto it = moved.find(entry);
    if (it == moved.end())
      return "the subsection Domain decomposition is now Contact solver "
             "(the paper's DD has its entries in Contact solver/Domain "
             "decomposition)";
    return "Domain decomposition/" + entry + " is now " + it->second;
  }

  void
  ContactSolverParameters::set_formulation(const bool         exact,
                                           const std::string &frictional_pair)
  {
    exact_formulation = exact;
    friction          = !frictional_pair.empty();
    const auto &can   = capabilities_of(solver);
    // Friction lives on the nodes of S_1 (a tangential multiplier beside
    // the normal one, doc/friction.md).
    if (friction && !can.friction)
      throw InputError("Contact pair " + frictional_pair +
                       "/Friction: friction is solved by Contact "
                       "solver/Solver = " +
                       solvers_with(&SolverCapabilities::friction) +
                       ", not by " + solver +
                       "; set Solver = dd-newton or Friction = none");
    if (friction && contact_pressure == ContactPressure::points)
      throw InputError("Contact pair " + frictional_pair +
                       "/Friction: friction needs the pressure on the nodes "
                       "of S_1; set Contact solver/Contact pressure = nodes "
                       "or auto");
    if (contact_pressure == ContactPressure::automatic || friction)
    {
      pressure_on_nodes = can.pressure_on_nodes &&
                          (!exact || friction || !can.auto_points_for_uzawa);
      return;
    }
    pressure_on_nodes = (contact_pressure == ContactPressure::nodes);
    if (pressure_on_nodes && !can.pressure_on_nodes)
      throw InputError(
        "Contact solver/Contact pressure = nodes needs Solver = " +
        solvers_with(&SolverCapabilities::pressure_on_nodes) + " (" + solver +
        " takes the pressure at the contact points)");
    // The Uzawa loop updates pointwise multipliers; dd-newton solves exact
    // contact on the nodes directly.
    if (pressure_on_nodes && exact && !can.exact_on_nodes)
      throw InputError("Contact solver/Contact pressure = nodes with "
                       "Solver = " +
                       solver +
                       " is a penalty; for exact contact "
                       "(Contact pair/Formulation = exact) on the nodes use "
                       "Solver = " +
                       solvers_with(&SolverCapabilities::exact_on_nodes) +
                       ", or set Formulation = penalty");
  }
} // namespace ddcontact
