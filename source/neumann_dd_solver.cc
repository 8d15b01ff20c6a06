#include <deal.II/base/thread_management.h>

#include <deal.II/lac/full_matrix.h>

#include <ddcontact/neumann_dd_solver.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    double
    norm(const std::vector<double> &v)
    {
      double s = 0;
      for (const double x : v)
        s += x * x;
      return std::sqrt(s);
    }

    double
    distance(const std::vector<double> &v, const std::vector<double> &w)
    {
      double s = 0;
      for (unsigned int i = 0; i < v.size(); ++i)
        s += (v[i] - w[i]) * (v[i] - w[i]);
      return std::sqrt(s);
    }

    /** Concatenate the bodies' vectors into one, and back. */
    Vector<double>
    flatten(const std::vector<Vector<double>> &u)
    {
      std::size_t n = 0;
      for (const auto &v : u)
        n += v.size();
      Vector<double> flat(n);
      std::size_t    offset = 0;
      for (const auto &v : u)
      {
        std::copy(v.begin(), v.end(), flat.begin() + offset);
        offset += v.size();
      }
      return flat;
    }

    void
    unflatten(const Vector<double> &flat, std::vector<Vector<double>> &u)
    {
      std::size_t offset = 0;
      for (auto &v : u)
      {
        std::copy(
          flat.begin() + offset, flat.begin() + offset + v.size(), v.begin());
        offset += v.size();
      }
    }
  } // namespace

  NeumannDDSolver::NeumannDDSolver(const DDParameters &parameters,
                                   const std::vector<ElasticBody<2> *> &bodies,
                                   const std::vector<ContactPair *>    &pairs,
                                   const BodyDistribution &distribution,
                                   ConditionalOStream     &pcout)
    : parameters(parameters)
    , bodies(bodies)
    , pairs(pairs)
    , distribution(distribution)
    , pcout(pcout)
  {
  }

  void
  NeumannDDSolver::solve_all(const std::vector<Vector<double>> &loads,
                             std::vector<Vector<double>>       &u) const
  {
    // A contact load beyond the floating-point range would come back as a
    // non-finite displacement blamed on the body; name the pairs instead.
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (loads[b].size() > 0 && !std::isfinite(loads[b].linfty_norm()))
      {
        std::string entries;
        for (const auto *pair : pairs)
          if (&pair->get_body_1() == bodies[b] ||
              &pair->get_body_2() == bodies[b])
            entries += (entries.empty() ? "" : ", ") +
                       ("Contact pair " + pair->name() + "/Gap");
        throw InputError(entries + ": the contact load on body '" +
                         bodies[b]->name() +
                         "' is beyond the floating-point range (gap / theta "
                         "overflows); check the gap's magnitude and the "
                         "Penalty");
      }
    // The body problems of (20) are independent: solve them concurrently,
    // each on the process that owns it.
    u.resize(bodies.size());
    distribution.solve_and_share(
      [&](const unsigned int b) { bodies[b]->solve(loads[b], u[b]); }, u);
  }

  unsigned int
  NeumannDDSolver::body_index(const ElasticBody<2> &body) const
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies[b] == &body)
        return b;
    Assert(false, ExcInternalError());
    return 0;
  }

  std::vector<double>
  NeumannDDSolver::pressure(const unsigned int                 p,
                            const std::vector<Vector<double>> &u) const
  {
    const auto         &pair = *pairs[p];
    std::vector<double> u_1n, u_2n;
    pair.normal_displacements(u[body_index(pair.get_body_1())],
                              u[body_index(pair.get_body_2())],
                              u_1n,
                              u_2n);
    const double        theta = pair.penalty();
    std::vector<double> sigma(u_1n.size());
    for (unsigned int q = 0; q < sigma.size(); ++q)
    {
      // (20): sigma_n = (1/theta) min(0, f_n - u_1n - u_2n), shifted by
      // the Uzawa multiplier.
      const double g = pair.points()[q].gap - u_1n[q] - u_2n[q];
      sigma[q]       = std::min(0., multipliers[p][q] + g / theta);
    }
    return sigma;
  }

  void
  NeumannDDSolver::check_finite_pressure(const unsigned int                 p,
                                         const std::vector<Vector<double>> &u,
                                         const unsigned int iteration) const
  {
    const auto &sigma = last_sigma_n[p];
    if (std::all_of(sigma.begin(),
                    sigma.end(),
                    [](const double x) { return std::isfinite(x); }))
      return;
    // Either the iterate itself is no longer finite (the iteration
    // diverged), or a finite gap over theta overflowed (theta too small).
    const bool finite_iterate = std::all_of(
      u.begin(),
      u.end(),
      [](const Vector<double> &v) { return std::isfinite(v.linfty_norm()); });
    if (finite_iterate)
    {
      std::ostringstream s;
      s << std::setprecision(3) << "Contact pair " << pairs[p]->name()
        << "/Penalty: the contact pressure is not finite at DD iteration "
        << iteration << ": theta = " << pairs[p]->penalty()
        << " is so small that gap / theta overflows; raise the Penalty (or "
           "the pair's Thickness)";
      throw InputError(s.str());
    }
    IterationRecord record;
    record.iteration          = iteration;
    record.residual           = std::numeric_limits<double>::quiet_NaN();
    const auto [best, best_k] = best_of_phase();
    throw DivergenceError(divergence_message(record, best, best_k));
  }

  std::pair<double, unsigned int>
  NeumannDDSolver::best_of_phase() const
  {
    double       best   = std::numeric_limits<double>::max();
    unsigned int best_k = 0;
    for (unsigned int i = phase_start; i < records.size(); ++i)
      if (records[i].residual < best)
      {
        best   = records[i].residual;
        best_k = records[i].iteration;
      }
    return {best, best_k};
  }

  void
  NeumannDDSolver::solve_bodies(const std::vector<std::vector<double>> &sigma_n,
                                std::vector<Vector<double>> &u_tilde) const
  {
    std::vector<Vector<double>> loads(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      loads[b].reinit(bodies[b]->n_dofs());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      pairs[p]->add_contact_loads(sigma_n[p],
                                  loads[body_index(pairs[p]->get_body_1())],
                                  loads[body_index(pairs[p]->get_body_2())]);

    solve_all(loads, u_tilde);
  }

  std::vector<std::vector<double>>
  NeumannDDSolver::normal_displacements_by_body(
    const std::vector<Vector<double>> &u) const
  {
    std::vector<std::vector<double>> by_body(bodies.size());
    for (const auto *pair : pairs)
    {
      std::vector<double> u_1n, u_2n;
      const unsigned int  b1 = body_index(pair->get_body_1());
      const unsigned int  b2 = body_index(pair->get_body_2());
      pair->normal_displacements(u[b1], u[b2], u_1n, u_2n);
      by_body[b1].insert(by_body[b1].end(), u_1n.begin(), u_1n.end());
      by_body[b2].insert(by_body[b2].end(), u_2n.begin(), u_2n.end());
    }
    return by_body;
  }

  void
  NeumannDDSolver::initialize()
  {
    records.clear();
    uzawa_updates      = 0;
    mesh_uzawa_updates = 0;
    phase_start        = 0;
    last_penetration   = std::numeric_limits<double>::max();
    mesh_limited       = false;
    gamma              = parameters.gamma;
    multipliers.assign(pairs.size(), {});
    for (unsigned int p = 0; p < pairs.size(); ++p)
      multipliers[p].assign(pairs[p]->points().size(), 0.);
    record_multiplier_points();
    previous_residual.reinit(0);
    delta_f.clear();
    delta_g.clear();
    timer.restart();

    std::vector<Vector<double>> u(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      u[b].reinit(bodies[b]->n_dofs());

    if (parameters.initial_guess == "winkler")
    {
      // Elastic-layer model: each body acts on S like a bed of springs of
      // stiffness E'/H (E' = E/(1-nu^2), H its thickness across S), in
      // series with the penalty; the pressure of this model, applied to
      // the contact-free solution's gap, loads the first solve.
      std::vector<Vector<double>> u_free;
      solve_all(std::vector<Vector<double>>(bodies.size()), u_free);

      std::vector<Vector<double>> loads(bodies.size());
      for (unsigned int b = 0; b < bodies.size(); ++b)
        loads[b].reinit(bodies[b]->n_dofs());
      for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const auto  &pair       = *pairs[p];
        const auto  &b1         = pair.get_body_1();
        const auto  &b2         = pair.get_body_2();
        const double H1         = pair.thickness_of_body_1();
        const auto   compliance = [&](const ElasticBody<2> &body, double H)
        {
          const auto &m = body.get_material();
          return H * (1 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
        };
        // Body 2's thickness measured like body 1's.
        const double c_w =
          compliance(b1, H1) + compliance(b2, pair.thickness_of_body_2());

        std::vector<double> u_1n, u_2n;
        pair.normal_displacements(
          u_free[body_index(b1)], u_free[body_index(b2)], u_1n, u_2n);
        std::vector<double> sigma(u_1n.size());
        for (unsigned int q = 0; q < sigma.size(); ++q)
          sigma[q] = std::min(0., pair.points()[q].gap - u_1n[q] - u_2n[q]) /
                     (pair.penalty() + c_w);
        pair.add_contact_loads(
          sigma, loads[body_index(b1)], loads[body_index(b2)]);
      }
      solve_all(loads, u);

      // The model knows neither bending nor chains of contacts (a plate
      // pressed onto a base bends through the gap the layer model fills),
      // and can start far worse than zero. Drop it when one step of (20)
      // moves it an order of magnitude more than it moves the zero guess
      // (three bodies: 5e4 times). A modest excess is no verdict: on the
      // paper's scene (1.08 times) and Hertz (3 times) it still saves
      // iterations.
      std::vector<Vector<double>> zero(bodies.size()), from_zero, from_layer;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        zero[b].reinit(bodies[b]->n_dofs());
      std::vector<std::vector<double>> sigma_zero(pairs.size()),
        sigma_layer(pairs.size());
      for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        sigma_zero[p]  = pressure(p, zero);
        sigma_layer[p] = pressure(p, u);
      }
      // Without an initial overlap the zero guess's step is the
      // contact-free solution already at hand.
      bool zero_is_loaded = false;
      for (const auto &sigma : sigma_zero)
        for (const double v : sigma)
          zero_is_loaded = zero_is_loaded || (v != 0);
      if (zero_is_loaded)
        solve_bodies(sigma_zero, from_zero);
      else
        from_zero = u_free;
      solve_bodies(sigma_layer, from_layer);
      double step_zero = 0, step_layer = 0;
      for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        step_zero += from_zero[b].norm_sqr();
        from_layer[b] -= u[b];
        step_layer += from_layer[b].norm_sqr();
      }
      if (step_layer > 100 * step_zero) // squared norms: 10 times
      {
        pcout << "  elastic-layer initial guess is worse than zero here ("
              << std::sqrt(step_layer / step_zero)
              << " times the first step); starting from zero" << std::endl;
        u = zero;
      }
    }

    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->get_solution() = u[b];

    if (parameters.relaxation == "auto")
    {
      // The optimal fixed gamma for a spectrum in [1, 1 + lambda_max] is
      // 2 / (2 + lambda_max); gamma* = 2 / (1 + lambda_max).
      const double limit      = estimate_gamma_limit();
      const double lambda_max = 2. / limit - 1.;
      gamma                   = 2. / (2. + lambda_max);
      pcout << "  automatic relaxation: gamma* = " << limit
            << ", gamma = " << gamma << std::endl;
    }
  }

  void
  NeumannDDSolver::record_multiplier_points()
  {
    multiplier_points.assign(pairs.size(), {});
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (const auto &pt : pairs[p]->points())
        multiplier_points[p].push_back(pt.x);
  }

  void
  NeumannDDSolver::reinit_after_refinement()
  {
    // The contact points live on the common refinement of S_1 and S_2, so
    // they move when either mesh is refined. lambda approximates the
    // contact pressure, a function on S: each new point takes the value of
    // the nearest old one (piecewise constant transfer; the next Uzawa
    // phases correct it on the new mesh).
    multipliers.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      const auto         &old_x = multiplier_points[p];
      std::vector<double> lambda(pairs[p]->points().size(), 0.);
      if (!old_x.empty() && multipliers[p].size() == old_x.size())
        for (unsigned int q = 0; q < lambda.size(); ++q)
        {
          const Point<2> &x       = pairs[p]->points()[q].x;
          unsigned int    nearest = 0;
          for (unsigned int i = 1; i < old_x.size(); ++i)
            if (x.distance_square(old_x[i]) < x.distance_square(old_x[nearest]))
              nearest = i;
          lambda[q] = multipliers[p][nearest];
        }
      multipliers[p] = std::move(lambda);
    }
    record_multiplier_points();
    // The penetration of the new mesh is judged anew.
    mesh_uzawa_updates = 0;
    last_penetration   = std::numeric_limits<double>::max();
    mesh_limited       = false;

    previous_residual.reinit(0);
    delta_f.clear();
    delta_g.clear();
    last_sigma_n.clear();
    last_u_tilde.clear();
    // The residual jumps with the new mesh: divergence is judged anew.
    phase_start = records.size();
  }

  void
  NeumannDDSolver::adopt_current_iterate()
  {
    last_u_tilde.resize(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      last_u_tilde[b] = bodies[b]->get_solution();
    last_sigma_n.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      last_sigma_n[p] = pressure(p, last_u_tilde);
  }

  const Vector<double> &
  NeumannDDSolver::last_body_solution(const ElasticBody<2> &body) const
  {
    Assert(last_u_tilde.size() == bodies.size(),
           ExcMessage("step() must be called first"));
    return last_u_tilde[body_index(body)];
  }

  BoundaryTractionSamples
  NeumannDDSolver::last_contact_traction(const ElasticBody<2> &body) const
  {
    Assert(last_sigma_n.size() == pairs.size(),
           ExcMessage("step() must be called first"));
    BoundaryTractionSamples samples;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (&pairs[p]->get_body_1() == &body || &pairs[p]->get_body_2() == &body)
        pairs[p]->add_traction_samples(last_sigma_n[p], body, samples);
    return samples;
  }

  void
  NeumannDDSolver::relax(const std::vector<Vector<double>> &u_tilde)
  {
    std::vector<Vector<double>> u(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      u[b] = bodies[b]->get_solution();
    const Vector<double> x = flatten(u);
    const Vector<double> g = flatten(u_tilde);
    Vector<double>       f = g;
    f -= x; // residual of the fixed-point map u -> u~
    Vector<double> x_new(x);

    if (parameters.relaxation == "fixed" || parameters.relaxation == "auto")
      x_new.add(gamma, f); // (21)
    else if (parameters.relaxation == "aitken")
    {
      // Aitken's dynamic relaxation: the secant estimate of the best
      // gamma for the residual's recent change.
      if (previous_residual.size() == f.size())
      {
        Vector<double> df = f;
        df -= previous_residual;
        const double dd = df * df;
        if (dd > 0)
          gamma = std::clamp(-gamma * (previous_residual * df) / dd, 1e-6, 1.);
      }
      previous_residual = f;
      x_new.add(gamma, f);
    }
    else // anderson
    {
      // Anderson acceleration (type II): combine the last m map values
      // so that the linearised residual is smallest (equivalent to GMRES
      // on a linear fixed-point map).
      if (previous_residual.size() == f.size())
      {
        Vector<double> df = f, dg = g;
        df -= previous_residual;
        dg -= previous_g;
        delta_f.push_back(df);
        delta_g.push_back(dg);
        if (delta_f.size() > parameters.anderson_depth)
        {
          delta_f.pop_front();
          delta_g.pop_front();
        }
      }
      previous_residual = f;
      previous_g        = g;
      // The least-squares problem min ||f - sum alpha_i df_i|| by a
      // modified Gram-Schmidt QR of the columns df_i, newest first. With a
      // stiff penalty the differences df_i become nearly parallel (the
      // residual is dominated by the few most compliant modes); a column
      // whose remainder after orthogonalisation is below 1e-6 of its norm
      // is dropped from the history (filtering): its coefficient would be
      // up to 1e6 times the step and extrapolate across the kinks of the
      // contact map (the Hertz scene diverged with 1e-10). 1e-6 on R is
      // what the 1e-12 trace regularisation of the normal equations used
      // before amounted to (their condition number is squared). The normal
      // equations used before square this condition number (the paper scene at
      // c = 1e-4 ran 3625 iterations into a non-finite iterate with them).
      std::vector<Vector<double>> q;
      FullMatrix<double>          r;
      for (bool complete = false; !complete;)
      {
        complete = true;
        q.clear();
        r.reinit(delta_f.size(), delta_f.size());
        for (unsigned int j = 0; j < delta_f.size(); ++j)
        {
          const unsigned int column = delta_f.size() - 1 - j; // newest first
          Vector<double>     v      = delta_f[column];
          for (unsigned int i = 0; i < j; ++i)
          {
            r(i, j) = q[i] * v;
            v.add(-r(i, j), q[i]);
          }
          r(j, j) = v.l2_norm();
          if (!(r(j, j) > 1e-6 * delta_f[column].l2_norm()))
          {
            delta_f.erase(delta_f.begin() + column);
            delta_g.erase(delta_g.begin() + column);
            complete = false;
            break;
          }
          v /= r(j, j);
          q.push_back(v);
        }
      }
      const unsigned int m_kept = q.size();
      Vector<double>     alpha(m_kept);
      for (unsigned int i = m_kept; i-- > 0;)
      {
        double sum = q[i] * f;
        for (unsigned int j = i + 1; j < m_kept; ++j)
          sum -= r(i, j) * alpha(j);
        alpha(i) = sum / r(i, i);
      }
      // x_new = (x + gamma f) - sum alpha_i (dx_i + gamma df_i), with
      // dx = dg - df (alpha(j) belongs to the j-th newest column).
      x_new.add(gamma, f);
      for (unsigned int j = 0; j < m_kept; ++j)
      {
        const unsigned int column = m_kept - 1 - j;
        x_new.add(-alpha(j), delta_g[column]);
        x_new.add(alpha(j) * (1. - gamma), delta_f[column]);
      }
    }

    unflatten(x_new, u);
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      bodies[b]->get_constraints().distribute(u[b]);
      bodies[b]->get_solution() = u[b];
    }
  }

  bool
  NeumannDDSolver::step()
  {
    const auto                  u = current_iterate();
    std::vector<Vector<double>> u_tilde;

    IterationRecord record;
    record.iteration = records.size() + 1;
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      const auto state = contact_state(p);
      record.force += state.force_1.norm();
      record.active_length += state.contact_length;
      record.max_penetration =
        std::max(record.max_penetration, state.max_penetration);
    }

    last_sigma_n.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      last_sigma_n[p] = pressure(p, u);
      check_finite_pressure(p, u, record.iteration);
    }
    solve_bodies(last_sigma_n, u_tilde);
    last_u_tilde        = u_tilde;
    const auto un       = normal_displacements_by_body(u);
    const auto un_tilde = normal_displacements_by_body(u_tilde);

    double diff2 = 0, norm2 = 0;
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      diff2 += std::pow(distance(un_tilde[b], un[b]), 2);
      norm2 += std::pow(norm(un_tilde[b]), 2);
    }
    record.residual = (norm2 > 0) ? std::sqrt(diff2 / norm2) : std::sqrt(diff2);
    record.gamma    = gamma;

    relax(u_tilde);

    std::vector<Vector<double>> u_new(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      u_new[b] = bodies[b]->get_solution();
    const auto un_new = normal_displacements_by_body(u_new);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!un_new[b].empty())
      {
        const double n   = norm(un_new[b]);
        const double d   = distance(un_new[b], un[b]);
        record.increment = std::max(record.increment, (n > 0) ? d / n : d);
      }
    record.time = timer.wall_time();
    records.push_back(record);
    if (iteration_callback)
      iteration_callback(record.iteration);

    const bool print = record.iteration <= 5 || record.iteration % 50 == 0 ||
                       record.residual <= parameters.eps_residual ||
                       record.increment <= parameters.eps_u;
    if (print)
      pcout << "  DD " << std::setw(5) << record.iteration << std::scientific
            << std::setprecision(3) << "  residual " << record.residual
            << "  increment " << record.increment << "  gamma " << record.gamma
            << "  force " << record.force << "  active " << record.active_length
            << "  penetration " << record.max_penetration << std::defaultfloat
            << std::fixed << std::setprecision(2) << "  t " << record.time
            << "s" << std::defaultfloat << std::endl;

    // Divergence: a non-finite residual, growth far above the best residual
    // so far, or no progress at all for many iterations (a 2-cycle between
    // overlap and separation, typical for gamma above gamma*).
    const bool finite          = std::isfinite(record.residual);
    const auto [best, best_k]  = best_of_phase();
    const unsigned int k_phase = record.iteration - phase_start;
    const bool         grew    = record.residual > 1e3 * best && k_phase > 3;
    const bool         stuck =
      record.iteration - best_k > std::max<unsigned int>(50, k_phase / 2);
    if (!finite || grew || stuck)
      throw DivergenceError(divergence_message(record, best, best_k));

    const bool residual_test = record.residual <= parameters.eps_residual;
    const bool paper_test    = record.increment <= parameters.eps_u;
    if (parameters.stopping == "residual")
      return residual_test;
    if (parameters.stopping == "paper")
      return paper_test;
    return residual_test || paper_test;
  }

  std::string
  NeumannDDSolver::divergence_message(const IterationRecord &record,
                                      const double           best,
                                      const unsigned int     best_k) const
  {
    // gamma* = 2/(1 + lambda_max) of the linearised iteration (21) tells
    // what went wrong: the relaxation (gamma above gamma*), the penalty
    // (lambda_max ~ compliance of S / theta so large that no relaxation
    // contracts in a useful number of steps), or the tolerance (the
    // residual cannot fall below round-off times lambda_max).
    const double       limit      = estimate_gamma_limit();
    const double       lambda_max = 2. / limit - 1.;
    std::ostringstream s;
    s << std::setprecision(3) << "the domain decomposition diverged at "
      << "iteration " << record.iteration << " (residual ";
    if (std::isfinite(record.residual))
      s << record.residual;
    else
      s << "not finite";
    s << ", best " << best << " at iteration " << best_k
      << "; estimated gamma* = " << limit << ")";

    std::string penalty_entries;
    for (const auto *pair : pairs)
      penalty_entries += (penalty_entries.empty() ? "" : ", ") +
                         ("Contact pair " + pair->name() + "/Penalty");

    const double round_off =
      1e3 * std::numeric_limits<double>::epsilon() * (1. + lambda_max);
    if (best <= round_off)
      s << ": the residual stagnates at the round-off level of this problem "
        << "(about " << round_off << " = 1000 eps (1 + lambda_max)); raise "
        << "Domain decomposition/eps_residual above " << 10 * best;
    else if (limit < 1e-3)
      s << ": the penalty is too stiff for the domain decomposition (the "
        << "contact-zone compliance is " << lambda_max << " times theta, so "
        << "every relaxation contracts by at most about 1 - gamma* per "
        << "iteration); raise " << penalty_entries
        << " (c of theta = c H/E_1) by a factor of about " << lambda_max / 40.
        << " (for gamma* ~ 0.05; with contrasting "
        << "materials, making the softer body Body 1 does the same) and set "
        << "Domain decomposition/Augmented Lagrangian = true for an exact "
        << "contact, or use Domain decomposition/Solver = monolithic";
    else if (parameters.relaxation == "fixed" && parameters.gamma > limit)
      s << ": Domain decomposition/Gamma = " << parameters.gamma
        << " is above the estimated stable limit gamma*; use Gamma below "
        << limit << " (about " << 2 * limit / (2 + limit)
        << " is fastest) or Relaxation = anderson";
    else if (parameters.relaxation == "fixed")
      s << ": Domain decomposition/Gamma = " << parameters.gamma
        << " is below the estimated gamma* of the linearised iteration, but "
        << "the active set oscillates; use a smaller Gamma or Relaxation = "
        << "anderson";
    else
      s << " with Relaxation = " << parameters.relaxation
        << "; use Relaxation = fixed with Gamma = " << 2 * limit / (2 + limit)
        << " (below gamma*), or a larger " << penalty_entries;
    return s.str();
  }

  double
  NeumannDDSolver::estimate_gamma_limit() const
  {
    // Power iteration on the linearised DD operator with every contact
    // point active: v -> A^{-1} (1/theta) C^T C v, whose largest eigenvalue
    // lambda_max gives the stability limit of (21), gamma* = 2/(1 +
    // lambda_max) (the spectrum of I + A^{-1} J'' lies in [1, 1 +
    // lambda_max]).
    std::vector<Vector<double>> base, v(bodies.size()), w;
    solve_all(std::vector<Vector<double>>(bodies.size()), base);
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      v[b] = bodies[b]->get_solution();
      v[b] -= base[b];
      // Scaled by its largest entry first: a diverged iterate (1e200)
      // would overflow the sums of squares below; a non-finite one is
      // replaced by a generic start vector.
      const double largest = v[b].linfty_norm();
      if (largest > 0 && std::isfinite(largest))
        v[b] /= largest;
      else
        for (unsigned int i = 0; i < v[b].size(); ++i)
          v[b](i) = 1. + 0.1 * std::sin(1. + i);
      bodies[b]->get_constraints().set_zero(v[b]);
    }
    double lambda = 0;
    for (unsigned int it = 0; it < 30; ++it)
    {
      std::vector<Vector<double>> loads(bodies.size());
      for (unsigned int b = 0; b < bodies.size(); ++b)
        loads[b].reinit(bodies[b]->n_dofs());
      for (const auto *pair : pairs)
      {
        const unsigned int  b1 = body_index(pair->get_body_1());
        const unsigned int  b2 = body_index(pair->get_body_2());
        std::vector<double> u_1n, u_2n;
        pair->normal_displacements(v[b1], v[b2], u_1n, u_2n);
        std::vector<double> sigma(u_1n.size());
        for (unsigned int q = 0; q < sigma.size(); ++q)
          sigma[q] = -(u_1n[q] + u_2n[q]) / pair->penalty();
        pair->add_contact_loads(sigma, loads[b1], loads[b2]);
      }
      solve_all(loads, w);
      double norm_v = 0, norm_w = 0;
      for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        w[b] -= base[b];
        w[b] *= -1.;
        norm_v += v[b].norm_sqr();
        norm_w += w[b].norm_sqr();
      }
      if (norm_w == 0 || norm_v == 0)
        break;
      lambda = std::sqrt(norm_w / norm_v);
      for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        v[b] = w[b];
        v[b] /= std::sqrt(norm_w);
      }
    }
    return 2. / (1. + lambda);
  }

  bool
  NeumannDDSolver::start_uzawa_phase()
  {
    if (!parameters.augmented_lagrangian ||
        mesh_uzawa_updates >= parameters.al_max_updates)
      return false;

    // The converged pressure min(0, lambda + g/theta) of every pair, and
    // how far the bodies still penetrate.
    std::vector<std::vector<double>> sigma_n(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      sigma_n[p] = pressure(p, current_iterate());
    const auto [max_penetration, ratio] = penetration();
    pcout << "  Uzawa check " << mesh_uzawa_updates + 1 << ": max penetration "
          << max_penetration << " (" << ratio << " of the approach)"
          << std::endl;
    mesh_limited = false;
    if (ratio <= parameters.al_tolerance)
      return false;
    if (mesh_uzawa_updates == 0)
      first_penetration = max_penetration;
    // With non-matching meshes the pointwise condition at every contact
    // point cannot hold exactly for the discrete displacements: stop when
    // the penetration no longer shrinks, after the updates have removed
    // most of it (a tenth or less of the first check's). A penetration
    // that shrinks slowly from the start (a soft penalty, e.g. c = 100:
    // 3 % per update) is not that limit: the updates go on, up to AL max
    // updates.
    if (max_penetration > 0.9 * last_penetration &&
        max_penetration <= 0.1 * first_penetration)
    {
      mesh_limited = true;
      pcout << "  Uzawa: the penetration no longer decreases (" << ratio
            << " of the approach, AL tolerance " << parameters.al_tolerance
            << "): the limit of the non-matching zone meshes; stopping"
            << std::endl;
      return false;
    }
    last_penetration = max_penetration;

    // lambda <- min(0, lambda + g/theta), and a new phase of the DD.
    multipliers = std::move(sigma_n);
    ++uzawa_updates;
    ++mesh_uzawa_updates;
    phase_start = records.size();
    previous_residual.reinit(0);
    delta_f.clear();
    delta_g.clear();
    gamma = (parameters.relaxation == "auto") ? gamma : parameters.gamma;
    return true;
  }

  std::vector<Vector<double>>
  NeumannDDSolver::current_iterate() const
  {
    std::vector<Vector<double>> u(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      u[b] = bodies[b]->get_solution();
    return u;
  }

  std::pair<double, double>
  NeumannDDSolver::penetration() const
  {
    double max_penetration = 0, max_displacement = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      const auto state = contact_state(p);
      max_penetration  = std::max(max_penetration, state.max_penetration);
      for (unsigned int q = 0; q < state.u_1n.size(); ++q)
        max_displacement = std::max(
          max_displacement, std::abs(state.u_1n[q]) + std::abs(state.u_2n[q]));
    }
    return {max_penetration,
            max_penetration / std::max(max_displacement, 1e-300)};
  }

  std::string
  NeumannDDSolver::augmented_lagrangian_shortfall() const
  {
    if (!parameters.augmented_lagrangian)
      return "";
    const double ratio = penetration().second;
    if (ratio <= parameters.al_tolerance || mesh_limited)
      return "";
    std::ostringstream s;
    s << std::setprecision(3)
      << "the augmented Lagrangian stopped with a penetration of " << ratio
      << " of the approach, above Domain decomposition/AL tolerance = "
      << parameters.al_tolerance << ", after " << mesh_uzawa_updates
      << " Uzawa updates on the last mesh (AL max updates = "
      << parameters.al_max_updates
      << "); results are written with status \"stalled\". Make the "
         "penalty stiffer (smaller Contact pair/Penalty) so that each "
         "update removes more of the penetration, or raise AL max updates";
    return s.str();
  }

  unsigned int
  NeumannDDSolver::run()
  {
    do
    {
      bool converged = false;
      while (!converged)
      {
        if (records.size() >= parameters.max_iterations)
        {
          std::ostringstream s;
          s << "the domain decomposition did not converge in "
            << parameters.max_iterations << " iterations (residual "
            << std::setprecision(3) << records.back().residual
            << ", eps_residual " << parameters.eps_residual
            << "); raise Domain decomposition/Max iterations, or use "
               "Relaxation = anderson";
          throw DivergenceError(s.str());
        }
        converged = step();
      }
    } while (start_uzawa_phase());
    return records.size();
  }

  ContactState
  NeumannDDSolver::contact_state(const unsigned int p) const
  {
    const auto &pair = *pairs[p];
    const auto  u    = current_iterate();

    ContactState state;
    pair.normal_displacements(u[body_index(pair.get_body_1())],
                              u[body_index(pair.get_body_2())],
                              state.u_1n,
                              state.u_2n);
    state.sigma_n = pressure(p, u);
    Vector<double> l1(pair.get_body_1().n_dofs()),
      l2(pair.get_body_2().n_dofs());
    std::tie(state.force_1, state.force_2) =
      pair.add_contact_loads(state.sigma_n, l1, l2);
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (unsigned int q = 0; q < state.sigma_n.size(); ++q)
    {
      const auto &pt     = pair.points()[q];
      state.max_pressure = std::max(state.max_pressure, -state.sigma_n[q]);
      if (state.sigma_n[q] < 0)
      {
        state.contact_length += pt.JxW;
        // Position along the tangent of S, for the half-width.
        const double s = pt.x[0] * pt.normal[1] - pt.x[1] * pt.normal[0];
        lo             = std::min(lo, s);
        hi             = std::max(hi, s);
      }
      state.max_penetration =
        std::max(state.max_penetration, state.u_1n[q] + state.u_2n[q] - pt.gap);
    }
    state.half_width = (hi >= lo) ? 0.5 * (hi - lo) : 0.;
    return state;
  }
} // namespace ddcontact
