#include <ddcontact/solvers/friction_history.h>

#include <cmath>

namespace ddcontact
{
  void
  FrictionHistory::clear()
  {
    slips.clear();
    tractions.clear();
    last_slips.clear();
    last_tractions.clear();
    point_slips.clear();
  }

  void
  FrictionHistory::start_load_step(const ContactProblem &problem)
  {
    slips     = last_slips;
    tractions = last_tractions;
    point_slips.assign(problem.get_pairs().size(), {});
    for (unsigned int k = 0; k < point_slips.size(); ++k)
      point_slips[k] = problem.law(k).get_friction().slip;
  }

  void
  FrictionHistory::publish(ContactProblem                         &problem,
                           const ContactInterface                 &interface,
                           const PointVector                      &p,
                           const PointVector                      &t,
                           const PointVector                      &nodal_slips,
                           const std::vector<std::vector<double>> &sigma_n)
  {
    const unsigned int n = interface.size();
    AssertDimension(t.size(), n);
    AssertDimension(nodal_slips.size(), n);
    last_slips          = nodal_slips;
    last_tractions      = t;
    const auto &pairs   = problem.get_pairs();
    const auto &bodies  = problem.get_bodies();
    const auto  minus_t = interface.normal_stresses(t);
    for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const auto &pair = *pairs[k];
      if (!pair.has_friction())
        continue;
      ContactLaw::Friction result;
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
          result.nodal_bound.push_back(
            interface.friction_bound(i) *
            (interface.friction_law(i) == FrictionLaw::tresca ? 1. : p[i]));
        }
      for (unsigned int q = 0; q < pair.points().size(); ++q)
      {
        const double t_q = -minus_t[k][q];
        result.t.push_back(t_q);
        // Slipping where |t| reaches the bound (to round-off).
        const double bound =
          pair.points()[q].friction *
          (pair.friction_law() == FrictionLaw::tresca ? 1. : -sigma_n[k][q]);
        result.state.push_back(sigma_n[k][q] == 0. ? ContactLaw::SlipState::open
                               : std::abs(t_q) >= (1 - 1e-9) * bound
                                 ? ContactLaw::SlipState::slip
                                 : ContactLaw::SlipState::stick);
      }
      problem.law(k).set_friction(result);
    }
  }
} // namespace ddcontact
