#include <ddcontact/solvers/interface_krylov_solver.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  namespace
  {
    /** E: an increment @p y of the active unknowns of @p step (of size
     * @p n, two per node of @p n_nodes), extended by the slipping
     * tangentials that follow their nodes' pressures. */
    PointVector
    extend_by_slip(const InterfaceKrylovSolver::Step &step,
                   const PointVector                 &y,
                   const unsigned int                 n,
                   const unsigned int                 n_nodes)
    {
      PointVector z(n, 0.);
      for (unsigned int q = 0; q < n; ++q)
        if (step.active[q])
          z[q] = y[q];
      for (unsigned int i = 0; i < n_nodes; ++i)
        if (step.coupling[i] != 0)
          z[n_nodes + i] = step.coupling[i] * y[i];
      return z;
    }

    /** Bring the new Hessenberg column @p h (j + 2 entries) to upper
     * triangular form: the earlier Givens rotations @p cs, @p sn, then a
     * new one, appended, that zeroes h[j + 1]. Returns that entry before
     * the rotation (zero at a breakdown). */
    double
    rotate_column(std::vector<double> &h,
                  const unsigned int   j,
                  std::vector<double> &cs,
                  std::vector<double> &sn)
    {
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
      return breakdown;
    }

    /** The least-squares coefficients y of GMRES: H y = g by back
     * substitution, H upper triangular, stored by columns. */
    std::vector<double>
    solve_upper_triangular(const std::vector<std::vector<double>> &H,
                           const std::vector<double>              &g)
    {
      const unsigned int  m = H.size();
      std::vector<double> y(m);
      for (unsigned int i = m; i-- > 0;)
      {
        double sum = g[i];
        for (unsigned int k = i + 1; k < m; ++k)
          sum -= H[k][i] * y[k];
        y[i] = sum / H[i][i];
      }
      return y;
    }
  } // namespace

  InterfaceKrylovSolver::InterfaceKrylovSolver(
    const ContactInterface &interface,
    RobinPreconditioner    &preconditioner,
    RigidModeCoarseSpace   &coarse)
    : interface(interface)
    , preconditioner(preconditioner)
    , coarse(coarse)
  {
  }

  unsigned int
  InterfaceKrylovSolver::solve(const Step              &step,
                               const double             tolerance,
                               PointVector             &x,
                               PointVector             &Sx,
                               ContactProblem::Iterate &u_x) const
  {
    last_used_gmres = std::any_of(step.coupling.begin(),
                                  step.coupling.end(),
                                  [](const double k) { return k != 0; });
    if (last_used_gmres)
      return gmres(step, tolerance, x, Sx, u_x);
    const auto        &active = step.active;
    const unsigned int n      = x.size();
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
    PointVector r = active_residual(step, x, Sx);
    project(r);
    last_residual      = interface.norm(r);
    last_met_tolerance = last_residual <= tolerance;
    if (last_met_tolerance)
      return 0;

    // Soft stages of the continuation: Theta^{-1}, without body solves.
    const bool jacobi       = step.penalty_preconditioner;
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
    bool                    exhausted  = false;
    while (iterations < max_cg_iterations)
    {
      // rho = (r, z) = 0: the preconditioned, projected residual vanishes,
      // nothing is left to solve on the active set (a floating body held
      // by as many active nodes as it has free modes: the coarse
      // correction alone solves it, and r is round-off). Going on would
      // divide 0 by 0 (a pin in a bore, issue 59).
      if (rho == 0)
      {
        exhausted = true;
        break;
      }
      interface.apply(s, u_s, Ss);
      ++iterations;
      const PointVector Ms        = operator_on_active(active, s, Ss);
      const double      curvature = interface.inner(s, Ms);
      // A singular or indefinite system: no step along s.
      if (!(curvature > 0))
        break;
      const double alpha = rho / curvature;
      add(x, alpha, s);
      add(Sx, alpha, Ss);
      add(u_x, alpha, u_s);
      add(r, -alpha, Ms);
      project(r);
      last_residual = interface.norm(r);
      // A breakdown (a non-positive curvature of a singular or indefinite
      // system) ends it too: the residual is then not finite.
      if (last_residual <= tolerance || !std::isfinite(last_residual))
        break;
      precondition(z, r);
      project(z);
      const double rho_new = interface.inner(r, z);
      for (unsigned int q = 0; q < n; ++q)
        s[q] = z[q] + (rho_new / rho) * s[q];
      rho = rho_new;
    }
    last_met_tolerance = exhausted || last_residual <= tolerance;
    return iterations;
  }

  unsigned int
  InterfaceKrylovSolver::gmres(const Step              &step,
                               const double             tolerance,
                               PointVector             &x,
                               PointVector             &Sx,
                               ContactProblem::Iterate &u_x) const
  {
    const auto        &active = step.active;
    const unsigned int n = x.size(), n_nodes = interface.size();

    // No coarse space: dd-newton refuses floating bodies with friction.
    Assert(coarse.empty(), ExcInternalError());
    PointVector  r     = active_residual(step, x, Sx);
    const double beta  = interface.norm(r);
    last_residual      = beta;
    last_met_tolerance = beta <= tolerance;
    if (last_met_tolerance)
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
      Z.push_back(extend_by_slip(step, Pv, n, n_nodes));
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
      h[j + 1]               = interface.norm(w);
      const double breakdown = rotate_column(h, j, cs, sn);
      H.push_back(h);
      g.push_back(-sn[j] * g[j]);
      g[j] *= cs[j];
      // |g_{j+1}| is the residual's M-norm after j + 1 directions.
      last_residual = std::abs(g[j + 1]);
      if (last_residual <= tolerance || breakdown == 0.)
        break;
      for (double &v : w)
        v /= breakdown;
      V.push_back(w);
    }
    last_met_tolerance          = last_residual <= tolerance;
    const std::vector<double> y = solve_upper_triangular(H, g);
    const unsigned int        m = H.size();
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
      if (step.coupling[i] != 0)
        x[n_nodes + i] = step.coupling[i] * x[i];
    return sets;
  }

  PointVector
  InterfaceKrylovSolver::operator_on_active(const std::vector<bool> &active,
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
  InterfaceKrylovSolver::active_residual(const Step        &step,
                                         const PointVector &x,
                                         const PointVector &Sx) const
  {
    PointVector r = operator_on_active(step.active, x, Sx);
    for (unsigned int q = 0; q < r.size(); ++q)
      r[q] = step.active[q] ? step.data[q] - r[q] : 0.;
    return r;
  }

} // namespace ddcontact
