#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ddcontact/solvers/robin_preconditioner.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace ddcontact
{
  RobinPreconditioner::RobinPreconditioner(const ContactProblem &problem)
    : problem(problem)
  {
  }

  double
  RobinPreconditioner::penalty(const unsigned int i) const
  {
    // Exact contact has theta = 0: the springs take 1e-3 of the compliance.
    return (interface->penalty(i) > 0)
             ? interface->penalty(i)
             : 1e-3 * interface->element_compliance(i);
  }

  RobinPreconditioner::Row
  RobinPreconditioner::make_row(const unsigned int i,
                                const bool         body_1,
                                const double       alpha,
                                const double       beta) const
  {
    const auto  &shares     = interface->shares(i);
    const auto  &pair       = *problem.get_pairs()[shares[0].pair];
    const double m          = interface->weight(i);
    const bool   tangential = interface->is_tangential(i);
    Row          row;
    row.unknown = i;
    row.alpha   = alpha;
    row.beta    = beta;
    set_penalty(row);

    std::map<types::global_dof_index, double> merged;
    for (const auto &share : shares)
    {
      const auto &point = pair.points()[share.point];
      const auto &dofs  = body_1 ? point.load_dofs_1 : point.load_dofs_2;
      // A tangential multiplier loads and reads along tau as a pressure
      // does along n (the same load and dofs, ContactPoint).
      const auto &c = tangential ? (body_1 ? point.load_t1 : point.load_t2)
                                 : (body_1 ? point.load_1 : point.load_2);
      // phi w / m, the node's test function as in S (ContactInterface):
      // exactly 1 for a point's own unknown.
      const double factor = (share.phi * point.JxW) / m;
      if (shares.size() == 1)
      {
        row.dofs = dofs;
        for (const double v : c)
          row.c.push_back(factor * v);
        return row;
      }
      for (unsigned int j = 0; j < dofs.size(); ++j)
        merged[dofs[j]] += factor * c[j];
    }
    for (const auto &[dof, v] : merged)
    {
      row.dofs.push_back(dof);
      row.c.push_back(v);
    }
    return row;
  }

  void
  RobinPreconditioner::set_penalty(Row &row) const
  {
    const double m     = interface->weight(row.unknown);
    const double theta = penalty(row.unknown);
    row.spring         = m / (row.alpha * theta);
    // rhs = C_b^T M (alpha Theta)^{-1} beta r: beta = alpha with both
    // bodies (then exactly m / theta), 1 with body 1 alone.
    row.load = m / theta * (row.beta / row.alpha);
  }

  void
  RobinPreconditioner::update_penalties()
  {
    for (auto &body_rows : rows)
      for (auto &row : body_rows)
        set_penalty(row);
    springs.clear();
  }

  bool
  RobinPreconditioner::body_2_determines_nodes(const unsigned int k) const
  {
    // A vertex of S_1 inside a face of S_2 is a node whose hat function
    // body 2's trace does not contain (body 2 coarser there): the points
    // nearest to it on its two faces of S_1 then lie on the same face of
    // S_2, with the same dofs. A vertex shared with S_2 separates two faces
    // of S_2; if all do, body 2's trace contains that of body 1.
    const auto &pair = *problem.get_pairs()[k];
    for (unsigned int i = 0; i < interface->size(); ++i)
    {
      const auto &shares = interface->shares(i);
      if (shares[0].pair != k)
        continue;
      // Per face of S_1 at the node, the point nearest to it.
      std::map<unsigned int, std::pair<double, unsigned int>> nearest;
      for (const auto &share : shares)
      {
        const unsigned int face = pair.points()[share.point].face;
        auto [it, inserted] =
          nearest.emplace(face, std::make_pair(share.psi, share.point));
        if (!inserted && share.psi > it->second.first)
          it->second = {share.psi, share.point};
      }
      if (nearest.size() < 2)
        continue;
      std::vector<std::vector<types::global_dof_index>> dofs;
      for (const auto &[face, point] : nearest)
      {
        auto d = pair.points()[point.second].load_dofs_2;
        if (d.empty())
          return false; // shapes of body 2 not held here
        std::sort(d.begin(), d.end());
        dofs.push_back(std::move(d));
      }
      if (std::adjacent_find(dofs.begin(), dofs.end()) != dofs.end())
        return false;
    }
    return true;
  }

  void
  RobinPreconditioner::setup(const ContactInterface &contact_interface)
  {
    interface          = &contact_interface;
    const auto &bodies = problem.get_bodies();
    const auto &pairs  = problem.get_pairs();

    // Body 2 takes its share of a pair wherever its trace determines the
    // unknowns: always on the points, for nodal multipliers when the
    // vertices of S_1 are vertices of S_2 (decided alike on every process:
    // one that does not hold body 2's shapes says no).
    both_bodies.assign(pairs.size(), !interface->on_nodes());
    if (interface->on_nodes())
      for (unsigned int k = 0; k < pairs.size(); ++k)
        both_bodies[k] = Utilities::MPI::min(body_2_determines_nodes(k) ? 1 : 0,
                                             MPI_COMM_WORLD) == 1;

    rows.assign(bodies.size(), {});
    std::vector<std::tuple<unsigned int, unsigned int, double>> held;
    // With friction the tangential multipliers of the frictional pairs get
    // their rows too: springs along tau at the sticking nodes.
    for (unsigned int i = 0; i < interface->n_unknowns(); ++i)
    {
      if (interface->is_tangential(i) &&
          !interface->law().frictional(interface->node(i)))
        continue;
      const unsigned int k    = interface->shares(i)[0].pair;
      const auto        &pair = *pairs[k];
      const double       c_1 =
        ContactInterface::surface_compliance(pair.get_body_1());
      const double c_2 =
        ContactInterface::surface_compliance(pair.get_body_2());
      const double alpha = c_1 / (c_1 + c_2);
      const auto   b_1   = problem.body_index(pair.get_body_1());
      const auto   b_2   = problem.body_index(pair.get_body_2());
      // Every process keeps the rows of every body: z needs them all.
      if (both_bodies[k])
      {
        rows[b_1].push_back(make_row(i, true, alpha, alpha));
        rows[b_2].push_back(make_row(i, false, 1. - alpha, 1. - alpha));
      }
      else
      {
        rows[b_1].push_back(make_row(i, true, alpha, 1.));
        held.push_back({b_2, i, 1. - alpha});
      }
    }
    // Where body 2 does not precondition a pair (nodal multipliers, zones
    // that do not nest) but preconditions another pair as body 1, its zone
    // of this pair is held by springs at the active nodes (the stiff side
    // of the series).
    for (const auto &[b, i, alpha] : held)
      if (std::any_of(rows[b].begin(),
                      rows[b].end(),
                      [](const Row &row) { return row.preconditions; }))
      {
        Row row           = make_row(i, false, alpha, 1.);
        row.preconditions = false;
        rows[b].push_back(std::move(row));
      }
    factors.clear();
    factors.resize(bodies.size());
    springs.clear();
    n_factorizations = 0;
    problem.get_distribution().for_each_body(
      [&](const unsigned int b)
      {
        if (!rows[b].empty())
          make_pattern(b);
      },
      true);
  }

  void
  RobinPreconditioner::update(const std::vector<bool> &active)
  {
    // The factorization of a superset A' of A is kept while A' \ A is at
    // most a tenth of A: extra springs only stiffen the bodies, so
    // P = Theta^{-1} (I - C (K + C_A'^T M Theta^{-1} C_A')^{-1} C_A^T M
    // Theta^{-1}) on A stays symmetric positive definite, and differs from
    // (Theta + S_AA)^{-1} only near the few extra points. (The active set
    // of exact contact shrinks by a node at each end of the zone per
    // Newton step.)
    if (springs.size() == active.size())
    {
      bool         subset   = true;
      unsigned int n_active = 0, n_extra = 0;
      for (unsigned int i = 0; i < active.size(); ++i)
      {
        subset = subset && (springs[i] || !active[i]);
        n_active += active[i];
        n_extra += springs[i] && !active[i];
      }
      if (subset && 10 * n_extra <= n_active)
        return;
    }
    springs = active;
    problem.get_distribution().for_each_body(
      [&](const unsigned int b)
      {
        if (!rows[b].empty())
          factorize(b);
      },
      true);
    ++n_factorizations;
  }

  void
  RobinPreconditioner::make_pattern(const unsigned int b)
  {
    factors[b] = std::make_unique<BodyFactor>();
    // A body of a process group builds its pattern with each factorization
    // (factorize_with_springs()).
    if (problem.get_bodies()[b]->is_solved_distributed())
      return;
    // The stiffness plus the springs c_i c_i^T of the body's unknowns, on
    // the masters of their dofs.
    const auto            &K = problem.get_bodies()[b]->get_stiffness_matrix();
    DynamicSparsityPattern dsp(K.m());
    for (types::global_dof_index i = 0; i < K.m(); ++i)
      for (auto it = K.begin(i); it != K.end(i); ++it)
        dsp.add(i, it->column());
    for (const auto &row : rows[b])
      for (const auto i : row.dofs)
        for (const auto j : row.dofs)
          dsp.add(i, j);
    factors[b]->sparsity.copy_from(dsp);
  }

  void
  RobinPreconditioner::factorize(const unsigned int b)
  {
    auto &factor = *factors[b];
    if (problem.get_bodies()[b]->is_solved_distributed())
    {
      // Springs m_i / (alpha theta_i) at the active unknowns, MUMPS over
      // the body's group.
      std::vector<DofSprings> active_springs;
      for (const auto &row : rows[b])
        if (springs[row.unknown])
          active_springs.push_back({row.dofs, row.c, row.spring});
      factor.group.reset();
      factor.group =
        problem.get_bodies()[b]->factorize_with_springs(active_springs);
      return;
    }
    const auto &K = problem.get_bodies()[b]->get_stiffness_matrix();
    factor.matrix.reinit(factor.sparsity);
    for (types::global_dof_index i = 0; i < K.m(); ++i)
      for (auto it = K.begin(i); it != K.end(i); ++it)
        factor.matrix.add(i, it->column(), it->value());
    // Springs m_i / (alpha theta_i) at the active unknowns.
    for (const auto &row : rows[b])
      if (springs[row.unknown])
        for (unsigned int i = 0; i < row.dofs.size(); ++i)
          for (unsigned int j = 0; j < row.dofs.size(); ++j)
            factor.matrix.add(
              row.dofs[i], row.dofs[j], row.spring * row.c[i] * row.c[j]);
    factor.direct.initialize(factor.matrix);
  }

  void
  RobinPreconditioner::vmult(PointVector             &z,
                             const PointVector       &r,
                             const std::vector<bool> &active) const
  {
    Assert(active.size() == springs.size(),
           ExcMessage("update() must be called first"));
    const auto &bodies = problem.get_bodies();

    // C_b^T M (alpha Theta)^{-1} beta r on every body, r restricted to the
    // active set.
    ContactProblem::Iterate rhs(bodies.size()), v(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      bodies[b]->reinit_vector(rhs[b]);
      for (const auto &row : rows[b])
        if (row.preconditions && active[row.unknown])
        {
          const double s = row.load * r[row.unknown];
          for (unsigned int i = 0; i < row.dofs.size(); ++i)
            rhs[b](row.dofs[i]) += s * row.c[i];
        }
    }
    // Only the traces of v are read below.
    problem.get_distribution().solve_and_share_traces(
      [&](const unsigned int b)
      {
        // A body without rows (body 2 of exact contact) adds nothing.
        bodies[b]->reinit_vector(v[b]);
        if (rows[b].empty())
          return;
        if (factors[b]->group)
        {
          factors[b]->group->solve(rhs[b], v[b]);
          return;
        }
        // UMFPACK on this process, whose vectors are whole.
        Vector<double> x(bodies[b]->n_dofs()), y(bodies[b]->n_dofs());
        std::copy(rhs[b].begin(), rhs[b].end(), y.begin());
        factors[b]->direct.vmult(x, y);
        std::copy(x.begin(), x.end(), v[b].begin());
      },
      v,
      problem.trace_dofs());
    ++applications;

    // z = Theta^{-1} (r - sum_b C_b v_b) on the active set (sum_b beta_b =
    // 1), with the preconditioner's theta.
    z.assign(r.size(), 0.);
    for (unsigned int q = 0; q < r.size(); ++q)
      if (active[q])
        z[q] = r[q];
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (const auto &row : rows[b])
        if (row.preconditions && active[row.unknown])
          for (unsigned int i = 0; i < row.dofs.size(); ++i)
            z[row.unknown] -= row.c[i] * v[b](row.dofs[i]);
    for (unsigned int q = 0; q < r.size(); ++q)
      z[q] /= penalty(q);
  }
} // namespace ddcontact
