#include <deal.II/lac/full_matrix.h>

#include <ddcontact/solvers/relaxation.h>
#include <ddcontact/tasks.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  namespace
  {
    // The entrywise operations of the strategies. A process may own no
    // entry of the iterate (a one-cell body on a group of several
    // processes: one owns every dof, the others none), and deal.II's
    // Vector refuses to operate on an empty vector; such a process still
    // takes every inner product, which may be collective.

    /** @p x -= @p y. */
    void
    subtract(Vector<double> &x, const Vector<double> &y)
    {
      AssertDimension(x.size(), y.size());
      if (x.size() > 0)
        x -= y;
    }

    /** @p x += @p a @p y. */
    void
    add(Vector<double> &x, const double a, const Vector<double> &y)
    {
      AssertDimension(x.size(), y.size());
      if (x.size() > 0)
        x.add(a, y);
    }

    /** @p x /= @p s. */
    void
    divide(Vector<double> &x, const double s)
    {
      if (x.size() > 0)
        x /= s;
    }
  } // namespace

  Relaxation::Relaxation(const double gamma)
    : gamma(gamma)
    , inner([](const Vector<double> &x, const Vector<double> &y)
            { return ordered_dot(x, y); })
  {
  }

  Vector<double>
  FixedRelaxation::update(const Vector<double> &x, const Vector<double> &g)
  {
    Vector<double> f(g);
    subtract(f, x);
    Vector<double> x_new(x);
    add(x_new, gamma, f); // (21): u^k + gamma (u~^{k+1} - u^k)
    return x_new;
  }

  void
  AitkenRelaxation::reset()
  {
    previous_residual.reinit(0);
    has_previous = false;
  }

  Vector<double>
  AitkenRelaxation::update(const Vector<double> &x, const Vector<double> &g)
  {
    Vector<double> f(g);
    subtract(f, x); // residual of the fixed-point map u -> u~
    // The secant estimate of the best gamma for the residual's recent
    // change.
    if (has_previous)
    {
      Vector<double> df(f);
      subtract(df, previous_residual);
      const double dd = inner(df, df);
      if (dd > 0)
        gamma =
          std::clamp(-gamma * inner(previous_residual, df) / dd, 1e-6, 1.);
    }
    previous_residual = f;
    has_previous      = true;
    Vector<double> x_new(x);
    add(x_new, gamma, f);
    return x_new;
  }

  AndersonRelaxation::AndersonRelaxation(const double       gamma,
                                         const unsigned int depth)
    : Relaxation(gamma)
    , depth(depth)
  {
  }

  void
  AndersonRelaxation::reset()
  {
    previous_residual.reinit(0);
    has_previous = false;
    delta_f.clear();
    delta_g.clear();
  }

  Vector<double>
  AndersonRelaxation::update(const Vector<double> &x, const Vector<double> &g)
  {
    Vector<double> f(g);
    subtract(f, x);
    if (has_previous)
    {
      Vector<double> df = f, dg = g;
      subtract(df, previous_residual);
      subtract(dg, previous_g);
      delta_f.push_back(df);
      delta_g.push_back(dg);
      if (delta_f.size() > depth)
      {
        delta_f.pop_front();
        delta_g.pop_front();
      }
    }
    previous_residual = f;
    previous_g        = g;
    has_previous      = true;

    // The least-squares problem min ||f - sum alpha_i df_i|| by a modified
    // Gram-Schmidt QR of the columns df_i, newest first. With a stiff
    // penalty the differences df_i become nearly parallel (the residual is
    // dominated by the few most compliant modes); a column whose remainder
    // after orthogonalisation is below 1e-6 of its norm is dropped from the
    // history (filtering): its coefficient would be up to 1e6 times the
    // step and extrapolate across the kinks of the contact map (the Hertz
    // scene diverged with 1e-10). The normal equations used before square
    // the condition number (the paper scene at c = 1e-4 ran 3625
    // iterations into a non-finite iterate with them).
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
          r(i, j) = inner(q[i], v);
          add(v, -r(i, j), q[i]);
        }
        r(j, j) = std::sqrt(inner(v, v));
        if (!(r(j, j) >
              1e-6 * std::sqrt(inner(delta_f[column], delta_f[column]))))
        {
          delta_f.erase(delta_f.begin() + column);
          delta_g.erase(delta_g.begin() + column);
          complete = false;
          break;
        }
        divide(v, r(j, j));
        q.push_back(v);
      }
    }
    const unsigned int m_kept = q.size();
    Vector<double>     alpha(m_kept);
    for (unsigned int i = m_kept; i-- > 0;)
    {
      double sum = inner(q[i], f);
      for (unsigned int j = i + 1; j < m_kept; ++j)
        sum -= r(i, j) * alpha(j);
      alpha(i) = sum / r(i, i);
    }
    // x_new = (x + gamma f) - sum alpha_i (dx_i + gamma df_i), with
    // dx = dg - df (alpha(j) belongs to the j-th newest column).
    Vector<double> x_new(x);
    add(x_new, gamma, f);
    for (unsigned int j = 0; j < m_kept; ++j)
    {
      const unsigned int column = m_kept - 1 - j;
      add(x_new, -alpha(j), delta_g[column]);
      add(x_new, alpha(j) * (1. - gamma), delta_f[column]);
    }
    return x_new;
  }

  std::unique_ptr<Relaxation>
  make_relaxation(const DomainDecompositionParameters &parameters)
  {
    if (parameters.relaxation == RelaxationType::aitken)
      return std::make_unique<AitkenRelaxation>(parameters.gamma);
    if (parameters.relaxation == RelaxationType::anderson)
      return std::make_unique<AndersonRelaxation>(parameters.gamma,
                                                  parameters.anderson_depth);
    return std::make_unique<FixedRelaxation>(parameters.gamma);
  }
} // namespace ddcontact
