#include <algorithm>
#include <array>
#include <cmath>
#include <ddcontact/body/reaction_forces.h>
#include <ddcontact/interruption.h>
#include <ddcontact/io/material_state_json.h>
#include <ddcontact/io/process_report.h>
#include <ddcontact/io/run_report.h>
#include <ddcontact/output_file.h>
#include <ddcontact/version.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

// RunReport's summary.json: the bodies, reactions, points, the contact and
// adaptation sections, timings, and the status the driver decided.
namespace ddcontact
{
  namespace
  {
    /** The smallest diameter of the cells of @p body with a face on the
     * boundary @p id (all processes' cells). */
    double
    zone_cell_diameter(const ElasticBody<2> &body, const unsigned int id)
    {
      double h = std::numeric_limits<double>::max();
      for (const auto &cell : body.get_triangulation().active_cell_iterators())
        if (body.computes(cell) && cell->at_boundary())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
            {
              h = std::min(h, cell->diameter(body.get_mapping()));
              break;
            }
      return body.is_mesh_distributed()
               ? Utilities::MPI::min(
                   h, body.get_triangulation().get_communicator())
               : h;
    }

    /** The warning of a pair that penetrates too far, or "". */
    std::string
    penetration_warning(const std::string     &pair,
                        const double           penetration,
                        const double           approach,
                        const double           h,
                        const SceneParameters &parameters)
    {
      const bool of_approach =
        approach > 0 &&
        penetration > RunReport::penetration_per_approach * approach;
      // (h is the largest double if the zone has no cells here.)
      const bool of_cell = penetration > RunReport::penetration_per_cell * h;
      // Below 1e-10 of a cell a penetration is round-off of the
      // displacements, whatever the approach (5e-21 on an approach of 1e-19
      // where nothing is pressed).
      const bool round_off =
        h < std::numeric_limits<double>::max() && penetration <= 1e-10 * h;
      if ((!of_approach && !of_cell) || round_off)
        return "";
      std::ostringstream s;
      const bool         exact = parameters.contact_solver.exact_contact();
      s << std::setprecision(2) << "contact pair " << pair
        << (exact ? ": exact contact leaves a penetration of "
                  : ": the penalty leaves a penetration of ")
        << penetration << ", ";
      if (approach > 0)
        s << 100 * penetration / approach << " % of the approach " << approach
          << " (limit " << 100 * RunReport::penetration_per_approach << " %), ";
      if (h < std::numeric_limits<double>::max())
        s << 100 * penetration / h << " % of the smallest cell " << h
          << " along the contact zone (limit "
          << 100 * RunReport::penetration_per_cell << " %), ";
      if (exact)
      {
        // No penalty is involved: exact contact holds at the nodes of S_1
        // (on the weighted gaps); between them the traces of non-matching
        // meshes differ, and the solver stops at Tolerance.
        s << "between the nodes of S_1, where exact contact holds only at "
             "the nodes; it falls with refinement of the contact zone (and "
             "with Contact solver/Tolerance if that is loose)";
        return s.str();
      }
      s << "an error of the penalty that mesh refinement does not remove; ";
      if (parameters.contact_solver.exact_formulation)
        s << "lower Contact solver/Uzawa/Tolerance or raise its Max updates";
      else
        s << "for exact contact set Contact pair " << pair
          << "/Formulation = exact, or lower Contact pair " << pair
          << "/Penalty";
      return s.str();
    }
    /** The largest |u_1n| + |u_2n| of @p state. max_penetration is the
     * largest u_1n + u_2n - f_n (at least 0), with u_an the displacement of
     * body a along its outward normal; the approach is the measure of the
     * AL tolerance (ContactProblem::penetration()): u_1n + u_2n itself is
     * the penetration on a zero gap, not how far the bodies were pressed
     * together. |u_1n| + |u_2n| is that distance for two blocks pressed
     * against each other, and twice it for a rigid punch on a soft body. */
    double
    approach_of(const ContactState &state)
    {
      double approach = 0;
      for (unsigned int q = 0; q < state.u_1n.size(); ++q)
        approach =
          std::max(approach, std::abs(state.u_1n[q]) + std::abs(state.u_2n[q]));
      return approach;
    }

