#include <ddcontact/solvers/dd_newton_solver.h>

#include <algorithm>

// DDNewtonSolver's side of the contact law: the Newton residual, the
// nodes' trial values and states (NodalContactLaw), and the active set.
namespace ddcontact
{
  PointVector
  DDNewtonSolver::newton_residual(const PointVector &x,
                                  const PointVector &Sx,
                                  const PointVector &Gx) const
  {
    PointVector        F(x.size());
    const unsigned int n = interface.size();
    for (unsigned int q = 0; q < n; ++q)
      F[q] = NodalContactLaw::normal_residual(trial(q, x, Sx, Gx));
    // Friction: c (t - the trial traction cut to the bound) at the closed
    // nodes, c t at the others (as MonolithicContactSolver's residual).
    for (unsigned int q = n; q < x.size(); ++q)
      F[q] =
        interface.complementarity_scale(q) *
        interface.law().tangential_residual(q - n, trial(q - n, x, Sx, Gx));
    return F;
  }

  NodalContactLaw::Trial
  DDNewtonSolver::trial(const unsigned int i,
                        const PointVector &x,
                        const PointVector &Sx,
                        const PointVector &Gx) const
  {
    NodalContactLaw::Trial v;
    v.p     = x[i];
    v.d     = d_0[i] - Sx[i] + Gx[i];
    v.theta = interface.penalty(i);
    v.c     = interface.complementarity_scale(i);
    if (interface.has_friction())
    {
      // d_0 holds s_0 - s_old + theta t_old at the tangential unknown j,
      // so that d_0,j - (S x)_j - theta t_j = ds - theta (t - t_old).
      const unsigned int j = interface.size() + i;
      v.t                  = x[j];
      v.r                  = d_0[j] - Sx[j] - interface.penalty(j) * x[j];
      v.c_t                = interface.complementarity_scale(j);
    }
    return v;
  }

  std::vector<bool>
  DDNewtonSolver::active_set(unsigned int &n_changed, const bool stick)
  {
    // The active set of the semismooth Newton step on min(c p, lambda):
    // lambda < c p, i.e. d(p) + (c - theta) p > 0; with friction the
    // sticking nodes' tangentials, and on the slipping ones
    // t = value + coupling p. With @p stick, a closed node keeps its state
    // of the last load step (slipping the same way), or sticks.
    const unsigned int n        = interface.size();
    const auto        &law      = interface.law();
    const bool         friction = interface.has_friction();
    const bool last_step = step_slip_directions.size() == (friction ? n : 0);
    const bool linearise =
      !stick && parameters.dd_newton.coulomb == CoulombLinearization::newton;
    std::vector<bool> active(p.size(), false);
    PointVector       d(n);
    slip_values.assign(friction ? n : 0, 0.);
    slip_coupling.assign(slip_values.size(), 0.);
    slip_directions.assign(slip_values.size(), 0);
    for (unsigned int i = 0; i < n; ++i)
    {
      const auto x = trial(i, p, Sp, Ga);
      d[i]         = x.d;
      const NodeStatus status =
        !stick ? law.status(i, x)
               : law.prescribed_status(
                   i, x, last_step && friction ? step_slip_directions[i] : 0);
      active[i] = status.closed();
      if (!friction)
        continue;
      active[n + i]      = status.state == NodeState::stick;
      slip_directions[i] = status.direction;
      const auto slip =
        law.slip_equation(i, status, law.bound(i, x), linearise);
      slip_values[i]   = slip.value;
      slip_coupling[i] = slip.coupling;
    }
    // Floating bodies need active unknowns that hold their rigid modes:
    // add those nearest to contact (largest d) until they do.
    forced.assign(p.size(), false);
    if (!coarse.holds(active))
    {
      std::vector<unsigned int> order(n);
      for (unsigned int q = 0; q < n; ++q)
        order[q] = q;
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int a, const unsigned int b)
                       { return d[a] > d[b]; });
      for (const unsigned int q : order)
        if (!active[q])
        {
          active[q] = true;
          forced[q] = true;
          if (coarse.holds(active))
            break;
        }
    }
    n_changed = 0;
    for (unsigned int q = 0; q < active.size(); ++q)
      n_changed += last_active.empty() || (active[q] != last_active[q]);
    // A node that slips the other way changes too.
    if (last_slip_directions.size() == slip_directions.size())
      for (unsigned int i = 0; i < slip_directions.size(); ++i)
        n_changed += slip_directions[i] != last_slip_directions[i];
    return active;
  }

  double
  DDNewtonSolver::fixed_value(const unsigned int q, const PointVector &x) const
  {
    if (!interface.is_tangential(q))
      return 0.;
    const unsigned int i = interface.node(q);
    return slip_coupling[i] != 0 ? slip_coupling[i] * x[i] : slip_values[i];
  }

} // namespace ddcontact
