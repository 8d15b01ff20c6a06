#ifndef ddcontact_simulation_h
#define ddcontact_simulation_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <ddcontact/adaptivity/adaptive_strategy.h>
#include <ddcontact/adaptivity/mesh_adaptation.h>
#include <ddcontact/body/body_distribution.h>
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/io/run_report.h>
#include <ddcontact/io/solution_output.h>
#include <ddcontact/loading/load_path_measures.h>
#include <ddcontact/parameters.h>
#include <ddcontact/solvers/contact_solver.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The driver of one run of a scene, shaped like step-42's run(): sets
   * up the bodies, the contact pairs with their solver and the adaptive
   * strategy (fixed meshes, nested or uniform refinement, or the combined
   * algorithm of Fig. 2), runs the strategy, and writes the results:
   * VTU/PVD for ParaView, and through its RunReport the CSV files and
   * summary.json in the output directory.
   */
  class Simulation
  {
  public:
    Simulation(const SceneParameters &parameters, std::ostream &screen);

    /** Removes the temporary directory of the meshes gmsh made. */
    ~Simulation();

    /** Set up the bodies, their meshes, the contact pairs, the solver and
     * the adaptive strategy, checking every entry on the way (InputError
     * on bad input). Writes nothing into the output directory, so that a
     * refused run leaves it as it was. */
    void
    setup();

    /** Run the scene (after setup(), which it calls if not called yet);
     * returns normally on success, throws InputError on bad input and
     * DivergenceError (NotConvergedError at Max iterations with a
     * falling residual) when the contact iteration fails, after writing
     * what it reached. While it runs, summary.json names the last step it
     * completed, and a signal writes "interrupted" there at once
     * (interruption::set_record()). */
    void
    run();

    /** The summary written at the end (also for tests). */
    const Json &
    summary() const
    {
      return report.summary();
    }

    const std::vector<std::unique_ptr<ElasticBody<2>>> &
    get_bodies() const
    {
      return bodies;
    }

    /** Which process solves which body. */
    const BodyDistribution &
    get_distribution() const
    {
      return *distribution;
    }

    const ContactSolver &
    get_contact_solver() const
    {
      return *contact_solver;
    }

    const std::vector<std::unique_ptr<ContactPair>> &
    get_contact_pairs() const
    {
      return contact_pairs;
    }

    /** The adaptation of each adapted body (empty without adaptation). */
    const std::vector<std::unique_ptr<AdaptiveRefinement>> &
    get_adaptations() const;

    /** Adaptation steps (refinements) made so far. */
    unsigned int
    n_adaptation_cycles() const
    {
      return adaptation ? adaptation->n_steps() : 0;
    }

  private:
    /** Call @p steps, translating std::bad_alloc into an
     * OutOfMemoryError that names the step the run was in. */
    template <typename Steps>
    void
    naming_memory_errors(const Steps &steps);

    /** setup() and run() without that translation. */
    void
    setup_steps();

    void
    run_steps();

    /** A step of the run is complete (@p what names it): summary.json
     * says so (status "running"), and a signal from now on writes it as
     * the last completed step of an interrupted run. */
    void
    record_progress(const std::string &what);

    /** What the run has computed so far, for the report. */
    RunReport::Results
    results() const;

    void
    setup_bodies();

    /** The contact pairs and their solver (Contact solver/Solver),
     * if the scene has contact pairs. */
    void
    setup_contact();

    /** Where the run allows it (dd-newton, not adapted by the FEM-BEM
     * estimator), let every body on a p4est mesh keep only its own part of
     * its vectors
     * (ElasticBody::distribute_vectors()). */
    void
    distribute_body_vectors();

    /** The MeshAdaptation of the adapted bodies, and the strategy of
     * Adaptation/Mode. */
    void
    setup_strategy();

    /** After each adaptation step: a row of statistics.csv and, if
     * @p write_mesh, the VTU and cells_<body>-NNNN.csv of the mesh. */
    void
    adaptation_step(unsigned int marked, bool write_mesh);

    /** Write step @p step of the bodies (OutputWriter) and of every
     * contact zone (ContactZoneWriter), if Output/Write vtu. */
    void
    output_results(unsigned int step);

    /** Run the strategy, then check its answer (check_answer()); on a
     * failure (divergence, a failed self-check, interruption) write what
     * was reached before passing the error on. */
    void
    solve();

    /** SelfChecks of the current answer into the report; a failed check
     * throws NotConvergedError with its line. */
    void
    check_answer();

    /** The load steps of Loading (simulation_load_steps.cc): a fixed
     * number, or with Steps = auto those that LoadStepControl accepts. */
    void
    run_load_steps();

    void
    run_fixed_load_steps();

    void
    run_automatic_load_steps();

    /** Whether the solution depends on the load path (a frictional
     * pair, or a body of a path-dependent law). */
    bool
    path_dependent() const;

    /** Solve at the load parameter @p t: the bodies' data of t, from the
     * second solve on the solver's new load step (or, if @p continuing,
     * the second part of the current one), then solve(). */
    void
    solve_at(double t, bool continuing = false);

    /** The load step [@p t_start, @p t_end] from the friction history
     * @p start, solved at once (unless @p one_step holds that solve's
     * measures already) and again in two halves, whose solution stays.
     * Returns the step's estimated load-path error, the same on every
     * process; @p one_step then holds the first half's measures (the
     * solve at once of the step a split tries next). */
    double
    solve_step_twice(double                           t_start,
                     double                           t_end,
                     const LoadStepStart             &start,
                     std::optional<LoadPathMeasures> &one_step);

    /** The measures of the current solution. Collective. */
    LoadPathMeasures
    path_measures() const;

    /** Load step @p k is done at @p t: its output, its row in
     * summary.json (with its load-path error if finite, when @p record),
     * and the progress record. */
    void
    finish_load_step(unsigned int       k,
                     double             t,
                     const std::string &of_steps,
                     bool               record,
                     double             path_error);

    /** After a DivergenceError or an interruption: history.csv, the
     * contact profiles, the VTU/PVD of the last iterate (if Output/Write
     * vtu) and summary.json with @p outcome (diverged, not_converged,
     * interrupted) and the @p error that ended the run. (Any other
     * error may come in the middle of a refinement, where the state is
     * not whole: main() then records it in the last progress summary,
     * RunRecord::close_after_error().) */
    void
    write_failed_run(RunOutcome outcome, const std::string &error = "");

    const SceneParameters parameters;
    ConditionalOStream    pcout;
    TimerOutput           timer;
    Timer                 wall_clock;
    RunReport             report;
    SolutionOutput        solution_output;

    std::vector<std::unique_ptr<ElasticBody<2>>> bodies;
    std::unique_ptr<BodyDistribution>            distribution;
    std::vector<std::unique_ptr<ContactPair>>    contact_pairs;
    std::unique_ptr<ContactSolver>               contact_solver;
    std::unique_ptr<MeshAdaptation>              adaptation;
    std::unique_ptr<AdaptiveStrategy>            strategy;
    // The step the run is in, for an out-of-memory message.
    std::string  step           = "the setup of the bodies";
    unsigned int n_output_steps = 0;
    bool         is_set_up      = false;
    // The load parameter of the bodies' data (assembled at t = 1) and the
    // solves so far (the first starts the solver, the next a load step).
    double       load_time = 1;
    unsigned int n_solves  = 0;
    // Where gmsh meshes the .geo files: a temporary directory of the run,
    // not the output directory (which setup() does not touch).
    std::string mesh_directory;
    // The last step completed (record_progress()); empty: none yet.
    std::string last_completed;
  };
} // namespace ddcontact

#endif
