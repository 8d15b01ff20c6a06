#include <ddcontact/adaptivity/adaptive_strategy.h>

namespace ddcontact
{
  std::unique_ptr<AdaptiveStrategy>
  AdaptiveStrategy::create(const AdaptationParameters &parameters,
                           const Context              &context)
  {
    if (!parameters.enabled())
      return std::make_unique<FixedMeshes>(parameters, context);
    // Without contact there is no DD step to interleave: one solve per
    // cycle, as in the nested loop.
    if (parameters.mode == AdaptationMode::combined && context.solver)
      return std::make_unique<CombinedAlgorithm>(parameters, context);
    return std::make_unique<NestedAdaptation>(parameters, context);
  }

  AdaptiveStrategy::AdaptiveStrategy(const AdaptationParameters &parameters,
                                     const Context              &context)
    : parameters(parameters)
    , context(context)
  {
  }

  void
  AdaptiveStrategy::solve_on_current_mesh()
  {
    if (context.solver == nullptr)
    {
      context.solve_bodies();
      return;
    }
    TimerOutput::Scope t(context.timer, "contact solve");
    context.solver->run();
  }

  std::string
  AdaptiveStrategy::stop_note(const unsigned int marked) const
  {
    const std::string reason =
      context.adaptation ? context.adaptation->stop_reason() : "";
    return (marked == 0 && !reason.empty()) ? " (" + reason + ")" : "";
  }

  void
  AdaptiveStrategy::start_solver()
  {
    if (context.solver && !started)
      context.solver->initialize();
    started = true;
  }

  void
  FixedMeshes::solve()
  {
    start_solver();
    solve_on_current_mesh();
  }

  void
  NestedAdaptation::solve()
  {
    auto &adaptation = *context.adaptation;
    start_solver();
    for (unsigned int cycle = 0;; ++cycle)
    {
      solve_on_current_mesh();
      const bool last = (cycle == parameters.max_cycles);
      // The last uniform mesh is not marked at all.
      const unsigned int marked =
        (last && parameters.mode == AdaptationMode::uniform)
          ? 0
          : adaptation.mark(context.solver, !last);
      context.pcout << "  adaptation cycle " << cycle << ": " << marked
                    << " cells marked" << stop_note(marked) << std::endl;
      const bool final = (marked == 0 || last);
      context.adaptation_step(marked, parameters.write_every_mesh || final);
      if (final)
        break;
      adaptation.refine(context.solver);
    }
  }

  void
  CombinedAlgorithm::solve()
  {
    auto &solver     = *context.solver;
    auto &adaptation = *context.adaptation;
    start_solver();
    // Max cycles counts the adaptation steps of this call (load step).
    const unsigned int first_step = adaptation.n_steps();
    // A step that marks no cell freezes the mesh: the estimate is skipped
    // until the DD has converged, when it is checked once more (the
    // indicator only moves with the data then, so this saves a BEM solve
    // per DD iteration without changing where the algorithm stops).
    bool frozen = false, first = true;
    while (true)
    {
      // One DD step (20)-(21), or one Newton step.
      bool converged;
      {
        TimerOutput::Scope t(context.timer, "contact solve");
        converged = solver.step_within_limit("the combined algorithm");
      }
      // A frozen mesh, or one that may not be refined any more (Max
      // cycles), is only checked again once the DD has converged.
      const bool may_refine =
        adaptation.n_steps() - first_step < parameters.max_cycles;
      if ((frozen || !may_refine) && !converged)
        continue;

      // One adaptation step: estimate and mark ...
      const unsigned int marked = adaptation.mark(&solver, may_refine);
      context.pcout << "  cycle " << adaptation.n_steps() << " (DD iteration "
                    << solver.history().size() << "): " << marked
                    << " cells marked" << stop_note(marked) << std::endl;
      context.adaptation_step(marked,
                              parameters.write_every_mesh || first ||
                                (marked == 0 && converged));
      first = false;
      // ... then refine and transfer the iterate;
      if (marked > 0)
      {
        adaptation.refine(&solver);
        frozen = false;
      }
      // or stop: converged on a mesh that marks nothing, with no new
      // Uzawa multipliers;
      else if (converged && !solver.start_uzawa_phase())
        break;
      // or go on with the mesh frozen: not converged yet, or a new Uzawa
      // phase with lambda <- sigma_n.
      else
        frozen = true;
    }
  }
} // namespace ddcontact
