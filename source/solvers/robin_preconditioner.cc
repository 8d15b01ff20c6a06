#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ddcontact/solvers/robin_preconditioner.h>

namespace ddcontact
{
  RobinPreconditioner::RobinPreconditioner(const ContactProblem &problem)
    : problem(problem)
  {
  }

  std::pair<const std::vector<types::global_dof_index> &,
            const std::vector<double> &>
  RobinPreconditioner::coefficients(const Side        &side,
                                    const unsigned int q) const
  {
    const auto &point = problem.get_pairs()[side.pair]->points()[q];
    if (side.body_1)
      return {point.load_dofs_1, point.load_1};
    return {point.load_dofs_2, point.load_2};
  }

  void
  RobinPreconditioner::setup(const ContactInterface &contact_interface)
  {
    interface          = &contact_interface;
    const auto &bodies = problem.get_bodies();
    const auto &pairs  = problem.get_pairs();
    sides.assign(bodies.size(), {});
    unsigned int first = 0;
    for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const double c_1 =
        ContactInterface::surface_compliance(pairs[k]->get_body_1());
      const double c_2 =
        ContactInterface::surface_compliance(pairs[k]->get_body_2());
      const double alpha = c_1 / (c_1 + c_2);
      sides[problem.body_index(pairs[k]->get_body_1())].push_back(
        {k, first, true, alpha});
      sides[problem.body_index(pairs[k]->get_body_2())].push_back(
        {k, first, false, 1. - alpha});
      first += pairs[k]->points().size();
    }

    for (const auto *body : bodies)
      if (body->is_solved_distributed())
        throw InputError("Domain decomposition/Solver = dd-newton: body '" +
                         body->name() +
                         "' is solved by a group of processes, whose "
                         "distributed matrix the preconditioner cannot "
                         "factorize; use at most one process per body "
                         "(Parallel/Body owners)");
    factors.clear();
    factors.resize(bodies.size());
    springs.clear();
    n_factorizations = 0;
    problem.get_distribution().for_each_body(
      [&](const unsigned int b) { make_pattern(b); }, true);
  }

  void
  RobinPreconditioner::update(const std::vector<bool> &active)
  {
    if (active == springs)
      return;
    springs = active;
    problem.get_distribution().for_each_body(
      [&](const unsigned int b) { factorize(b); }, true);
    ++n_factorizations;
  }

  void
  RobinPreconditioner::make_pattern(const unsigned int b)
  {
    // The stiffness plus the springs c_q c_q^T of the body's contact
    // points, on the masters of their dofs.
    const auto            &K = problem.get_bodies()[b]->get_stiffness_matrix();
    DynamicSparsityPattern dsp(K.m());
    for (types::global_dof_index i = 0; i < K.m(); ++i)
      for (auto it = K.begin(i); it != K.end(i); ++it)
        dsp.add(i, it->column());
    for_each_point(b,
                   nullptr,
                   [&](const Side &,
                       const auto &,
                       unsigned int,
                       const auto &dofs,
                       const auto &)
                   {
                     for (const auto i : dofs)
                       for (const auto j : dofs)
                         dsp.add(i, j);
                   });
    factors[b] = std::make_unique<BodyFactor>();
    factors[b]->sparsity.copy_from(dsp);
  }

  void
  RobinPreconditioner::factorize(const unsigned int b)
  {
    const auto &K      = problem.get_bodies()[b]->get_stiffness_matrix();
    auto       &factor = *factors[b];
    factor.matrix.reinit(factor.sparsity);
    for (types::global_dof_index i = 0; i < K.m(); ++i)
      for (auto it = K.begin(i); it != K.end(i); ++it)
        factor.matrix.add(i, it->column(), it->value());
    // Springs w_q / (alpha theta_q) at the active points.
    for_each_point(
      b,
      &springs,
      [&](const Side        &side,
          const auto        &contact_point,
          const unsigned int point,
          const auto        &dofs,
          const auto        &c)
      {
        const double spring =
          contact_point.JxW / (side.alpha * interface->penalty(point));
        for (unsigned int i = 0; i < dofs.size(); ++i)
          for (unsigned int j = 0; j < dofs.size(); ++j)
            factor.matrix.add(dofs[i], dofs[j], spring * c[i] * c[j]);
      });
    factor.direct.initialize(factor.matrix);
  }

  void
  RobinPreconditioner::vmult(PointVector             &z,
                             const PointVector       &r,
                             const std::vector<bool> &active) const
  {
    Assert(active == springs, ExcMessage("update() must be called first"));
    const auto &bodies = problem.get_bodies();

    // C_b^T W Theta^{-1} r on every body, r restricted to the active set.
    std::vector<Vector<double>> rhs(bodies.size()), v(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      rhs[b].reinit(bodies[b]->n_dofs());
      for_each_point(b,
                     &active,
                     [&](const Side &,
                         const auto        &contact_point,
                         const unsigned int point,
                         const auto        &dofs,
                         const auto        &c)
                     {
                       const double s = contact_point.JxW * r[point] /
                                        interface->penalty(point);
                       for (unsigned int i = 0; i < dofs.size(); ++i)
                         rhs[b](dofs[i]) += s * c[i];
                     });
    }
    problem.get_distribution().solve_and_share(
      [&](const unsigned int b)
      {
        v[b].reinit(bodies[b]->n_dofs());
        factors[b]->direct.vmult(v[b], rhs[b]);
      },
      v);
    ++applications;

    // z = Theta^{-1} (r - sum_b C_b v_b) on the active set.
    z.assign(r.size(), 0.);
    for (unsigned int q = 0; q < r.size(); ++q)
      if (active[q])
        z[q] = r[q];
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for_each_point(b,
                     &active,
                     [&](const Side &,
                         const auto &,
                         const unsigned int point,
                         const auto        &dofs,
                         const auto        &c)
                     {
                       for (unsigned int i = 0; i < dofs.size(); ++i)
                         z[point] -= c[i] * v[b](dofs[i]);
                     });
    for (unsigned int q = 0; q < r.size(); ++q)
      z[q] /= interface->penalty(q);
  }
} // namespace ddcontact
