#include <ddcontact/adaptivity/contact_zone_grading.h>
#include <ddcontact/adaptivity/marking.h>
#include <ddcontact/adaptivity/mesh_adaptation.h>
#include <ddcontact/interruption.h>
#include <ddcontact/tasks.h>

#include <algorithm>

namespace ddcontact
{
  MeshAdaptation::MeshAdaptation(const AdaptationParameters &parameters,
                                 const bool grade_contact_zones,
                                 const std::vector<ElasticBody<2> *> &bodies,
                                 const std::vector<ContactPair *>    &pairs,
                                 BodyDistribution   &distribution,
                                 TimerOutput        &timer,
                                 ConditionalOStream &pcout)
    : parameters(parameters)
    , grade_contact_zones(grade_contact_zones)
    , pairs(pairs)
    , distribution(distribution)
    , timer(timer)
    , pcout(pcout)
  {
    for (const auto &name : parameters.bodies)
      for (auto *body : bodies)
        if (body->name() == name)
          adaptations.push_back(
            std::make_unique<AdaptiveRefinement>(*body, parameters));
  }

  unsigned int
  MeshAdaptation::estimate_and_mark(const ContactSolver *solver)
  {
    TimerOutput::Scope t(timer, "adaptation: estimate and mark");
    unsigned int       marked = 0;
    if (parameters.mode == AdaptationMode::uniform)
    {
      for (auto &a : adaptations)
        marked += a->mark_all();
      return marked;
    }
    for (auto &a : adaptations)
    {
      const auto &body = a->get_body();
      if (solver == nullptr)
        a->estimate(body.get_solution(), BoundaryTractionSamples());
      else
        // The FEM solution of (20) and its load, not the relaxed iterate
        // (21): the BEM must solve the same boundary value problem.
        a->estimate(solver->last_body_solution(body),
                    solver->last_contact_traction(body));
    }

    // Fraction and Doerfler marking rank the cells of all adapted bodies
    // together, so that the body with the larger error gets more of the
    // refinement; over all processes' cells, with the same cells flagged
    // on any number of processes.
    if (parameters.marking == MarkingType::threshold)
      for (auto &a : adaptations)
        marked += a->mark_above_delta();
    else
    {
      std::vector<double> contributions;
      for_each_counted_cell([&](const double c, bool)
                            { contributions.push_back(c); });
      const double threshold = joint_marking_threshold(
        contributions, parameters, marking_communicator());
      for (auto &a : adaptations)
        marked += a->mark_above(threshold);
    }

    // Multipliers on the nodes of S_1 need an S_2 at least as fine
    // (grade_contact_zone()); the paper's penalty on the points is left as
    // the paper has it.
    if (marked > 0 && grade_contact_zones)
      for (const auto *pair : pairs)
        for (auto &a : adaptations)
        {
          auto &body = a->get_body();
          if (&body == &pair->get_body_2())
            marked += grade_contact_zone(
              *pair, body.get_triangulation(), parameters.max_level);
        }
    return marked;
  }

  unsigned int
  MeshAdaptation::mark(const ContactSolver *solver, const bool may_refine)
  {
    interruption::check("adaptation cycle " + std::to_string(n_refinements));
    doing = "adaptation step " + std::to_string(n_refinements + 1) +
            " (estimate and marking)";
    unsigned int marked = estimate_and_mark(solver);
    // Adaptation/Target error: the estimate of the relative energy-norm
    // error decides, whatever the marking rule flagged.
    const double target   = parameters.target_error;
    const double estimate = relative_energy_error_estimate(adaptations);
    stop.clear();
    if (target > 0 && estimate >= 0 && estimate <= target)
    {
      if (marked > 0)
        pcout << "  Adaptation/Target error reached: estimated relative "
                 "energy-norm error "
              << estimate << " <= " << target << std::endl;
      return 0;
    }
    if (target > 0 && estimate >= 0)
    {
      pcout << "  estimated relative energy-norm error " << estimate
            << " (target " << target << ")" << std::endl;
      // Above the target, every cycle refines at least a set share of the
      // estimated error, so that neither a threshold that flags nothing
      // nor one that flags a few cells per cycle stalls the run.
      marked = ensure_error_share(marked);
    }
    if (!may_refine && marked > 0)
    {
      pcout << "  Adaptation/Max cycles reached: " << marked
            << " marked cells stay unrefined" << std::endl;
      stop = "Adaptation/Max cycles (" + std::to_string(parameters.max_cycles) +
             ") was reached";
      return 0;
    }
    // Why nothing is refined, for the console and summary.json (with or
    // without a Target error: a cap that stops the marking is never
    // silent).
    if (marked == 0)
      stop = reason_for_no_marking();
    return marked;
  }

