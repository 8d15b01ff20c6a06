#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ddcontact/solvers/monolithic_solver.h>

#include <algorithm>

// The monolithic system on a mesh: one numbering of all bodies' dofs,
// their constraints, the nodes' penetration functionals and the sparsity.
namespace ddcontact
{
  double
  MonolithicContactSolver::Penetration::operator()(
    const Vector<double> &u) const
  {
    double gu = 0;
    for (unsigned int j = 0; j < dofs.size(); ++j)
      gu += g[j] * u(dofs[j]);
    return gu - f;
  }

  double
  MonolithicContactSolver::Penetration::slip(const Vector<double> &u) const
  {
    double hu = 0;
    for (unsigned int j = 0; j < h.size(); ++j)
      hu += h[j] * u(dofs[j]);
    return hu;
  }

  void
  MonolithicContactSolver::setup_constraints()
  {
    const auto &bodies = problem.get_bodies();
    // One global numbering: the bodies' dofs one after another.
    offset.assign(bodies.size() + 1, 0);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      offset[b + 1] = offset[b] + bodies[b]->n_dofs();

    // The bodies' constraints (hanging nodes, Dirichlet data), shifted.
    constraints.clear();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (const auto &line : bodies[b]->get_constraints().get_lines())
      {
        constraints.add_line(line.index + offset[b]);
        for (const auto &[column, weight] : line.entries)
          constraints.add_entry(
            line.index + offset[b], column + offset[b], weight);
        constraints.set_inhomogeneity(line.index + offset[b],
                                      line.inhomogeneity);
      }
    constraints.close();
  }

  void
  MonolithicContactSolver::setup_penetrations()
  {
    // d_i = (1/m_i) sum_q w_q psi_i(x_q) d_q over the points the unknown
    // spreads to, d_q = u_1n + u_2n - f~_n: the normal shape values of both
    // cells (on the points a single point with psi = 1 and m_i = w_q, whose
    // coefficients are then the shape values as they are).
    interface.reinit();
    const auto &pairs = problem.get_pairs();
    penetrations.assign(interface.size(), Penetration());
    for (unsigned int i = 0; i < interface.size(); ++i)
    {
      auto &d  = penetrations[i];
      d.weight = interface.weight(i);
      d.theta  = interface.penalty(i);
      d.scale  = interface.complementarity_scale(i);
      // The normal (v) and, with friction, tangential (w) coefficient of
      // a dof.
      const auto add =
        [&](const types::global_dof_index dof, const double v, const double w)
      {
        const auto it = std::find(d.dofs.begin(), d.dofs.end(), dof);
        if (it == d.dofs.end())
        {
          d.dofs.push_back(dof);
          d.g.push_back(v);
          if (friction)
            d.h.push_back(w);
        }
        else
        {
          d.g[it - d.dofs.begin()] += v;
          if (friction)
            d.h[it - d.dofs.begin()] += w;
        }
      };
      for (const auto &share : interface.shares(i))
      {
        const auto &pair = *pairs[share.pair];
        const auto &p    = pair.points()[share.point];
        // The node's test function phi_i (ContactInterface).
        const double       s         = share.phi * p.JxW / d.weight;
        const unsigned int b1        = problem.body_index(pair.get_body_1());
        const unsigned int b2        = problem.body_index(pair.get_body_2());
        const bool         with_slip = friction && pair.has_friction();
        for (unsigned int j = 0; j < p.a.size(); ++j)
          add(
            p.dofs_1[j] + offset[b1], s * p.a[j], with_slip ? s * p.at[j] : 0.);
        for (unsigned int j = 0; j < p.b.size(); ++j)
          add(
            p.dofs_2[j] + offset[b2], s * p.b[j], with_slip ? s * p.bt[j] : 0.);
        // lambda + g/theta = (f_n + theta lambda - u_1n - u_2n)/theta: the
        // multipliers shift the gap (not on the nodes, ContactLaw).
        d.f += s * problem.law(share.pair).shifted_gap(share.point);
      }
      // The state at the end of the last load step (the same nodes).
      d.s_old = history.old_slip(i);
      d.t_old = history.old_traction(i);
    }
  }

  void
  MonolithicContactSolver::setup_sparsity()
  {
    const auto &bodies = problem.get_bodies();
    const auto  n      = offset.back();
    // On the nodes the pressures follow the displacements.
    const unsigned int n_multipliers =
      on_nodes ? (friction ? 2 : 1) * penetrations.size() : 0;
    DynamicSparsityPattern dsp(n + n_multipliers);
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      const auto &K = bodies[b]->get_stiffness_matrix();
      for (types::global_dof_index i = 0; i < K.m(); ++i)
        for (auto it = K.begin(i); it != K.end(i); ++it)
          dsp.add(i + offset[b], it->column() + offset[b]);
    }
    for (unsigned int i = 0; i < penetrations.size(); ++i)
    {
      auto dofs = penetrations[i].dofs;
      if (on_nodes)
        dofs.push_back(n + i);
      if (friction)
        dofs.push_back(n + penetrations.size() + i);
      constraints.add_entries_local_to_global(dofs, dsp, false);
    }
    sparsity.copy_from(dsp);
  }
} // namespace ddcontact