    /** summary.json's record of the contact search at the pair's last
     * setup. */
    Json
    search_json(const ContactSearchReport &found)
    {
      Json search;
      search["search_distance"]     = found.search_distance;
      search["points_examined"]     = found.n_examined;
      search["points_with_partner"] = found.n_points;
      if (found.n_points > 0)
      {
        // The gap in use: the meshes' (or the expression's) less the
        // Interference.
        const double min_gap      = found.min_gap - found.interference;
        search["min_initial_gap"] = min_gap;
        search["max_initial_gap"] = found.max_gap - found.interference;
        search["min_initial_gap_at"] =
          Json::array({found.min_gap_at[0], found.min_gap_at[1]});
        search["deepest_initial_overlap"] = std::max(0., -min_gap);
        if (found.interference != 0)
          search["interference"] = found.interference;
      }
      if (found.worst_excess > 0)
        search["gap_below_geometry"] = {
          {"expression", found.worst_expression},
          {"geometric", found.worst_geometric},
          {"at",
           Json::array({found.worst_excess_at[0], found.worst_excess_at[1]})}};
      return search;
    }
    /** An approach beyond the fraction @p limit of the thinner body is no
     * small-strain contact (units, most likely): the warning, or "". */
    std::string
    small_strain_warning(const ContactPair &pair,
                         const double       approach,
                         const double       limit)
    {
      const double thinner =
        std::min(pair.thickness_of_body_1(), pair.thickness_of_body_2());
      if (!(approach > limit * thinner))
        return "";
      std::ostringstream s;
      s << std::setprecision(3) << "contact pair " << pair.name()
        << ": the bodies approach by " << approach << ", "
        << 100 * approach / thinner << " % of the thinner body (" << thinner
        << "), beyond the " << 100 * limit
        << " % of a small-strain problem; check the units of the loads, "
           "the prescribed displacements and Young's modulus";
      return s.str();
    }

    /** The multipliers on the nodes of an S_1 finer than S_2 oscillate
     * (the mortar inf-sup condition). A flat punch's pressure
     * (../shared/cases/fine_multiplier_side.prm) deviates from its local
     * mean by 0.4 % at 1.4 faces of S_1 per cell of S_2, 1.4 % at 1.8,
     * 100 % (nodes at zero) at 2.0, 3 % at 2.5. The adaptive refinement
     * keeps S_2 as fine as S_1 within 1.5 (grade_contact_zone()); meshes
     * given otherwise are told. */
    std::string
    multiplier_side_warning(const ContactPair     &pair,
                            const SceneParameters &parameters)
    {
      const double ratio = pair.multiplier_side_ratio();
      if (!parameters.contact_solver.multipliers_on_nodes() || ratio < 1.5)
        return "";
      std::ostringstream s;
      s << std::setprecision(2) << "contact pair " << pair.name()
        << ": S_1 on body '" << pair.get_body_1().name() << "' has " << ratio
        << " faces for every cell of body '" << pair.get_body_2().name()
        << "' it faces; the pressure multipliers on the nodes of a finer S_1 "
           "oscillate (the mortar inf-sup condition: on a flat punch by 1.4 % "
           "at 1.8 faces per cell, 100 % at 2); make the coarser surface "
           "Body 1 of the pair, or refine body 2 there";
      return s.str();
    }

    /** A pair whose zones face each other (the search found points) but
     * touch nowhere at the end of a converged run carries no force:
     * said, with the likeliest cause, a clearance written as a negative
     * Interference (issue 59: every force 0 and "converged", nothing
     * else). */
    std::string
    no_contact_warning(const ContactPair &pair, const ContactState &state)
    {
      const auto &found = pair.search_report();
      if (found.n_points == 0 || state.contact_length > 0)
        return "";
      std::ostringstream s;
      s << std::setprecision(3) << "contact pair " << pair.name()
        << ": no point is in contact at the end of the run, so the pair "
           "carries no force";
      if (found.interference < 0)
        s << "; its Interference " << found.interference
          << " is a clearance (an interference fit's overlap is positive)";
      else
        s << " (the smallest initial gap is "
          << found.min_gap - found.interference
          << "); check the loads or prescribed displacements and the Gap";
      return s.str();
    }
  } // namespace

