// The load steps of a run (Loading): a fixed number, or with Steps = auto
// the steps that LoadStepControl accepts by step doubling.
#include <deal.II/base/mpi.h>

#include <ddcontact/body/material_state_fields.h>
#include <ddcontact/loading/load_step_control.h>
#include <ddcontact/simulation.h>
#include <ddcontact/tasks.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <regex>
#include <sstream>

namespace ddcontact
{
  bool
  Simulation::path_dependent() const
  {
    if (!contact_solver)
      return false;
    for (const auto &pair : contact_pairs)
      if (pair->has_friction())
        return true;
    for (const auto &body : bodies)
      if (body->get_material_law().is_path_dependent())
        return true;
    return false;
  }

  namespace
  {
    /** Whether @p expression names the load parameter t (a word t, not
     * a part of a longer name). */
    bool
    uses_load_parameter(const std::string &expression)
    {
      static const std::regex word("(^|[^A-Za-z0-9_])t([^A-Za-z0-9_]|$)");
      return std::regex_search(expression, word);
    }
  } // namespace

  void
  Simulation::run_load_steps()
  {
    // Steps over data that do not depend on t solve one problem again and
    // again: most likely a t forgotten in an expression.
    const auto &loading = parameters.loading;
    if (loading.automatic || loading.n_steps > 1)
    {
      bool uses_t = false;
      for (const auto &body : parameters.bodies)
        uses_t = uses_t || uses_load_parameter(body.dirichlet) ||
                 uses_load_parameter(body.neumann) ||
                 uses_load_parameter(body.body_force);
      if (!uses_t)
      {
        const std::string warning =
          "Loading/Steps = " + loading.steps_text() +
          ", but no Dirichlet, Neumann or body-force expression uses the "
          "load parameter t: every step solves the same problem (write the "
          "load path with t, e.g. Dirichlet = 3: y: -Delta*t)";
        report.add_warning(warning); // printed with the results
      }
    }
    if (parameters.loading.automatic && path_dependent())
      run_automatic_load_steps();
    else
    {
      if (parameters.loading.automatic)
        pcout << "Loading/Steps = auto: without friction or a "
                 "path-dependent material law the solution does not depend "
                 "on the load path; one step"
              << std::endl;
      run_fixed_load_steps();
    }
  }

  void
  Simulation::solve_at(const double t, const bool continuing)
  {
    if (t != load_time)
    {
      TimerOutput::Scope timer_scope(timer, "setup");
      const bool         partitioned = parameters.parallel.process_groups(
        Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
        parameters.bodies.size());
      run_tasks(
        bodies.size(),
        [&](const unsigned int b) { bodies[b]->set_load_time(t); },
        partitioned);
      load_time = t;
    }
    // The first solve starts the solver (FixedMeshes); the next go on from
    // the last one's iterate and history.
    if (n_solves > 0 && contact_solver)
    {
      if (continuing)
        contact_solver->continue_load_step();
      else
        contact_solver->start_load_step();
    }
    // Without contact the bodies' states are committed here (the contact
    // solver's start_load_step() does it otherwise).
    if (n_solves > 0 && !contact_solver && !continuing)
      for (auto &body : bodies)
        body->get_material_state().commit();
    solve();
    ++n_solves;
  }

