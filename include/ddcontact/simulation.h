#ifndef ddcontact_simulation_h
#define ddcontact_simulation_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <ddcontact/adaptivity/adaptive_refinement.h>
#include <ddcontact/body/body_distribution.h>
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/io/contact_zone_writer.h>
#include <ddcontact/io/output_writer.h>
#include <ddcontact/io/run_report.h>
#include <ddcontact/parameters.h>
#include <ddcontact/solvers/contact_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The driver of one run of a scene: builds the bodies from the
   * parameters and solves, on the fixed meshes, by the combined algorithm
   * of Fig. 2 or by the nested loop; writes VTU/PVD for ParaView, and its
   * RunReport writes the CSV files and summary.json into the output
   * directory.
   */
  class Simulation
  {
  public:
    Simulation(const SceneParameters &parameters, std::ostream &screen);

    /** Run the scene; returns normally on success, throws InputError on
     * bad input and DivergenceError (NotConvergedError at Max iterations
     * with a falling residual) when the contact iteration fails, after
     * writing what it reached. */
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
    get_dd_solver() const
    {
      return *dd_solver;
    }

    const std::vector<std::unique_ptr<ContactPair>> &
    get_contact_pairs() const
    {
      return contact_pairs;
    }

    /** The adaptation of each adapted body (empty without adaptation). */
    const std::vector<std::unique_ptr<AdaptiveRefinement>> &
    get_adaptations() const
    {
      return adaptations;
    }

    /** Adaptation steps (refinements) made so far. */
    unsigned int
    n_adaptation_cycles() const
    {
      return n_adaptation_steps;
    }

  private:
    /** run() without its translation of std::bad_alloc. */
    void
    run_steps();

    /** What the run has computed so far, for the report. */
    RunReport::Results
    results() const;

    void
    setup_bodies();

    /** One AdaptiveRefinement per adapted body. */
    void
    setup_adaptation();

    /** Solve by the algorithm of Adaptation/Mode (the contact problem or
     * the body problems alone); returns the number of DD iterations. */
    unsigned int
    solve();

    /**
     * The combined algorithm of Fig. 2: each cycle does one DD step
     * (20)-(21) and one adaptation step (estimate, mark, refine and
     * transfer); it stops when the DD stopping test holds and no cell is
     * marked. Once a step marks no cell the mesh is frozen and the
     * estimate is skipped until the DD has converged, when it is checked
     * once more (the indicator only moves with the data then, so this
     * saves a BEM solve per DD iteration without changing where the
     * algorithm stops). Returns the number of DD iterations.
     */
    unsigned int
    solve_combined();

    /**
     * The classical nested loop (Mode = nested) and uniform refinement
     * (Mode = uniform): solve on each mesh to convergence (DD, or the body
     * problems alone without contact), then adapt.
     */
    unsigned int
    solve_nested();

    /** The problem on the current meshes to convergence: the contact
     * solve, or the body problems when there is no contact. */
    unsigned int
    solve_on_current_mesh();

    /** Estimate and mark on every adapted body from the FEM solutions of
     * the last body problems (20); returns the number of marked cells. */
    unsigned int
    estimate_and_mark();

    /** estimate_and_mark(), but marking nothing (and saying so) unless
     * @p may_refine: the last cycle allowed by Adaptation/Max cycles. */
    unsigned int
    mark_cells(bool may_refine);

    /** Above Adaptation/Target error: if the cells @p marked carry less
     * than AdaptationParameters::min_refined_error_share of the estimated
     * error, mark the fewest cells that carry that share instead (Doerfler
     * over all adapted bodies). Returns the marked cells. */
    unsigned int
    ensure_error_share(unsigned int marked);

    /** Refine the marked cells, transfer the iterates, rebuild the
     * contact pairs and the DD's vectors. */
    void
    refine_and_transfer();

    /** Write VTU (with the estimator fields) and the adapted meshes'
     * cells_<body>-NNNN.csv. */
    void
    output_adaptation_step();

    /** Solve every body problem at once (one task per body). */
    void
    solve_bodies();

    void
    setup_contact();

    /** The contact problem on the current meshes, from the current
     * iterate, by DD (20)-(21) or by the monolithic Newton solver, each
     * with its Uzawa updates if the augmented Lagrangian is on; returns
     * the number of DD iterations it took. */
    unsigned int
    solve_contact();

    /** Write step @p step of the bodies (OutputWriter) and of every
     * contact zone (ContactZoneWriter), if Output/Write vtu. */
    void
    output_results(unsigned int step);

    /** After a DivergenceError: history.csv, the contact profiles, the
     * VTU/PVD of the last iterate (if Output/Write vtu) and summary.json
     * with @p status ("diverged" or "not_converged"). */
    void
    write_failed_run(const std::string &status);

    const SceneParameters parameters;
    ConditionalOStream    pcout;
    TimerOutput           timer;
    Timer                 wall_clock;
    RunReport             report;

    std::vector<std::unique_ptr<ElasticBody<2>>> bodies;
    std::unique_ptr<BodyDistribution>            distribution;
    /** Process 0 writes the files (every process holds all results). */
    const bool                                       writes_files;
    std::vector<std::unique_ptr<ContactPair>>        contact_pairs;
    std::unique_ptr<ContactSolver>                   dd_solver;
    unsigned int                                     n_contact_iterations = 0;
    unsigned int                                     n_newton_iterations  = 0;
    std::unique_ptr<OutputWriter>                    output_writer;
    std::unique_ptr<ContactZoneWriter>               contact_zone_writer;
    std::vector<std::unique_ptr<AdaptiveRefinement>> adaptations;
    unsigned int                                     n_adaptation_steps = 0;
    /** What stopped the refinement while the estimate was still above
     * Adaptation/Target error ("" while it goes on). */
    std::string adaptation_stop;
    // The step the run is in, for an out-of-memory message.
    std::string  step           = "the setup of the bodies";
    unsigned int n_output_steps = 0;
  };
} // namespace ddcontact

#endif