  Json
  RunReport::bodies_json(const Results                   &results,
                         const std::vector<ContactState> &states) const
  {
    Json list = Json::array();
    for (const auto &body : results.bodies)
    {
      Json b;
      b["name"]             = body->name();
      b["cells"]            = body->n_active_cells();
      b["distributed_mesh"] = body->is_mesh_distributed();
      // What the mesh, its dofs and constraints take on the process that
      // holds the most of them (a distributed mesh: its share).
      const double mesh_mb = (body->get_triangulation().memory_consumption() +
                              body->get_dof_handler().memory_consumption() +
                              body->get_constraints().memory_consumption()) /
                             1048576.;
      b["mesh_memory_mb"]    = Utilities::MPI::max(mesh_mb, MPI_COMM_WORLD);
      b["dofs"]              = body->n_dofs();
      b["min_cell_diameter"] = body->get_mesh().min_cell_diameter();
      // The elastic energy of a linear body; a plastic one's state.
      if (body->get_material_law().is_linear())
        b["strain_energy"] = body->stresses().strain_energy();
      const MaterialStateSummary state = summarize_material_state(*body);
      if (!state.names.empty())
        add_material_state(state, b);
      const auto [strain, rotation] =
        body->stresses().largest_strain_and_rotation();
      b["largest_strain"]   = Utilities::MPI::max(strain, MPI_COMM_WORLD);
      b["largest_rotation"] = Utilities::MPI::max(rotation, MPI_COMM_WORLD);
      add_reactions(results, states, *body, b);
      list.push_back(b);
    }
    return list;
  }

  std::vector<ContactState>
  RunReport::contact_states(const Results &results)
  {
    std::vector<ContactState> states;
    if (results.contact_solver != nullptr)
      for (unsigned int p = 0; p < results.contact_pairs.size(); ++p)
        states.push_back(results.contact_solver->contact_state(p));
    return states;
  }

  RunReport::Answer
  RunReport::answer_of(const Results &results)
  {
    Answer answer;
    answer.states = contact_states(results);
    for (const auto &body : results.bodies)
      answer.reactions.push_back(reactions_of(results, answer.states, *body));
    return answer;
  }

  const RunReport::Answer &
  RunReport::fix_answer(const Results &results)
  {
    fixed_answer = answer_of(results);
    return *fixed_answer;
  }

  std::vector<ContactState>
  RunReport::current_states(const Results &results) const
  {
    return fixed_answer ? fixed_answer->states : contact_states(results);
  }

  ReactionForces<2>
  RunReport::current_reactions(const Results                   &results,
                               const std::vector<ContactState> &states,
                               const ElasticBody<2>            &body) const
  {
    if (fixed_answer)
      for (unsigned int b = 0; b < results.bodies.size(); ++b)
        if (results.bodies[b].get() == &body)
          return fixed_answer->reactions[b];
    return reactions_of(results, states, body);
  }

  ReactionForces<2>
  RunReport::reactions_of(const Results                   &results,
                          const std::vector<ContactState> &states,
                          const ElasticBody<2>            &body)
  {
    // The contact traction the bodies were loaded with: with the dual
    // basis not the reported one (contact_<pair>.csv), whose share of a
    // node held by a Dirichlet condition differs (issue 59: 2 % of the
    // force of clamped blocks went missing from the supports).
    BodyVector contact_load;
    for (unsigned int p = 0; p < states.size(); ++p)
    {
      const auto &pair = *results.contact_pairs[p];
      if (&pair.get_body_1() != &body && &pair.get_body_2() != &body)
        continue;
      if (contact_load.size() == 0)
        body.reinit_vector(contact_load);
      // (Loads of earlier points, before a refinement, are not taken.)
      const auto &loaded = results.contact_solver->solution_of(p);
      const auto  taken  = [&](const std::vector<double> &load,
                             const std::vector<double> &reported)
      { return load.size() == pair.points().size() ? load : reported; };
      pair.add_unconstrained_contact_load(
        taken(loaded.load_sigma_n, states[p].sigma_n), body, contact_load);
      pair.add_unconstrained_friction_load(
        taken(loaded.load_t, states[p].t), body, contact_load);
    }
    return ReactionForces<2>(body, body.get_solution(), contact_load);
  }

