#ifndef ddcontact_adaptive_strategy_h
#define ddcontact_adaptive_strategy_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <ddcontact/adaptivity/adaptation_parameters.h>
#include <ddcontact/adaptivity/mesh_adaptation.h>
#include <ddcontact/solvers/contact_solver.h>

#include <functional>
#include <memory>

namespace ddcontact
{
  using namespace dealii;

  /**
   * How a run alternates solving and adapting (Adaptation/Mode): fixed
   * meshes, the nested loop or uniform refinement, or the combined
   * algorithm of Fig. 2. A strategy drives any ContactSolver through its
   * interface, and the MeshAdaptation of the adapted bodies; it tells the
   * driver about each adaptation step through a callback.
   */
  class AdaptiveStrategy
  {
  public:
    /** What a strategy works with. */
    struct Context
    {
      /** The contact solver; nullptr in a scene without contact. */
      ContactSolver *solver;
      /** Solves the bodies' problems in a scene without contact. */
      std::function<void()> solve_bodies;
      /** The adapted bodies; nullptr on fixed meshes. */
      MeshAdaptation *adaptation;
      /** Called after every adaptation step with the marked cells and
       * whether the mesh is to be written (Adaptation/Write every mesh,
       * or the mesh the run ends on). */
      std::function<void(unsigned int marked, bool write_mesh)> adaptation_step;
      TimerOutput                                              &timer;
      ConditionalOStream                                       &pcout;
    };

    /** The strategy of Adaptation/Mode. */
    static std::unique_ptr<AdaptiveStrategy>
    create(const AdaptationParameters &parameters, const Context &context);

    AdaptiveStrategy(const AdaptationParameters &parameters,
                     const Context              &context);

    virtual ~AdaptiveStrategy() = default;

    /** Solve the scene, adapting as the strategy does. Throws what the
     * solver throws (DivergenceError, NotConvergedError). */
    virtual void
    solve() = 0;

  protected:
    /** The problem on the current meshes to convergence: the contact
     * solve (with its Uzawa updates), or the body problems alone. */
    void
    solve_on_current_mesh();

    /** Start the contact solver at the first solve(); the next calls (the
     * load steps of Loading/Steps) go on from its last iterate and
     * history, on the meshes the last step left. */
    void
    start_solver();

    /** " (why)" after "0 cells marked" when the marking stopped on a cap
     * (MeshAdaptation::stop_reason()), else empty. */
    std::string
    stop_note(unsigned int marked) const;

    const AdaptationParameters parameters;
    Context                    context;

  private:
    bool started = false;
  };

  /** Adaptation/Mode = none: one solve on the meshes of the input. */
  class FixedMeshes : public AdaptiveStrategy
  {
  public:
    using AdaptiveStrategy::AdaptiveStrategy;

    void
    solve() override;
  };

  /**
   * The classical nested loop (Mode = nested) and uniform refinement
   * (Mode = uniform): solve on each mesh to convergence, then estimate,
   * mark, refine and transfer, until nothing is marked or Max cycles.
   * With load steps every step adapts so, from the meshes of the last.
   */
  class NestedAdaptation : public AdaptiveStrategy
  {
  public:
    using AdaptiveStrategy::AdaptiveStrategy;

    void
    solve() override;
  };

  /**
   * The combined algorithm of Fig. 2 (Mode = combined): one DD step
   * (20)-(21) (or one Newton step), then one adaptation step, until the
   * DD has converged on a mesh that marks no cell. See solve(). With
   * load steps every step adapts so (Max cycles per step), from the
   * meshes of the last.
   */
  class CombinedAlgorithm : public AdaptiveStrategy
  {
  public:
    using AdaptiveStrategy::AdaptiveStrategy;

    void
    solve() override;
  };
} // namespace ddcontact

#endif