  LoadPathMeasures
  Simulation::path_measures() const
  {
    std::vector<ContactState>    states;
    std::vector<FrictionResults> friction;
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      states.push_back(contact_solver->contact_state(p));
      friction.push_back(contact_solver->solution_of(p).friction);
    }
    // Path-dependent bodies: how far each has yielded.
    std::vector<double> plastic_strain;
    for (const auto &body : bodies)
      if (body->get_material_law().is_path_dependent())
      {
        const MaterialStateSummary state = summarize_material_state(*body);
        plastic_strain.push_back(state.largest.empty() ? 0. : state.largest[0]);
      }
    return LoadPathMeasures(states, friction, plastic_strain);
  }

  double
  Simulation::solve_step_twice(const double                     t_start,
                               const double                     t_end,
                               const LoadStepStart             &start,
                               std::optional<LoadPathMeasures> &one_step)
  {
    if (!one_step)
    {
      solve_at(t_end);
      one_step = path_measures();
    }
    contact_solver->return_to_load_step_start(start);
    solve_at((t_start + t_end) / 2);
    LoadPathMeasures first_half = path_measures();
    solve_at(t_end, true);
    const double error = Utilities::MPI::max(
      LoadPathMeasures::difference(*one_step, path_measures()), MPI_COMM_WORLD);
    one_step = std::move(first_half);
    return error;
  }

  void
  Simulation::finish_load_step(const unsigned int k,
                               const double       t,
                               const std::string &of_steps,
                               const bool         record,
                               const double       path_error)
  {
    if (!adaptation)
      output_results(k - 1);
    if (record)
      report.record_load_step(results(), k, t, path_error);
    if (record)
    {
      std::ostringstream what;
      what << "load step " << k << of_steps << " (t = " << t << ")";
      record_progress(what.str());
    }
  }

  void
  Simulation::run_fixed_load_steps()
  {
    const auto              &loading = parameters.loading;
    const unsigned int       n_steps = loading.n_steps;
    const bool               check   = loading.check_path && path_dependent();
    const double             none    = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::string> warnings;
    double                   path_error = 0;
    for (unsigned int k = 1; k <= n_steps; ++k)
    {
      const double t = double(k) / n_steps, t_start = double(k - 1) / n_steps;
      if (n_steps > 1)
        pcout << "load step " << k << ": t = " << t << std::endl;
      step = (k == 1) ? "the first solve" : "load step " + std::to_string(k);
      double error = none;
      if (check)
      {
        // The step as asked, then again in two halves from its start,
        // whose more accurate solution is kept.
        std::optional<LoadPathMeasures> one_step;
        error = solve_step_twice(
          t_start, t, contact_solver->load_step_start(), one_step);
        path_error += error;
        const double allowed = loading.path_tolerance;
        pcout << "  load-path error of the step " << std::setprecision(3)
              << error << " (allowed " << allowed << ")" << std::endl;
        if (!(error <= allowed))
        {
          std::ostringstream s;
          s << std::setprecision(3) << "load step " << k << " (t = " << t_start
            << " to " << t << "): the estimated load-path error " << error
            << " exceeds Loading/Path tolerance = " << allowed
            << "; more Loading/Steps, or Steps = auto";
          warnings.push_back(s.str());
        }
      }
      else
        solve_at(t);
      finish_load_step(
        k, t, " of " + std::to_string(n_steps), n_steps > 1, error);
    }
    if (path_dependent())
    {
      Json path;
      path["steps"]          = loading.steps_text();
      path["path_tolerance"] = loading.path_tolerance;
      if (check)
        path["path_error"] = path_error;
      else
      {
        // Friction and plasticity depend on the path, and nothing
        // measured how well these steps follow it.
        path["path_error"] = Json();
        bool friction      = false;
        for (const auto &pair : contact_pairs)
          friction = friction || pair->has_friction();
        pcout << "note: " << (friction ? "friction" : "a path-dependent law")
              << " on " << n_steps << " fixed load step"
              << (n_steps > 1 ? "s" : "")
              << "; the load-path error is not estimated (Loading/Steps = "
                 "auto controls it, Check path = true estimates it)"
              << std::endl;
      }
      report.record_load_path(path, warnings);
    }
  }

  void
  Simulation::run_automatic_load_steps()
  {
    const auto     &loading = parameters.loading;
    LoadStepControl control(loading.path_tolerance, loading.max_splits);
    // The state every trial of the current step starts from, and the
    // measures of the step solved at once, when a split made them known
    // (the first half of the rejected step is the whole of the next:
    // solve_step_twice() leaves them).
    LoadStepStart                   start = contact_solver->load_step_start();
    std::optional<LoadPathMeasures> one_step;
    unsigned int                    k = 0;
    while (!control.finished())
    {
      const double t_start = control.start(), t_end = control.end();
      step = "load step " + std::to_string(k + 1) +
             " (t = " + std::to_string(t_start) + " to " +
             std::to_string(t_end) + ")";
      const double error = solve_step_twice(t_start, t_end, start, one_step);
      // t to the step's precision: a step of 2^-10 printed with two digits
      // read "[0.98, 0.98]".
      const int digits =
        std::max(3, 2 + int(std::ceil(-std::log10(t_end - t_start))));
      pcout << "load step [" << std::setprecision(digits) << t_start << ", "
            << t_end << "]: load-path error " << std::setprecision(3) << error
            << " (allowed " << control.allowed_error() << ")";
      if (control.judge(error))
      {
        pcout << ", accepted" << std::endl;
        ++k;
        finish_load_step(k, t_end, "", true, error);
        start = contact_solver->load_step_start();
        one_step.reset();
      }
      else
        pcout << ", split" << std::endl; // one_step: the first half's
    }

    Json                     path, over = Json::array();
    std::vector<std::string> warnings;
    double                   smallest = 1, largest = 0;
    for (const auto &s : control.accepted())
    {
      smallest = std::min(smallest, s.t_end - s.t_start);
      largest  = std::max(largest, s.error);
      if (s.over_tolerance)
        over.push_back(Json::array({s.t_start, s.t_end}));
    }
    if (!over.empty())
    {
      std::ostringstream s;
      s << std::setprecision(3) << "Loading/Steps = auto: " << over.size()
        << " step(s) of the smallest length 2^-" << loading.max_splits
        << " exceed Loading/Path tolerance (the first from t = "
        << over[0][0].get<double>()
        << "): the slip changes faster than the steps resolve, as at a "
           "jump of the load; raise Loading/Max splits or the tolerance";
      warnings.push_back(s.str());
    }
    path["steps"]              = "auto";
    path["path_tolerance"]     = loading.path_tolerance;
    path["path_error"]         = control.path_error();
    path["largest_step_error"] = largest;
    path["accepted_steps"]     = control.accepted().size();
    path["rejected_steps"]     = control.n_rejected();
    path["smallest_step"]      = smallest;
    path["solves"]             = n_solves;
    path["over_tolerance"]     = over;
    report.record_load_path(path, warnings);
    pcout << "load path: " << control.accepted().size() << " steps ("
          << control.n_rejected() << " split, " << n_solves
          << " solves), estimated load-path error " << std::setprecision(3)
          << control.path_error() << " (Path tolerance "
          << loading.path_tolerance << ")" << std::endl;
  }
} // namespace ddcontact