  void
  RunReport::add_reactions(const Results                   &results,
                           const std::vector<ContactState> &states,
                           const ElasticBody<2>            &body,
                           Json                            &json) const
  {
    const ReactionForces<2> reactions =
      current_reactions(results, states, body);
    const auto vector = [](const Tensor<1, 2> &f) { return Json{f[0], f[1]}; };
    Json       supports = Json::array();
    for (const auto &support : reactions.supports())
    {
      std::string prescribed;
      for (unsigned int c = 0; c < 2; ++c)
        if (support.prescribed[c])
          prescribed += (c == 0) ? "x" : "y";
      supports.push_back({{"boundary_id", support.id},
                          {"force", vector(support.force)},
                          {"prescribed", prescribed}});
    }
    json["reactions"]     = supports;
    json["applied_load"]  = vector(reactions.applied_load());
    json["contact_force"] = vector(reactions.contact_force());
    // What the forces leave over, against the largest of them: the
    // contact solver's tolerance (or a floating body's clamped modes).
    // An axisymmetric body's radial forces are held by its hoop stresses:
    // only the axial balance is a check.
    json["force_imbalance"] = reactions.relative_imbalance(
      body.get_geometry() == Geometry::axisymmetric,
      1e-6 * ReactionForces<2>::force_scale(body, body.get_solution()));
  }

  void
  RunReport::print_reactions() const
  {
    for (const auto &b : summary_json.at("bodies"))
      for (const auto &r : b.at("reactions"))
        pcout << std::setprecision(6) << "  body '"
              << b.at("name").get<std::string>() << "', Dirichlet id "
              << r.at("boundary_id").get<int>() << ": reaction ("
              << r.at("force")[0].get<double>() << ", "
              << r.at("force")[1].get<double>() << ")" << std::endl;
  }

  Json
  RunReport::points_json(const Results &results) const
  {
    Json points = Json::array();
    for (const auto &point : parameters.points)
    {
      const auto it =
        std::find_if(results.bodies.begin(),
                     results.bodies.end(),
                     [&](const auto &b) { return b->name() == point.body; });
      const auto v = (*it)->stresses().at_point(point.x);

      Json p;
      p["body"] = point.body;
      p["x"]    = Json::array({point.x[0], point.x[1]});
      p["u"]    = Json::array({v.displacement[0], v.displacement[1]});
      p["stress"] =
        Json::array({v.stress[0][0], v.stress[1][1], v.stress[0][1]});
      // An axisymmetric body's hoop stress (plane strain's sigma_33 is
      // nu (sigma_11 + sigma_22), not written).
      if ((*it)->get_geometry() == Geometry::axisymmetric)
        p["sigma_hoop"] = v.out_of_plane;
      p["von_mises"] = v.von_mises;
      // At a vertex or an edge the stress of one cell is off by the jump
      // between cells (a shrink fit's sigma_rr by 9.6 % at a node); the
      // mean of the cells around the point is O(h^2) at an interior vertex
      // (issue 60).
      const auto a = (*it)->stresses().averaged_at_point(point.x);
      p["stress_averaged"] =
        Json::array({a.stress[0][0], a.stress[1][1], a.stress[0][1]});
      if ((*it)->get_geometry() == Geometry::axisymmetric)
        p["sigma_hoop_averaged"] = a.out_of_plane;
      p["von_mises_averaged"] = a.von_mises;
      points.push_back(p);
      pcout << "  point " << point.body << " (" << point.x << "): u = ("
            << std::scientific << std::setprecision(6) << v.displacement[0]
            << ", " << v.displacement[1] << "), von Mises = " << v.von_mises;
      if (a.von_mises != v.von_mises)
        pcout << " (" << a.von_mises << " averaged over the cells around it)";
      pcout << std::defaultfloat << std::endl;
    }
    return points;
  }

