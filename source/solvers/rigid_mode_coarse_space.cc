#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <ddcontact/parameter_tools.h>
#include <ddcontact/solvers/rigid_mode_coarse_space.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  namespace
  {
    /** The smallest singular value of @p h scaled to a unit diagonal by
     * the diagonal @p d (of H on all unknowns). */
    double
    smallest_scaled_singular_value(const FullMatrix<double>  &h,
                                   const std::vector<double> &d)
    {
      const unsigned int       n = h.m();
      LAPACKFullMatrix<double> scaled(n, n);
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          scaled(a, b) = h(a, b) / std::sqrt(d[a] * d[b]);
      scaled.compute_svd();
      return scaled.singular_value(n - 1);
    }

    /** Whether contact holds the modes [first, last) (of one body, or all
     * of them): their block of @p h, with the diagonal @p diagonal, is
     * regular, and no mode has a diagonal entry that vanishes against the
     * interface's @p total_weight. */
    bool
    are_held(const FullMatrix<double>  &h,
             const std::vector<double> &diagonal,
             const double               total_weight,
             const unsigned int         first,
             const unsigned int         last)
    {
      FullMatrix<double>  block(last - first, last - first);
      std::vector<double> d(diagonal.begin() + first, diagonal.begin() + last);
      for (unsigned int a = first; a < last; ++a)
      {
        if (!(diagonal[a] > 1e-20 * total_weight))
          return false;
        for (unsigned int b = first; b < last; ++b)
          block(a - first, b - first) = h(a, b);
      }
      return smallest_scaled_singular_value(block, d) > 1e-10;
    }
  } // namespace

  RigidModeCoarseSpace::RigidModeCoarseSpace(const ContactProblem   &problem,
                                             const ContactInterface &interface)
    : problem(problem)
    , interface(interface)
  {
  }

  void
  RigidModeCoarseSpace::reinit()
  {
    columns.clear();
    loads.clear();
    mode_of.clear();
    active.clear();
    const auto &bodies = problem.get_bodies();
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      const auto &modes = bodies[b]->get_rigid_modes();
      if (modes.size() == 0)
        continue;
      // The loads are assembled where the body is solved; every process
      // runs the Newton iteration, so its owner sends them to all.
      std::vector<double> e = bodies[b]->get_mode_loads();
      e.resize(modes.size());
      if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        Utilities::MPI::broadcast(e.data(),
                                  e.size(),
                                  problem.get_distribution().owner_of(b),
                                  MPI_COMM_WORLD);
      for (unsigned int k = 0; k < modes.size(); ++k)
      {
        auto u = problem.zero_iterate();
        u[b]   = modes.mode(k);
        columns.push_back(interface.normal_approach(u));
        loads.push_back(e[k]);
        mode_of.emplace_back(b, k);
      }
    }
    if (empty())
      return;

    // Contact must be able to hold every mode: on all unknowns H has to be
    // regular. A mode that moves no gap (a translation along a flat zone)
    // has H_kk = 0 against about the zone's length for the others (the
    // modes are scaled to values of order one).
    double total_weight = 0;
    for (unsigned int i = 0; i < interface.size(); ++i)
      total_weight += interface.weight(i);
    const FullMatrix<double> h = gram({});
    diagonal.assign(size(), 0.);
    for (unsigned int k = 0; k < size(); ++k)
      diagonal[k] = h(k, k);
    const auto held = [&](const unsigned int first, const unsigned int last)
    { return are_held(h, diagonal, total_weight, first, last); };
    if (!held(0, size()))
    {
      // The body whose own modes contact cannot hold, else the first.
      unsigned int culprit = mode_of[0].first;
      for (unsigned int first = 0, last = 0; first < size(); first = last)
      {
        last = first;
        while (last < size() && mode_of[last].first == mode_of[first].first)
          ++last;
        if (!held(first, last))
        {
          culprit = mode_of[first].first;
          break;
        }
      }
      const auto &body = *bodies[culprit];
      throw InputError("Body " + body.name() +
                       "/Dirichlet: the body is floating (free " +
                       body.get_rigid_modes().description() +
                       "), and contact cannot hold a rigid motion of it: it "
                       "moves no contact gap (e.g. sliding along a flat "
                       "zone); prescribe that displacement component "
                       "somewhere");
    }
  }

  std::string
  RigidModeCoarseSpace::description() const
  {
    std::string s;
    for (unsigned int k = 0; k < size(); ++k)
      if (mode_of[k].second == 0)
      {
        const auto &body = *problem.get_bodies()[mode_of[k].first];
        s += std::string(s.empty() ? "" : ", ") + body.name() + ": free " +
             body.get_rigid_modes().description();
      }
    return s;
  }

  FullMatrix<double>
  RigidModeCoarseSpace::gram(const std::vector<bool> &on) const
  {
    FullMatrix<double> h(size(), size());
    for (unsigned int a = 0; a < size(); ++a)
      for (unsigned int b = 0; b <= a; ++b)
      {
        double sum = 0;
        for (unsigned int i = 0; i < interface.size(); ++i)
          if (on.empty() || on[i])
            sum += interface.weight(i) * columns[a][i] * columns[b][i];
        h(a, b) = h(b, a) = sum;
      }
    return h;
  }

  bool
  RigidModeCoarseSpace::holds(const std::vector<bool> &on) const
  {
    if (empty())
      return true;
    if (std::none_of(on.begin(), on.end(), [](const bool a) { return a; }))
      return false;
    return smallest_scaled_singular_value(gram(on), diagonal) > 1e-12;
  }

  void
  RigidModeCoarseSpace::set_active(const std::vector<bool> &on)
  {
    AssertThrow(holds(on),
                ExcMessage("the active set does not hold the floating "
                           "bodies' rigid modes"));
    active  = on;
    inverse = gram(on);
    inverse.gauss_jordan();
  }

  std::vector<double>
  RigidModeCoarseSpace::moments(const PointVector &r) const
  {
    std::vector<double> m(size(), 0.);
    for (unsigned int k = 0; k < size(); ++k)
      for (unsigned int i = 0; i < r.size(); ++i)
        if (active[i])
          m[k] += interface.weight(i) * columns[k][i] * r[i];
    return m;
  }

  std::vector<double>
  RigidModeCoarseSpace::solve(const std::vector<double> &m) const
  {
    std::vector<double> y(size(), 0.);
    for (unsigned int a = 0; a < size(); ++a)
      for (unsigned int b = 0; b < size(); ++b)
        y[a] += inverse(a, b) * m[b];
    return y;
  }

  std::vector<double>
  RigidModeCoarseSpace::amplitudes(const PointVector &r) const
  {
    return solve(moments(r));
  }

  PointVector
  RigidModeCoarseSpace::approach(const std::vector<double> &alpha) const
  {
    PointVector g(interface.size(), 0.);
    for (unsigned int k = 0; k < size(); ++k)
      for (unsigned int i = 0; i < g.size(); ++i)
        g[i] += alpha[k] * columns[k][i];
    return g;
  }

  PointVector
  RigidModeCoarseSpace::correction(const PointVector &x) const
  {
    std::vector<double> m = moments(x);
    // An imbalance at the round-off of the loads and moments is no
    // imbalance: correcting it costs a set of body solves and changes
    // nothing (one process summed the loads of a body in another order
    // than a process group, and corrected 2e-16 where the other saw 0).
    double scale = 0, imbalance = 0;
    for (unsigned int k = 0; k < size(); ++k)
    {
      scale     = std::max({scale, std::abs(loads[k]), std::abs(m[k])});
      m[k]      = loads[k] - m[k];
      imbalance = std::max(imbalance, std::abs(m[k]));
    }
    if (imbalance <= 1e-12 * scale)
      return PointVector(x.size(), 0.);
    PointVector c = approach(solve(m));
    for (unsigned int i = 0; i < c.size(); ++i)
      if (!active[i])
        c[i] = 0;
    return c;
  }

  void
  RigidModeCoarseSpace::project(PointVector &r) const
  {
    const PointVector g = approach(amplitudes(r));
    for (unsigned int i = 0; i < r.size(); ++i)
      r[i] = active[i] ? r[i] - g[i] : 0.;
  }

  void
  RigidModeCoarseSpace::add_motion(const std::vector<double> &alpha,
                                   ContactProblem::Iterate   &u) const
  {
    const auto &bodies = problem.get_bodies();
    for (unsigned int k = 0; k < size(); ++k)
    {
      const auto [b, m] = mode_of[k];
      u[b].add(alpha[k], bodies[b]->get_rigid_modes().mode(m));
    }
  }
} // namespace ddcontact
