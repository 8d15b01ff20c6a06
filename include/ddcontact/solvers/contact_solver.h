#ifndef ddcontact_contact_solver_h
#define ddcontact_contact_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_distribution.h>
#include <ddcontact/contact/contact_problem.h>
#include <ddcontact/contact/friction_history.h>
#include <ddcontact/iteration_errors.h>
#include <ddcontact/parameter_tools.h>
#include <ddcontact/solvers/contact_solver_parameters.h>
#include <ddcontact/solvers/uzawa_loop.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** What one outer iteration measured (one row of history.csv): a DD
   * iteration (20)-(21) of NeumannDDSolver, or a Newton step of
   * DDNewtonSolver. */
  struct IterationRecord
  {
    unsigned int iteration = 0;
    double       increment = 0; // the paper's test, max over bodies
    double       residual  = 0; // the solver's relative residual
    double       gamma     = 0; // relaxation, or Newton damping
    double       force     = 0; // the normal force on S_1 (int p), all pairs
    double       active_length   = 0;
    double       max_penetration = 0;
    double       time            = 0;
  };

  /** The work of a contact solve, in sets of body solves (one solve of
   * every body, concurrently: the cost of one DD iteration). */
  struct SolverCounts
  {
    /** Sets of solves with the bodies' stiffness matrices (Neumann
     * problems on the contact zones): the "DD iterations". */
    unsigned int body_solve_sets = 0;
    /** Sets of solves with the preconditioner's factorizations. */
    unsigned int preconditioner_solve_sets = 0;
    /** Factorizations of all bodies for the preconditioner. */
    unsigned int preconditioner_factorizations = 0;
    /** Pairs whose two bodies share the preconditioner (RobinPreconditioner;
     * the others are preconditioned by body 1 alone). */
    unsigned int pairs_preconditioned_by_both = 0;
    unsigned int newton_steps                 = 0;
    unsigned int krylov_iterations            = 0;
  };

  /** The path-dependent state a load step starts from
   * (ContactSolver::load_step_start()): the friction history and each
   * body's material state. */
  struct LoadStepStart
  {
    FrictionHistory                                  friction;
    std::vector<QuadraturePointHistory<2>::Snapshot> bodies;
  };

  /**
   * A solver of the contact problem (16) of several bodies: the one
   * interface through which the adaptive strategies (adaptivity/) and the
   * report reach every solver, the paper's relaxed DD (NeumannDDSolver),
   * the semismooth Newton method on the contact pressure (DDNewtonSolver)
   * and the monolithic reference (MonolithicContactSolver).
   *
   * - initialize() starts on the current meshes, step() is one outer
   *   iteration (what the combined algorithm of Fig. 2 calls between two
   *   adaptation steps), reinit_after_refinement() follows a mesh change,
   *   counts() and history() give the work;
   * - run() iterates to convergence inside the augmented Lagrangian's
   *   Uzawa loop (written once, here: start_uzawa_phase());
   * - what the FEM-BEM estimator and the report need is published:
   *   last_body_solution(), last_contact_traction(), contact_state().
   *
   * Contact solver/Solver selects the solver in create(), from the
   * table in contact_solver.cc: adding a solver is its own files, one line
   * there, and its test.
   */
  class ContactSolver
  {
  public:
    ContactSolver(const ContactSolverParameters       &parameters,
                  const std::vector<ElasticBody<2> *> &bodies,
                  const std::vector<ContactPair *>    &pairs,
                  const BodyDistribution              &distribution,
                  ConditionalOStream                  &pcout);

    virtual ~ContactSolver() = default;

    /** The solver of Contact solver/Solver, after the checks that
     * solver makes of the scene. */
    static std::unique_ptr<ContactSolver>
    create(const ContactSolverParameters       &parameters,
           const std::vector<ElasticBody<2> *> &bodies,
           const std::vector<ContactPair *>    &pairs,
           const BodyDistribution              &distribution,
           ConditionalOStream                  &pcout);

    /** InputError naming the first floating body of @p bodies (its free
     * rigid motions), followed by @p reason. */
    static void
    refuse_floating_bodies(const std::vector<ElasticBody<2> *> &bodies,
                           const std::string                   &reason);

    /** A new run on the current meshes: resets the history and the
     * multipliers (derived classes then set up their iterate). Call after
     * the bodies and pairs have been set up. */
    virtual void
    initialize();

    /** One outer iteration; returns true when the stopping test holds.
     * Throws DivergenceError. */
    virtual bool
    step() = 0;

    /** Iterate until converged (with Uzawa updates if requested); returns
     * the number of outer iterations. Throws DivergenceError, or
     * NotConvergedError at Max iterations with a falling residual. */
    unsigned int
    run();

    /** step(), unless Contact solver/Max iterations is reached, where
     * stop_at_iteration_limit(@p loop) throws instead; then the iterate is
     * made whole on every process (complete_iterate()). */
    bool
    step_within_limit(const std::string &loop);

    /** Contact solver/Max iterations is reached: throw
     * NotConvergedError or DivergenceError with a message that says what
     * to change. @p what names the loop ("the domain decomposition", "the
     * combined algorithm"). */
    [[noreturn]] virtual void
    stop_at_iteration_limit(const std::string &what) const = 0;

    /** Re-create internal vectors after a mesh change (the bodies keep
     * their transferred solutions and the pairs have been set up again).
     * The multipliers move to the new contact points (each takes the value
     * of the nearest old point), and the Uzawa loop starts afresh on the
     * new mesh. */
    virtual void
    reinit_after_refinement();

    /** A new load step (Loading/Steps) on the same meshes, whose bodies
     * have new data (ElasticBody::set_load_time()): the solvers' data are
     * set up again (as after a refinement, with the same points), warm
     * started from the last iterate; with friction the last step's slip
     * and traction become the history, and the bodies' material states of
     * the last iterate are committed. */
    virtual void
    start_load_step();

    /** start_load_step() for the second part of the current load step
     * (Loading/Steps = auto solves a step in two halves): the history
     * moves on, the slip increment and the dissipated energy of the
     * results still count from the load step's start. */
    void
    continue_load_step();

    /** The path-dependent state a load step starts from: a copy of the
     * friction history (empty without friction) and the bodies' material
     * states (empty for laws without state). */
    LoadStepStart
    load_step_start() const;

    /** Go back to @p start (from load_step_start()) to solve the load
     * step again; the next start_load_step() starts from it. The iterate
     * stays as it is: it only starts the next solve. */
    void
    return_to_load_step_start(const LoadStepStart &start);

    /**
     * The augmented Lagrangian's outer step (UzawaLoop::update()) after
     * the iteration on the current multipliers has converged; on an update
     * a new phase of the iteration starts. Also drives the monolithic
     * solver's Uzawa loop.
     */
    virtual bool
    start_uzawa_phase();

    /** "dd", "dd-newton" or "monolithic", as Contact solver/Solver
     * writes it. */
    virtual std::string
    name() const = 0;

    /** The work so far (summary.json). */
    virtual SolverCounts
    counts() const = 0;

    /** The number of DD iterations (sets of body solves) of the run so
     * far, which the summary reports as dd_iterations. */
    virtual unsigned int
    n_dd_iterations() const
    {
      return records.size();
    }

    /** Whether the last inner linear solve (dd-newton's CG or GMRES on
     * the interface) reached its tolerance; true for the solvers whose
     * inner solves are direct. */
    virtual bool
    inner_solve_converged() const
    {
      return true;
    }

    /** Contact state of pair @p p for the current iterate. */
    ContactState
    contact_state(unsigned int p) const;

    /** What the solver computed on pair @p p beyond the iterate: its
     * friction and the peak of a nodal pressure (PairSolution). */
    const PairSolution &
    solution_of(const unsigned int p) const
    {
      AssertIndexRange(p, published.size());
      return published[p];
    }

    /** The contact problem (bodies, pairs, laws) the solver iterates on. */
    const ContactProblem &
    get_problem() const
    {
      return problem;
    }

    /** Called after every iteration with its number (e.g. to write the
     * contact profiles of every iterate, the paper's Fig. 9). */
    void
    set_iteration_callback(const std::function<void(unsigned int)> &callback)
    {
      iteration_callback = callback;
    }

    const std::vector<IterationRecord> &
    history() const
    {
      return records;
    }

    /** Uzawa updates over the whole run (all meshes). */
    unsigned int
    n_uzawa_updates() const
    {
      return uzawa.n_updates();
    }

    /** See UzawaLoop::shortfall(). */
    std::string
    augmented_lagrangian_shortfall() const
    {
      return uzawa.shortfall(problem);
    }

    /**
     * Estimate the stability limit gamma* of the paper's fixed relaxation
     * (21) on this problem by power iteration on the linearised DD
     * operator with every contact point active (costs about 30 solves of
     * each body).
     */
    double
    estimate_gamma_limit() const;

    /**
     * The FEM solution u~ of the body problem (20) of @p body in the last
     * step, before any relaxation: the FEM side of the FEM-BEM estimator,
     * which must solve the same boundary value problem as the BEM.
     */
    const BodyVector &
    last_body_solution(const ElasticBody<2> &body) const;

    /** The contact traction that loaded @p body in the last step (20). */
    BoundaryTractionSamples
    last_contact_traction(const ElasticBody<2> &body) const;

  protected:
    /** The friction history of a frictional solver, nullptr for one
     * without friction. */
    virtual FrictionHistory *
    friction_history()
    {
      return nullptr;
    }

    /** Take the bodies' current solutions as the last body solutions,
     * loaded by their own contact pressure: after a solver that converged
     * without DD steps (the monolithic one), the converged u solves (20)
     * with that load, so the estimator sees the same problem. */
    void
    adopt_current_iterate();

    /** Contact solver/Initial guess into the bodies' solutions: zero
     * or the elastic-layer (Winkler) guess of elastic_layer_guess(). */
    void
    set_initial_guess();

    /** A new phase of the iteration (first mesh, new mesh, new Uzawa
     * multipliers): derived classes drop what depends on the old one. */
    virtual void
    start_phase();

    /** step() within Contact solver/Max iterations, without
     * complete_iterate(). */
    bool
    checked_step(const std::string &loop);

    /** @p work, then complete_iterate(), also when @p work stops with an
     * error that every process meets (divergence, interruption). */
    bool
    completing(const std::function<bool()> &work);

    /** Make the bodies' solutions and last_body_solution() whole on
     * every process, for whoever reads them after step() or run() (the
     * estimator, the output, the report, the iteration callback). A
     * solver whose steps exchange less (dd-newton: the traces) sends the
     * rest here; collective. */
    virtual void
    complete_iterate()
    {
    }

    /** Publish (PairSolution) what the bodies were loaded with and the
     * nodal law of the unknowns @p x of @p interface (the pressures, then
     * with friction the tangential tractions), its weak gaps taken from
     * the bodies' displacements @p u: what SelfChecks and the reactions
     * read. Nothing for a pressure at the points. */
    void
    publish_nodal_law(const ContactInterface        &interface,
                      const PointVector             &x,
                      const ContactProblem::Iterate &u);

    /** Append @p record to the history and call the iteration callback. */
    void
    add_record(const IterationRecord &record);

    /** Force, active length and penetration of the iterate @p u, summed
     * (or the largest) over the pairs, into @p record. */
    void
    measure_contact(const ContactProblem::Iterate &u,
                    IterationRecord               &record) const;

    /** "Contact pair A/Penalty, Contact pair B/Penalty": the entries that
     * set theta, for messages. */
    std::string
    penalty_entries() const;

    const ContactSolverParameters parameters;
    ContactProblem                problem;
    UzawaLoop                     uzawa;
    ConditionalOStream           &pcout;
    std::vector<IterationRecord>  records;
    // The last step's loads sigma_n (per pair) and body solutions u~.
    std::vector<std::vector<double>> last_sigma_n;
    ContactProblem::Iterate          last_u_tilde;
    // What the last step published on each pair (PairSolution).
    std::vector<PairSolution> published;
    unsigned int              phase_start = 0; // first record
    Timer                     timer;

  private:
    std::function<void(unsigned int)> iteration_callback;
  };
} // namespace ddcontact

#endif