  void
  RunReport::add_contact(const Results                   &results,
                         const std::vector<ContactState> &states,
                         const bool                       judge_penetration,
                         Json                            &json) const
  {
    const ContactSolver &contact_solver = *results.contact_solver;
    json["dd_iterations"]               = contact_solver.n_dd_iterations();
    json["gamma"]                       = parameters.contact_solver.dd.gamma;
    json["relaxation"]    = to_string(parameters.contact_solver.dd.relaxation);
    json["uzawa_updates"] = contact_solver.n_uzawa_updates();
    // The work in sets of body solves (one solve of every body), and the
    // Newton and Krylov steps of dd-newton (zero for the relaxed DD).
    const SolverCounts counts         = contact_solver.counts();
    json["contact_solver"]            = contact_solver.name();
    json["body_solve_sets"]           = counts.body_solve_sets;
    json["preconditioner_solve_sets"] = counts.preconditioner_solve_sets;
    json["preconditioner_factorizations"] =
      counts.preconditioner_factorizations;
    json["pairs_preconditioned_by_both_bodies"] =
      counts.pairs_preconditioned_by_both;
    json["newton_steps"]      = counts.newton_steps;
    json["krylov_iterations"] = counts.krylov_iterations;
    Json thetas = Json::array(), contact = Json::array();
    for (unsigned int p = 0; p < results.contact_pairs.size(); ++p)
    {
      const auto &state = states[p];
      thetas.push_back(results.contact_pairs[p]->penalty());
      Json c;
      c["pair"] = results.contact_pairs[p]->name();
      c["force"] =
        Json::array({Json::array({state.force_1[0], state.force_1[1]}),
                     Json::array({state.force_2[0], state.force_2[1]})});
      c["normal_force"] = state.normal_force;
      c["max_pressure"] = state.max_pressure;
      if (state.max_nodal_pressure > 0)
        c["max_nodal_pressure"] = state.max_nodal_pressure;
      c["contact_length"]    = state.contact_length;
      c["half_width"]        = state.half_width;
      c["extent_resolution"] = state.extent_resolution;
      if (state.contact_radius >= 0)
        c["contact_radius"] = state.contact_radius;
      if (state.stick_radius >= 0)
        c["stick_radius"] = state.stick_radius;
      c["max_penetration"] = state.max_penetration;
      if (!state.t.empty())
        c["friction"] =
          selection_name(results.contact_pairs[p]->friction_law());
      add_friction(state, c);
      const double approach        = approach_of(state);
      const auto  &pair_parameters = parameters.contact_pairs[p];
      const auto  &pair            = *results.contact_pairs[p];
      const double h               = std::min(
        zone_cell_diameter(pair.get_body_1(), pair_parameters.boundary_id_1),
        zone_cell_diameter(pair.get_body_2(), pair_parameters.boundary_id_2));
      c["approach"] = approach;
      if (const auto w =
            small_strain_warning(pair, approach, small_strain_limit);
          !w.empty())
        json["warnings"].push_back(w);
      c["search"] = search_json(pair.search_report());
      for (const auto &warning : pair.setup_warnings())
        json["warnings"].push_back(warning);
      if (const auto w = multiplier_side_warning(pair, parameters); !w.empty())
        json["warnings"].push_back(w);
      if (judge_penetration)
        if (const auto w = no_contact_warning(pair, state); !w.empty())
          json["warnings"].push_back(w);
      if (h < std::numeric_limits<double>::max())
        c["min_zone_cell_diameter"] = h;
      contact.push_back(c);
      const std::string warning =
        judge_penetration
          ? penetration_warning(
              pair.name(), state.max_penetration, approach, h, parameters)
          : "";
      if (!warning.empty())
        json["warnings"].push_back(warning);
    }
    json["theta"]   = thetas;
    json["contact"] = contact;
    if (!contact_solver.history().empty())
    {
      json["dd_residual"]  = contact_solver.history().back().residual;
      json["dd_increment"] = contact_solver.history().back().increment;
    }
  }

