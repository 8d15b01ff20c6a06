#include <ddcontact/contact/contact_problem.h>
#include <ddcontact/parameter_tools.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ddcontact
{
  ContactProblem::ContactProblem(const std::vector<ElasticBody<2> *> &bodies,
                                 const std::vector<ContactPair *>    &pairs,
                                 const BodyDistribution &distribution)
    : bodies(bodies)
    , pairs(pairs)
    , distribution(distribution)
  {
    reset_laws();
  }

  unsigned int
  ContactProblem::body_index(const ElasticBody<2> &body) const
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies[b] == &body)
        return b;
    Assert(false, ExcInternalError());
    return 0;
  }

  void
  ContactProblem::reset_laws()
  {
    laws.clear();
    for (const auto *pair : pairs)
    {
      laws.emplace_back(*pair);
      laws.back().set_solver_pressure(solver_pressure);
    }
  }

  void
  ContactProblem::set_pressure_from_solver(const bool from_solver)
  {
    solver_pressure = from_solver;
    for (auto &law : laws)
      law.set_solver_pressure(from_solver);
  }

  ContactProblem::Iterate
  ContactProblem::current_iterate() const
  {
    Iterate u(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      copy_stored(bodies[b]->get_solution(), u[b]);
    return u;
  }

  ContactProblem::Iterate
  ContactProblem::zero_iterate() const
  {
    Iterate u(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      bodies[b]->reinit_vector(u[b]);
      // Its ghosts (a distributed body's traces) are valid zeros: the
      // contact evaluations may read them without an import.
      u[b].set_ghost_state(true);
    }
    return u;
  }

  std::vector<std::vector<types::global_dof_index>>
  ContactProblem::trace_dofs() const
  {
    std::vector<std::vector<types::global_dof_index>> dofs(bodies.size());
    for (const auto *pair : pairs)
    {
      auto &d1 = dofs[body_index(pair->get_body_1())];
      auto &d2 = dofs[body_index(pair->get_body_2())];
      for (const auto &point : pair->points())
      {
        d1.insert(d1.end(), point.dofs_1.begin(), point.dofs_1.end());
        d1.insert(d1.end(), point.load_dofs_1.begin(), point.load_dofs_1.end());
        d2.insert(d2.end(), point.dofs_2.begin(), point.dofs_2.end());
        d2.insert(d2.end(), point.load_dofs_2.begin(), point.load_dofs_2.end());
      }
    }
    for (auto &d : dofs)
    {
      std::sort(d.begin(), d.end());
      d.erase(std::unique(d.begin(), d.end()), d.end());
    }
    return dofs;
  }

  void
  ContactProblem::update_vector_layouts() const
  {
    const auto traces = trace_dofs();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies[b]->has_distributed_vectors())
        bodies[b]->distribute_vectors(traces[b]);
  }

  void
  ContactProblem::solve_all(const Iterate &loads,
                            Iterate       &u,
                            const bool     homogeneous,
                            const Exchange exchange) const
  {
    // A contact load beyond the floating-point range would come back as a
    // non-finite displacement blamed on the body; name the pairs instead.
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (loads[b].size() > 0 && !std::isfinite(loads[b].linfty_norm()))
      {
        std::string entries;
        for (const auto *pair : pairs)
          if (&pair->get_body_1() == bodies[b] ||
              &pair->get_body_2() == bodies[b])
            entries += (entries.empty() ? "" : ", ") +
                       ("Contact pair " + pair->name() + "/Gap");
        throw InputError(entries + ": the contact load on body '" +
                         bodies[b]->name() +
                         "' is beyond the floating-point range (gap / theta "
                         "overflows); check the gap's magnitude and the "
                         "Penalty");
      }
    // The body problems of (20) are independent: solve them concurrently,
    // each on the process that owns it.
    u.resize(bodies.size());
    const auto solve = [&](const unsigned int b)
    {
      if (homogeneous)
        bodies[b]->solve_homogeneous(loads[b], u[b]);
      else
        bodies[b]->solve(loads[b], u[b]);
    };
    if (exchange == Exchange::traces)
      distribution.solve_and_share_traces(solve, u, trace_dofs());
    else
      distribution.solve_and_share(solve, u);
  }

  void
  ContactProblem::solve_bodies(const std::vector<std::vector<double>> &sigma_n,
                               Iterate                                &u,
                               const bool     homogeneous,
                               const Exchange exchange) const
  {
    solve_bodies(sigma_n, {}, u, homogeneous, exchange);
  }

  void
  ContactProblem::solve_bodies(const std::vector<std::vector<double>> &sigma_n,
                               const std::vector<std::vector<double>> &t,
                               Iterate                                &u,
                               const bool     homogeneous,
                               const Exchange exchange) const
  {
    Iterate loads = zero_iterate();
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      auto &load_1 = loads[body_index(pairs[p]->get_body_1())];
      auto &load_2 = loads[body_index(pairs[p]->get_body_2())];
      pairs[p]->add_contact_loads(sigma_n[p], load_1, load_2);
      if (!t.empty())
        pairs[p]->add_friction_loads(t[p], load_1, load_2);
    }
    solve_all(loads, u, homogeneous, exchange);
  }

  std::vector<double>
  ContactProblem::gaps(const unsigned int p, const Iterate &u) const
  {
    const auto         &pair = *pairs[p];
    std::vector<double> u_1n, u_2n;
    pair.normal_displacements(u[body_index(pair.get_body_1())],
                              u[body_index(pair.get_body_2())],
                              u_1n,
                              u_2n);
    std::vector<double> g(u_1n.size());
    for (unsigned int q = 0; q < g.size(); ++q)
      g[q] = pair.points()[q].gap - u_1n[q] - u_2n[q];
    return g;
  }

  std::vector<double>
  ContactProblem::pressure(const unsigned int p, const Iterate &u) const
  {
    return laws[p].pressure(gaps(p, u));
  }

  std::vector<std::vector<double>>
  ContactProblem::normal_displacements_by_body(const Iterate &u) const
  {
    std::vector<std::vector<double>> by_body(bodies.size());
    for (const auto *pair : pairs)
    {
      std::vector<double> u_1n, u_2n;
      const unsigned int  b1 = body_index(pair->get_body_1());
      const unsigned int  b2 = body_index(pair->get_body_2());
      pair->normal_displacements(u[b1], u[b2], u_1n, u_2n);
      by_body[b1].insert(by_body[b1].end(), u_1n.begin(), u_1n.end());
      by_body[b2].insert(by_body[b2].end(), u_2n.begin(), u_2n.end());
    }
    return by_body;
  }

  namespace
  {
    /** Half the arc length along S_1 of the points @p q of @p pair for
     * which @p selected(q) holds (0 for none; ZoneArcLength): the
     * half-width of the active set or of the stick zone. */
    template <typename Selected>
    double
    half_extent(const ContactPair &pair, const Selected &selected)
    {
      std::vector<unsigned int> faces;
      std::vector<Point<2>>     x;
      for (unsigned int q = 0; q < pair.points().size(); ++q)
        if (selected(q))
        {
          faces.push_back(pair.points()[q].face);
          x.push_back(pair.points()[q].x);
        }
      return pair.zone_arc_length().half_extent(faces, x);
    }
  } // namespace

  ContactState
  ContactProblem::contact_state(const unsigned int  p,
                                const Iterate      &u,
                                const PairSolution *published) const
  {
    const auto  &pair = *pairs[p];
    ContactState state;
    pair.normal_displacements(u[body_index(pair.get_body_1())],
                              u[body_index(pair.get_body_2())],
                              state.u_1n,
                              state.u_2n);
    state.sigma_n = pressure(p, u);
    BodyVector l1, l2;
    pair.get_body_1().reinit_vector(l1);
    pair.get_body_2().reinit_vector(l2);
    std::tie(state.force_1, state.force_2) =
      pair.add_contact_loads(state.sigma_n, l1, l2);
    static const FrictionResults none;
    const auto &friction = published ? published->friction : none;
    if (pair.has_friction() && !pair.points().empty() &&
        friction.t.size() == pair.points().size())
    {
      state.t              = friction.t;
      state.slip_increment = friction.slip_increment;
      state.slip           = friction.slip;
      state.slip_state     = friction.state;
      state.dissipation    = friction.dissipation;
      const auto forces    = pair.add_friction_loads(friction.t, l1, l2);
      state.force_1 += forces.first;
      state.force_2 += forces.second;
      // The integral of the traction -t tau on body 1 along each point's
      // own tangent tau (on a straight zone, the force along its tangent).
      state.tangential_force = 0;
      for (unsigned int q = 0; q < friction.t.size(); ++q)
        state.tangential_force -= friction.t[q] * pair.points()[q].JxW;
      state.stick_half_width =
        half_extent(pair,
                    [&](const unsigned int q)
                    { return friction.state[q] == NodeState::stick; });
    }
    for (unsigned int q = 0; q < state.sigma_n.size(); ++q)
    {
      const auto &pt     = pair.points()[q];
      state.max_pressure = std::max(state.max_pressure, -state.sigma_n[q]);
      state.normal_force -= state.sigma_n[q] * pt.JxW;
      if (state.sigma_n[q] < 0)
        state.contact_length += pt.ds;
      state.max_penetration =
        std::max(state.max_penetration, state.u_1n[q] + state.u_2n[q] - pt.gap);
    }
    state.half_width = half_extent(
      pair, [&](const unsigned int q) { return state.sigma_n[q] < 0; });
    if (pair.get_body_1().get_geometry() == Geometry::axisymmetric)
    {
      state.contact_radius = 0;
      for (unsigned int q = 0; q < state.sigma_n.size(); ++q)
        if (state.sigma_n[q] < 0)
          state.contact_radius =
            std::max(state.contact_radius, pair.points()[q].x[0]);
      if (!state.slip_state.empty())
      {
        state.stick_radius = 0;
        for (unsigned int q = 0; q < state.slip_state.size(); ++q)
          if (state.slip_state[q] == NodeState::stick)
            state.stick_radius =
              std::max(state.stick_radius, pair.points()[q].x[0]);
      }
    }
    // The peak is that of the field written to the CSV and the VTU, at the
    // contact points; the largest nodal multiplier (exact contact, Contact
    // pressure = nodes) lies at a node of S_1 and is kept beside it.
    state.max_nodal_pressure = published ? published->peak_nodal_pressure : 0.;
    return state;
  }

  std::pair<double, double>
  ContactProblem::penetration(const Iterate &u) const
  {
    double max_penetration = 0, max_displacement = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      const auto state = contact_state(p, u);
      max_penetration  = std::max(max_penetration, state.max_penetration);
      for (unsigned int q = 0; q < state.u_1n.size(); ++q)
        max_displacement = std::max(
          max_displacement, std::abs(state.u_1n[q]) + std::abs(state.u_2n[q]));
    }
    return {max_penetration,
            max_penetration / std::max(max_displacement, 1e-300)};
  }
} // namespace ddcontact
