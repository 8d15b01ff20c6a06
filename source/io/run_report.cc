#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <ddcontact/body/reaction_forces.h>
#include <ddcontact/interruption.h>
#include <ddcontact/io/material_state_json.h>
#include <ddcontact/io/process_report.h>
#include <ddcontact/io/run_report.h>
#include <ddcontact/output_file.h>
#include <ddcontact/version.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace ddcontact
{
  RunReport::RunReport(const SceneParameters    &parameters,
                       const TimerOutput        &timer,
                       const Timer              &wall_clock,
                       const ConditionalOStream &pcout)
    : parameters(parameters)
    , timer(timer)
    , wall_clock(wall_clock)
    , pcout(pcout)
    , writes_files(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
  }

  void
  RunReport::open_statistics(
    const std::vector<std::unique_ptr<ElasticBody<2>>> &bodies)
  {
    if (!writes_files)
      return;
    statistics.open(parameters.output_directory + "/statistics.csv");
    if (!statistics)
      throw WriteError("cannot write '" + parameters.output_directory +
                       "/statistics.csv'");
    statistics << "cycle,dd_iterations";
    for (const auto &body : bodies)
      statistics << ",cells_" << body->name() << ",dofs_" << body->name();
    statistics << ",bem_unknowns,estimated,marked,capped,eta_max,eta_sum,"
                  "relative_error_estimate,dd_residual,dd_increment,"
                  "normal_force,t_dd_s,t_estimate_s,t_refine_s,wall_time_s,"
                  "relative_energy_error_estimate\n";
    statistics.flush();
    // Written row by row under its own name: listed after every row.
    run_manifest::record_file(parameters.output_directory + "/statistics.csv");
  }

  void
  RunReport::write_statistics_row(const Results     &results,
                                  const unsigned int marked,
                                  const bool         estimated)
  {
    if (!writes_files)
      return;
    const ContactSolver *contact_solver = results.contact_solver;
    auto                &out            = statistics;
    out << std::setprecision(10) << results.n_adaptation_steps << ','
        << (contact_solver ? contact_solver->history().size() : 0);
    for (const auto &body : results.bodies)
      out << ',' << body->n_active_cells() << ',' << body->n_dofs();
    unsigned int bem_unknowns = 0, capped = 0;
    double       eta_max = 0, eta_sum = 0, error2 = 0, norm2 = 0;
    for (const auto &a : results.adaptations)
    {
      if (a->fem_bem())
      {
        bem_unknowns += a->fem_bem()->bem_unknowns();
        error2 += std::pow(a->fem_bem()->global_error(), 2);
        norm2 += std::pow(a->fem_bem()->stress_norm(), 2);
      }
      eta_max = std::max(eta_max, a->eta_max());
      eta_sum += a->eta_sum();
      capped += a->n_capped();
    }
    const IterationRecord last =
      (contact_solver && !contact_solver->history().empty())
        ? contact_solver->history().back()
        : IterationRecord();
    const auto sections = timer.get_summary_data(TimerOutput::total_wall_time);
    const auto seconds  = [&](const std::string &section)
    {
      const auto it = sections.find(section);
      return it == sections.end() ? 0. : it->second;
    };
    // The relative error estimate is that of all adapted bodies together.
    out << ',' << bem_unknowns << ',' << estimated << ',' << marked << ','
        << capped << ',' << eta_max << ',' << eta_sum << ','
        << (norm2 > 0 ? std::sqrt(error2 / norm2) : 0.) << ',' << last.residual
        << ',' << last.increment << ',' << last.force << ','
        << seconds("contact solve") + seconds("solve") << ','
        << seconds("adaptation: estimate and mark") << ','
        << seconds("adaptation: refine and transfer") << ','
        << wall_clock.wall_time() << ','
        << std::max(0., relative_energy_error_estimate(results.adaptations))
        << '\n';
    out.flush();
    if (!out)
      throw WriteError("cannot write '" + parameters.output_directory +
                       "/statistics.csv'; is the disk full?");
    run_manifest::record_file(parameters.output_directory + "/statistics.csv");
  }

  void
  RunReport::write_history(const std::vector<IterationRecord> &history) const
  {
    if (!writes_files)
      return;
    OutputFile file(parameters.output_directory + "/history.csv");
    auto      &out = file.stream();
    out << "k,residual,increment,gamma,normal_force,active_length,"
           "max_penetration,time_s\n";
    out << std::setprecision(10);
    for (const auto &r : history)
      out << r.iteration << ',' << r.residual << ',' << r.increment << ','
          << r.gamma << ',' << r.force << ',' << r.active_length << ','
          << r.max_penetration << ',' << r.time << '\n';
    file.commit();
  }

  void
  RunReport::write_contact_profiles(const Results     &results,
                                    const std::string &suffix) const
  {
    if (writes_files)
      write_contact_profiles(results, current_states(results), suffix);
  }

  void
  RunReport::write_contact_profiles(const Results                   &results,
                                    const std::vector<ContactState> &states,
                                    const std::string &suffix) const
  {
    if (!writes_files)
      return;
    for (unsigned int p = 0; p < results.contact_pairs.size(); ++p)
    {
      const auto &state = states[p];
      const auto &pair  = *results.contact_pairs[p];
      const auto &pts   = pair.points();
      OutputFile  file(parameters.output_directory + "/contact_" + pair.name() +
                      suffix + ".csv");
      auto       &out = file.stream();
      // With friction also the tangential traction t (the traction
      // -t tau on body 1, tau = n_1 turned by +90 degrees), the slip
      // increment and slip along tau, and the state (0 open, 1 stick, 2
      // slip).
      const bool friction = !state.t.empty();
      out << "x1,x2,pressure,u_1n,u_2n,gap,weight"
          << (friction ? ",tangential_traction,slip_increment,slip,state" : "")
          << '\n'
          << std::setprecision(12);
      // (0 - sigma_n: no "-0" where the pressure is zero.)
      for (unsigned int q = 0; q < pts.size(); ++q)
      {
        out << pts[q].x[0] << ',' << pts[q].x[1] << ',' << 0. - state.sigma_n[q]
            << ',' << state.u_1n[q] << ',' << state.u_2n[q] << ',' << pts[q].gap
            << ',' << pts[q].JxW;
        if (friction)
          out << ',' << state.t[q] << ',' << state.slip_increment[q] << ','
              << state.slip[q] << ',' << static_cast<int>(state.slip_state[q]);
        out << '\n';
      }
      file.commit();
    }
  }

  void
  RunReport::add_friction(const ContactState &state, Json &json)
  {
    if (state.t.empty())
      return;
    // The integral of the traction on body 1 along each point's tangent
    // tau = n_1 turned by +90 degrees.
    json["tangential_force"]  = state.tangential_force;
    json["stick_half_width"]  = state.stick_half_width;
    json["stick_resolution"]  = state.stick_resolution;
    json["dissipated_energy"] = state.dissipation;
  }

  void
  RunReport::record_load_step(const Results     &results,
                              const unsigned int step,
                              const double       t,
                              const double       path_error)
  {
    record_load_step(results, step, t);
    if (std::isfinite(path_error))
      load_steps.back()["path_error"] = path_error;
  }

  void
  RunReport::record_load_path(const Json                     &path,
                              const std::vector<std::string> &warnings)
  {
    load_path = path;
    run_warnings.insert(run_warnings.end(), warnings.begin(), warnings.end());
  }

  void
  RunReport::add_warning(const std::string &warning)
  {
    run_warnings.push_back(warning);
  }

  void
  RunReport::record_load_step(const Results     &results,
                              const unsigned int step,
                              const double       t)
  {
    std::ostringstream suffix;
    suffix << "_step" << std::setw(4) << std::setfill('0') << step;
    const auto states = current_states(results);
    write_contact_profiles(results, states, suffix.str());
    Json row, pairs = Json::array();
    row["step"] = step;
    row["t"]    = t;
    for (unsigned int p = 0; p < results.contact_pairs.size(); ++p)
    {
      const auto &state = states[p];
      Json        c;
      c["pair"]         = results.contact_pairs[p]->name();
      c["force"]        = Json::array({state.force_1[0], state.force_1[1]});
      c["normal_force"] = state.normal_force;
      c["max_pressure"] = state.max_pressure;
      c["half_width"]   = state.half_width;
      if (state.contact_radius >= 0)
        c["contact_radius"] = state.contact_radius;
      if (state.stick_radius >= 0)
        c["stick_radius"] = state.stick_radius;
      add_friction(state, c);
      pairs.push_back(c);
    }
    row["pairs"] = pairs;
    // Bodies with a state (plasticity): how far they have yielded.
    Json bodies = Json::array();
    for (const auto &body : results.bodies)
    {
      const MaterialStateSummary state = summarize_material_state(*body);
      if (state.names.empty())
        continue;
      Json b;
      b["body"] = body->name();
      add_material_state(state, b);
      if (state.yielded())
        b["location_of_largest"] = state.location_of_largest;
      bodies.push_back(b);
    }
    if (!bodies.empty())
      row["bodies"] = bodies;
    record_supports(results, states, step, t, row);
    load_steps.push_back(row);
  }

  void
  RunReport::record_supports(const Results                   &results,
                             const std::vector<ContactState> &states,
                             const unsigned int               step,
                             const double                     t,
                             Json                            &row)
  {
    Json supports = Json::array();
    for (const auto &body : results.bodies)
    {
      const auto reactions = current_reactions(results, states, *body);
      for (const auto &s : reactions.supports())
      {
        Json support;
        support["body"]        = body->name();
        support["boundary_id"] = s.id;
        support["displacement"] =
          Json::array({s.displacement[0], s.displacement[1]});
        support["force"] = Json::array({s.force[0], s.force[1]});
        supports.push_back(support);
        std::ostringstream line;
        line << std::setprecision(12) << step << ',' << t << ',' << body->name()
             << ',' << s.id << ',' << s.displacement[0] << ','
             << s.displacement[1] << ',' << s.force[0] << ',' << s.force[1]
             << '\n';
        force_displacement_rows.push_back(line.str());
      }
    }
    row["supports"] = supports;
    if (!writes_files || supports.empty())
      return;
    // The curve of every driven boundary (u and its reaction), one row per
    // load step and Dirichlet id; the whole file at every step, so that an
    // interrupted run keeps the steps it finished.
    OutputFile file(parameters.output_directory + "/force_displacement.csv");
    auto      &out = file.stream();
    out << "step,t,body,boundary_id,u_x,u_y,force_x,force_y\n";
    for (const auto &r : force_displacement_rows)
      out << r;
    file.commit();
  }

  void
  RunReport::print_contact_states(const Results                   &results,
                                  const std::vector<ContactState> &states) const
  {
    for (unsigned int p = 0; p < results.contact_pairs.size(); ++p)
    {
      const auto &state = states[p];
      pcout << std::setprecision(6) << "  contact "
            << results.contact_pairs[p]->name() << ": normal force "
            << state.normal_force;
      if (!state.t.empty())
        pcout << ", tangential force " << state.tangential_force;
      pcout << ", force vector on "
            << results.contact_pairs[p]->get_body_1().name() << " ("
            << state.force_1[0] << ", " << state.force_1[1]
            << "), peak pressure " << state.max_pressure
            << " (at the contact points, as written)";
      if (state.max_nodal_pressure > 0)
        pcout << ", largest nodal multiplier " << state.max_nodal_pressure;
      // The extents with the cells their edges lie in (ZoneExtent); a zone
      // about the axis has its contact radius as its half-width.
      if (state.contact_radius >= 0)
        pcout << ", contact radius " << state.contact_radius;
      if (state.contact_radius != state.half_width)
        pcout << ", half-width " << state.half_width;
      if (state.extent_resolution > 0)
        pcout << " (edges inside cells of " << state.extent_resolution << ")";
      pcout << ", max penetration " << state.max_penetration;
      if (!state.t.empty())
      {
        if (state.stick_radius >= 0)
          pcout << "; stick radius " << state.stick_radius;
        if (state.stick_radius != state.stick_half_width)
          pcout << "; stick half-width " << state.stick_half_width;
        if (state.stick_resolution > 0)
          pcout << " (edges inside cells of " << state.stick_resolution << ")";
        pcout << ", dissipated " << state.dissipation;
      }
      pcout << std::endl;
    }
  }

  void
  RunReport::write_cells(const Results &results, const unsigned int step) const
  {
    // The rows of a distributed mesh come from all processes, in their
    // order.
    for (const auto &a : results.adaptations)
    {
      const auto &body = a->get_body();
      if (!writes_files && !body.is_mesh_distributed())
        continue;
      std::ostringstream rows;
      rows << std::setprecision(8);
      // The von Mises stress at the cell's centre.
      const auto         &eta = a->indicators();
      std::vector<double> third;
      const auto          stress = body.stresses().at_cell_centres(&third);
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
        rows << cell->level() << ',' << von_mises_stress(stress[c], third[c])
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
           << std::setw(4) << std::setfill('0') << step << ".csv";
      OutputFile out(name.str());
      out.stream() << "x0,y0,x1,y1,x2,y2,x3,y3,level,von_mises,eta\n" << text;
      out.commit();
    }
  }

  void
  RunReport::write_final(const Results &results, const RunOutcome outcome)
  {
    const auto states = current_states(results);
    if (const auto *solver = results.contact_solver)
    {
      write_history(solver->history());
      write_contact_profiles(results, states, "");
      print_contact_states(results, states);
    }
    write_summary(results, states, outcome, "");
    print_reactions();
    print_warnings();
  }

  void
  RunReport::print_warnings() const
  {
    for (const auto &warning : summary_json.at("warnings"))
      pcout << "warning: " << warning.get<std::string>() << std::endl;
  }
} // namespace ddcontact