  void
  RunReport::add_adaptation(const Results &results, Json &json) const
  {
    json["adaptation_cycles"] = results.n_adaptation_steps;
    unsigned int bem_unknowns = 0;
    Json         estimator;
    estimator["mode"]    = to_string(parameters.adaptation.mode);
    estimator["type"]    = to_string(parameters.adaptation.estimator);
    estimator["marking"] = to_string(parameters.adaptation.marking);
    estimator["delta"]   = parameters.adaptation.delta;
    Json per_body        = Json::array();
    for (const auto &a : results.adaptations)
    {
      Json e;
      e["body"]         = a->get_body().name();
      e["eta_max"]      = a->eta_max();
      e["eta_sum"]      = a->eta_sum();
      e["capped_cells"] = a->n_capped();
      if (const auto *fb = a->fem_bem())
      {
        bem_unknowns += fb->bem_unknowns();
        e["bem_unknowns"]          = fb->bem_unknowns();
        e["stress_error_estimate"] = fb->global_error();
        e["bem_stress_norm"]       = fb->stress_norm();
        e["relative_error_estimate"] =
          fb->stress_norm() > 0 ? fb->global_error() / fb->stress_norm() : 0.;
      }
      per_body.push_back(e);
    }
    estimator["bodies"]  = per_body;
    json["bem_unknowns"] = bem_unknowns;
    json["estimator"]    = estimator;
    // The global estimate of the adapted bodies and the target it was
    // held against (null: none, or no FEM-BEM estimator).
    const double estimate = relative_energy_error_estimate(results.adaptations);
    const double target   = parameters.adaptation.target_error;
    json["relative_energy_error_estimate"] =
      estimate >= 0 ? Json(estimate) : Json();
    json["target_error"] = target > 0 ? Json(target) : Json();
    json["target_reached"] =
      (target > 0 && estimate >= 0) ? Json(estimate <= target) : Json();
    if (target > 0 && estimate > target)
      json["warnings"].push_back(target_shortfall(results));
    if (!results.adaptation_stop.empty())
      json["adaptation_stopped_by"] = results.adaptation_stop;
  }