  std::string
  MeshAdaptation::reason_for_no_marking() const
  {
    unsigned int capped = 0;
    bool         full   = false;
    for (const auto &a : adaptations)
    {
      capped += a->n_capped();
      full = full || a->get_body().n_active_cells() + 3 > parameters.max_cells;
    }
    if (full)
      return "Adaptation/Max cells (" + std::to_string(parameters.max_cells) +
             ") leaves no room for another refinement";
    if (capped > 0)
      return std::to_string(capped) +
             " flagged cells are at Adaptation/Max level (" +
             std::to_string(parameters.max_level) + ")";
    return "the marking flagged no cell";
  }

  unsigned int
  MeshAdaptation::ensure_error_share(const unsigned int marked)
  {
    // The error the flagged cells carry, relative to the whole estimate
    // (sums of squared contributions, all adapted bodies, all processes).
    double              flagged = 0, total = 0;
    std::vector<double> contributions;
    for_each_counted_cell(
      [&](const double c, const bool is_flagged)
      {
        contributions.push_back(c);
        total += c * c;
        if (is_flagged)
          flagged += c * c;
      });
    const MPI_Comm comm = marking_communicator();
    flagged             = ordered_sum(flagged, comm);
    total               = ordered_sum(total, comm);
    if (!(total > 0) ||
        flagged >= AdaptationParameters::min_refined_error_share * total)
      return marked;
    AdaptationParameters doerfler = parameters;
    doerfler.marking              = MarkingType::doerfler;
    doerfler.fraction = AdaptationParameters::min_refined_error_share;
    const double threshold =
      joint_marking_threshold(contributions, doerfler, comm);
    unsigned int now = 0;
    for (auto &a : adaptations)
      now += a->mark_above(threshold);
    pcout << "  the marking flagged " << marked << " cells carrying "
          << 100. * flagged / total << " % of the estimated error: marking "
          << now << " cells (Doerfler, "
          << 100. * AdaptationParameters::min_refined_error_share
          << " %) instead" << std::endl;
    return now;
  }

  MPI_Comm
  MeshAdaptation::marking_communicator() const
  {
    for (const auto &a : adaptations)
      if (a->get_body().is_mesh_distributed())
        return distribution.get_communicator();
    return MPI_COMM_SELF;
  }

  void
  MeshAdaptation::for_each_counted_cell(
    const std::function<void(double, bool)> &f) const
  {
    // A p4est body counts its own cells on each process; a body held
    // whole (serial or shared mesh) is counted by the first process when
    // the sums run over the processes, else by each process alone.
    const bool whole_here =
      marking_communicator() == MPI_COMM_SELF ||
      Utilities::MPI::this_mpi_process(distribution.get_communicator()) == 0;
    for (const auto &a : adaptations)
    {
      const auto &body = a->get_body();
      const auto &c    = a->error_contributions();
      for (const auto &cell : body.get_triangulation().active_cell_iterators())
        if (body.is_mesh_distributed() ? cell->is_locally_owned() : whole_here)
          f(c(cell->active_cell_index()), cell->refine_flag_set());
    }
  }

  void
  MeshAdaptation::refine(ContactSolver *solver)
  {
    TimerOutput::Scope t(timer, "adaptation: refine and transfer");
    doing = "adaptation step " + std::to_string(n_refinements + 1) +
            " (refinement and transfer)";
    // The adapted bodies' meshes are independent: refine them at once
    // (one after the other on partitioned meshes, whose refinement is
    // collective).
    run_tasks(
      adaptations.size(),
      [&](const unsigned int i) { adaptations[i]->refine(); },
      distribution.uses_process_groups());
    ++n_refinements;
    doing = "the solve after adaptation step " + std::to_string(n_refinements);
    // Refinement changed the bodies' sizes: balance them again.
    if (distribution.distribute())
      pcout << "  bodies now solved on processes " << distribution.describe()
            << std::endl;
    for (auto *pair : pairs)
      pair->setup();
    if (solver != nullptr)
    {
      solver->get_problem().update_vector_layouts();
      solver->reinit_after_refinement();
    }
  }
} // namespace ddcontact
