#include <ddcontact/adaptivity/contact_zone_grading.h>
#include <ddcontact/adaptivity/marking.h>
#include <ddcontact/interruption.h>
#include <ddcontact/simulation.h>
#include <ddcontact/solvers/monolithic_solver.h>
#include <ddcontact/tasks.h>
#include <ddcontact/version.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** The objects of a list of owners, for the solvers that only use
     * them. */
    template <typename T>
    std::vector<T *>
    raw_pointers(const std::vector<std::unique_ptr<T>> &owners)
    {
      std::vector<T *> pointers;
      for (const auto &o : owners)
        pointers.push_back(o.get());
      return pointers;
    }

    /** Call @p work on every object: as concurrent tasks, or one after
     * the other (in the same order on every process) when the work is
     * collective over MPI, as on partitioned meshes. */
    template <typename T>
    void
    for_each_object(const std::vector<std::unique_ptr<T>> &objects,
                    const bool                             in_turn,
                    const std::function<void(T &)>        &work)
    {
      run_tasks(
        objects.size(),
        [&](const unsigned int i) { work(*objects[i]); },
        in_turn);
    }
  } // namespace

  Simulation::Simulation(const SceneParameters &parameters,
                         std::ostream          &screen)
    : parameters(parameters)
    , pcout(screen, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    // The member copy of the parameters, which outlives the argument.
    , report(this->parameters, timer, wall_clock, pcout)
    , writes_files(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
  }

  RunReport::Results
  Simulation::results() const
  {
    return {bodies,
            *distribution,
            contact_pairs,
            dd_solver.get(),
            adaptations,
            n_adaptation_steps,
            n_contact_iterations,
            n_newton_iterations,
            adaptation_stop};
  }

  void
  Simulation::setup_bodies()
  {
    TimerOutput::Scope t(timer, "setup");
    bodies.clear();
    // With process groups every mesh is partitioned over the world (and
    // its refinement is collective); otherwise each body is serial.
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const bool partitioned =
      parameters.parallel.process_groups(n_processes, parameters.bodies.size());
    for (const auto &body_parameters : parameters.bodies)
    {
      bodies.push_back(std::make_unique<ElasticBody<2>>(
        body_parameters,
        parameters.constants,
        parameters.parallel.mesh_kind(
          body_parameters, n_processes, parameters.bodies.size())));
      // Assembled and factorized only where it is solved, below.
      bodies.back()->set_solved_here(false);
      bodies.back()->make_mesh(parameters.output_directory);
    }
    for_each_object<ElasticBody<2>>(
      bodies, partitioned, [](ElasticBody<2> &body) { body.setup_system(); });
    // A floating body (ElasticBody::is_floating()) is held by contact
    // alone; without a contact pair nothing holds it.
    for (const auto &body : bodies)
      if (body->is_floating() && std::none_of(parameters.contact_pairs.begin(),
                                              parameters.contact_pairs.end(),
                                              [&](const auto &p) {
                                                return p.body_1 ==
                                                         body->name() ||
                                                       p.body_2 == body->name();
                                              }))
        throw InputError("Body " + body->name() +
                         "/Dirichlet: the body is in no contact pair, so "
                         "nothing holds its free " +
                         body->get_rigid_modes().description() +
                         "; prescribe the displacement on a boundary");

    distribution = std::make_unique<BodyDistribution>(
      raw_pointers(bodies), parameters.parallel, MPI_COMM_WORLD);
    distribution->distribute();
    if (distribution->n_processes() > 1)
      pcout << "  " << distribution->n_processes()
            << " MPI processes; bodies solved on processes "
            << distribution->describe() << std::endl;

    for (const auto &body : bodies)
      pcout << "  body " << std::setw(10) << std::left << body->name()
            << std::right << std::setw(9) << body->n_active_cells() << " cells "
            << std::setw(9) << body->n_dofs() << " dofs  ("
            << (body->is_simplex() ? "triangles" : "quadrilaterals")
            << (body->is_mesh_distributed() ? ", p4est" : "") << ", "
            << body->get_fe().get_name() << ")" << std::endl;
    for (const auto &body : bodies)
      for (const auto &circle : body->get_mesh().circular_boundaries())
        pcout << "    " << body->name() << ", curved boundary " << circle
              << std::endl;
    for (const auto &body : bodies)
      if (body->get_mesh().n_merged_vertices() > 0)
        pcout << "    " << body->name() << ", merged "
              << body->get_mesh().n_merged_vertices()
              << " coincident vertices of its mesh file (Mesh/Merge "
                 "coincident vertices)"
              << std::endl;
  }

  void
  Simulation::solve_bodies()
  {
    TimerOutput::Scope          t(timer, "solve");
    std::vector<Vector<double>> u(bodies.size());
    distribution->solve_and_share(
      [&](const unsigned int b)
      {
        bodies[b]->solve();
        u[b] = bodies[b]->get_solution();
      },
      u);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->get_solution() = u[b];
  }

  void
  Simulation::setup_contact()
  {
    TimerOutput::Scope t(timer, "contact setup");
    const auto         find = [&](const std::string &name) -> ElasticBody<2> &
    {
      for (auto &b : bodies)
        if (b->name() == name)
          return *b;
      throw InputError("no body named '" + name + "'");
    };
    contact_pairs.clear();
    for (const auto &p : parameters.contact_pairs)
    {
      contact_pairs.push_back(std::make_unique<ContactPair>(
        p, find(p.body_1), find(p.body_2), parameters.constants));
      const ContactPair &pair = *contact_pairs.back();
      contact_pairs.back()->setup();
      const auto &found = pair.search_report();
      pcout << "  contact pair " << p.name << ": " << p.body_1 << " -> "
            << p.body_2 << ", " << found.n_points << " of " << found.n_examined
            << " points of S_1 face S_2 within the search distance "
            << found.search_distance;
      if (found.n_points > 0)
        pcout << ", initial gap " << found.min_gap << " to " << found.max_gap;
      if (!parameters.dd.exact_contact())
        pcout << ", theta = " << pair.penalty();
      pcout << std::endl;
      for (const auto &warning : pair.setup_warnings())
        pcout << "warning: " << warning << std::endl;
    }
    dd_solver = ContactSolver::create(parameters.dd,
                                      raw_pointers(bodies),
                                      raw_pointers(contact_pairs),
                                      *distribution,
                                      pcout);
    if (parameters.dd.write_every_iteration)
      dd_solver->set_iteration_callback(
        [this](const unsigned int k)
        {
          std::ostringstream suffix;
          suffix << '_' << std::setw(4) << std::setfill('0') << k;
          report.write_contact_profiles(results(), suffix.str());
        });
  }

  unsigned int
  Simulation::solve_contact()
  {
    TimerOutput::Scope t(timer, "contact solve");
    if (parameters.dd.solver != ContactSolverType::monolithic)
    {
      const unsigned int before = dd_solver->n_dd_iterations();
      dd_solver->run();
      return dd_solver->n_dd_iterations() - before;
    }

    // Semismooth Newton on the penalised problem, inside the same Uzawa
    // loop as the DD when the augmented Lagrangian is on.
    MonolithicContactSolver newton(dd_solver->get_problem(),
                                   parameters.dd.pressure_on_nodes,
                                   parameters.dd.n_newton,
                                   pcout);
    do
      n_newton_iterations += newton.run();
    while (dd_solver->start_uzawa_phase());
    dd_solver->adopt_current_iterate();
    return 0;
  }

  void
  Simulation::setup_adaptation()
  {
    adaptations.clear();
    for (const auto &name : parameters.adaptation.bodies)
      for (auto &body : bodies)
        if (body->name() == name)
          adaptations.push_back(
            std::make_unique<AdaptiveRefinement>(*body, parameters.adaptation));
    report.open_statistics(bodies);
  }

  unsigned int
  Simulation::solve_on_current_mesh()
  {
    if (contact_pairs.empty())
    {
      solve_bodies();
      return 0;
    }
    return solve_contact();
  }

  unsigned int
  Simulation::estimate_and_mark()
  {
    TimerOutput::Scope t(timer, "adaptation: estimate and mark");
    unsigned int       marked = 0;
    if (parameters.adaptation.mode == AdaptationMode::uniform)
    {
      for (auto &a : adaptations)
        marked += a->mark_all();
      return marked;
    }
    for (auto &a : adaptations)
    {
      const auto &body = a->get_body();
      if (contact_pairs.empty())
        a->estimate(body.get_solution(), BoundaryTractionSamples());
      else
        // The FEM solution of (20) and its load, not the relaxed iterate
        // (21): the BEM must solve the same boundary value problem.
        a->estimate(dd_solver->last_body_solution(body),
                    dd_solver->last_contact_traction(body));
    }

    // Fraction and Doerfler marking rank the cells of all adapted bodies
    // together, so that the body with the larger error gets more of the
    // refinement (on one process; a distributed mesh marks its own).
    bool joint = parameters.adaptation.marking != MarkingType::threshold &&
                 adaptations.size() > 1;
    std::vector<const Vector<double> *> contributions;
    for (const auto &a : adaptations)
    {
      joint = joint && !a->get_body().is_mesh_distributed();
      contributions.push_back(&a->error_contributions());
    }
    const double threshold =
      joint ? joint_marking_threshold(contributions, parameters.adaptation)
            : 0.;
    for (auto &a : adaptations)
      marked += joint ? a->mark_above(threshold) : a->mark();

    // Multipliers on the nodes of S_1 need an S_2 at least as fine
    // (grade_contact_zone()); the paper's penalty on the points is left as
    // the paper has it.
    if (marked > 0 && parameters.dd.multipliers_on_nodes())
      for (const auto &pair : contact_pairs)
        for (auto &body : bodies)
        {
          const bool adapted = std::any_of(
            adaptations.begin(),
            adaptations.end(),
            [&](const auto &a) { return &a->get_body() == body.get(); });
          if (body.get() == &pair->get_body_2() && adapted &&
              !body->is_mesh_distributed())
            marked += grade_contact_zone(*pair,
                                         body->get_triangulation(),
                                         parameters.adaptation.max_level);
        }
    return marked;
  }

  void
  Simulation::refine_and_transfer()
  {
    TimerOutput::Scope t(timer, "adaptation: refine and transfer");
    step = "adaptation step " + std::to_string(n_adaptation_steps + 1) +
           " (refinement and transfer)";
    // The adapted bodies' meshes are independent: refine them at once
    // (one after the other on partitioned meshes, whose refinement is
    // collective).
    for_each_object<AdaptiveRefinement>(adaptations,
                                        distribution->uses_process_groups(),
                                        [](AdaptiveRefinement &a)
                                        { a.refine(); });
    ++n_adaptation_steps;
    step =
      "the solve after adaptation step " + std::to_string(n_adaptation_steps);
    // Refinement changed the bodies' sizes: balance them again.
    if (distribution->distribute())
      pcout << "  bodies now solved on processes " << distribution->describe()
            << std::endl;
    if (!contact_pairs.empty())
    {
      for (auto &pair : contact_pairs)
        pair->setup();
      dd_solver->reinit_after_refinement();
    }
  }

  unsigned int
  Simulation::mark_cells(const bool may_refine)
  {
    interruption::check("adaptation cycle " +
                        std::to_string(n_adaptation_steps));
    step = "adaptation step " + std::to_string(n_adaptation_steps + 1) +
           " (estimate and marking)";
    unsigned int marked = estimate_and_mark();
    // Adaptation/Target error: the estimate of the relative energy-norm
    // error decides, whatever the marking rule flagged.
    const double target   = parameters.adaptation.target_error;
    const double estimate = relative_energy_error_estimate(adaptations);
    adaptation_stop.clear();
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
      adaptation_stop = "Adaptation/Max cycles (" +
                        std::to_string(parameters.adaptation.max_cycles) +
                        ") was reached";
      return 0;
    }
    if (marked == 0 && target > 0 && estimate > target)
    {
      unsigned int capped = 0;
      bool         full   = false;
      for (const auto &a : adaptations)
      {
        capped += a->n_capped();
        full = full || a->get_body().n_active_cells() + 3 >
                         parameters.adaptation.max_cells;
      }
      adaptation_stop =
        full ? "Adaptation/Max cells (" +
                 std::to_string(parameters.adaptation.max_cells) +
                 ") leaves no room for another refinement"
        : capped > 0 ? std::to_string(capped) +
                         " flagged cells are at Adaptation/Max level (" +
                         std::to_string(parameters.adaptation.max_level) + ")"
                     : "the marking flagged no cell";
    }
    return marked;
  }

  unsigned int
  Simulation::ensure_error_share(const unsigned int marked)
  {
    // The error the flagged cells carry, relative to the whole estimate
    // (sums of squared contributions, all adapted bodies).
    double                              flagged = 0, total = 0;
    bool                                serial = true;
    std::vector<const Vector<double> *> contributions;
    for (const auto &a : adaptations)
    {
      const auto &body = a->get_body();
      serial           = serial && !body.is_mesh_distributed();
      const auto &c    = a->error_contributions();
      contributions.push_back(&c);
      for (const auto &cell : body.get_triangulation().active_cell_iterators())
      {
        const double c2 =
          c(cell->active_cell_index()) * c(cell->active_cell_index());
        total += c2;
        if (cell->refine_flag_set())
          flagged += c2;
      }
    }
    // (Distributed meshes mark their own cells: left as the rule marked.)
    if (!serial || !(total > 0) ||
        flagged >= AdaptationParameters::min_refined_error_share * total)
      return marked;
    AdaptationParameters doerfler = parameters.adaptation;
    doerfler.marking              = MarkingType::doerfler;
    doerfler.fraction      = AdaptationParameters::min_refined_error_share;
    const double threshold = joint_marking_threshold(contributions, doerfler);
    unsigned int now       = 0;
    for (auto &a : adaptations)
      now += a->mark_above(threshold);
    pcout << "  the marking flagged " << marked << " cells carrying "
          << 100. * flagged / total << " % of the estimated error: marking "
          << now << " cells (Doerfler, "
          << 100. * AdaptationParameters::min_refined_error_share
          << " %) instead" << std::endl;
    return now;
  }

  void
  Simulation::output_adaptation_step()
  {
    output_results(n_output_steps);
    report.write_cells(results(), n_output_steps);
    ++n_output_steps;
  }

  unsigned int
  Simulation::solve_nested()
  {
    unsigned int n_iterations = 0;
    if (!contact_pairs.empty())
      dd_solver->initialize();
    for (unsigned int cycle = 0;; ++cycle)
    {
      n_iterations += solve_on_current_mesh();
      const bool last = (cycle == parameters.adaptation.max_cycles);
      // The last uniform mesh is not marked at all.
      const unsigned int marked =
        (last && parameters.adaptation.mode == AdaptationMode::uniform)
          ? 0
          : mark_cells(!last);
      pcout << "  adaptation cycle " << cycle << ": " << marked
            << " cells marked" << std::endl;
      report.write_statistics_row(results(), marked, true);
      if (parameters.adaptation.write_every_mesh || marked == 0 || last)
        output_adaptation_step();
      if (marked == 0 || last)
        break;
      refine_and_transfer();
    }
    return n_iterations;
  }

  unsigned int
  Simulation::solve_combined()
  {
    if (contact_pairs.empty())
      return solve_nested(); // no DD: one solve per cycle

    dd_solver->initialize();
    bool frozen = false;
    while (true)
    {
      bool converged;
      {
        TimerOutput::Scope t(timer, "contact solve");
        if (dd_solver->history().size() >= parameters.dd.max_iterations)
          dd_solver->stop_at_iteration_limit("the combined algorithm");
        converged = dd_solver->step(); // (20)-(21), or one Newton step
      }
      // A frozen mesh, or one that may not be refined any more, is only
      // checked again once the DD has converged.
      const bool may_refine =
        n_adaptation_steps < parameters.adaptation.max_cycles;
      if ((frozen || !may_refine) && !converged)
        continue;

      const unsigned int marked = mark_cells(may_refine);
      pcout << "  cycle " << n_adaptation_steps << " (DD iteration "
            << dd_solver->history().size() << "): " << marked << " cells marked"
            << std::endl;
      report.write_statistics_row(results(), marked, true);
      if (parameters.adaptation.write_every_mesh ||
          (marked == 0 && converged) || n_output_steps == 0)
        output_adaptation_step();
      if (marked > 0)
      {
        refine_and_transfer();
        frozen = false;
      }
      else if (converged && !dd_solver->start_uzawa_phase())
        break;
      else
        // Not converged, or a new Uzawa phase with lambda <- sigma_n: the
        // mesh is checked again when the DD has converged.
        frozen = true;
    }
    return dd_solver->n_dd_iterations();
  }

  void
  Simulation::output_results(const unsigned int step)
  {
    // Partitioned meshes are written in pieces by all processes.
    if (!writes_files && !distribution->uses_process_groups())
      return;
    if (!parameters.write_vtu)
      return;
    TimerOutput::Scope t(timer, "output");
    if (!output_writer)
      output_writer = std::make_unique<OutputWriter>(
        parameters.output_directory,
        distribution->uses_process_groups() ? MPI_COMM_WORLD : MPI_COMM_SELF,
        parameters.smoothed_stresses);
    std::vector<const ElasticBody<2> *> body_pointers;
    std::vector<const Vector<double> *> solutions;
    std::vector<OutputWriter::CellData> cell_data(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      body_pointers.push_back(bodies[b].get());
      solutions.push_back(&bodies[b]->get_solution());
      for (const auto &a : adaptations)
        if (&a->get_body() == bodies[b].get())
          cell_data[b] = a->cell_data();
    }
    output_writer->write_step(step, step, body_pointers, solutions, cell_data);

    // Every contact zone in the same step, with its multipliers if the
    // augmented Lagrangian is on.
    if (!writes_files || contact_pairs.empty())
      return;
    if (!contact_zone_writer)
      contact_zone_writer =
        std::make_unique<ContactZoneWriter>(parameters.output_directory);
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
      contact_zone_writer->write_step(
        step,
        step,
        *contact_pairs[p],
        dd_solver->contact_state(p),
        parameters.dd.augmented_lagrangian
          ? dd_solver->get_problem().law(p).multipliers()
          : std::vector<double>());
  }

  unsigned int
  Simulation::solve()
  {
    if (!parameters.adaptation.enabled())
    {
      // The fixed meshes of the input.
      if (!contact_pairs.empty())
        dd_solver->initialize();
      return solve_on_current_mesh();
    }
    if (parameters.adaptation.mode == AdaptationMode::combined)
      return solve_combined();
    return solve_nested();
  }

  void
  Simulation::write_failed_run(const std::string &status)
  {
    n_contact_iterations = dd_solver->n_dd_iterations();
    report.write_history(dd_solver->history());
    report.write_contact_profiles(results(), "");
    // The last iterate as the next output step, for diagnosis; a failure
    // to write it must not hide why the run stopped.
    try
    {
      output_results(n_output_steps);
    }
    catch (const std::exception &e)
    {
      pcout << "  the last iterate could not be written: " << e.what()
            << std::endl;
    }
    report.write_summary(results(), status);
  }

  void
  Simulation::run()
  {
    try
    {
      run_steps();
    }
    catch (const OutOfMemoryError &)
    {
      throw;
    }
    catch (const std::bad_alloc &)
    {
      throw OutOfMemoryError("out of memory in " + step +
                             "; refine less (Mesh/Initial refinement, "
                             "Adaptation/Max cells or Max level) or run on "
                             "more processes");
    }
  }

  void
  Simulation::run_steps()
  {
    wall_clock.restart();
    std::filesystem::create_directories(parameters.output_directory);
    pcout << version_banner() << std::endl
          << "scene '" << parameters.scene_name << "', output in "
          << parameters.output_directory << std::endl;

    setup_bodies();
    // An Output/Points entry outside its body is refused now, not after
    // the solve (the evaluation names the entry and the point).
    for (const auto &point : parameters.points)
      for (const auto &body : bodies)
        if (body->name() == point.body)
          body->stresses().at_point(point.x);
    if (parameters.adaptation.enabled())
      setup_adaptation();
    if (!parameters.contact_pairs.empty())
    {
      step = "the contact setup";
      setup_contact();
    }

    try
    {
      step                 = "the first solve";
      n_contact_iterations = solve();
    }
    catch (const DivergenceError &error)
    {
      if (dd_solver)
        write_failed_run(dynamic_cast<const NotConvergedError *>(&error)
                           ? "not_converged"
                           : "diverged");
      throw;
    }
    catch (const InterruptedError &)
    {
      // The history so far, the last iterate and summary.json "interrupted".
      if (dd_solver)
        write_failed_run("interrupted");
      else
        report.write_summary(results(), "interrupted");
      throw;
    }

    std::string status = "completed", shortfall;
    if (dd_solver)
    {
      report.write_history(dd_solver->history());
      report.write_contact_profiles(results(), "");
      report.print_contact_states(results());
      // "converged" only if the augmented Lagrangian met its tolerance too.
      shortfall = dd_solver->augmented_lagrangian_shortfall();
      status    = shortfall.empty() ? "converged" : "stalled";
    }
    if (!parameters.adaptation.enabled())
      output_results(0);
    // A Target error that the adaptation stopped above is a shortfall of
    // the run, named in summary.json and by the exit code 5.
    const double target   = parameters.adaptation.target_error;
    const double estimate = relative_energy_error_estimate(adaptations);
    const bool   missed   = parameters.adaptation.enabled() && target > 0 &&
                        estimate > target && shortfall.empty();
    if (missed)
      status = "target_not_reached";
    report.write_summary(results(), status);
    report.print_reactions();
    report.print_warnings();
    if (!shortfall.empty())
      throw DivergenceError(shortfall);
    if (missed)
      for (const auto &warning : report.summary().at("warnings"))
        if (warning.get<std::string>().rfind("Adaptation/Target error", 0) == 0)
          throw TargetNotReachedError(warning.get<std::string>());

    timer.print_summary();
    pcout << "wall time " << std::fixed << std::setprecision(2)
          << wall_clock.wall_time() << " s" << std::defaultfloat << std::endl;
  }
} // namespace ddcontact
