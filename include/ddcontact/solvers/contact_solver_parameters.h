#ifndef ddcontact_contact_solver_parameters_h
#define ddcontact_contact_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <ddcontact/parameter_tools.h>

#include <string>

namespace ddcontact
{
  using namespace dealii;

  /** Contact solver/Domain decomposition/Relaxation: the paper's fixed gamma of
   * (21), the optimal fixed gamma estimated at the start ("auto"), Aitken or
   * Anderson. */
  enum class RelaxationType
  {
    fixed,
    automatic,
    aitken,
    anderson
  };

  /** Contact solver/Domain decomposition/Stopping test. */
  enum class StoppingTest
  {
    residual, // u~^{k+1} - u^k on S
    paper,    // the paper's increment test with eps_u
    both      // either
  };

  /** Contact solver/Initial guess. */
  enum class InitialGuess
  {
    zero,
    elastic_layer // "elastic-layer" (the Winkler model)
  };

  /** Contact solver/DD-Newton/Coulomb linearization: how a Newton step of
   * dd-newton treats the Coulomb bound mu p of a slipping node. */
  enum class CoulombLinearization
  {
    fixed_point, // "fixed-point": mu times the trial pressure, lagged
    newton       // t = sigma mu p coupled into the step (GMRES)
  };

  /** Contact solver/Contact pressure: the discrete pressure's space. */
  enum class ContactPressure
  {
    automatic, // "auto": nodes wherever the solver takes them
    points,    // a value at every contact point
    nodes      // one value per node of S_1
  };

  /** What a contact solver can take; ContactSolverParameters::
   * set_formulation() and ContactSolver::create() refuse the rest. One
   * row per solver, beside its factory (contact_solver.cc). */
  struct SolverCapabilities
  {
    /** Tresca and Coulomb friction (tangential multipliers on the nodes
     * of S_1). */
    bool friction = false;
    /** Bodies held by contact alone, without friction. */
    bool floating_bodies = false;
    /** One pressure per node of S_1 (Contact pressure = nodes). */
    bool pressure_on_nodes = false;
    /** Exact contact solved directly on the nodes, without the Uzawa
     * loop: always, or only with friction. */
    bool exact_on_nodes               = false;
    bool exact_on_nodes_with_friction = false;
    /** With a frictionless exact contact, auto takes the points (the
     * Uzawa loop's pointwise multipliers) rather than the nodes. */
    bool auto_points_for_uzawa = false;
    /** Single outer steps, which the combined algorithm (Fig. 2)
     * interleaves with the refinement. */
    bool single_steps = false;
    /** Runs under mpirun (bodies on several processes). */
    bool several_processes = false;
    /** Bodies of a nonlinear material law (MaterialLaw::is_linear()): a
     * body Newton loop per solve (dd-newton: and the interface problem
     * relinearized at every Newton step). */
    bool nonlinear_laws = false;
  };

  /** The capabilities of Contact solver/Solver = @p solver, from the
   * table of solvers in contact_solver.cc. */
  const SolverCapabilities &
  capabilities_of(const std::string &solver);

  /** "dd-newton or monolithic": the solvers that have @p capability, for
   * messages. */
  std::string
  solvers_with(bool SolverCapabilities::*capability);

  /** Contact solver/Solver's entry values (the table's names) as a
   * selection, and its documentation (each solver's description). */
  Patterns::Selection
  contact_solver_pattern();

  std::string
  contact_solver_documentation();

  DDCONTACT_DECLARE_SELECTION(ContactPressure)
  DDCONTACT_DECLARE_SELECTION(CoulombLinearization)
  DDCONTACT_DECLARE_SELECTION(RelaxationType)
  DDCONTACT_DECLARE_SELECTION(StoppingTest)
  DDCONTACT_DECLARE_SELECTION(InitialGuess)

  /** The entry value of a relaxation ("fixed", "auto", ...), as
   * summary.json and the messages write it. */
  std::string
  to_string(RelaxationType value);

