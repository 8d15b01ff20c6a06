#ifndef ddcontact_simulation_h
#define ddcontact_simulation_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <ddcontact/body_output.h>
#include <ddcontact/contact_pair.h>
#include <ddcontact/elastic_body.h>
#include <ddcontact/neumann_dd_solver.h>
#include <ddcontact/parameters.h>
#include <ddcontact/summary.h>

#include <memory>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The driver of one run of a scene: builds the bodies from the
   * parameters, solves, reports the requested point values, writes VTU/PVD
   * for ParaView and summary.json into the output directory.
   */
  class Simulation
  {
  public:
    Simulation(const SceneParameters &parameters, std::ostream &screen);

    /** Run the scene; returns normally on success, throws InputError on
     * bad input. */
    void
    run();

    /** The summary written at the end (also for tests). */
    const Json &
    summary() const
    {
      return summary_json;
    }

    const std::vector<std::unique_ptr<ElasticBody<2>>> &
    get_bodies() const
    {
      return bodies;
    }

    const NeumannDDSolver &
    get_dd_solver() const
    {
      return *dd_solver;
    }

    const std::vector<std::unique_ptr<ContactPair>> &
    get_contact_pairs() const
    {
      return contact_pairs;
    }

  private:
    void
    setup_bodies();

    /** Solve every body problem at once (one task per body). */
    void
    solve_bodies();

    void
    setup_contact();

    /** The contact problem by DD (20)-(21) or by the monolithic Newton
     * solver; returns the iteration count. */
    unsigned int
    solve_contact();

    void
    write_history() const;

    void
    write_contact_profiles(const std::string &suffix) const;

    void
    output_results(unsigned int step);

    void
    write_summary(const std::string &status);

    const SceneParameters parameters;
    ConditionalOStream    pcout;
    TimerOutput           timer;
    Timer                 wall_clock;

    std::vector<std::unique_ptr<ElasticBody<2>>> bodies;
    std::vector<std::unique_ptr<ContactPair>>    contact_pairs;
    std::unique_ptr<NeumannDDSolver>             dd_solver;
    unsigned int                                 n_contact_iterations = 0;
    unsigned int                                 n_newton_iterations  = 0;
    std::unique_ptr<OutputWriter>                output_writer;
    Json                                         summary_json;
  };
} // namespace ddcontact

#endif
