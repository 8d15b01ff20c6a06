#ifndef ddcontact_io_run_report_h
#define ddcontact_io_run_report_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <ddcontact/adaptivity/adaptive_refinement.h>
#include <ddcontact/body/body_distribution.h>
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/reaction_forces.h>
#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/io/json.h>
#include <ddcontact/io/run_outcome.h>
#include <ddcontact/parameters.h>
#include <ddcontact/solvers/contact_solver.h>

#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The files of a run besides the VTU output, written into the output
   * directory from the results the driver (Simulation) passes in:
   *
   * - history.csv: one row per DD iteration (20)-(21);
   * - statistics.csv: one row per adaptation step (mesh sizes, estimator,
   *   DD state, phase times);
   * - cells_<body>-NNNN.csv: the adapted meshes with the von Mises stress
   *   and eta per cell, for plots without ParaView (Figs. 4 and 7);
   * - contact_<pair>.csv: the contact pressure and displacements at the
   *   contact points;
   * - summary.json: the run's numbers (point values, contact forces,
   *   estimator, timings, memory), also kept for the tests.
   *
   * Process 0 writes the files (every process holds all results); the
   * writers that gather from all processes (write_cells(), write_summary())
   * are collective and called on every process.
   */
  class RunReport
  {
  public:
    /** What a run has computed, as the driver holds it; only read here. */
    struct Results
    {
      const std::vector<std::unique_ptr<ElasticBody<2>>> &bodies;
      const BodyDistribution                             &distribution;
      const std::vector<std::unique_ptr<ContactPair>>    &contact_pairs;
      /** The contact solver; nullptr in a scene without contact. */
      const ContactSolver                                    *contact_solver;
      const std::vector<std::unique_ptr<AdaptiveRefinement>> &adaptations;
      /** Refinement steps done so far. */
      unsigned int n_adaptation_steps;
      /** What stopped the refinement above Adaptation/Target error, or "". */
      std::string adaptation_stop = "";
    };

    /** The report of a run of @p parameters, timed by @p timer and
     * @p wall_clock; the point values are also printed on @p pcout. */
    RunReport(const SceneParameters    &parameters,
              const TimerOutput        &timer,
              const Timer              &wall_clock,
              const ConditionalOStream &pcout);

    /** Open statistics.csv and write its header (a cell and a dof column
     * per body). */
    void
    open_statistics(const std::vector<std::unique_ptr<ElasticBody<2>>> &bodies);

    /** One row of statistics.csv, after an adaptation step that marked
     * @p marked cells. */
    void
    write_statistics_row(const Results &results,
                         unsigned int   marked,
                         bool           estimated);

    /** history.csv: one row per DD iteration. */
    void
    write_history(const std::vector<IterationRecord> &history) const;

    /** contact_<pair><suffix>.csv for every contact pair, in its current
     * state. */
    void
    write_contact_profiles(const Results     &results,
                           const std::string &suffix) const;

    /** The same, in the pairs' states @p states (contact_states()). */
    void
    write_contact_profiles(const Results                   &results,
                           const std::vector<ContactState> &states,
                           const std::string               &suffix) const;

    /** Force, peak pressure, half-width and penetration of every contact
     * pair (@p states), on the screen. */
    void
    print_contact_states(const Results                   &results,
                         const std::vector<ContactState> &states) const;

    /** cells_<body>-NNNN.csv (NNNN = @p step) for every adapted body.
     * Collective over the processes of a distributed mesh. */
    void
    write_cells(const Results &results, unsigned int step) const;

    /** Build summary.json with the run's @p outcome as its status and its
     * warnings (and @p error, the message of the error that ended the
     * run, if any), and write it. Collective. */
    void
    write_summary(const Results     &results,
                  RunOutcome         outcome,
                  const std::string &error = "");

    /** The summary of a run still under way, or ended at once by a
     * signal: its @p outcome, the last step it completed, @p error if
     * any, and the load steps recorded so far. Local: no collective, no
     * solver state, so that it holds whatever the run is doing. */
    Json
    progress_summary(RunOutcome outcome, const std::string &error) const;

    /** The last step the run completed (a load step, an adaptation
     * cycle), named in every summary from now on. */
    void
    set_last_completed_step(const std::string &what)
    {
      last_completed_step = what;
    }

    /** The contact state of every pair, in the order of the pairs. */
    static std::vector<ContactState>
    contact_states(const Results &results);

    /** The reactions of @p body in the current state, loaded by its
     * contact tractions (@p states, contact_states()). Collective over a
     * partitioned mesh. */
    static ReactionForces<2>
    reactions_of(const Results                   &results,
                 const std::vector<ContactState> &states,
                 const ElasticBody<2>            &body);

    /** The contact states and every body's reactions of one answer: the
     * post-processing that SelfChecks and the summary share. */
    struct Answer
    {
      std::vector<ContactState> states;
      /** In the order of Results::bodies. */
      std::vector<ReactionForces<2>> reactions;
    };

    /** The Answer of the current solution. Collective. */
    static Answer
    answer_of(const Results &results);

    /** The Answer of the current solution, computed now and used by every
     * report until forget_answer(): the driver fixes it once a solve has
     * returned, so that its checks and its files cost one evaluation.
     * Collective. */
    const Answer &
    fix_answer(const Results &results);

    /** The solution is about to change: the reports compute again. */
    void
    forget_answer()
    {
      fixed_answer.reset();
    }

    /** summary.json's `self_checks` (SelfChecks::json()) of the last
     * solve, in every summary from now on. */
    void
    set_self_checks(const Json &checks)
    {
      self_checks = checks;
    }

    /** The end of a solve that returned: history.csv, the contact
     * profiles and states, and summary.json with the @p outcome the driver
     * decided. Collective. */
    void
    write_final(const Results &results, RunOutcome outcome);

    /** Why the run stopped above Adaptation/Target error (the estimate of
     * @p results against it), or "" if it did not. */
    std::string
    target_shortfall(const Results &results) const;

    /** After load step @p step (from 1) of Loading/Steps, at the load
     * parameter @p t: the contact profiles contact_<pair>_step<k>.csv and
     * a row of summary.json's load_steps (per pair the force and peak
     * pressure, with friction the tangential force, the stick zone's
     * half-width and the energy dissipated in the step). Collective. */
    void
    record_load_step(const Results &results, unsigned int step, double t);

    /** record_load_step() with the step's estimated load-path error
     * (Loading/Steps = auto or Check path), written as path_error if
     * finite (NaN: not estimated). */
    void
    record_load_step(const Results &results,
                     unsigned int   step,
                     double         t,
                     double         path_error);

    /** The summary's load_path (how the steps were chosen, the estimated
     * load-path error) and its @p warnings, written with every summary
     * from now on. */
    void
    record_load_path(const Json                     &path,
                     const std::vector<std::string> &warnings);

    /** A warning of the run (summary.json's warnings, printed at the
     * end), kept for every summary from now on. */
    void
    add_warning(const std::string &warning);

    /** The reaction of every Dirichlet id of every body in the summary
     * last written, one line each. */
    void
    print_reactions() const;

    /** Each warning of the summary last written, one line each. */
    void
    print_warnings() const;

    /** An accurate penalty solution penetrates by at most this fraction of
     * the approach of its pair (the largest u_1n + u_2n)... */
    static constexpr double penetration_per_approach = 0.05;
    /** ... and by at most this fraction of the smallest cell diameter
     * along the contact zone (doc/running.md, summary.json `warnings`). */
    static constexpr double penetration_per_cell = 0.1;
    /** Linear elasticity (small strains (1), small rotations, the small-gap
     * assumption) is trusted up to strains and rotations of this size, and
     * an approach of this fraction of the thinner body of a pair; beyond,
     * the run warns and names units as the likely cause. */
    static constexpr double small_strain_limit = 0.05;

    /** The summary last written (also for tests). */
    const Json &
    summary() const
    {
      return summary_json;
    }

  private:
    /** The fixed answer's states (fix_answer()), or those of now. */
    std::vector<ContactState>
    current_states(const Results &results) const;

    /** The fixed answer's reactions of @p body, or reactions_of() now. */
    ReactionForces<2>
    current_reactions(const Results                   &results,
                      const std::vector<ContactState> &states,
                      const ElasticBody<2>            &body) const;

    /** write_summary() in the pairs' contact @p states
     * (contact_states()). */
    void
    write_summary(const Results                   &results,
                  const std::vector<ContactState> &states,
                  RunOutcome                       outcome,
                  const std::string               &error);

    /** Name, size, memory, strain energy and reactions (in the contact
     * @p states) of every body. */
    Json
    bodies_json(const Results                   &results,
                const std::vector<ContactState> &states) const;

    /** The reaction forces of @p body (ReactionForces): per Dirichlet id,
     * with its applied load, contact force and their imbalance, into
     * @p json. Collective over a partitioned mesh. */
    void
    add_reactions(const Results                   &results,
                  const std::vector<ContactState> &states,
                  const ElasticBody<2>            &body,
                  Json                            &json) const;

    /** Each Dirichlet id's mean displacement and reaction at load step
     * @p step (t), in the contact @p states: summary.json's
     * load_steps[].supports and the rows of force_displacement.csv,
     * rewritten whole. Collective. */
    void
    record_supports(const Results                   &results,
                    const std::vector<ContactState> &states,
                    unsigned int                     step,
                    double                           t,
                    Json                            &row);

    /** The values at the requested points, also printed on the screen. */
    Json
    points_json(const Results &results) const;

    /** DD iterations, penalties and contact forces of every pair; after a
     * converged contact iteration (@p judge_penetration), a warning in
     * json["warnings"] for every pair that penetrates more than
     * penetration_per_approach of its approach or penetration_per_cell of
     * the smallest cell along its zone, naming the remedy; the forces are
     * those of the contact @p states. Collective (the cell sizes of
     * distributed meshes). */
    void
    add_contact(const Results                   &results,
                const std::vector<ContactState> &states,
                bool                             judge_penetration,
                Json                            &json) const;

    /** With friction, a pair's tangential force, stick half-width and
     * dissipated energy into @p json. */
    static void
    add_friction(const ContactState &state, Json &json);

    /** The estimator's settings and results per adapted body. */
    void
    add_adaptation(const Results &results, Json &json) const;

    /** Wall time of every phase, the BEM's included. */
    Json
    timings_json(const Results &results) const;

    const SceneParameters    &parameters;
    const TimerOutput        &timer;
    const Timer              &wall_clock;
    const ConditionalOStream &pcout;
    /** Process 0 writes the files. */
    const bool    writes_files;
    std::ofstream statistics;
    Json          summary_json;
    Json          self_checks;                // set_self_checks()
    Json          load_steps = Json::array(); // record_load_step()
    // force_displacement.csv's rows, one per step and Dirichlet id.
    std::vector<std::string> force_displacement_rows;
    Json                     load_path;    // record_load_path()
    std::vector<std::string> run_warnings; // record_load_path(), add_warning()
    std::string              last_completed_step;
    std::optional<Answer>    fixed_answer; // fix_answer()
  };
} // namespace ddcontact

#endif