  /** Contact solver/Uzawa: the outer loop of exact contact for the
   * solvers that reach it through penalties (dd, monolithic; UzawaLoop). */
  struct UzawaParameters
  {
    double       tolerance   = 1e-3; // penetration / approach
    unsigned int max_updates = 30;

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };

  /** Contact solver/Domain decomposition: the paper's DD (20)-(21),
   * Solver = dd (NeumannDDSolver). */
  struct DomainDecompositionParameters
  {
    RelaxationType relaxation          = RelaxationType::fixed;
    double         gamma               = 0.02; // gamma of (21)
    unsigned int   anderson_depth      = 8;
    StoppingTest   stopping            = StoppingTest::residual;
    double         increment_tolerance = 1.5e-3; // the paper's eps_u (Sec. 3)

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };

  /** Contact solver/DD-Newton: Solver = dd-newton (DDNewtonSolver). */
  struct DDNewtonParameters
  {
    unsigned int         max_newton_iterations = 50;
    bool                 penalty_continuation  = true;
    CoulombLinearization coulomb               = CoulombLinearization::newton;

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };

  /** Contact solver/Monolithic: Solver = monolithic
   * (MonolithicContactSolver). */
  struct MonolithicParameters
  {
    unsigned int max_newton_iterations = 50;

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };

  /**
   * The subsection "Contact solver": which solver, the entries every solver
   * reads (iteration limit, tolerance, initial guess, the discrete
   * pressure), and one subsection per solver with its own entries.
   */
  struct ContactSolverParameters
  {
    /** Contact solver/Solver: the name of a row of the table of solvers
     * (contact_solver.cc). */
    std::string  solver         = "dd-newton";
    unsigned int max_iterations = 5000;
    double       tolerance      = 1e-8; // relative residual on S
    InitialGuess initial_guess  = InitialGuess::elastic_layer;
    /** The pairs' Formulation = exact (exact contact, solved directly or
     * by the Uzawa loop): set by the scene from its pairs, not read
     * here. */
    bool exact_formulation     = false;
    bool write_every_iteration = false;
    bool print_every_iteration = false; // Output/Verbosity = full
    bool pressure_on_nodes     = false; // Contact pressure
    /** Multiplier basis = dual: the nodal multipliers' test and load
     * functions biorthogonal to the hat functions (ContactInterface). */
    bool dual_multipliers = true;
    /** A pair has friction (Contact pair/Friction): set by the scene. */
    bool            friction         = false;
    ContactPressure contact_pressure = ContactPressure::automatic; // entry

    UzawaParameters               uzawa;
    DomainDecompositionParameters dd;
    DDNewtonParameters            dd_newton;
    MonolithicParameters          monolithic;

    /** Exact contact (theta = 0) solved directly with one multiplier per
     * node of S_1 (ContactInterface), by dd-newton and, with friction, by
     * the monolithic solver; otherwise the Uzawa loop reaches it. */
    bool
    exact_contact() const
    {
      const auto &can = capabilities_of(solver);
      return exact_formulation &&
             (can.exact_on_nodes ||
              (friction && can.exact_on_nodes_with_friction));
    }

    /** dd-newton's unknowns are one pressure per node of S_1: for exact
     * contact, and for the penalty with Contact pressure = nodes. */
    bool
    multipliers_on_nodes() const
    {
      return exact_contact() ||
             (pressure_on_nodes && capabilities_of(solver).exact_on_nodes);
    }

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);

    /** Set the formulation of the scene's pairs (exact or the penalty) and
     * with it the Contact pressure of auto: nodes wherever the solver
     * takes them (dd-newton; monolithic with the penalty or with
     * friction), else points. Refuses an explicit nodes that the solver
     * cannot take, and friction (on the pair @p frictional_pair, empty:
     * none) with a solver that has none yet or on the points. */
    void
    set_formulation(bool exact, const std::string &frictional_pair = "");
  };

  /** The one-line error for an entry (@p entry as written there) of the
   * retired top-level subsection "Domain decomposition": where it is now. */
  std::string
  moved_solver_entry(const std::string &entry);
} // namespace ddcontact

#endif
