#include <deal.II/base/parallel.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <ddcontact/bem/collocation_system.h>

#include <algorithm>
#include <numeric>

namespace ddcontact
{
  namespace
  {
    // Indices sorted by key (ties by index, so the order is deterministic).
    std::vector<unsigned int>
    sorted_by(const std::vector<double> &keys)
    {
      std::vector<unsigned int> order(keys.size());
      std::iota(order.begin(), order.end(), 0u);
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](unsigned int a, unsigned int b)
                       { return keys[a] < keys[b]; });
      return order;
    }
  } // namespace

  void
  CollocationSystem::initialize(FullMatrix<double>       &&new_matrix,
                                const std::vector<double> &row_keys,
                                const std::vector<double> &column_keys,
                                const Method               method)
  {
    Assert(new_matrix.m() == new_matrix.n(), ExcInternalError());
    matrix         = std::move(new_matrix);
    dense_lu_ready = false;
    iterations     = 0;
    previous_solution.reinit(0);
    hodlr = HodlrMatrix();

    const bool ordered =
      row_keys.size() == matrix.m() && column_keys.size() == matrix.n();
    const bool direct =
      !ordered || method == Method::dense_lu ||
      (method == Method::automatic && matrix.m() < dense_lu_limit);
    if (direct)
    {
      compute_dense_lu();
      return;
    }

    row_order            = sorted_by(row_keys);
    column_order         = sorted_by(column_keys);
    const unsigned int n = matrix.m();
    FullMatrix<double> ordered_matrix(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        ordered_matrix(i, j) = matrix(row_order[i], column_order[j]);
    hodlr.factorize(ordered_matrix, compression_tolerance);
  }

  void
  CollocationSystem::compute_dense_lu()
  {
    lu.reinit(matrix.m(), matrix.n());
    lu = matrix;
    lu.compute_lu_factorization();
    dense_lu_ready = true;
  }

  void
  CollocationSystem::vmult(Vector<double> &y, const Vector<double> &x) const
  {
    const unsigned int n = matrix.m();
    parallel::apply_to_subranges(
      0u,
      n,
      [&](const unsigned int begin, const unsigned int end)
      {
        for (unsigned int r = begin; r < end; ++r)
        {
          const double *row = &matrix(r, 0);
          double        sum = 0;
          for (unsigned int c = 0; c < n; ++c)
            sum += row[c] * x(c);
          y(r) = sum;
        }
      },
      32);
  }

  void
  CollocationSystem::Preconditioner::vmult(Vector<double>       &x,
                                           const Vector<double> &b) const
  {
    // A = P_r^T H P_c with H the HODLR matrix in boundary order, so
    // A^{-1} b = P_c^T H^{-1} P_r b.
    const unsigned int n = b.size();
    Vector<double>     ordered_b(n), ordered_x(n);
    for (unsigned int i = 0; i < n; ++i)
      ordered_b(i) = b(system.row_order[i]);
    system.hodlr.vmult(ordered_x, ordered_b);
    for (unsigned int j = 0; j < n; ++j)
      x(system.column_order[j]) = ordered_x(j);
  }

  void
  CollocationSystem::solve(Vector<double> &b)
  {
    AssertDimension(b.size(), matrix.m());
    if (!dense_lu_ready)
    {
      Vector<double> x(b.size());
      if (previous_solution.size() == b.size())
        x = previous_solution;
      // Relative to the right-hand side: the system is scaled (lengths by
      // the diameter, tractions by mu), so its entries are of order one.
      SolverControl control(100, tolerance * b.l2_norm(), false, false);
      SolverGMRES<Vector<double>> gmres(
        control, SolverGMRES<Vector<double>>::AdditionalData(50, true));
      try
      {
        // A zero load has the zero solution, whatever the warm start.
        if (b.l2_norm() > 0)
          gmres.solve(*this, x, b, Preconditioner{*this});
        else
          x = 0.;
        iterations        = control.last_step();
        previous_solution = x;
        b                 = x;
        return;
      }
      catch (const SolverControl::NoConvergence &)
      {
        // A correct answer at the LU's price rather than none.
        compute_dense_lu();
      }
    }
    iterations = 0;
    lu.solve(b);
  }
} // namespace ddcontact
