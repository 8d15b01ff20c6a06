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
    /** The relative accuracy of the pressure that the stopping test asks
     * on the points (stopping_tolerance()). */
    constexpr double pressure_accuracy = 1e-3;

  } // namespace

  void
  DDNewtonSolver::initialize()
  {
    problem.set_pressure_from_solver(parameters.multipliers_on_nodes());
    ContactSolver::initialize();
    continuation.reset(parameters.dd_newton.penalty_continuation);
    interface.reinit();
    interface.set_reference_lengths({});
    p.assign(interface.n_unknowns(), 0.);
    history.clear();
    step_slip_directions.clear();
    mesh_ready = false;
    setup_mesh();
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
    keep_scale  = false;
    last_active.clear();
    last_slip_directions.clear();
    alpha_stale = !coarse.empty();
  }

  void
  DDNewtonSolver::setup_mesh()
  {
    AssertDimension(p.size(), interface.n_unknowns());
    const bool kept_mesh = same_mesh;
    if (!same_mesh)
      preconditioner.setup(interface);
    same_mesh = false;
    coarse.reinit();
    alpha.assign(coarse.size(), 0.);
    Ga.assign(p.size(), 0.);
    alpha_stale = !coarse.empty();
    balanced    = coarse.empty();
    nonlinear   = problem.has_nonlinear_bodies();
    if (nonlinear)
    {
      // A new load step starts from the last step's displacement; a new
      // mesh from zero.
      relinearize(kept_mesh && u_0.size() == problem.get_bodies().size()
                    ? prediction()
                    : ContactProblem::Iterate(problem.get_bodies().size()));
      // From zero pressure (a new mesh or the first step) the first
      // iterates keep this linearization: the contact problem of the start's
      // tangent first, its pressure then the first load of the bodies' own
      // laws (the early iterates' pressures, peaked at a few nodes or
      // pulling, are no load a plastic body carries).
      tangent_start =
        std::all_of(p.begin(), p.end(), [](const double x) { return x == 0; });
    }
    else
    {
      problem.solve_all(ContactProblem::Iterate(problem.get_bodies().size()),
                        u_0,
                        false,
                        ContactProblem::Exchange::traces);
      ++n_data_solves;
      respond_to_pressure();
    }
    mesh_ready  = true;
    phase_ready = false;
    keep_scale  = false;
  }

  void
  DDNewtonSolver::respond_to_pressure()
  {
    u_p = problem.zero_iterate();
    Sp.assign(p.size(), 0.);
    if (std::any_of(p.begin(), p.end(), [](const double x) { return x != 0; }))
      interface.apply(p, u_p, Sp);
  }

  ContactProblem::Iterate
  DDNewtonSolver::prediction() const
  {
    ContactProblem::Iterate u;
    ContactProblem::assign(u, u_0);
    add(u, 1., u_p);
    return u;
  }

  void
  DDNewtonSolver::relinearize(const ContactProblem::Iterate &warm_start)
  {
    // u(p): every body under the contact loads of p, the nonlinear ones by
    // their Newton loops, which leave their tangents factorized.
    ContactProblem::Iterate u_k;
    ContactProblem::assign(u_k, warm_start);
    if (interface.has_friction())
      problem.solve_bodies(interface.normal_stresses(p),
                           interface.tangential_tractions(p),
                           u_k,
                           false,
                           ContactProblem::Exchange::traces);
    else
      problem.solve_bodies(interface.normal_stresses(p),
                           u_k,
                           false,
                           ContactProblem::Exchange::traces);
    ++n_data_solves;
    // S of the tangents: u_p = K_T^{-1} B^T p and u_0 = u(p) - u_p, so that
    // u_0 + u_x is the tangent's prediction of the bodies under x.
    respond_to_pressure();
    ContactProblem::assign(u_0, u_k);
    add(u_0, -1., u_p);
    phase_ready = false;
    keep_scale  = true;
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
      {
        problem.law(k).set_contact_pressure(last_sigma_n[k]);
        published[k].peak_nodal_pressure = peak[k];
      }
      publish_nodal_law(interface, p, last_u_tilde);
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
                      last_sigma_n,
                      published);
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

  void
  DDNewtonSolver::update_data()
  {
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
      // A new linearization of a nonlinear body keeps the phase's scale.
      if (!keep_scale)
        scale = interface.norm(overlap);
      keep_scale  = false;
      phase_ready = true;
    }
  }

  void
  DDNewtonSolver::prepare_step()
  {
    if (!mesh_ready)
      setup_mesh();
    update_data();
    if (continuation.is_pending())
      continuation.start(d_0, problem.get_pairs());
    if (alpha_stale)
    {
      estimate_amplitudes();
      alpha_stale = false;
    }
    if (records.size() - phase_start >=
        parameters.dd_newton.max_newton_iterations)
      stop_at_iteration_limit("the Newton method of dd-newton");
  }

  void
  DDNewtonSolver::check_mechanism(const unsigned int n_changed) const
  {
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
  }

  void
  DDNewtonSolver::warm_start(const std::vector<bool> &active,
                             PointVector             &x,
                             PointVector             &Sx,
                             ContactProblem::Iterate &u_x) const
  {
    // x off the new active set takes its fixed value (zero, or sigma b at
    // a slipping node), and S x with it.
    x  = p;
    Sx = Sp;
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
  }

  double
  DDNewtonSolver::damping(const double       psi,
                          const bool         full_step,
                          const PointVector &x,
                          const PointVector &Sx,
                          const PointVector &Gx,
                          double            &psi_new) const
  {
    // The largest tau = 1, 1/2, ... that reduces ||Phi||_W (d is affine in
    // p, so every trial is free); the full step if none does. With
    // floating bodies only between two pressures in equilibrium, so that
    // the damped one is in equilibrium too. Not from an iterate that
    // already meets the tolerance: there the residual is round-off, which
    // no step reduces, and damping would keep the active set from being
    // confirmed by a full step.
    psi_new = interface.norm(newton_residual(x, Sx, Gx));
    if (psi_new < psi || psi <= stopping_tolerance(p) || !balanced || full_step)
      return 1.;
    for (double t = 0.5; t > 1e-3; t /= 2)
    {
      PointVector p_t = p, Sp_t = Sp, Ga_t = Ga;
      blend(p_t, t, x);
      blend(Sp_t, t, Sx);
      blend(Ga_t, t, Gx);
      const double psi_t = interface.norm(newton_residual(p_t, Sp_t, Ga_t));
      if (psi_t < (1 - 1e-4 * t) * psi)
      {
        psi_new = psi_t;
        return t;
      }
    }
    return 1.;
  }

  IterationRecord
  DDNewtonSolver::take_step(double                        &tau,
                            const PointVector             &x,
                            const PointVector             &Sx,
                            const ContactProblem::Iterate &u_x,
                            const PointVector             &Gx,
                            const std::vector<double>     &alpha_x,
                            double                        &psi_new,
                            const double                   psi,
                            const bool                     full_step)
  {
    PointVector change = x;
    add(change, -1., p);
    const double increment = interface.norm(change);
    // The iterate before the step, for a nonlinear body that cannot carry
    // the step's pressure.
    const PointVector       p_old = p, Sp_old = Sp, Ga_old = Ga;
    const auto              alpha_old = alpha;
    ContactProblem::Iterate u_p_old, u_0_old;
    if (nonlinear)
    {
      ContactProblem::assign(u_p_old, u_p);
      ContactProblem::assign(u_0_old, u_0);
    }
    const auto restore = [&]()
    {
      p  = p_old;
      Sp = Sp_old;
      Ga = Ga_old;
      ContactProblem::assign(u_p, u_p_old);
      ContactProblem::assign(u_0, u_0_old);
      alpha = alpha_old;
      tau /= 2;
    };
    const bool judge_true_residual =
      !full_step && psi > stopping_tolerance(p_old);
    for (;;)
    {
      // p + tau (x - p), and S p and u_p alike (both linear in p).
      blend(p, tau, x);
      blend(Sp, tau, Sx);
      blend(u_p, tau, u_x);
      blend(Ga, tau, Gx);
      blend(alpha, tau, alpha_x);
      balanced = true;
      if (!nonlinear || tangent_start)
        break;
      // Nonlinear bodies: solved under the new p, and the model taken
      // there; its residual at p is then the true one (psi_new was the
      // model's). A pressure beyond what a body carries (a perfectly
      // plastic body past its limit load, where the model's pressure
      // peaks at a node) stops the body's Newton loop: the step is halved.
      try
      {
        relinearize(prediction());
      }
      catch (const DivergenceError &e)
      {
        if (tau < 1. / 64)
          throw;
        restore();
        pcout << "  a body's Newton loop failed under the step's pressure ("
              << e.what() << "): step halved to tau = " << tau << std::endl;
        continue;
      }
      update_data();
      psi_new = interface.norm(newton_residual(p, Sp, Ga));
      // damping() judged the model; the step must also reduce the true
      // residual (as damping() asks of the model, with its exceptions),
      // or the active sets of contact, friction and yield cycle.
      if (!judge_true_residual || tau < 1. / 64 ||
          psi_new < (1 - 1e-4 * tau) * psi)
        break;
      restore();
    }
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
    return record;
  }

  bool
  DDNewtonSolver::step()
  {
    prepare_step();
    // The first step of a phase lets every closed node stick, or keep its
    // state of the last load step: its iterate is no Newton iterate of
    // these data (a trial traction t + ds / c with c an element's
    // compliance would throw every node with a slip increment into slip),
    // and sticking, the zone finds the direction of every slip from its
    // traction.
    const bool        first     = records.size() == phase_start;
    unsigned int      n_changed = 0;
    std::vector<bool> active    = active_set(n_changed, first);
    if (!last_active.empty() &&
        continuation.advance(n_changed,
                             std::count(active.begin(), active.end(), true)))
      active = active_set(n_changed, first);
    const double psi = interface.norm(newton_residual(p, Sp, Ga));
    check_mechanism(n_changed);
    PointVector             x, Sx;
    ContactProblem::Iterate u_x;
    warm_start(active, x, Sx, u_x);
    // Inexact Newton: 0.1 of the residual while the active set moves, the
    // final tolerance (with a margin) once it has settled.
    const double final_tolerance = 0.5 * stopping_tolerance(p);
    // Not below the round-off of the step's data on its active set: with
    // every node open at p = 0 the residual and its scale vanish, and a
    // floating body's coarse correction leaves the CG a residual of
    // round-off to reduce to 0 (a pin in a bore, issue 59). (The data of
    // the open nodes, far gaps, would set a floor far above that.)
    PointVector active_data(d_0.size(), 0.);
    for (unsigned int q = 0; q < d_0.size(); ++q)
      if (active[q])
        active_data[q] = d_0[q];
    // Nonlinear bodies: every step to the final tolerance. A crude early
    // step's pressure (one CG iteration, peaked at a few nodes) is no load
    // a plastic body carries, and each step costs the bodies' Newton loops
    // (relinearize()) more than the Krylov iterations it saves.
    const bool   settled = n_changed == 0 || nonlinear;
    const double tolerance =
      std::max((settled && interface.get_continuation() == 0)
                 ? final_tolerance
                 : std::max(final_tolerance, 0.1 * psi),
               1e-14 * interface.norm(active_data));
    const unsigned int factorizations = preconditioner.factorizations();
    const unsigned int cg             = krylov.solve(
      {active, d_0, slip_coupling, continuation.penalty_dominates()},
      tolerance,
      x,
      Sx,
      u_x);
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
    // Not damped: the first step with friction, where every closed node
    // sticks: it may raise the residual (the sticking traction exceeds
    // the bound at the zone's ends), and a damped stick step leaves slip
    // increments whose trial tractions (ds / c, c an element's
    // compliance) throw every node into slip.
    double psi_new = 0;
    double tau =
      damping(psi, first && interface.has_friction(), x, Sx, Gx, psi_new);
    const IterationRecord record = take_step(tau,
                                             x,
                                             Sx,
                                             u_x,
                                             Gx,
                                             alpha_x,
                                             psi_new,
                                             psi,
                                             first && interface.has_friction());

    // Converged only after a full step solved to the final tolerance on an
    // active set that the new iterate keeps: the residual weighs a tension
    // p < 0 by the surface's compliance c, far below the compliance of a
    // bending plate, so that damped steps on a zone still too wide passed
    // the residual test alone (slender plate of doc/stability.md: 3 % off
    // in force at Tolerance = 1e-6, 10 % at c = 0.05).
    unsigned int n_next = 0;
    active_set(n_next);
    bool converged = interface.get_continuation() == 0 && n_changed == 0 &&
                     tau == 1 && n_next == 0 &&
                     psi_new <= stopping_tolerance(p);
    print_step(record, active, n_changed, cg);
    if (converged && tangent_start)
    {
      // The start's tangent problem is solved: from here every step
      // relinearizes at its pressure.
      tangent_start = false;
      relinearize(prediction());
      update_data();
      store_iterate();
      converged = false;
    }
    return converged;
  }

  void
  DDNewtonSolver::print_step(const IterationRecord   &record,
                             const std::vector<bool> &active,
                             const unsigned int       n_changed,
                             const unsigned int       cg) const
  {
    // The closed nodes (with friction: and the sticking ones).
    const auto middle = active.begin() + interface.size();
    pcout << "  Newton " << std::setw(3) << record.iteration << std::scientific
          << std::setprecision(3) << "  residual " << record.residual
          << "  active " << std::count(active.begin(), middle, true);
    if (interface.has_friction())
      pcout << " (" << std::count(middle, active.end(), true) << " stick)";
    pcout << " (" << n_changed << " changed)  CG " << cg << "  tau "
          << std::defaultfloat << record.gamma << std::scientific
          << "  normal force " << record.force << "  penetration "
          << record.max_penetration << std::defaultfloat << "  body solve sets "
          << n_dd_iterations() << "  factorizations " << n_factorizations
          << std::fixed << std::setprecision(2) << "  t " << record.time << "s"
          << std::defaultfloat << std::endl;
    if (!std::isfinite(record.residual))
      throw DivergenceError(
        "the Newton method of dd-newton produced a non-finite residual at "
        "step " +
        std::to_string(record.iteration) + ", after " + std::to_string(cg) +
        " CG iterations on the active set (limit " +
        std::to_string(InterfaceKrylovSolver::max_cg_iterations) +
        "): the Newton system is singular or indefinite there, as when the "
        "active contact nodes do not hold a floating body's rigid motion; "
        "Formulation = penalty (" +
        penalty_entries() +
        ") regularizes it, or prescribe the free motion of the body "
        "somewhere (Boundary conditions/Dirichlet)");
    // A CG at its limit has not solved the step's system: its iterate is
    // no Newton step, and Newton steps after it would converge on a
    // meaningless pressure (a 9.7e19 force written "converged"). GMRES at
    // its direction limit is an inexact Newton step by design.
    if (!krylov.used_gmres() && !krylov.met_tolerance())
    {
      std::ostringstream s;
      s << std::setprecision(3) << "the CG of dd-newton's Newton step "
        << record.iteration << " stopped after " << cg << " iterations (limit "
        << InterfaceKrylovSolver::max_cg_iterations << ") with the residual "
        << krylov.final_residual()
        << " above its tolerance: the Newton system on the active set is "
           "singular, as where the Dirichlet conditions of both bodies "
           "prescribe the motion of a contact node (a contact zone ending "
           "at nodes held on both sides) or the active nodes do not hold a "
           "floating body; hold the end of the zone on one body only, or "
           "try Contact solver/Solver = monolithic";
      throw DivergenceError(s.str());
    }
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
