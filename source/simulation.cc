#include <ddcontact/interruption.h>
#include <ddcontact/io/json.h>
#include <ddcontact/io/scene_summary.h>
#include <ddcontact/io/self_checks.h>
#include <ddcontact/output_file.h>
#include <ddcontact/simulation.h>
#include <ddcontact/tasks.h>
#include <ddcontact/version.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>

#include <stdlib.h>

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

  } // namespace

  Simulation::Simulation(const SceneParameters &parameters,
                         std::ostream          &screen)
    : parameters(parameters)
    , pcout(screen, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    // The member copy of the parameters, which outlives the argument.
    , report(this->parameters, timer, wall_clock, pcout)
    , solution_output(this->parameters)
  {
  }

  Simulation::~Simulation()
  {
    std::error_code error;
    if (!mesh_directory.empty())
      std::filesystem::remove_all(mesh_directory, error);
  }

  const std::vector<std::unique_ptr<AdaptiveRefinement>> &
  Simulation::get_adaptations() const
  {
    static const std::vector<std::unique_ptr<AdaptiveRefinement>> none;
    return adaptation ? adaptation->refinements() : none;
  }

  RunReport::Results
  Simulation::results() const
  {
    return {bodies,
            *distribution,
            contact_pairs,
            contact_solver.get(),
            get_adaptations(),
            n_adaptation_cycles(),
            adaptation ? adaptation->stop_reason() : std::string()};
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
    const bool meshes_geometry = std::any_of(
      parameters.bodies.begin(),
      parameters.bodies.end(),
      [](const BodyParameters &b)
      {
        return b.mesh_type == MeshType::file && b.mesh_file.size() >= 4 &&
               b.mesh_file.compare(b.mesh_file.size() - 4, 4, ".geo") == 0;
      });
    if (meshes_geometry && mesh_directory.empty())
    {
      std::string name =
        (std::filesystem::temp_directory_path() / "ddcontact-meshes-XXXXXX")
          .string();
      if (mkdtemp(name.data()) == nullptr)
        throw WriteError("cannot make a temporary directory for gmsh's "
                         "meshes in " +
                         std::filesystem::temp_directory_path().string());
      mesh_directory = name;
    }
    for (const auto &body_parameters : parameters.bodies)
    {
      bodies.push_back(std::make_unique<ElasticBody<2>>(
        body_parameters,
        parameters.constants,
        parameters.parallel.mesh_kind(
          body_parameters, n_processes, parameters.bodies.size())));
      // Assembled and factorized only where it is solved, below.
      bodies.back()->set_solved_here(false);
      bodies.back()->make_mesh(mesh_directory);
    }
    run_tasks(
      bodies.size(),
      [&](const unsigned int b) { bodies[b]->setup_system(); },
      partitioned);
    // A floating body (ElasticBody::is_floating()) is held by contact
    // alone; without a contact pair nothing holds it.
    for (const auto &body : bodies)
      if (body->is_floating() && !parameters.in_contact_pair(body->name()))
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
      pcout << describe_body(*body);
    // An Output/Points entry outside its body is refused now, not after
    // the solve (the evaluation names the entry and the point).
    for (const auto &point : parameters.points)
      for (const auto &body : bodies)
        if (body->name() == point.body)
          body->stresses().at_point(point.x);
  }

  void
  Simulation::setup_contact()
  {
    if (parameters.contact_pairs.empty())
      return;
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
      contact_pairs.back()->setup();
      pcout << describe_contact_pair(*contact_pairs.back(),
                                     parameters.contact_solver.exact_contact());
    }
    distribute_body_vectors();
    contact_solver = ContactSolver::create(parameters.contact_solver,
                                           raw_pointers(bodies),
                                           raw_pointers(contact_pairs),
                                           *distribution,
                                           pcout);
    if (parameters.contact_solver.write_every_iteration)
      contact_solver->set_iteration_callback(
        [this](const unsigned int k)
        {
          std::ostringstream suffix;
          suffix << '_' << std::setw(4) << std::setfill('0') << k;
          report.write_contact_profiles(results(), suffix.str());
        });
  }

  void
  Simulation::distribute_body_vectors()
  {
    // The solvers read a body's iterate only on the contact zones (the
    // traces), in the body's own solves and, adapting, on the body's own
    // cells (the FEM stresses of the estimators), so a body on a p4est
    // mesh keeps just its part; the paper's relaxation (21) is entrywise,
    // with inner products over the processes.
    const auto traces = ContactProblem(raw_pointers(bodies),
                                       raw_pointers(contact_pairs),
                                       *distribution)
                          .trace_dofs();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies[b]->is_mesh_distributed())
        bodies[b]->distribute_vectors(traces[b]);
  }

  void
  Simulation::setup_strategy()
  {
    if (parameters.adaptation.enabled())
    {
      adaptation = std::make_unique<MeshAdaptation>(
        parameters.adaptation,
        parameters.contact_solver.multipliers_on_nodes(),
        raw_pointers(bodies),
        raw_pointers(contact_pairs),
        *distribution,
        timer,
        pcout);
    }
    strategy = AdaptiveStrategy::create(
      parameters.adaptation,
      {contact_solver.get(),
       [this]()
       {
         TimerOutput::Scope t(timer, "solve");
         distribution->solve_bodies();
       },
       adaptation.get(),
       [this](const unsigned int marked, const bool write_mesh)
       { adaptation_step(marked, write_mesh); },
       timer,
       pcout});
  }

  void
  Simulation::record_progress(const std::string &what)
  {
    last_completed = what;
    report.set_last_completed_step(what);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const std::string summary = parameters.output_directory + "/summary.json";
    write_json_file(report.progress_summary(RunOutcome::running, ""), summary);
    std::array<std::string, 2> texts;
    for (const unsigned int s : {0u, 1u})
      texts[s] =
        report
          .progress_summary(RunOutcome::interrupted,
                            std::string(s == 0 ? "SIGINT" : "SIGTERM") +
                              " received: the run stopped in " + step + ", " +
                              (what.empty() ? "before any step "
                                              "was complete"
                                            : "after " + what))
          .dump(2, ' ', false, Json::error_handler_t::replace) +
        '\n';
    interruption::set_record(summary, texts);
  }

  void
  Simulation::adaptation_step(const unsigned int marked, const bool write_mesh)
  {
    report.write_statistics_row(results(), marked, true);
    if (write_mesh)
    {
      output_results(n_output_steps);
      report.write_cells(results(), n_output_steps);
      ++n_output_steps;
    }
    record_progress("adaptation cycle " +
                    std::to_string(n_adaptation_cycles()) + " of " + step);
  }

  void
  Simulation::output_results(const unsigned int step)
  {
    TimerOutput::Scope t(timer, "output");
    solution_output.write_step(results(), step);
  }

  void
  Simulation::write_failed_run(const RunOutcome   outcome,
                               const std::string &error)
  {
    report.write_history(contact_solver->history());
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
    report.write_summary(results(), outcome, error);
  }

  template <typename Steps>
  void
  Simulation::naming_memory_errors(const Steps &steps)
  {
    try
    {
      steps();
    }
    catch (const OutOfMemoryError &)
    {
      throw;
    }
    catch (const std::bad_alloc &)
    {
      // During the solve, the adaptation knows which step it is in.
      const std::string where = (adaptation && step == "the first solve")
                                  ? adaptation->activity()
                                  : step;
      throw OutOfMemoryError("out of memory in " + where +
                             "; refine less (Mesh/Initial refinement, "
                             "Adaptation/Max cells or Max level) or run on "
                             "more processes");
    }
  }

  void
  Simulation::setup()
  {
    naming_memory_errors([this]() { setup_steps(); });
  }

  void
  Simulation::run()
  {
    naming_memory_errors(
      [this]()
      {
        if (!is_set_up)
          setup_steps();
        run_steps();
      });
  }

  void
  Simulation::setup_steps()
  {
    wall_clock.restart();
    pcout << version_banner() << std::endl
          << "scene '" << parameters.scene_name << "', output in "
          << parameters.output_directory << std::endl;

    setup_bodies();
    step = "the contact setup";
    setup_contact();
    setup_strategy();
    is_set_up = true;
  }

  void
  Simulation::run_steps()
  {
    // (main() made it and claimed it; a program of its own may not have.)
    std::filesystem::create_directories(parameters.output_directory);
    if (adaptation)
      report.open_statistics(bodies);
    record_progress("");
    run_load_steps();
    // The outcome the run earned: "converged" only if the Uzawa loop met
    // its tolerance too; a Target error that the adaptation stopped above
    // is a shortfall of the run (exit code 5). Written, then thrown.
    const std::string stalled =
      contact_solver ? contact_solver->augmented_lagrangian_shortfall() : "";
    const std::string missed =
      adaptation ? report.target_shortfall(results()) : "";
    const RunOutcome outcome = !stalled.empty() ? RunOutcome::stalled
                               : !missed.empty()
                                 ? RunOutcome::target_not_reached
                               : contact_solver ? RunOutcome::converged
                                                : RunOutcome::completed;
    report.write_final(results(), outcome);
    if (outcome == RunOutcome::stalled)
      throw DivergenceError(stalled);
    if (outcome == RunOutcome::target_not_reached)
      throw TargetNotReachedError(missed);

    timer.print_summary();
    pcout << "wall time " << std::fixed << std::setprecision(2)
          << wall_clock.wall_time() << " s" << std::defaultfloat << std::endl;
  }

  void
  Simulation::check_answer()
  {
    // The contact states and reactions, which the report writes too.
    timer.enter_subsection("states and reactions");
    const RunReport::Answer &answer = report.fix_answer(results());
    timer.leave_subsection();
    TimerOutput::Scope t(timer, "self-checks");
    const SelfChecks   checks(
      results(), answer, parameters.contact_solver.tolerance);
    report.set_self_checks(checks.json());
    if (!checks.passed())
      throw NotConvergedError(checks.failure());
  }

  void
  Simulation::solve()
  {
    try
    {
      // The answer changes here; the report and the checks share the next.
      report.forget_answer();
      strategy->solve();
      report.forget_answer();
      check_answer();
    }
    catch (const DivergenceError &error)
    {
      if (contact_solver)
        write_failed_run(dynamic_cast<const NotConvergedError *>(&error)
                           ? RunOutcome::not_converged
                           : RunOutcome::diverged);
      throw;
    }
    catch (const InterruptedError &error)
    {
      // The history so far, the last iterate and summary.json "interrupted".
      if (contact_solver)
        write_failed_run(RunOutcome::interrupted, error.what());
      else
        report.write_summary(results(), RunOutcome::interrupted, error.what());
      throw;
    }
  }

} // namespace ddcontact
