#include <ddcontact/contact/friction_history.h>

#include <cmath>

namespace ddcontact
{
  void
  FrictionHistory::clear()
  {
    nodes.clear();
    slips.clear();
    tractions.clear();
    last_slips.clear();
    last_tractions.clear();
    point_slips.clear();
    points.clear();
    last_point_slips.clear();
    last_dissipation.clear();
    carried_dissipation.clear();
    continuing = false;
  }

  namespace
  {
    /** The positions of pair @p k's contact points. */
    std::vector<Point<2>>
    positions(const ContactProblem &problem, const unsigned int k)
    {
      std::vector<Point<2>> x;
      for (const auto &point : problem.get_pairs()[k]->points())
        x.push_back(point.x);
      return x;
    }
  } // namespace

  void
  FrictionHistory::start_load_step(const ContactProblem   &problem,
                                   const ContactInterface &interface)
  {
    nodes                      = interface.positions();
    slips                      = last_slips;
    tractions                  = last_tractions;
    const unsigned int n_pairs = problem.get_pairs().size();
    if (continuing && carried_dissipation.size() == n_pairs)
    {
      // A part of the same load step: the slip increment still counts
      // from the step's start (point_slips stay), the energy dissipated
      // so far is carried.
      for (unsigned int k = 0; k < n_pairs; ++k)
        carried_dissipation[k] =
          (k < last_dissipation.size()) ? last_dissipation[k] : 0.;
      continuing = false;
      return;
    }
    continuing = false;
    carried_dissipation.assign(n_pairs, 0.);
    point_slips.assign(n_pairs, {});
    points.assign(n_pairs, {});
    for (unsigned int k = 0; k < n_pairs; ++k)
    {
      if (k < last_point_slips.size())
        point_slips[k] = last_point_slips[k];
      points[k] = positions(problem, k);
    }
  }

  void
  FrictionHistory::transfer(const ContactProblem   &problem,
                            const ContactInterface &interface)
  {
    if (slips.empty())
      return;
    AssertDimension(slips.size(), nodes.size());
    const auto &to = interface.positions();
    slips          = interpolated_node_values(nodes, slips, to);
    tractions      = interpolated_node_values(nodes, tractions, to);
    nodes          = to;
    for (unsigned int k = 0; k < point_slips.size(); ++k)
    {
      auto x         = positions(problem, k);
      point_slips[k] = nearest_point_values(points[k], point_slips[k], x);
      points[k]      = std::move(x);
    }
  }

  void
  FrictionHistory::publish(const ContactProblem                   &problem,
                           const ContactInterface                 &interface,
                           const PointVector                      &p,
                           const PointVector                      &t,
                           const PointVector                      &nodal_slips,
                           const std::vector<bool>                &sticking,
                           const std::vector<std::vector<double>> &sigma_n,
                           std::vector<PairSolution>              &published)
  {
    const unsigned int n = interface.size();
    AssertDimension(t.size(), n);
    AssertDimension(nodal_slips.size(), n);
    AssertDimension(sticking.size(), n);
    last_slips        = nodal_slips;
    last_tractions    = t;
    const auto &pairs = problem.get_pairs();
    last_point_slips.assign(pairs.size(), {});
    last_dissipation.assign(pairs.size(), 0.);
    const auto &bodies  = problem.get_bodies();
    const auto  field_t = interface.reported_field(t);
    // The points with a sticking node.
    std::vector<std::vector<bool>> sticks(pairs.size());
    for (unsigned int k = 0; k < pairs.size(); ++k)
      sticks[k].assign(pairs[k]->points().size(), false);
    for (unsigned int i = 0; i < n; ++i)
      if (sticking[i])
        for (const auto &share : interface.shares(i))
          if (share.psi > 0)
            sticks[share.pair][share.point] = true;
    for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const auto &pair = *pairs[k];
      if (!pair.has_friction())
        continue;
      FrictionResults result;
      if (k < carried_dissipation.size())
        result.dissipation = carried_dissipation[k];
      result.slip = pair.slips(
        bodies[problem.body_index(pair.get_body_1())]->get_solution(),
        bodies[problem.body_index(pair.get_body_2())]->get_solution());
      // The slip since the last load step (the undeformed state at the
      // first).
      result.slip_increment = result.slip;
      if (k < point_slips.size() && point_slips[k].size() == result.slip.size())
        for (unsigned int q = 0; q < result.slip.size(); ++q)
          result.slip_increment[q] -= point_slips[k][q];
      for (unsigned int i = 0; i < n; ++i)
        if (interface.shares(i)[0].pair == k)
        {
          const double ds    = nodal_slips[i] - old_slip(i);
          const double theta = interface.target_penalty(i);
          result.dissipation += interface.weight(i) * t[i] *
                                (ds - theta * (t[i] - old_traction(i)));
          result.nodal_t.push_back(t[i]);
          result.nodal_slip_increment.push_back(ds);
          result.nodal_inelastic_slip.push_back(
            ds - theta * (t[i] - old_traction(i)));
          result.nodal_bound.push_back(
            interface.law().converged_bound(i, p[i]));
        }
      for (unsigned int q = 0; q < pair.points().size(); ++q)
      {
        result.t.push_back(field_t[k][q]);
        result.state.push_back(sigma_n[k][q] == 0. ? NodeState::open
                               : sticks[k][q]      ? NodeState::stick
                                                   : NodeState::slip);
      }
      last_point_slips[k]   = result.slip;
      last_dissipation[k]   = result.dissipation;
      published[k].friction = std::move(result);
    }
  }
} // namespace ddcontact
