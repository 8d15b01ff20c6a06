#include <deal.II/base/thread_management.h>

#include <ddcontact/monolithic_solver.h>
#include <ddcontact/simulation.h>
#include <ddcontact/version.h>

#include <filesystem>
#include <fstream>
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
  } // namespace

  Simulation::Simulation(const SceneParameters &parameters,
                         std::ostream          &screen)
    : parameters(parameters)
    , pcout(screen, true)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
  {
  }

  void
  Simulation::setup_bodies()
  {
    TimerOutput::Scope t(timer, "setup");
    bodies.clear();
    for (const auto &body_parameters : parameters.bodies)
    {
      bodies.push_back(std::make_unique<ElasticBody<2>>(body_parameters,
                                                        parameters.constants));
      bodies.back()->make_mesh(parameters.output_directory);
    }

    // Assembly and factorization of the bodies are independent.
    Threads::TaskGroup<void> tasks;
    for (auto &body : bodies)
      tasks += Threads::new_task([&body]() { body->setup_and_factorize(); });
    tasks.join_all();

    for (const auto &body : bodies)
      pcout << "  body " << std::setw(10) << std::left << body->name()
            << std::right << std::setw(9)
            << body->get_triangulation().n_active_cells() << " cells "
            << std::setw(9) << body->n_dofs() << " dofs  ("
            << (body->is_simplex() ? "triangles" : "quadrilaterals") << ", "
            << body->get_fe().get_name() << ")" << std::endl;
  }

  void
  Simulation::solve_bodies()
  {
    TimerOutput::Scope       t(timer, "solve");
    Threads::TaskGroup<void> tasks;
    for (auto &body : bodies)
      tasks += Threads::new_task([&body]() { body->solve(); });
    tasks.join_all();
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
    dd_solver = std::make_unique<NeumannDDSolver>(
      parameters.dd, raw_pointers(bodies), raw_pointers(contact_pairs), pcout);
  }

  unsigned int
  Simulation::solve_contact()
  {
    TimerOutput::Scope t(timer, "contact solve");
    dd_solver->initialize();
    if (parameters.dd.write_every_iteration)
      dd_solver->set_iteration_callback(
        [this](const unsigned int k)
        {
          std::ostringstream suffix;
          suffix << '_' << std::setw(4) << std::setfill('0') << k;
          write_contact_profiles(suffix.str());
        });
    if (parameters.dd.solver == "dd")
      return dd_solver->run();

    MonolithicContactSolver newton(raw_pointers(bodies),
                                   raw_pointers(contact_pairs),
                                   parameters.dd.n_newton,
                                   pcout);
    n_newton_iterations = newton.run();
    return 0;
  }

  void
  Simulation::write_history() const
  {
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
    if (!parameters.write_vtu)
      return;
    TimerOutput::Scope t(timer, "output");
    if (!output_writer)
      output_writer =
        std::make_unique<OutputWriter>(parameters.output_directory);
    std::vector<const ElasticBody<2> *> body_pointers;
    std::vector<const Vector<double> *> solutions;
    for (const auto &body : bodies)
    {
      body_pointers.push_back(body.get());
      solutions.push_back(&body->get_solution());
    }
    output_writer->write_step(step, step, body_pointers, solutions);
  }

  void
  Simulation::write_summary(const std::string &status)
  {
    Json json = Json::object();
    json.set("scene", parameters.scene_name);
    json.set("status", status);

    Json body_list = Json::array();
    for (const auto &body : bodies)
    {
      Json b = Json::object();
      b.set("name", body->name());
      b.set("cells", body->get_triangulation().n_active_cells());
      b.set("dofs", static_cast<unsigned long>(body->n_dofs()));
      b.set("min_cell_diameter", body->min_cell_diameter());
      b.set("strain_energy", body->strain_energy(body->get_solution()));
      body_list.push_back(b);
    }
    json.set("bodies", body_list);

    Json points = Json::array();
    for (const auto &point : parameters.points)
    {
      const auto it =
        std::find_if(bodies.begin(),
                     bodies.end(),
                     [&](const auto &b) { return b->name() == point.body; });
      const auto values = (*it)->point_values(point.x, (*it)->get_solution());
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
      json.set("relaxation", parameters.dd.relaxation);
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
    json.set("wall_time_s", wall_clock.wall_time());

    Json timings = Json::object();
    for (const auto &[section, seconds] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      timings.set(section, seconds);
    json.set("timings", timings);

    summary_json = json;
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
    if (parameters.contact_pairs.empty())
    {
      solve_bodies();
      output_results(0);
      write_summary("completed");
    }
    else
    {
      setup_contact();
      try
      {
        n_contact_iterations = solve_contact();
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
        pcout << std::setprecision(6) << "  contact " << contact_pairs[p]->name() << ": force "
              << state.force_1.norm() << ", peak pressure "
              << state.max_pressure << ", half-width " << state.half_width
              << ", max penetration " << state.max_penetration << std::endl;
      }
      output_results(0);
      write_summary("converged");
    }

    timer.print_summary();
    pcout << "wall time " << std::fixed << std::setprecision(2)
          << wall_clock.wall_time() << " s" << std::defaultfloat << std::endl;
  }
} // namespace ddcontact
