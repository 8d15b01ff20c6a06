#ifndef ddcontact_mesh_adaptation_h
#define ddcontact_mesh_adaptation_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <ddcontact/adaptivity/adaptation_parameters.h>
#include <ddcontact/adaptivity/adaptive_refinement.h>
#include <ddcontact/body/body_distribution.h>
#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/solvers/contact_solver.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * One adaptation step of all adapted bodies at once (sections 4-5 of the
   * paper README): estimate the error of each body's last FEM solution,
   * mark (ranking the cells of all adapted bodies together, and grading
   * S_2 against S_1 under nodal multipliers), then refine and transfer,
   * after which the contact pairs and the solver follow the new meshes.
   *
   * It also decides when refinement stops short of Adaptation/Target
   * error, and says why (stop_reason()), for summary.json.
   */
  class MeshAdaptation
  {
  public:
    /** @p grade_contact_zones: the solver's multipliers sit on the nodes
     * of S_1 (grade_contact_zone()). */
    MeshAdaptation(const AdaptationParameters          &parameters,
                   bool                                 grade_contact_zones,
                   const std::vector<ElasticBody<2> *> &bodies,
                   const std::vector<ContactPair *>    &pairs,
                   BodyDistribution                    &distribution,
                   TimerOutput                         &timer,
                   ConditionalOStream                  &pcout);

    /**
     * Estimate from the last body problems (20) of @p solver (the bodies'
     * solutions without contact, @p solver null) and mark. Above
     * Adaptation/Target error at least a set share of the estimate is
     * marked; at or below it, nothing. Unless @p may_refine (Max cycles
     * reached) the flags are dropped. Returns the number of marked cells.
     */
    unsigned int
    mark(const ContactSolver *solver, bool may_refine);

    /** Refine the marked cells and transfer the bodies' iterates; the
     * pairs are set up again and @p solver (if any) follows the new
     * meshes. */
    void
    refine(ContactSolver *solver);

    /** Refinement steps made so far. */
    unsigned int
    n_steps() const
    {
      return n_refinements;
    }

    /** The adaptation of each adapted body. */
    const std::vector<std::unique_ptr<AdaptiveRefinement>> &
    refinements() const
    {
      return adaptations;
    }

    /** What stopped the refinement while the estimate was still above
     * Adaptation/Target error, or "" while it goes on. */
    const std::string &
    stop_reason() const
    {
      return stop;
    }

    /** What the adaptation is doing, for a message on running out of
     * memory ("adaptation step 3 (estimate and marking)"). */
    const std::string &
    activity() const
    {
      return doing;
    }

  private:
    /** Estimate and mark on every adapted body; returns the marked
     * cells. */
    unsigned int
    estimate_and_mark(const ContactSolver *solver);

    /** If the cells @p marked carry less than
     * AdaptationParameters::min_refined_error_share of the estimate, mark
     * the fewest cells that carry that share instead (Doerfler over all
     * adapted bodies). Returns the marked cells. */
    unsigned int
    ensure_error_share(unsigned int marked);

    /** The processes over which the cells' error contributions are
     * summed and ranked: all, if an adapted body is on p4est (each process
     * holds its own cells); this process alone otherwise. */
    MPI_Comm
    marking_communicator() const;

    /** @p f(contribution, flagged) for every cell of the adapted bodies
     * that this process counts in sums over marking_communicator(), body
     * by body in cell order. */
    void
    for_each_counted_cell(const std::function<void(double, bool)> &f) const;

    /** The reason the refinement stopped above the target, after a
     * marking that flagged nothing. */
    std::string
    reason_for_no_marking() const;

    const AdaptationParameters                       parameters;
    const bool                                       grade_contact_zones;
    std::vector<ContactPair *>                       pairs;
    BodyDistribution                                &distribution;
    TimerOutput                                     &timer;
    ConditionalOStream                              &pcout;
    std::vector<std::unique_ptr<AdaptiveRefinement>> adaptations;
    unsigned int                                     n_refinements = 0;
    std::string                                      stop;
    std::string                                      doing = "the first solve";
  };
} // namespace ddcontact

#endif
