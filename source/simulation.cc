#include <deal.II/base/thread_management.h>

#include <ddcontact/simulation.h>
#include <ddcontact/version.h>

#include <filesystem>
#include <iomanip>

namespace ddcontact
{
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
    solve_bodies();
    output_results(0);
    write_summary("completed");

    timer.print_summary();
    pcout << "wall time " << std::fixed << std::setprecision(2)
          << wall_clock.wall_time() << " s" << std::defaultfloat << std::endl;
  }
} // namespace ddcontact
