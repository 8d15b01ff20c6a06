#include <ddcontact/contact/contact_law.h>
#include <ddcontact/solvers/dd_newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** x += a y. */
    void
    add(PointVector &x, const double a, const PointVector &y)
    {
      for (unsigned int q = 0; q < x.size(); ++q)
        x[q] += a * y[q];
    }

    void
    add(ContactProblem::Iterate       &u,
        const double                   a,
        const ContactProblem::Iterate &v)
    {
      for (unsigned int b = 0; b < u.size(); ++b)
        u[b].add(a, v[b]);
    }

    /** x <- (1 - tau) x + tau y. */
    void
    blend(PointVector &x, const double tau, const PointVector &y)
    {
      for (unsigned int q = 0; q < x.size(); ++q)
        x[q] = (1 - tau) * x[q] + tau * y[q];
    }

    void
    blend(ContactProblem::Iterate       &u,
          const double                   tau,
          const ContactProblem::Iterate &v)
    {
      for (unsigned int b = 0; b < u.size(); ++b)
        u[b].sadd(1 - tau, tau, v[b]);
    }

    /** The continuation's stages: t = 1, 1e-2, 1e-4, ... (with 1, 0.1,
     * 0.01: 30 and 32 sets at paper refinements 4 and 5, against 24 and
     * 25; the stage t = 0.1 costs more steps than it saves). */
    constexpr double continuation_factor = 1e-2;

    /** Penalty continuation only where a pair's overlap covers at least
     * this many unknowns (paper scene: 75 at refinement 2 took 19 sets
     * without and 23 with it, 150 at refinement 3 35 and 33). */
    constexpr unsigned int min_continuation_unknowns = 100;

    /** The relative accuracy of the pressure that the stopping test asks
     * on the points (stopping_tolerance()). */
    constexpr double pressure_accuracy = 1e-3;

    /** The Newton iteration stops after at most this many CG iterations
     * per step (a safeguard; the counts are tens). */
    constexpr unsigned int max_cg_iterations = 500;

    /** GMRES (Coulomb linearization = newton) keeps at most this many
     * directions, each with the bodies' response: the step goes on with
     * what they give (the counts are a few per step). */
    constexpr unsigned int max_gmres_directions = 50;
  } // namespace

  void
  DDNewtonSolver::check_scene(const ContactSolverParameters       &parameters,
                              const std::vector<ElasticBody<2> *> &bodies)
  {
    if (parameters.friction)
      refuse_floating_bodies(bodies,
                             ", and dd-newton solves floating bodies without "
                             "friction only; hold the body by a Dirichlet "
                             "condition, or set Friction = none on its "
                             "contact pairs");
  }

  void
  DDNewtonSolver::initialize()
  {
    problem.set_pressure_from_solver(parameters.multipliers_on_nodes());
    ContactSolver::initialize();
    interface.set_continuation(0.);
    interface.reinit();
    interface.set_reference_lengths({});
    continuation_pending = parameters.dd_newton.penalty_continuation;
    p.assign(interface.n_unknowns(), 0.);
    history.clear();
    step_slip_directions.clear();
    mesh_ready = false;
    setup_mesh();
  }

  void
  DDNewtonSolver::start_continuation()
  {
    // theta_ref over the length of the overlap where it is shorter than
    // the bodies are thick: a Hertzian zone is held by the compliance of
    // its own length.
    std::vector<double>       lengths(problem.get_pairs().size(), 0.);
    std::vector<unsigned int> overlapping(lengths.size(), 0);
    for (unsigned int q = 0; q < interface.size(); ++q)
      if (d_0[q] > 0)
      {
        lengths[interface.shares(q)[0].pair] += interface.weight(q);
        ++overlapping[interface.shares(q)[0].pair];
      }
    for (double &L : lengths)
      if (L == 0)
        L = std::numeric_limits<double>::infinity();
    interface.set_reference_lengths(lengths);
    // An active set method takes about a step per unknown that it releases
    // at each end of a zone; on small zones that is fewer than the stages.
    // Only on the nodes: on the points S has a kernel, a stage's pressure
    // is determined only to the residual over theta, and on the slender
    // plate at c = 0.05 the last stage ended on a force 6.6 times the
    // nodes' (without stages the points do not converge there).
    const bool large_zone =
      *std::max_element(overlapping.begin(), overlapping.end()) >=
      min_continuation_unknowns;
    if (large_zone && interface.on_nodes())
      enter_stage(continuation_stage(1.));
    continuation_pending = false;
  }

  void
  DDNewtonSolver::enter_stage(const double t)
  {
    if (t == interface.get_continuation())
      return;
    interface.set_continuation(t);
    preconditioner.update_penalties();
    pcout << "  continuation: theta + " << t << " theta_ref" << std::endl;
  }

  double
  DDNewtonSolver::stopping_tolerance(const PointVector &x) const
  {
    // On the points S has a kernel, and lambda_min(Theta + S_AA) is only
    // theta: a residual r leaves the pressure uncertain by up to
    // ||r||_W / theta. Asking ||r||_W <= 1e-3 ||theta p||_W bounds that by
    // 0.1 % of the pressure. (Slender plate of doc/stability.md at c = 1:
    // Tolerance = 1e-6 of the overlap alone passed a force 5 % off.)
    double tolerance = parameters.tolerance * scale;
    if (!interface.on_nodes())
    {
      PointVector theta_x(x.size());
      for (unsigned int q = 0; q < x.size(); ++q)
        theta_x[q] = interface.penalty(q) * x[q];
      const double bound = pressure_accuracy * interface.norm(theta_x);
      if (bound > 0)
        tolerance = std::min(tolerance, bound);
    }
    return tolerance;
  }

  bool
  DDNewtonSolver::penalty_dominates() const
  {
    // Theta^{-1} (Theta + S) has a condition number of at most
    // 1 + theta_ref / theta = 1 + 1 / t (S is at most the compliance
    // across the bodies). It is taken when that is below t theta_ref / e,
    // the stage's springs in units of an element's compliance e: such a
    // soft stage does not pay for the Robin factorization (paper scene,
    // refinement 5: the stage t = 1 in 6 sets without factorization).
    // With friction the sticking nodes' tangential unknowns have no
    // continuation: the Robin problems precondition them.
    const double t = interface.get_continuation();
    if (t == 0 || interface.has_friction())
      return false;
    double ratio = 0;
    for (unsigned int q = 0; q < interface.size(); ++q)
      ratio = std::max(ratio,
                       interface.reference_penalty(q) /
                         std::max(interface.target_penalty(q),
                                  interface.element_compliance(q)));
    return 1 / t < t * ratio;
  }

  double
  DDNewtonSolver::continuation_stage(const double t) const
  {
    for (unsigned int q = 0; q < interface.size(); ++q)
      if (t * interface.reference_penalty(q) >
          std::max(10 * interface.target_penalty(q),
                   interface.element_compliance(q)))
        return t;
    return 0.;
  }

  void
  DDNewtonSolver::reinit_after_refinement()
  {
    ContactSolver::reinit_after_refinement();
    const std::vector<Point<2>> old_positions = interface.positions();
    const unsigned int          n_old         = old_positions.size();
    interface.reinit();
    const auto move = [&](const PointVector &values)
    {
      return interface.on_nodes()
               ? interpolated_node_values(
                   old_positions, values, interface.positions())
               : nearest_point_values(
                   old_positions, values, interface.positions());
    };
    // The pressure, and with friction the tangential multipliers after it.
    const PointVector old = p;
    p                     = move(PointVector(old.begin(), old.begin() + n_old));
    if (interface.has_friction())
    {
      const PointVector t = move(PointVector(old.begin() + n_old, old.end()));
      p.insert(p.end(), t.begin(), t.end());
    }
    // The load-step history moves with the nodes; the states of the last
    // step do not (the first step on the new mesh sticks).
    history.transfer(problem, interface);
    step_slip_directions.clear();
    mesh_ready = false;
  }

  void
  DDNewtonSolver::start_load_step()
  {
    // The states of the last step start the next (monotonic loading keeps
    // most of them; from sticking everywhere the stick zone would shrink
    // back by about a node at each end per Newton step).
    const auto directions = last_slip_directions;
    history.start_load_step(problem, interface);
    ContactSolver::start_load_step();
    step_slip_directions = directions;
    // The same points and stiffness: the preconditioner's rows and its
    // last factorization stay valid.
    same_mesh = true;
  }

  void
  DDNewtonSolver::start_phase()
  {
    ContactSolver::start_phase();
    phase_ready = false;
    last_active.clear();
    last_slip_directions.clear();
    alpha_stale = !coarse.empty();
  }

  void
  DDNewtonSolver::setup_mesh()
  {
    AssertDimension(p.size(), interface.n_unknowns());
    if (!same_mesh)
      preconditioner.setup(interface);
    same_mesh = false;
    coarse.reinit();
    alpha.assign(coarse.size(), 0.);
    Ga.assign(p.size(), 0.);
    alpha_stale = !coarse.empty();
    balanced    = coarse.empty();
    problem.solve_all(ContactProblem::Iterate(problem.get_bodies().size()),
                      u_0,
                      false,
                      ContactProblem::Exchange::traces);
    ++n_data_solves;
    u_p = problem.zero_iterate();
    Sp.assign(p.size(), 0.);
    if (std::any_of(p.begin(), p.end(), [](const double x) { return x != 0; }))
      interface.apply(p, u_p, Sp);
    mesh_ready  = true;
    phase_ready = false;
  }

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

  void
  DDNewtonSolver::estimate_amplitudes()
  {
    // On P = {p > 0} the gaps close: (Theta + S) p - d_0 = G alpha there,
    // solved for alpha in the least-squares sense of (.,.)_M.
    std::vector<bool> positive(p.size());
    for (unsigned int q = 0; q < p.size(); ++q)
      positive[q] = p[q] > 0;
    std::fill(alpha.begin(), alpha.end(), 0.);
    if (coarse.holds(positive))
    {
      coarse.set_active(positive);
      alpha = fitted_amplitudes(p, Sp);
    }
    Ga = coarse.approach(alpha);
  }

  std::vector<double>
  DDNewtonSolver::fitted_amplitudes(const PointVector &x,
                                    const PointVector &Sx) const
  {
    PointVector r(x.size());
    for (unsigned int q = 0; q < x.size(); ++q)
      r[q] = interface.penalty(q) * x[q] + Sx[q] - d_0[q];
    return coarse.amplitudes(r);
  }

  PointVector
  DDNewtonSolver::operator_on_active(const std::vector<bool> &active,
                                     const PointVector       &y,
                                     const PointVector       &Sy) const
  {
    PointVector My(y.size(), 0.);
    for (unsigned int q = 0; q < y.size(); ++q)
      if (active[q])
        My[q] = interface.penalty(q) * y[q] + Sy[q];
    return My;
  }

  PointVector
  DDNewtonSolver::active_residual(const std::vector<bool> &active,
                                  const PointVector       &x,
                                  const PointVector       &Sx) const
  {
    PointVector r = operator_on_active(active, x, Sx);
    for (unsigned int q = 0; q < r.size(); ++q)
      r[q] = active[q] ? d_0[q] - r[q] : 0.;
    return r;
  }

  double
  DDNewtonSolver::fixed_value(const unsigned int q, const PointVector &x) const
  {
    if (!interface.is_tangential(q))
      return 0.;
    const unsigned int i = interface.node(q);
    return slip_coupling[i] != 0 ? slip_coupling[i] * x[i] : slip_values[i];
  }

  unsigned int
  DDNewtonSolver::solve_coupled_system(const std::vector<bool> &active,
                                       const double             tolerance,
                                       PointVector             &x,
                                       PointVector             &Sx,
                                       ContactProblem::Iterate &u_x)
  {
    const unsigned int n = x.size(), n_nodes = interface.size();
    // E: an increment y of the active unknowns, extended by the slipping
    // tangentials that follow their nodes' pressures.
    const auto extend = [&](const PointVector &y)
    {
      PointVector z(n, 0.);
      for (unsigned int q = 0; q < n; ++q)
        if (active[q])
          z[q] = y[q];
      for (unsigned int i = 0; i < n_nodes; ++i)
        if (slip_coupling[i] != 0)
          z[n_nodes + i] = slip_coupling[i] * y[i];
      return z;
    };

    // No coarse space: dd-newton refuses floating bodies with friction.
    Assert(coarse.empty(), ExcInternalError());
    PointVector  r    = active_residual(active, x, Sx);
    const double beta = interface.norm(r);
    if (beta <= tolerance)
      return 0;
    preconditioner.update(active);

    // GMRES, right preconditioned by the Robin problems, in the inner
    // product of M. Ours, not deal.II's SolverGMRES: it keeps each Krylov
    // direction's extension Z_j = E P v_j with S Z_j and the bodies'
    // response, so that the increment sum_j y_j Z_j comes with its S and
    // its displacements without another set of body solves.
    std::vector<PointVector>             V{r}, Z, SZ;
    std::vector<ContactProblem::Iterate> UZ;
    for (double &v : V[0])
      v /= beta;
    std::vector<std::vector<double>> H; // H[j] = column j, j + 2 entries
    std::vector<double>              cs, sn, g{beta};
    unsigned int                     sets = 0;
    for (unsigned int j = 0; j < max_gmres_directions; ++j)
    {
      PointVector Pv;
      preconditioner.vmult(Pv, V[j], active);
      Z.push_back(extend(Pv));
      SZ.emplace_back();
      UZ.emplace_back();
      interface.apply(Z[j], UZ[j], SZ[j]);
      ++sets;
      PointVector w = operator_on_active(active, Z[j], SZ[j]);
      // Arnoldi by modified Gram-Schmidt.
      std::vector<double> h(j + 2, 0.);
      for (unsigned int i = 0; i <= j; ++i)
      {
        h[i] = interface.inner(w, V[i]);
        add(w, -h[i], V[i]);
      }
      h[j + 1] = interface.norm(w);
      // The earlier rotations, then a new one that zeroes h[j + 1].
      for (unsigned int i = 0; i < j; ++i)
      {
        const double a = h[i], b = h[i + 1];
        h[i]     = cs[i] * a + sn[i] * b;
        h[i + 1] = -sn[i] * a + cs[i] * b;
      }
      const double rho = std::hypot(h[j], h[j + 1]);
      cs.push_back(rho > 0 ? h[j] / rho : 1.);
      sn.push_back(rho > 0 ? h[j + 1] / rho : 0.);
      const double breakdown = h[j + 1];
      h[j]                   = rho;
      h[j + 1]               = 0.;
      H.push_back(h);
      g.push_back(-sn[j] * g[j]);
      g[j] *= cs[j];
      // |g_{j+1}| is the residual's M-norm after j + 1 directions.
      if (std::abs(g[j + 1]) <= tolerance || breakdown == 0.)
        break;
      for (double &v : w)
        v /= breakdown;
      V.push_back(w);
    }
    // The least-squares coefficients: H y = g, H upper triangular.
    const unsigned int  m = H.size();
    std::vector<double> y(m);
    for (unsigned int i = m; i-- > 0;)
    {
      double sum = g[i];
      for (unsigned int k = i + 1; k < m; ++k)
        sum -= H[k][i] * y[k];
      y[i] = sum / H[i][i];
    }
    for (unsigned int j = 0; j < m; ++j)
    {
      add(x, y[j], Z[j]);
      add(Sx, y[j], SZ[j]);
      add(u_x, y[j], UZ[j]);
    }
    // The sum leaves t_i = sigma mu p_i to round-off; exactly, so that the
    // next step's warm start finds it in place (a difference of an ulp
    // would cost a set of body solves, or not, by the round-off of the
    // bodies' solvers, which differs with the number of processes).
    for (unsigned int i = 0; i < n_nodes; ++i)
      if (slip_coupling[i] != 0)
        x[n_nodes + i] = slip_coupling[i] * x[i];
    return sets;
  }

  unsigned int
  DDNewtonSolver::solve_active_system(const std::vector<bool> &active,
                                      const double             tolerance,
                                      PointVector             &x,
                                      PointVector             &Sx,
                                      ContactProblem::Iterate &u_x)
  {
    if (std::any_of(slip_coupling.begin(),
                    slip_coupling.end(),
                    [](const double k) { return k != 0; }))
      return solve_coupled_system(active, tolerance, x, Sx, u_x);
    const unsigned int n = x.size();
    // Floating bodies: x in equilibrium (one set of solves if it was not),
    // then residuals and directions M-orthogonal to G on the active set.
    if (!coarse.empty())
    {
      coarse.set_active(active);
      const PointVector c = coarse.correction(x);
      if (std::any_of(c.begin(), c.end(), [](const double v) { return v; }))
      {
        PointVector             Sc;
        ContactProblem::Iterate u_c;
        interface.apply(c, u_c, Sc);
        add(x, 1., c);
        add(Sx, 1., Sc);
        add(u_x, 1., u_c);
      }
    }
    const auto project = [&](PointVector &v)
    {
      if (!coarse.empty())
        coarse.project(v);
    };
    PointVector r = active_residual(active, x, Sx);
    project(r);
    if (interface.norm(r) <= tolerance)
      return 0;

    // Soft stages of the continuation: Theta^{-1}, without body solves.
    const bool jacobi       = penalty_dominates();
    const auto precondition = [&](PointVector &z, const PointVector &r)
    {
      if (!jacobi)
        return preconditioner.vmult(z, r, active);
      z.assign(n, 0.);
      for (unsigned int q = 0; q < n; ++q)
        if (active[q])
          z[q] = r[q] / interface.penalty(q);
    };
    if (!jacobi)
      preconditioner.update(active);
    PointVector z;
    precondition(z, r);
    project(z);
    PointVector             s   = z, Ss;
    double                  rho = interface.inner(r, z);
    ContactProblem::Iterate u_s;
    unsigned int            iterations = 0;
    while (iterations < max_cg_iterations)
    {
      interface.apply(s, u_s, Ss);
      ++iterations;
      const PointVector Ms    = operator_on_active(active, s, Ss);
      const double      alpha = rho / interface.inner(s, Ms);
      add(x, alpha, s);
      add(Sx, alpha, Ss);
      add(u_x, alpha, u_s);
      add(r, -alpha, Ms);
      project(r);
      if (interface.norm(r) <= tolerance)
        break;
      precondition(z, r);
      project(z);
      const double rho_new = interface.inner(r, z);
      for (unsigned int q = 0; q < n; ++q)
        s[q] = z[q] + (rho_new / rho) * s[q];
      rho = rho_new;
    }
    return iterations;
  }

  void
  DDNewtonSolver::store_iterate()
  {
    const auto &bodies = problem.get_bodies();
    ContactProblem::assign(last_u_tilde, u_0);
    add(last_u_tilde, 1., u_p);
    if (!coarse.empty())
      coarse.add_motion(alpha, last_u_tilde);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      copy_stored(last_u_tilde[b], bodies[b]->get_solution());
    iterate_complete = false;
    // u_0 + u_p solves the body problems (20) loaded by sigma_n = -p.
    last_sigma_n = interface.reported_field(p, -1.);
    if (interface.on_nodes())
    {
      const auto peak = interface.peak_pressures(p);
      for (unsigned int k = 0; k < last_sigma_n.size(); ++k)
        problem.law(k).set_contact_pressure(last_sigma_n[k], peak[k]);
    }
    if (interface.has_friction())
    {
      // The states of the step: a sticking node's t is active.
      const unsigned int      n = interface.size();
      const std::vector<bool> sticking(last_active.begin() + n,
                                       last_active.end());
      history.publish(problem,
                      interface,
                      PointVector(p.begin(), p.begin() + n),
                      PointVector(p.begin() + n, p.end()),
                      interface.slip_average(last_u_tilde),
                      sticking,
                      last_sigma_n);
    }
  }

  void
  DDNewtonSolver::complete_iterate()
  {
    if (iterate_complete)
      return;
    problem.get_distribution().share(last_u_tilde);
    const auto &bodies = problem.get_bodies();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      copy_stored(last_u_tilde[b], bodies[b]->get_solution());
    iterate_complete = true;
  }

  bool
  DDNewtonSolver::step()
  {
    if (!mesh_ready)
      setup_mesh();
    if (!phase_ready)
    {
      d_0 = interface.penetration(u_0);
      PointVector overlap(d_0.size());
      for (unsigned int q = 0; q < d_0.size(); ++q)
        overlap[q] = std::max(0., d_0[q]);
      // Friction: the data of a sticking node's row are the slip of u_0
      // less the history's, s_0 - s_old + theta t_old (the residual is
      // measured against the whole slip of the data).
      for (unsigned int q = interface.size(); q < d_0.size(); ++q)
      {
        const unsigned int i = interface.node(q);
        d_0[q] +=
          interface.penalty(q) * history.old_traction(i) - history.old_slip(i);
        overlap[q] = std::abs(d_0[q]);
      }
      scale       = interface.norm(overlap);
      phase_ready = true;
    }
    if (continuation_pending)
      start_continuation();
    if (alpha_stale)
    {
      estimate_amplitudes();
      alpha_stale = false;
    }
    if (records.size() - phase_start >=
        parameters.dd_newton.max_newton_iterations)
      stop_at_iteration_limit("the Newton method of dd-newton");

    // The first step of a phase lets every closed node stick, or keep its
    // state of the last load step: its iterate is no Newton iterate of
    // these data (a trial traction t + ds / c with c an element's
    // compliance would throw every node with a slip increment into slip),
    // and sticking, the zone finds the direction of every slip from its
    // traction.
    const bool        first     = records.size() == phase_start;
    unsigned int      n_changed = 0;
    std::vector<bool> active    = active_set(n_changed, first);
    // Penalty continuation: once the active set of a stage has settled,
    // the next, stiffer one starts from it. A stage has settled when at most 1
    // % of its active set changes (the last changes of a stage are the
    // node-by-node peeling that the next stage does anyway).
    if (interface.get_continuation() > 0 && !last_active.empty() &&
        100 * n_changed <= std::count(active.begin(), active.end(), true))
    {
      enter_stage(
        continuation_stage(continuation_factor * interface.get_continuation()));
      active = active_set(n_changed, first);
    }
    const double psi = interface.norm(newton_residual(p, Sp, Ga));
    // The closed nodes (with friction: and the sticking ones).
    const unsigned int n_active =
      std::count(active.begin(), active.begin() + interface.size(), true);
    const unsigned int n_sticking =
      std::count(active.begin() + interface.size(), active.end(), true);
    // The same active set again, completed by unknowns that pull (p < 0):
    // only tension holds the floating modes, and the Newton method would
    // repeat this step for ever.
    bool pulled = false;
    for (unsigned int q = 0; q < p.size(); ++q)
      pulled = pulled || (forced[q] && p[q] < 0);
    if (n_changed == 0 && pulled)
      throw DivergenceError(
        "contact holds the rigid motion of the floating bodies (" +
        coarse.description() +
        ") only by tension: they form a mechanism (e.g. a cylinder turning "
        "about its axis, or a punch without a load toward its support); "
        "prescribe that displacement component on a boundary, or load the "
        "body toward the contact");
    // Warm start: x off the new active set takes its fixed value (zero,
    // or sigma b at a slipping node), and S x with it.
    PointVector             x = p, Sx = Sp;
    ContactProblem::Iterate u_x;
    ContactProblem::assign(u_x, u_p);
    PointVector fixing(p.size(), 0.);
    bool        any_fixed = false;
    for (unsigned int q = 0; q < p.size(); ++q)
    {
      const double fixed = fixed_value(q, p);
      if (!active[q] && p[q] != fixed)
      {
        fixing[q] = fixed - p[q];
        x[q]      = fixed;
        any_fixed = true;
      }
    }
    if (any_fixed)
    {
      PointVector             S_fixing;
      ContactProblem::Iterate u_fixing;
      interface.apply(fixing, u_fixing, S_fixing);
      add(Sx, 1., S_fixing);
      add(u_x, 1., u_fixing);
    }
    // Inexact Newton: 0.1 of the residual while the active set moves, the
    // final tolerance (with a margin) once it has settled.
    const double final_tolerance = 0.5 * stopping_tolerance(p);
    const double tolerance =
      (n_changed == 0 && interface.get_continuation() == 0)
        ? final_tolerance
        : std::max(final_tolerance, 0.1 * psi);
    const unsigned int factorizations = preconditioner.factorizations();
    const unsigned int cg = solve_active_system(active, tolerance, x, Sx, u_x);
    n_factorizations += preconditioner.factorizations() - factorizations;
    krylov_iterations += cg;
    last_active          = active;
    last_slip_directions = slip_directions;
    // The floating modes' amplitudes: (Theta + S) x - d_0 = G alpha on the
    // active set (projected CG leaves only that part of the residual).
    std::vector<double> alpha_x;
    PointVector         Gx(x.size(), 0.);
    if (!coarse.empty())
    {
      alpha_x = fitted_amplitudes(x, Sx);
      Gx      = coarse.approach(alpha_x);
    }

    // Damping: the largest tau = 1, 1/2, ... that reduces ||Phi||_W (d is
    // affine in p, so every trial is free); the full step if none does.
    // With floating bodies only between two pressures in equilibrium, so
    // that the damped one is in equilibrium too. Not the first step with
    // friction, where every closed node sticks: it may raise the residual
    // (the sticking traction exceeds the bound at the zone's ends), and a
    // damped stick step leaves slip increments whose trial tractions
    // (ds / c, c an element's compliance) throw every node into slip.
    double     tau             = 1;
    double     psi_new         = interface.norm(newton_residual(x, Sx, Gx));
    const bool full_stick_step = first && interface.has_friction();
    // Nor a step from an iterate that already meets the tolerance: there
    // the residual is round-off, which no step reduces, and damping would
    // keep the active set from being confirmed by a full step.
    if (psi_new >= psi && psi > stopping_tolerance(p) && balanced &&
        !full_stick_step)
      for (double t = 0.5; t > 1e-3; t /= 2)
      {
        PointVector p_t = p, Sp_t = Sp, Ga_t = Ga;
        blend(p_t, t, x);
        blend(Sp_t, t, Sx);
        blend(Ga_t, t, Gx);
        const double psi_t = interface.norm(newton_residual(p_t, Sp_t, Ga_t));
        if (psi_t < (1 - 1e-4 * t) * psi)
        {
          tau     = t;
          psi_new = psi_t;
          break;
        }
      }
    PointVector change = x;
    add(change, -1., p);
    const double increment = interface.norm(change);
    // p + tau (x - p), and S p and u_p alike (both linear in p).
    blend(p, tau, x);
    blend(Sp, tau, Sx);
    blend(u_p, tau, u_x);
    blend(Ga, tau, Gx);
    blend(alpha, tau, alpha_x);
    balanced = true;
    // A floating body's d_0 is that of its clamped components, which may
    // carry the whole load and see no overlap: the residual is then
    // measured against the approach of the bodies under the pressure.
    if (!coarse.empty())
      scale = std::max(scale, interface.norm(Sp));
    store_iterate();

    IterationRecord record;
    record.iteration = records.size() + 1;
    record.residual  = (scale > 0) ? psi_new / scale : psi_new;
    record.increment = tau * increment / std::max(interface.norm(p), 1e-300);
    record.gamma     = tau;
    measure_contact(last_u_tilde, record);
    record.time = timer.wall_time();
    add_record(record);

    // Converged only after a full step solved to the final tolerance on an
    // active set that the new iterate keeps: the residual weighs a tension
    // p < 0 by the surface's compliance c, far below the compliance of a
    // bending plate, so that damped steps on a zone still too wide passed
    // the residual test alone (slender plate of doc/stability.md: 3 % off
    // in force at Tolerance = 1e-6, 10 % at c = 0.05).
    unsigned int n_next = 0;
    active_set(n_next);
    const bool converged = interface.get_continuation() == 0 &&
                           n_changed == 0 && tau == 1 && n_next == 0 &&
                           psi_new <= stopping_tolerance(p);
    pcout << "  Newton " << std::setw(3) << record.iteration << std::scientific
          << std::setprecision(3) << "  residual " << record.residual
          << "  active " << n_active;
    if (interface.has_friction())
      pcout << " (" << n_sticking << " stick)";
    pcout << " (" << n_changed << " changed)  CG " << cg << "  tau "
          << std::defaultfloat << tau << std::scientific << "  normal force "
          << record.force << "  penetration " << record.max_penetration
          << std::defaultfloat << "  body solve sets " << n_dd_iterations()
          << "  factorizations " << n_factorizations << std::fixed
          << std::setprecision(2) << "  t " << record.time << "s"
          << std::defaultfloat << std::endl;
    if (!std::isfinite(record.residual))
      throw DivergenceError(
        "the Newton method of dd-newton produced a non-finite residual at "
        "step " +
        std::to_string(record.iteration) + ", after " + std::to_string(cg) +
        " CG iterations on the active set (limit " +
        std::to_string(max_cg_iterations) +
        "): the Newton system is singular or indefinite there, as when the "
        "active contact nodes do not hold a floating body's rigid motion; "
        "Formulation = penalty (" +
        penalty_entries() +
        ") regularizes it, or prescribe the free motion of the body "
        "somewhere (Boundary conditions/Dirichlet)");
    return converged;
  }

  SolverCounts
  DDNewtonSolver::counts() const
  {
    SolverCounts c;
    c.body_solve_sets               = n_dd_iterations();
    c.preconditioner_solve_sets     = preconditioner.n_applications();
    c.preconditioner_factorizations = n_factorizations;
    c.pairs_preconditioned_by_both  = preconditioner.pairs_with_both_bodies();
    c.newton_steps                  = records.size();
    c.krylov_iterations             = krylov_iterations;
    return c;
  }

  void
  DDNewtonSolver::stop_at_iteration_limit(const std::string &what) const
  {
    // Falling: the residual of the last step is below that of five steps
    // before (the active set still moves toward the solution); otherwise
    // the active set cycles.
    const unsigned int n = records.size();
    const double       r = (n > 0) ? records.back().residual : 0.;
    std::ostringstream s;
    s << std::setprecision(3) << what << " has not converged in "
      << n - phase_start << " Newton steps (" << n_dd_iterations()
      << " sets of body solves; residual " << r << ", Tolerance "
      << parameters.tolerance << ")";
    // Under six steps there is nothing to judge a cycle by: the limit
    // itself is what stopped the run.
    const bool too_few = n < phase_start + 6;
    const bool falling = !too_few && r < 0.5 * records[n - 6].residual;
    if (too_few || falling)
    {
      s << (too_few ? ", too few steps to tell" : ", falling")
        << "; raise Contact solver/DD-Newton/Max Newton iterations or "
           "Contact solver/Max iterations";
      throw NotConvergedError(s.str());
    }
    if (const std::string tresca = tresca_lift_off_note(problem.get_pairs());
        !tresca.empty())
    {
      s << ": the active set does not settle" << tresca;
      throw DivergenceError(s.str());
    }
    s << ": the active set does not settle; raise " << penalty_entries();
    if (!interface.on_nodes())
      s << ", or set Contact solver/Contact pressure = nodes (one "
           "pressure per node of S_1, for stiff penalties)";
    s << ", or use Contact solver/Solver = monolithic";
    throw DivergenceError(s.str());
  }
} // namespace ddcontact
