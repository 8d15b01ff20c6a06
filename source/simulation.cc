#include <deal.II/base/thread_management.h>

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <ddcontact/simulation.h>
#include <ddcontact/solvers/monolithic_solver.h>
#include <ddcontact/tasks.h>
#include <ddcontact/version.h>

#include <array>
#include <filesystem>
#include <fstream>
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
    , writes_files(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
  }

  void
  Simulation::setup_bodies()
  {
    TimerOutput::Scope t(timer, "setup");
    bodies.clear();
    // With process groups every mesh is partitioned over the world (and
    // its refinement is collective); otherwise each body is serial.
    const bool partitioned = parameters.parallel.process_groups(
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
      parameters.bodies.size());
    for (const auto &body_parameters : parameters.bodies)
    {
      // A p4est mesh where the body allows it (Parallel/Mesh).
      bodies.push_back(std::make_unique<ElasticBody<2>>(
        body_parameters,
        parameters.constants,
        partitioned ? MPI_COMM_WORLD : MPI_COMM_SELF,
        partitioned &&
          parameters.parallel.distributed_mesh(
            body_parameters, Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD))));
      // Assembled and factorized only where it is solved, below.
      bodies.back()->set_solved_here(false);
      bodies.back()->make_mesh(parameters.output_directory);
    }
    for_each_object<ElasticBody<2>>(
      bodies, partitioned, [](ElasticBody<2> &body) { body.setup_system(); });

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
      contact_pairs.back()->setup();
      pcout << "  contact pair " << p.name << ": " << p.body_1 << " -> "
            << p.body_2 << ", " << contact_pairs.back()->points().size()
            << " contact points, theta = " << contact_pairs.back()->penalty()
            << std::endl;
    }
    dd_solver = std::make_unique<NeumannDDSolver>(parameters.dd,
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
          write_contact_profiles(suffix.str());
        });
  }

  unsigned int
  Simulation::solve_contact()
  {
    TimerOutput::Scope t(timer, "contact solve");
    if (parameters.dd.solver == ContactSolverType::dd)
    {
      const unsigned int before = dd_solver->history().size();
      dd_solver->run();
      return dd_solver->history().size() - before;
    }

    // Semismooth Newton on the penalised problem, inside the same Uzawa
    // loop as the DD when the augmented Lagrangian is on.
    MonolithicContactSolver newton(
      dd_solver->get_problem(), parameters.dd.n_newton, pcout);
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

    if (!writes_files)
      return;
    statistics = std::make_unique<std::ofstream>(parameters.output_directory +
                                                 "/statistics.csv");
    auto &out  = *statistics;
    out << "cycle,dd_iterations";
    for (const auto &body : bodies)
      out << ",cells_" << body->name() << ",dofs_" << body->name();
    out << ",bem_unknowns,estimated,marked,capped,eta_max,eta_sum,"
           "relative_error_estimate,dd_residual,dd_increment,contact_force,"
           "t_dd_s,t_estimate_s,t_refine_s,wall_time_s\n";
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
    for (auto &a : adaptations)
    {
      if (parameters.adaptation.mode == AdaptationMode::uniform)
      {
        marked += a->mark_all();
        continue;
      }
      const auto &body = a->get_body();
      if (contact_pairs.empty())
        a->estimate(body.get_solution(), BoundaryTractionSamples());
      else
        // The FEM solution of (20) and its load, not the relaxed iterate
        // (21): the BEM must solve the same boundary value problem.
        a->estimate(dd_solver->last_body_solution(body),
                    dd_solver->last_contact_traction(body));
      marked += a->mark();
    }
    return marked;
  }

  void
  Simulation::refine_and_transfer()
  {
    TimerOutput::Scope t(timer, "adaptation: refine and transfer");
    // The adapted bodies' meshes are independent: refine them at once
    // (one after the other on partitioned meshes, whose refinement is
    // collective).
    for_each_object<AdaptiveRefinement>(adaptations,
                                        distribution->uses_process_groups(),
                                        [](AdaptiveRefinement &a)
                                        { a.refine(); });
    ++n_adaptation_steps;
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

  void
  Simulation::output_adaptation_step()
  {
    output_results(n_output_steps);
    // The adapted meshes with the von Mises stress and eta per cell, for
    // plots without ParaView (the paper's Figs. 4 and 7). The rows of a
    // distributed mesh come from all processes, in their order.
    for (const auto &a : adaptations)
    {
      const auto &body = a->get_body();
      if (!writes_files && !body.is_mesh_distributed())
        continue;
      std::ostringstream rows;
      rows << std::setprecision(8);
      const auto &eta    = a->indicators();
      const auto  stress = body.stresses().at_cell_centres();
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      {
        if (!body.computes(cell))
          continue;
        // Counter-clockwise corners (deal.II numbers those of a
        // quadrilateral lexicographically; a triangle repeats its last).
        const std::array<unsigned int, 4> corners =
          (cell->n_vertices() == 3) ? std::array<unsigned int, 4>{{0, 1, 2, 2}}
                                    : std::array<unsigned int, 4>{{0, 1, 3, 2}};
        for (const unsigned int v : corners)
          rows << cell->vertex(v)[0] << ',' << cell->vertex(v)[1] << ',';
        const unsigned int c = cell->active_cell_index();
        rows << cell->level() << ',' << body.get_material().von_mises(stress[c])
             << ','
             << (eta.size() == body.get_triangulation().n_active_cells()
                   ? eta(c)
                   : 0.)
             << '\n';
      }
      std::string text = rows.str();
      if (body.is_mesh_distributed())
      {
        const auto pieces = Utilities::MPI::gather(
          body.get_triangulation().get_communicator(), text, 0);
        text.clear();
        for (const auto &piece : pieces)
          text += piece;
      }
      if (!writes_files)
        continue;
      std::ostringstream name;
      name << parameters.output_directory << "/cells_" << body.name() << '-'
           << std::setw(4) << std::setfill('0') << n_output_steps << ".csv";
      std::ofstream out(name.str());
      out << "x0,y0,x1,y1,x2,y2,x3,y3,level,von_mises,eta\n" << text;
    }
    ++n_output_steps;
  }

  void
  Simulation::write_statistics_row(const unsigned int marked,
                                   const bool         estimated)
  {
    if (!writes_files)
      return;
    auto &out = *statistics;
    out << std::setprecision(10) << n_adaptation_steps << ','
        << (dd_solver ? dd_solver->history().size() : 0);
    for (const auto &body : bodies)
      out << ',' << body->n_active_cells() << ',' << body->n_dofs();
    unsigned int bem_unknowns = 0;
    double       eta_max = 0, eta_sum = 0, error2 = 0, norm2 = 0;
    for (const auto &a : adaptations)
    {
      if (a->fem_bem())
      {
        bem_unknowns += a->fem_bem()->bem_unknowns();
        error2 += std::pow(a->fem_bem()->global_error(), 2);
        norm2 += std::pow(a->fem_bem()->stress_norm(), 2);
      }
      eta_max = std::max(eta_max, a->eta_max());
      eta_sum += a->eta_sum();
    }
    unsigned int capped = 0;
    for (const auto &a : adaptations)
      capped += a->n_capped();
    const IterationRecord last = (dd_solver && !dd_solver->history().empty())
                                   ? dd_solver->history().back()
                                   : IterationRecord();
    const auto sections = timer.get_summary_data(TimerOutput::total_wall_time);
    const auto seconds  = [&](const std::string &section)
    {
      const auto it = sections.find(section);
      return it == sections.end() ? 0. : it->second;
    };
    out << ',' << bem_unknowns << ',' << estimated << ',' << marked << ','
        << capped << ',' << eta_max << ',' << eta_sum << ','
        << (norm2 > 0 ? std::sqrt(error2 / norm2) : 0.) << ',' << last.residual
        << ',' << last.increment << ',' << last.force << ','
        << seconds("contact solve") + seconds("solve") << ','
        << seconds("adaptation: estimate and mark") << ','
        << seconds("adaptation: refine and transfer") << ','
        << wall_clock.wall_time() << '\n';
    out.flush();
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
      const bool   last   = (cycle == parameters.adaptation.max_cycles);
      unsigned int marked = 0;
      if (!last || parameters.adaptation.mode != AdaptationMode::uniform)
        marked = estimate_and_mark();
      if (last && marked > 0)
      {
        pcout << "  Adaptation/Max cycles reached: " << marked
              << " marked cells stay unrefined" << std::endl;
        marked = 0;
      }
      pcout << "  adaptation cycle " << cycle << ": " << marked
            << " cells marked" << std::endl;
      write_statistics_row(marked, true);
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
          throw DivergenceError(
            "the combined algorithm did not converge in " +
            std::to_string(parameters.dd.max_iterations) +
            " DD iterations; raise Domain decomposition/Max iterations");
        converged = dd_solver->step(); // (20)-(21)
      }
      // A frozen mesh, or one that may not be refined any more, is only
      // checked again once the DD has converged.
      const bool may_refine =
        n_adaptation_steps < parameters.adaptation.max_cycles;
      if ((frozen || !may_refine) && !converged)
        continue;

      unsigned int marked = estimate_and_mark();
      if (!may_refine && marked > 0)
      {
        pcout << "  Adaptation/Max cycles reached: " << marked
              << " marked cells stay unrefined" << std::endl;
        marked = 0;
      }
      pcout << "  cycle " << n_adaptation_steps << " (DD iteration "
            << dd_solver->history().size() << "): " << marked << " cells marked"
            << std::endl;
      write_statistics_row(marked, true);
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
    return dd_solver->history().size();
  }

  void
  Simulation::write_history() const
  {
    if (!writes_files)
      return;
    std::ofstream out(parameters.output_directory + "/history.csv");
    out << "k,residual,increment,gamma,contact_force,active_length,"
           "max_penetration,time_s\n";
    out << std::setprecision(10);
    for (const auto &r : dd_solver->history())
      out << r.iteration << ',' << r.residual << ',' << r.increment << ','
          << r.gamma << ',' << r.force << ',' << r.active_length << ','
          << r.max_penetration << ',' << r.time << '\n';
  }

  void
  Simulation::write_contact_profiles(const std::string &suffix) const
  {
    if (!writes_files)
      return;
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      const auto    state = dd_solver->contact_state(p);
      const auto   &pts   = contact_pairs[p]->points();
      std::ofstream out(parameters.output_directory + "/contact_" +
                        contact_pairs[p]->name() + suffix + ".csv");
      out << "x1,x2,pressure,u_1n,u_2n,gap,weight\n" << std::setprecision(12);
      for (unsigned int q = 0; q < pts.size(); ++q)
        out << pts[q].x[0] << ',' << pts[q].x[1] << ',' << -state.sigma_n[q]
            << ',' << state.u_1n[q] << ',' << state.u_2n[q] << ',' << pts[q].gap
            << ',' << pts[q].JxW << '\n';
    }
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
        distribution->uses_process_groups() ? MPI_COMM_WORLD : MPI_COMM_SELF);
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
  }

  void
  Simulation::write_summary(const std::string &status)
  {
    std::map<std::string, double> timings_extra; // phases timed elsewhere
    Json                          json = Json::object();
    json.set("scene", parameters.scene_name);
    json.set("status", status);

    Json body_list = Json::array();
    for (const auto &body : bodies)
    {
      Json b = Json::object();
      b.set("name", body->name());
      b.set("cells", body->n_active_cells());
      b.set("distributed_mesh", body->is_mesh_distributed());
      // What the mesh, its dofs and constraints take on the process that
      // holds the most of them (a distributed mesh: its share).
      const double mesh_mb = (body->get_triangulation().memory_consumption() +
                              body->get_dof_handler().memory_consumption() +
                              body->get_constraints().memory_consumption()) /
                             1048576.;
      b.set("mesh_memory_mb", Utilities::MPI::max(mesh_mb, MPI_COMM_WORLD));
      b.set("dofs", static_cast<unsigned long>(body->n_dofs()));
      b.set("min_cell_diameter", body->get_mesh().min_cell_diameter());
      b.set("strain_energy", body->stresses().strain_energy());
      body_list.push_back(b);
    }
    json.set("bodies", body_list);
    json.set("mpi_processes", distribution->n_processes());
    json.set("body_owners", distribution->describe());

    Json points = Json::array();
    for (const auto &point : parameters.points)
    {
      const auto it =
        std::find_if(bodies.begin(),
                     bodies.end(),
                     [&](const auto &b) { return b->name() == point.body; });
      const auto values = (*it)->stresses().at_point(point.x);
      Json       p      = Json::object();
      p.set("body", point.body);
      p.set("x", json_array({point.x[0], point.x[1]}));
      p.set("u", json_array({values.displacement[0], values.displacement[1]}));
      p.set("stress",
            json_array(
              {values.stress[0][0], values.stress[1][1], values.stress[0][1]}));
      p.set("von_mises", values.von_mises);
      points.push_back(p);
      pcout << "  point " << point.body << " (" << point.x << "): u = ("
            << std::scientific << std::setprecision(6) << values.displacement[0]
            << ", " << values.displacement[1]
            << "), von Mises = " << values.von_mises << std::defaultfloat
            << std::endl;
    }
    json.set("points", points);

    if (!contact_pairs.empty())
    {
      json.set("dd_iterations", n_contact_iterations);
      json.set("gamma", parameters.dd.gamma);
      json.set("relaxation", to_string(parameters.dd.relaxation));
      json.set("uzawa_updates", dd_solver->n_uzawa_updates());
      Json thetas  = Json::array();
      Json contact = Json::array();
      for (unsigned int p = 0; p < contact_pairs.size(); ++p)
      {
        const auto state = dd_solver->contact_state(p);
        thetas.push_back(contact_pairs[p]->penalty());
        Json c = Json::object();
        c.set("pair", contact_pairs[p]->name());
        Json forces = Json::array();
        forces.push_back(json_array({state.force_1[0], state.force_1[1]}));
        forces.push_back(json_array({state.force_2[0], state.force_2[1]}));
        c.set("force", forces);
        c.set("max_pressure", state.max_pressure);
        c.set("contact_length", state.contact_length);
        c.set("half_width", state.half_width);
        c.set("max_penetration", state.max_penetration);
        contact.push_back(c);
      }
      json.set("theta", thetas);
      json.set("contact", contact);
      if (!dd_solver->history().empty())
      {
        const auto &last = dd_solver->history().back();
        json.set("dd_residual", last.residual);
        json.set("dd_increment", last.increment);
      }
    }
    if (parameters.adaptation.enabled())
    {
      json.set("adaptation_cycles", n_adaptation_steps);
      unsigned int bem_unknowns = 0;
      Json         estimator    = Json::object();
      estimator.set("mode", to_string(parameters.adaptation.mode));
      estimator.set("type", to_string(parameters.adaptation.estimator));
      estimator.set("marking", to_string(parameters.adaptation.marking));
      estimator.set("delta", parameters.adaptation.delta);
      Json per_body = Json::array();
      for (const auto &a : adaptations)
      {
        Json e = Json::object();
        e.set("body", a->get_body().name());
        e.set("eta_max", a->eta_max());
        e.set("eta_sum", a->eta_sum());
        e.set("capped_cells", a->n_capped());
        if (const auto *fb = a->fem_bem())
        {
          bem_unknowns += fb->bem_unknowns();
          e.set("bem_unknowns", fb->bem_unknowns());
          e.set("stress_error_estimate", fb->global_error());
          e.set("bem_stress_norm", fb->stress_norm());
          e.set("relative_error_estimate",
                fb->stress_norm() > 0 ? fb->global_error() / fb->stress_norm()
                                      : 0.);
          const auto &t = fb->timings();
          timings_extra["BEM setup (assembly, LU)"] += t.bem_setup;
          timings_extra["BEM solve"] += t.bem_solve;
          timings_extra["BEM interior stresses"] += t.bem_interior;
        }
        per_body.push_back(e);
      }
      estimator.set("bodies", per_body);
      json.set("bem_unknowns", bem_unknowns);
      json.set("estimator", estimator);
    }
    json.set("wall_time_s", wall_clock.wall_time());

    Json timings = Json::object();
    for (const auto &[section, seconds] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      timings.set(section, seconds);
    for (const auto &[section, seconds] : timings_extra)
      timings.set(section, seconds);
    // The body solves and the exchange of their solutions (on process 0;
    // the exchange includes waiting for the slowest process).
    timings.set("body solves", distribution->solve_seconds());
    if (distribution->n_processes() > 1)
      timings.set("exchange between processes",
                  distribution->exchange_seconds());
    json.set("timings", timings);

    // Peak resident memory (VmHWM) of the processes: what a distributed
    // mesh saves.
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const double peak_mb = memory.VmHWM / 1024.;
    Json         peak    = Json::object();
    peak.set("largest_process_mb",
             Utilities::MPI::max(peak_mb, MPI_COMM_WORLD));
    peak.set("all_processes_mb", Utilities::MPI::sum(peak_mb, MPI_COMM_WORLD));
    json.set("peak_memory", peak);

    summary_json = json;
    if (writes_files)
      json.write_file(parameters.output_directory + "/summary.json");
  }

  void
  Simulation::run()
  {
    wall_clock.restart();
    std::filesystem::create_directories(parameters.output_directory);
    pcout << version_banner() << std::endl
          << "scene '" << parameters.scene_name << "', output in "
          << parameters.output_directory << std::endl;

    setup_bodies();
    if (parameters.adaptation.enabled())
      setup_adaptation();
    if (parameters.contact_pairs.empty())
    {
      if (parameters.adaptation.enabled())
        solve_nested();
      else
      {
        solve_bodies();
        output_results(0);
      }
      write_summary("completed");
    }
    else
    {
      setup_contact();
      try
      {
        if (!parameters.adaptation.enabled())
        {
          dd_solver->initialize();
          n_contact_iterations = solve_contact();
        }
        else if (parameters.adaptation.mode == AdaptationMode::combined)
          n_contact_iterations = solve_combined();
        else
          n_contact_iterations = solve_nested();
      }
      catch (const DivergenceError &)
      {
        n_contact_iterations = dd_solver->history().size();
        write_history();
        write_summary("diverged");
        throw;
      }
      write_history();
      write_contact_profiles("");
      for (unsigned int p = 0; p < contact_pairs.size(); ++p)
      {
        const auto state = dd_solver->contact_state(p);
        pcout << std::setprecision(6) << "  contact "
              << contact_pairs[p]->name() << ": force " << state.force_1.norm()
              << ", peak pressure " << state.max_pressure << ", half-width "
              << state.half_width << ", max penetration "
              << state.max_penetration << std::endl;
      }
      if (!parameters.adaptation.enabled())
        output_results(0);
      // "converged" only if the augmented Lagrangian met its tolerance too.
      const std::string shortfall = dd_solver->augmented_lagrangian_shortfall();
      write_summary(shortfall.empty() ? "converged" : "stalled");
      if (!shortfall.empty())
        throw DivergenceError(shortfall);
    }

    timer.print_summary();
    pcout << "wall time " << std::fixed << std::setprecision(2)
          << wall_clock.wall_time() << " s" << std::defaultfloat << std::endl;
  }
} // namespace ddcontact
