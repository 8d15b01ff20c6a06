#include <deal.II/lac/sparse_direct.h>

#include <ddcontact/iteration_errors.h>
#include <ddcontact/solvers/monolithic_solver.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  namespace
  {
    /** Body @p b's part of the flattened displacement @p u. */
    template <typename VectorType>
    VectorType
    body_part(const Vector<double>                       &u,
              const std::vector<types::global_dof_index> &offset,
              const unsigned int                          b)
    {
      VectorType u_b(offset[b + 1] - offset[b]);
      std::copy(u.begin() + offset[b], u.begin() + offset[b + 1], u_b.begin());
      return u_b;
    }
  } // namespace

  MonolithicContactSolver::MonolithicContactSolver(
    const ContactSolverParameters       &parameters,
    const std::vector<ElasticBody<2> *> &bodies,
    const std::vector<ContactPair *>    &pairs,
    const BodyDistribution              &distribution,
    ConditionalOStream                  &pcout)
    : ContactSolver(parameters, bodies, pairs, distribution, pcout)
    , on_nodes(parameters.pressure_on_nodes)
    , friction(parameters.friction)
    , max_iterations(parameters.monolithic.max_newton_iterations)
    , interface(this->problem,
                on_nodes,
                parameters.exact_contact(),
                false, // its own tangential rows
                parameters.dual_multipliers)
  {
  }

  void
  MonolithicContactSolver::initialize()
  {
    ContactSolver::initialize();
    history.clear();
    warm_start = false;
    set_initial_guess();
  }

  void
  MonolithicContactSolver::reinit_after_refinement()
  {
    ContactSolver::reinit_after_refinement();
    // The load-step history moves to the new nodes.
    interface.reinit();
    history.transfer(problem, interface);
    warm_start = false;
  }

  void
  MonolithicContactSolver::start_load_step()
  {
    // The last solve's slips and tractions.
    history.start_load_step(problem, interface);
    ContactSolver::start_load_step();
    // The multipliers of the last step start the Newton method: its
    // active set is that of the last step where the data change little.
    warm_start = true;
  }

  bool
  MonolithicContactSolver::step()
  {
    n_newton_steps += solve_newton();
    // The converged u solves (20) loaded by its own pressure: that is the
    // body problem the FEM-BEM estimator compares with the BEM.
    adopt_current_iterate();
    IterationRecord record;
    record.iteration = records.size() + 1;
    record.residual  = final_residual;
    measure_contact(problem.current_iterate(), record);
    record.time = timer.wall_time();
    add_record(record);
    return true;
  }

  void
  MonolithicContactSolver::stop_at_iteration_limit(const std::string &) const
  {
    // The caller's label names a DD loop; here each step is a whole solve.
    throw NotConvergedError("the Uzawa loop of the monolithic solver "
                            "reached Contact solver/Max iterations (" +
                            std::to_string(parameters.max_iterations) +
                            " solves); raise it, or Contact "
                            "solver/Uzawa/Tolerance");
  }

  SolverCounts
  MonolithicContactSolver::counts() const
  {
    SolverCounts c;
    c.newton_steps = n_newton_steps;
    return c;
  }

  PointVector
  MonolithicContactSolver::penalty_pressure(const Vector<double> &u) const
  {
    PointVector p(penetrations.size());
    for (unsigned int i = 0; i < p.size(); ++i)
      p[i] = std::max(0., penetrations[i](u)) / penetrations[i].theta;
    return p;
  }

  NodalContactLaw::Trial
  MonolithicContactSolver::trial(const unsigned int    i,
                                 const Vector<double> &u,
                                 const PointVector    &p) const
  {
    const auto            &d = penetrations[i];
    NodalContactLaw::Trial x;
    x.p     = p[i];
    x.d     = d(u);
    x.theta = d.theta;
    x.c     = d.scale;
    if (friction)
    {
      // r = ds - theta (t - t_old): the slip increment beyond the law's
      // elastic slip.
      x.t   = p[penetrations.size() + i];
      x.r   = d.slip(u) - d.s_old - d.theta * (x.t - d.t_old);
      x.c_t = d.scale;
    }
    return x;
  }

  std::vector<NodeStatus>
  MonolithicContactSolver::active_set(const Vector<double> &u,
                                      const PointVector    &p,
                                      const bool            stick) const
  {
    const auto             &law = interface.law();
    std::vector<NodeStatus> active(penetrations.size());
    for (unsigned int i = 0; i < active.size(); ++i)
      active[i] = stick ? law.prescribed_status(i, trial(i, u, p), 0)
                        : law.status(i, trial(i, u, p));
    return active;
  }

  void
  MonolithicContactSolver::add_node_rows(const unsigned int             i,
                                         const std::vector<NodeStatus> &active,
                                         const Vector<double>          &u,
                                         const PointVector             &p,
                                         SparseMatrix<double>          &matrix,
                                         Vector<double> &rhs) const
  {
    const auto         n    = offset.back();
    const unsigned int n_t  = penetrations.size(); // offset of the t_i
    const auto        &d    = penetrations[i];
    const unsigned int k    = d.g.size();
    auto               dofs = d.dofs;
    // Row and column of p_i: m g^T u - m theta p = m f, or p_i = 0.
    dofs.push_back(n + i);
    const unsigned int size = friction ? k + 2 : k + 1;
    FullMatrix<double> local_matrix(size, size);
    Vector<double>     local_rhs(size);
    if (active[i].closed())
    {
      for (unsigned int j = 0; j < k; ++j)
        local_matrix(j, k) = local_matrix(k, j) = d.weight * d.g[j];
      local_matrix(k, k) = -d.weight * d.theta;
      local_rhs(k)       = d.weight * d.f;
    }
    else
      local_matrix(k, k) = 1;
    if (friction)
    {
      // Column of t_i (the force m t h) and its row: stick
      // m h^T u - m theta t = m (s_old - theta t_old), slip t = sigma g
      // (Tresca) or t - sigma mu p = 0 (Coulomb), else t = 0.
      const unsigned int kt = k + 1;
      dofs.push_back(n + n_t + i);
      for (unsigned int j = 0; j < d.h.size(); ++j)
        local_matrix(j, kt) = d.weight * d.h[j];
      if (active[i].state == NodeState::stick)
      {
        for (unsigned int j = 0; j < d.h.size(); ++j)
          local_matrix(kt, j) = d.weight * d.h[j];
        local_matrix(kt, kt) = -d.weight * d.theta;
        local_rhs(kt)        = d.weight * (d.s_old - d.theta * d.t_old);
      }
      else
      {
        // t = value + coupling p (Coulomb linearised: t = sigma mu p).
        const auto slip = interface.law().slip_equation(
          i, active[i], interface.law().bound(i, trial(i, u, p)), true);
        local_matrix(kt, kt) = 1;
        local_matrix(kt, k)  = -slip.coupling;
        local_rhs(kt)        = slip.value;
      }
    }
    constraints.distribute_local_to_global(
      local_matrix, local_rhs, dofs, matrix, rhs);
  }

  void
  MonolithicContactSolver::solve_linearised(
    const std::vector<NodeStatus> &active,
    Vector<double>                &u,
    PointVector                   &p) const
  {
    const auto          &bodies = problem.get_bodies();
    const auto           n      = offset.back();
    const unsigned int   n_p    = on_nodes ? p.size() : 0;
    SparseMatrix<double> matrix(sparsity);
    Vector<double>       rhs(n + n_p);
    // blockdiag(K_a) and the bodies' condensed loads (12). A nonlinear
    // body linearized at u: K_T u_new = K_T u + l_a - F(u), the Newton step
    // written for the displacement itself.
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      const bool linear = bodies[b]->get_material_law().is_linear();
      if (!linear)
        bodies[b]->linearize_at(body_part<BodyVector>(u, offset, b));
      const auto &K = bodies[b]->get_stiffness_matrix();
      for (types::global_dof_index i = 0; i < K.m(); ++i)
        for (auto it = K.begin(i); it != K.end(i); ++it)
          matrix.add(i + offset[b], it->column() + offset[b], it->value());
      const auto &L = bodies[b]->get_load_vector();
      std::copy(L.begin(), L.end(), rhs.begin() + offset[b]);
      if (!linear)
      {
        Vector<double> K_u(K.m());
        K.vmult(K_u, body_part<Vector<double>>(u, offset, b));
        for (types::global_dof_index i = 0; i < K.m(); ++i)
          rhs(i + offset[b]) += K_u(i);
      }
    }
    for (unsigned int i = 0; i < penetrations.size(); ++i)
    {
      const auto        &d    = penetrations[i];
      const unsigned int k    = d.g.size();
      auto               dofs = d.dofs;
      if (on_nodes)
        add_node_rows(i, active, u, p, matrix, rhs);
      else if (active[i].closed())
      {
        // (m/theta) g g^T and (m/theta) f g (f shifted by theta lambda).
        FullMatrix<double> local_matrix(k, k);
        Vector<double>     local_rhs(k);
        const double       w = d.weight / d.theta;
        for (unsigned int j = 0; j < k; ++j)
        {
          local_rhs(j) = w * d.f * d.g[j];
          for (unsigned int l = 0; l < k; ++l)
            local_matrix(j, l) = w * d.g[j] * d.g[l];
        }
        constraints.distribute_local_to_global(
          local_matrix, local_rhs, dofs, matrix, rhs);
      }
    }
    SparseDirectUMFPACK solver;
    solver.initialize(matrix);
    Vector<double> solution(n + n_p);
    solver.vmult(solution, rhs);
    std::copy(solution.begin(), solution.begin() + n, u.begin());
    constraints.distribute(u);
    const auto finite = [](const double v) { return std::isfinite(v); };
    if (!std::all_of(u.begin(), u.end(), finite) ||
        !std::all_of(solution.begin() + n, solution.end(), finite))
      throw DivergenceError("the monolithic Newton solver produced a "
                            "non-finite displacement");
    if (on_nodes)
      std::copy(solution.begin() + n, solution.end(), p.begin());
    else
      p = penalty_pressure(u);
  }

  double
  MonolithicContactSolver::residual_norm(const Vector<double> &u,
                                         const PointVector    &p) const
  {
    const auto    &bodies = problem.get_bodies();
    Vector<double> r(u.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      Vector<double> r_b(bodies[b]->n_dofs());
      if (bodies[b]->get_material_law().is_linear())
      {
        bodies[b]->get_stiffness_matrix().vmult(
          r_b, body_part<Vector<double>>(u, offset, b));
        r_b -= bodies[b]->get_load_vector();
      }
      else
      {
        // F(u) - l_a of the linearization at u (which sets the trial state).
        bodies[b]->linearize_at(body_part<BodyVector>(u, offset, b));
        r_b = bodies[b]->get_load_vector();
        r_b *= -1.;
      }
      std::copy(r_b.begin(), r_b.end(), r.begin() + offset[b]);
    }
    double sum = 0;
    for (unsigned int i = 0; i < penetrations.size(); ++i)
    {
      const auto    &d = penetrations[i];
      const auto     x = trial(i, u, p);
      Vector<double> local(d.g.size());
      for (unsigned int j = 0; j < d.g.size(); ++j)
        local(j) = d.weight * p[i] * d.g[j];
      // The friction force m t h, and the law: t the trial traction cut
      // to the bound (0 where the node is open).
      if (friction)
      {
        for (unsigned int j = 0; j < d.h.size(); ++j)
          local(j) += d.weight * x.t * d.h[j];
        const double law = interface.law().tangential_residual(i, x);
        sum += d.weight * law * d.weight * law;
      }
      constraints.distribute_local_to_global(local, d.dofs, r);
      // The normal law, as a nodal force: (m / c) min(c p, theta p - d).
      const double law =
        d.weight * NodalContactLaw::normal_residual(x) / d.scale;
      sum += law * law;
    }
    constraints.set_zero(r);
    return std::sqrt(r.norm_sqr() + sum);
  }

  double
  MonolithicContactSolver::damping(const Vector<double> &u,
                                   const PointVector    &p,
                                   const Vector<double> &u_new,
                                   const PointVector    &p_new) const
  {
    const double r = residual_norm(u, p);
    for (double tau = 1; tau > 1e-3; tau /= 2)
    {
      Vector<double> u_tau(u);
      u_tau.sadd(1 - tau, tau, u_new);
      PointVector p_tau(p);
      for (unsigned int i = 0; i < p.size(); ++i)
        p_tau[i] = (1 - tau) * p[i] + tau * p_new[i];
      if (!on_nodes)
        p_tau = penalty_pressure(u_tau);
      if (residual_norm(u_tau, p_tau) < (1 - 1e-4 * tau) * r)
        return tau;
    }
    return 1;
  }

  void
  MonolithicContactSolver::print_active_set(
    const unsigned int iteration, const std::vector<NodeStatus> &active) const
  {
    pcout << "  Newton " << iteration << ": "
          << std::count_if(active.begin(),
                           active.end(),
                           [](const NodeStatus &s) { return s.closed(); })
          << (on_nodes ? " active nodes" : " active contact points");
    if (friction)
      pcout << " ("
            << std::count_if(active.begin(),
                             active.end(),
                             [](const NodeStatus &s)
                             { return s.direction != 0; })
            << " slipping)";
    pcout << std::endl;
  }

  void
  MonolithicContactSolver::stop_unsettled(const bool cycled) const
  {
    const std::string unsettled =
      "the monolithic Newton solver did not settle its active set in " +
      std::to_string(max_iterations) + " iterations";
    const std::string tresca = tresca_lift_off_note(problem.get_pairs());
    // No active set met twice: still moving, stopped by the limit alone
    // (with Tresca, more likely nodes lifted off by g: tresca says so).
    if (!cycled)
      throw NotConvergedError(
        unsettled + " (no active set repeated)" +
        (tresca.empty()
           ? "; raise Contact solver/Monolithic/Max Newton iterations"
           : tresca));
    throw DivergenceError(
      unsettled +
      " (the active set cycles when theta is small against the compliance "
      "of the contact zone, e.g. a slender body); raise the contact pairs' "
      "Penalty (c) or Contact solver/Monolithic/Max Newton iterations" +
      (on_nodes ? std::string()
                : ", or set Contact solver/Contact pressure = nodes") +
      tresca);
  }

  unsigned int
  MonolithicContactSolver::solve_newton()
  {
    // On the nodes the pressure is the solver's, and the gap unshifted.
    problem.set_pressure_from_solver(on_nodes);
    const auto &bodies = problem.get_bodies();
    setup_constraints();
    setup_penetrations();
    setup_sparsity();

    // Current state, flattened; on the nodes no pressure yet.
    Vector<double> u(offset.back());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (types::global_dof_index i = 0; i < bodies[b]->n_dofs(); ++i)
        u(i + offset[b]) = bodies[b]->get_solution()(i);
    PointVector p =
      on_nodes ? PointVector((friction ? 2 : 1) * penetrations.size(), 0.)
               : penalty_pressure(u);
    if (on_nodes && warm_start && last_multipliers.size() == p.size())
      p = last_multipliers;

    // The active sets met so far: one met again without settling is a
    // cycle, and damping starts.
    std::vector<std::vector<NodeStatus>> seen;
    bool                                 full_step = false, damped = false;
    unsigned int                         iteration = 0;
    // The Newton residual of the zero iterate: the reference of the
    // history's residual, and with nonlinear bodies of the stopping test.
    const bool   nonlinear = problem.has_nonlinear_bodies();
    const double zero_residual =
      residual_norm(Vector<double>(u.size()), PointVector(p.size(), 0.));
    for (; iteration < max_iterations; ++iteration)
    {
      const auto active = active_set(u, p, iteration == 0);
      print_active_set(iteration, active);
      // Settled: (u, p) solves the linear system of its own active set;
      // with nonlinear bodies once the residual is below the tolerance too.
      const bool settled = full_step && active == seen.back();
      if (settled && (!nonlinear || residual_norm(u, p) <=
                                      parameters.tolerance * zero_residual))
        break;
      // A cycle: an active set met before, not the last one (which
      // nonlinear bodies keep while their laws iterate).
      damped =
        damped || ((!nonlinear || !settled) &&
                   std::find(seen.begin(), seen.end(), active) != seen.end());
      seen.push_back(active);

      Vector<double> u_new(u);
      PointVector    p_new(p);
      solve_linearised(active, u_new, p_new);
      const double tau = damped ? damping(u, p, u_new, p_new) : 1.;
      full_step        = (tau == 1);
      if (full_step)
      {
        u = u_new;
        p = p_new;
        continue;
      }
      pcout << "  Newton " << iteration << ": the active set cycles, step "
            << tau << std::endl;
      u.sadd(1 - tau, tau, u_new);
      for (unsigned int i = 0; i < p.size(); ++i)
        p[i] = (1 - tau) * p[i] + tau * p_new[i];
      if (!on_nodes)
        p = penalty_pressure(u);
    }
    // The bodies get the last iterate also when the active set did not
    // settle, so that the output of the failed run shows it (not zero).
    store_iterate(u, p);
    // The Newton residual relative to that of the zero iterate, for the
    // history (round-off once the active set has settled).
    final_residual =
      residual_norm(u, p) / (zero_residual > 0 ? zero_residual : 1.);
    if (iteration == max_iterations)
      stop_unsettled(damped);
    return iteration;
  }

  void
  MonolithicContactSolver::store_iterate(const Vector<double> &u,
                                         const PointVector    &p)
  {
    const auto &bodies = problem.get_bodies();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (types::global_dof_index i = 0; i < bodies[b]->n_dofs(); ++i)
        bodies[b]->get_solution()(i) = u(i + offset[b]);
    if (!on_nodes)
      return;
    last_multipliers = p;
    // The pressure p(x) = sum_i p_i psi_i(x) at the points, and its peak.
    const unsigned int n_nodes = penetrations.size();
    const PointVector  pressure(p.begin(), p.begin() + n_nodes);
    const auto         sigma_n = interface.reported_field(pressure, -1.);
    const auto         peaks   = interface.peak_pressures(pressure);
    for (unsigned int k = 0; k < sigma_n.size(); ++k)
    {
      problem.law(k).set_contact_pressure(sigma_n[k]);
      published[k].peak_nodal_pressure = peaks[k];
    }
    publish_nodal_law(interface, p, problem.current_iterate());
    if (!friction)
      return;

    // The averaged slips of the nodes, for the laws' results and the
    // history.
    PointVector       slips(n_nodes);
    std::vector<bool> sticking(n_nodes);
    const auto        states = active_set(u, p);
    for (unsigned int i = 0; i < n_nodes; ++i)
    {
      slips[i]    = penetrations[i].slip(u);
      sticking[i] = states[i].state == NodeState::stick;
    }
    history.publish(problem,
                    interface,
                    pressure,
                    PointVector(p.begin() + n_nodes, p.end()),
                    slips,
                    sticking,
                    sigma_n,
                    published);
  }
} // namespace ddcontact
