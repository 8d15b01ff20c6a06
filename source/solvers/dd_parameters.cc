#include <deal.II/base/utilities.h>

#include <ddcontact/solvers/dd_parameters.h>

namespace ddcontact
{
  DDCONTACT_SELECTION(ContactSolverType,
                      {"dd", ContactSolverType::dd},
                      {"monolithic", ContactSolverType::monolithic},
                      {"dd-newton", ContactSolverType::dd_newton})
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
                      {"elastic-layer", InitialGuess::elastic_layer})

  std::string
  to_string(const RelaxationType value)
  {
    return selection_name(value);
  }

  void
  DDParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Solver",
      "dd-newton",
      selection_pattern<ContactSolverType>(),
      "dd-newton (the default): semismooth Newton on the contact pressure "
      "of (20), whose linear systems are solved by preconditioned CG with "
      "one set of body solves per iteration (doc/contact-solvers.md); dd: "
      "the paper's parallel Neumann domain decomposition (20)-(21) with the "
      "Relaxation below, kept for reproducing the paper (and needed when a "
      "body is solved by a process group); monolithic: semismooth Newton on "
      "the penalised problem (16) for all bodies at once (the reference).");
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
    // Retired: it meant a direct solve with dd-newton but a Uzawa loop
    // elsewhere; Contact pair/Formulation says what is solved.
    prm.declare_entry("Augmented Lagrangian",
                      "",
                      Patterns::Anything(),
                      "Retired: set Contact pair <name>/Formulation = exact "
                      "(the default) or penalty instead.");
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
                      "Iteration limit of the monolithic Newton solver "
                      "and of the Newton steps of dd-newton on one mesh "
                      "and multiplier.");
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
      "Penalty continuation",
      "true",
      Patterns::Bool(),
      "dd-newton from zero pressure on the nodes (exact contact, Contact "
      "pressure = nodes) where a zone overlaps on at least 100 nodes: find "
      "the active set along a path of softer penalties (theta + t "
      "H (1 - nu^2)/E of both bodies, t = 1, 1e-2, ...) before the pair's "
      "own theta or exact contact, so that the Newton steps do not grow as "
      "the mesh is refined.");
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
    if (prm.get("Initial guess") == "winkler")
      throw InputError("Domain decomposition/Initial guess: 'winkler' is now "
                       "called 'elastic-layer'");
    initial_guess = parse_selection<InitialGuess>(prm.get("Initial guess"));
    if (!Utilities::trim(prm.get("Augmented Lagrangian")).empty())
      throw InputError(
        "Domain decomposition/Augmented Lagrangian is retired: set Contact "
        "pair <name>/Formulation = exact (exact contact, the default) or "
        "penalty");
    al_tolerance          = prm.get_double("AL tolerance");
    al_max_updates        = prm.get_integer("AL max updates");
    write_every_iteration = prm.get_bool("Write every iteration");
    n_newton              = prm.get_integer("Max Newton iterations");
    contact_pressure      = prm.get("Contact pressure");
    penalty_continuation  = prm.get_bool("Penalty continuation");
    if (!(gamma > 0. && gamma <= 1.))
      throw InputError("Domain decomposition/Gamma: " + prm.get("Gamma") +
                       " must lie in (0, 1]");
  }

  void
  DDParameters::set_formulation(const bool exact)
  {
    augmented_lagrangian = exact;
    if (contact_pressure == "auto")
    {
      pressure_on_nodes = solver == ContactSolverType::dd_newton ||
                          (solver == ContactSolverType::monolithic && !exact);
      return;
    }
    pressure_on_nodes = (contact_pressure == "nodes");
    if (pressure_on_nodes && solver == ContactSolverType::dd)
      throw InputError("Domain decomposition/Contact pressure = nodes needs "
                       "Solver = dd-newton or monolithic (the DD takes the "
                       "pressure at the contact points)");
    // The Uzawa loop updates pointwise multipliers; dd-newton solves exact
    // contact on the nodes directly.
    if (pressure_on_nodes && exact && solver == ContactSolverType::monolithic)
      throw InputError("Domain decomposition/Contact pressure = nodes with "
                       "Solver = monolithic is a penalty; for exact contact "
                       "(Contact pair/Formulation = exact) on the nodes use "
                       "Solver = dd-newton, or set Formulation = penalty");
  }
} // namespace ddcontact