  Json
  RunReport::timings_json(const Results &results) const
  {
    Json timings = Json::object();
    for (const auto &[section, seconds] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      timings[section] = seconds;
    // The BEM's phases, timed by the estimators.
    std::map<std::string, double> bem;
    for (const auto &a : results.adaptations)
      if (const auto *fb = a->fem_bem())
      {
        bem["BEM setup (assembly, LU)"] += fb->timings().bem_setup;
        bem["BEM solve"] += fb->timings().bem_solve;
        bem["BEM interior stresses"] += fb->timings().bem_interior;
      }
    for (const auto &[section, seconds] : bem)
      timings[section] = seconds;
    // The body solves and the exchange of their solutions (on process 0;
    // the exchange includes waiting for the slowest process).
    timings["body solves"] = results.distribution.solve_seconds();
    if (results.distribution.n_processes() > 1)
      timings["exchange between processes"] =
        results.distribution.exchange_seconds();
    return timings;
  }

  Json
  RunReport::progress_summary(const RunOutcome   outcome,
                              const std::string &error) const
  {
    Json json;
    json["scene"]         = parameters.scene_name;
    json["code_revision"] = git_revision();
    json["status"]        = status_name(outcome);
    json["last_completed_step"] =
      last_completed_step.empty() ? Json() : Json(last_completed_step);
    if (!error.empty())
      json["error"] = error;
    json["warnings"] = run_warnings;
    if (!load_steps.empty())
      json["load_steps"] = load_steps;
    if (!load_path.is_null())
      json["load_path"] = load_path;
    json["wall_time_s"] = wall_clock.wall_time();
    return json;
  }

  void
  RunReport::write_summary(const Results     &results,
                           const RunOutcome   outcome,
                           const std::string &error)
  {
    write_summary(results, current_states(results), outcome, error);
  }

  void
  RunReport::write_summary(const Results                   &results,
                           const std::vector<ContactState> &states,
                           const RunOutcome                 outcome,
                           const std::string               &error)
  {
    Json json;
    json["scene"]         = parameters.scene_name;
    json["code_revision"] = git_revision();
    json["status"]        = status_name(outcome);
    if (!error.empty())
      json["error"] = error;
    json["last_completed_step"] =
      last_completed_step.empty() ? Json() : Json(last_completed_step);
    // The code takes any consistent system of units; the scene's comments
    // say which one it uses (e.g. cm and MPa).
    json["units"] =
      (!results.bodies.empty() &&
       results.bodies.front()->get_geometry() == Geometry::axisymmetric)
        ? "consistent units of the scene; forces and energies over the whole "
          "ring (axisymmetric: 2 pi r)"
        : "consistent units of the scene; forces and energies per unit "
          "thickness (plane strain)";
    json["warnings"] = run_warnings; // added to below
    json["bodies"]   = bodies_json(results, states);
    for (const auto &b : json["bodies"])
    {
      const double strain   = b["largest_strain"].get<double>();
      const double rotation = b["largest_rotation"].get<double>();
      if (!(std::max(strain, rotation) <= small_strain_limit))
      {
        std::ostringstream s;
        s << std::setprecision(3) << "body '" << b["name"].get<std::string>()
          << "': the largest strain is " << strain << " and the largest "
          << "rotation " << rotation << ", beyond the "
          << 100 * small_strain_limit
          << " % where linear elasticity (small strains (1)) holds; the "
             "loads or displacements and Young's modulus are probably in "
             "different units (a load in Pa with E in MPa is 1e6 times too "
             "large)";
        json["warnings"].push_back(s.str());
      }
    }
    json["mpi_processes"] = results.distribution.n_processes();
    json["body_owners"]   = results.distribution.describe();
    json["points"]        = points_json(results);
    if (!load_steps.empty())
      json["load_steps"] = load_steps;
    // The first load step at which a point of a body yields, and where.
    for (const auto &row : load_steps)
      if (row.contains("bodies") && !json.contains("first_yield"))
        for (const auto &b : row.at("bodies"))
          if (b.at("plastic_zone_measure").get<double>() > 0 &&
              !json.contains("first_yield"))
            json["first_yield"] = {{"step", row.at("step")},
                                   {"t", row.at("t")},
                                   {"body", b.at("body")},
                                   {"location", b.at("location_of_largest")}};
    if (!load_path.is_null())
      json["load_path"] = load_path;
    // The penetration is judged only where the contact iteration converged
    // (also "stalled": the DD converged, the Uzawa loop did not).
    if (!results.contact_pairs.empty())
      add_contact(results, states, contact_converged(outcome), json);
    if (!self_checks.is_null())
      json["self_checks"] = self_checks;
    if (parameters.adaptation.enabled())
      add_adaptation(results, json);
    json["wall_time_s"] = wall_clock.wall_time();
    json["timings"]     = timings_json(results);

    // Peak resident memory (VmHWM): what a distributed mesh saves; per
    // process, with its dofs and the bytes it sent.
    json["peak_memory"] = peak_memory_json();
    json["processes"]   = processes_json(
      results.distribution,
      results.contact_solver ? results.contact_solver->history().size() : 0);

    summary_json = json;
    // From here the run's own record is true: a signal no longer writes
    // one (interruption::set_record()).
    interruption::clear_record();
    if (writes_files)
      write_json_file(json, parameters.output_directory + "/summary.json");
  }

  std::string
  RunReport::target_shortfall(const Results &results) const
  {
    const double estimate = relative_energy_error_estimate(results.adaptations);
    const double target   = parameters.adaptation.target_error;
    if (!(target > 0 && estimate > target))
      return "";
    std::ostringstream s;
    s << "Adaptation/Target error " << target
      << " not reached: the estimated relative energy-norm error is "
      << estimate << " after " << results.n_adaptation_steps
      << " refinement cycles, and "
      << (results.adaptation_stop.empty() ? "the refinement stopped"
                                          : results.adaptation_stop)
      << "; raise the cap that stopped it, or set a larger Target error";
    return s.str();
  }

} // namespace ddcontact
