#include <ddcontact/contact/contact_problem.h>
#include <ddcontact/contact/zone_extent.h>
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

  bool
  ContactProblem::has_nonlinear_bodies() const
  {
    for (const auto *body : bodies)
      if (!body->get_material_law().is_linear())
        return true;
    return false;
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
      else if (bodies[b]->get_material_law().is_linear())
        bodies[b]->solve(loads[b], u[b]);
      else
        bodies[b]->solve_nonlinear(loads[b], u[b]);
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
    /** @p value at the points of @p pair as samples along S_1. */
    std::vector<ZoneExtent::Sample>
    point_samples(const ContactPair &pair, const std::vector<double> &value)
    {
      std::vector<ZoneExtent::Sample> samples;
      for (unsigned int q = 0; q < value.size(); ++q)
      {
        const auto [c, s] = pair.zone_arc_length().position(
          pair.points()[q].face, pair.points()[q].x);
        samples.push_back({c, s, value[q]});
      }
      return samples;
    }

    /** The nodal values p_i of a field sum_i p_i phi_i given at the points
     * of @p pair (@p value): on each face of S_1 the line through its
     * points, at the face's ends (one sample per node of S_1). */
    std::vector<ZoneExtent::Sample>
    nodal_samples(const ContactPair &pair, const std::vector<double> &value)
    {
      const auto &arcs  = pair.zone_arc_length();
      const auto &faces = pair.zone_faces_1();
      std::vector<std::vector<std::pair<double, double>>> on_face(faces.size());
      for (unsigned int q = 0; q < value.size(); ++q)
      {
        const auto &pt = pair.points()[q];
        on_face[pt.face].emplace_back(arcs.position(pt.face, pt.x).second,
                                      value[q]);
      }
      std::vector<ZoneExtent::Sample> nodes;
      double                          shortest = 0;
      for (unsigned int f = 0; f < faces.size(); ++f)
      {
        const auto &points = on_face[f];
        if (points.empty())
          continue;
        // Least squares: exact for the linear field on the face.
        double s_mean = 0, v_mean = 0;
        for (const auto &[s, v] : points)
        {
          s_mean += s / points.size();
          v_mean += v / points.size();
        }
        double ss = 0, sv = 0;
        for (const auto &[s, v] : points)
        {
          ss += (s - s_mean) * (s - s_mean);
          sv += (s - s_mean) * (v - v_mean);
        }
        const double slope = (ss > 0) ? sv / ss : 0.;
        for (const auto &end : faces[f])
        {
          const auto [c, s] = arcs.position(f, end);
          nodes.push_back({c, s, v_mean + slope * (s - s_mean)});
        }
        const double length = faces[f][0].distance(faces[f][1]);
        shortest = (shortest == 0) ? length : std::min(shortest, length);
      }
      // A node shared by two faces once, with the mean of its two values
      // (equal up to round-off); on a closed curve s = L is s = 0.
      const double same = 1e-8 * shortest;
      for (auto &x : nodes)
        if (arcs.is_closed(x.curve) && arcs.length(x.curve) - x.s < same)
          x.s = 0;
      std::sort(nodes.begin(),
                nodes.end(),
                [](const auto &a, const auto &b)
                { return std::tie(a.curve, a.s) < std::tie(b.curve, b.s); });
      std::vector<ZoneExtent::Sample> merged;
      unsigned int                    count = 0;
      for (const auto &x : nodes)
        if (!merged.empty() && merged.back().curve == x.curve &&
            x.s - merged.back().s < same)
        {
          ++count;
          merged.back().value += (x.value - merged.back().value) / count;
        }
        else
        {
          merged.push_back(x);
          count = 1;
        }
      return merged;
    }

    /** The extents of the zone @p zone into @p half_width (half the
     * extent; a zone that reaches the axis of an axisymmetric body counts
     * its mirror image: a sphere's half-width is its contact radius), and,
     * in axisymmetry, the largest r of its edges into @p radius. */
    void
    measure(const ContactPair &pair,
            const ZoneExtent  &zone,
            double            &half_width,
            double            *radius)
    {
      const auto &arcs    = pair.zone_arc_length();
      const auto  on_axis = [&](const unsigned int c, const double s)
      { return std::abs(arcs.point(c, s)[0]) <= 1e-10 * arcs.length(c); };
      half_width = 0.5 * zone.extent();
      if (radius == nullptr)
        return;
      half_width += 0.5 * zone.extent_at(on_axis);
      *radius = 0;
      for (const auto &e : zone.edges())
        *radius = std::max(*radius, arcs.point(e.curve, e.s)[0]);
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
    }
    for (unsigned int q = 0; q < state.sigma_n.size(); ++q)
    {
      const auto &pt     = pair.points()[q];
      state.max_pressure = std::max(state.max_pressure, -state.sigma_n[q]);
      state.normal_force -= state.sigma_n[q] * pt.JxW;
      state.max_penetration =
        std::max(state.max_penetration, state.u_1n[q] + state.u_2n[q] - pt.gap);
    }
    // The zone's extents to a fraction of a cell (ZoneExtent): from the
    // nodal multipliers where the solver has them (the nodal values of the
    // reported field sum_i p_i psi_i, the points' values between), else
    // from the pressure at the points.
    const bool axisymmetric =
      pair.get_body_1().get_geometry() == Geometry::axisymmetric;
    const bool nodal = published && !pair.points().empty() &&
                       published->load_sigma_n.size() == pair.points().size();
    std::vector<double> p_zone(state.sigma_n.size());
    for (unsigned int q = 0; q < p_zone.size(); ++q)
      p_zone[q] = -state.sigma_n[q];
    const ZoneExtent zone(pair.zone_arc_length(),
                          nodal ? nodal_samples(pair, p_zone)
                                : point_samples(pair, p_zone),
                          ZoneExtent::EdgeModel::square_root);
    state.contact_length    = zone.length();
    state.extent_resolution = zone.resolution();
    measure(pair,
            zone,
            state.half_width,
            axisymmetric ? &state.contact_radius : nullptr);
    if (!state.slip_state.empty())
    {
      // The stick zone ends where the margin |t| < bound closes, between
      // a sticking point and the next one that does not stick.
      std::vector<double> stick(state.slip_state.size());
      for (unsigned int q = 0; q < stick.size(); ++q)
        stick[q] = (state.slip_state[q] == NodeState::stick) ? 1. : -1.;
      const ZoneExtent stick_zone(pair.zone_arc_length(),
                                  point_samples(pair, stick),
                                  ZoneExtent::EdgeModel::midpoint);
      state.stick_resolution = stick_zone.resolution();
      measure(pair,
              stick_zone,
              state.stick_half_width,
              axisymmetric ? &state.stick_radius : nullptr);
      // A stick zone that reaches the zone's edge (a point that does not
      // stick beyond it is open, not slipping) ends with it.
      state.stick_half_width =
        std::min(state.stick_half_width, state.half_width);
      if (axisymmetric)
        state.stick_radius = std::min(state.stick_radius, state.contact_radius);
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
    // The normal displacements alone: the penetration needs no pressure,
    // loads or extents (contact_state()), which the Uzawa loop would pay
    // for at every update.
    std::vector<double> u_1n, u_2n;
    for (const ContactPair *pair : pairs)
    {
      pair->normal_displacements(u[body_index(pair->get_body_1())],
                                 u[body_index(pair->get_body_2())],
                                 u_1n,
                                 u_2n);
      for (unsigned int q = 0; q < u_1n.size(); ++q)
      {
        max_penetration =
          std::max(max_penetration, u_1n[q] + u_2n[q] - pair->points()[q].gap);
        max_displacement =
          std::max(max_displacement, std::abs(u_1n[q]) + std::abs(u_2n[q]));
      }
    }
    return {max_penetration,
            max_penetration / std::max(max_displacement, 1e-300)};
  }
} // namespace ddcontact
