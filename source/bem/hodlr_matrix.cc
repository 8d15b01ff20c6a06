#include <ddcontact/bem/hodlr_matrix.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  void
  HodlrMatrix::factorize(const FullMatrix<double> &matrix,
                         const double              tolerance,
                         const unsigned int        leaf_size)
  {
    AssertDimension(matrix.m(), matrix.n());
    nodes.clear();
    root = build(0, matrix.m(), std::max(1u, leaf_size));
    factorize_node(root, matrix, tolerance);
  }

  int
  HodlrMatrix::build(const unsigned int begin,
                     const unsigned int end,
                     const unsigned int leaf_size)
  {
    const int index = nodes.size();
    nodes.emplace_back();
    nodes[index].begin = begin;
    nodes[index].end   = end;
    if (end - begin > leaf_size)
    {
      const unsigned int middle = begin + (end - begin) / 2;
      const int          first  = build(begin, middle, leaf_size);
      const int          second = build(middle, end, leaf_size);
      nodes[index].children[0]  = first;
      nodes[index].children[1]  = second;
    }
    return index;
  }

  namespace
  {
    /** Index of the entry of largest magnitude (the first one on a tie). */
    unsigned int
    index_of_largest(const std::vector<double> &v)
    {
      return static_cast<unsigned int>(
        std::max_element(v.begin(),
                         v.end(),
                         [](double a, double b)
                         { return std::abs(a) < std::abs(b); }) -
        v.begin());
    }

    double
    squared_norm(const std::vector<double> &v)
    {
      double sum = 0;
      for (const double x : v)
        sum += x * x;
      return sum;
    }

    /** The rows (or columns) of a block of @p size checked after the
     * crosses: the first and last few, and a stride. */
    std::vector<unsigned int>
    sample_indices(const unsigned int size)
    {
      std::vector<unsigned int> s;
      const unsigned int        stride = std::max(1u, size / 16);
      for (unsigned int k = 0; k < size; ++k)
        if (k < 4 || k + 4 >= size || k % stride == 0)
          s.push_back(k);
      return s;
    }

    /** The crosses u_l v_l^T of an adaptive cross approximation of one
     * block of a matrix, built one at a time from rows and columns of the
     * residual (the block minus the crosses so far), so that the block is
     * never formed; with the squared Frobenius norm of their sum. */
    class CrossApproximation
    {
    public:
      CrossApproximation(const FullMatrix<double> &matrix,
                         const unsigned int        row_begin,
                         const unsigned int        row_end,
                         const unsigned int        column_begin,
                         const unsigned int        column_end)
        : matrix(matrix)
        , row_begin(row_begin)
        , column_begin(column_begin)
        , m(row_end - row_begin)
        , n(column_end - column_begin)
        , row_used(m, false)
      {
      }

      /** Crosses through the rows of largest |u| entry, starting at row
       * @p next, until two successive ones are below @p tolerance relative
       * to the whole approximation (or the rank is full); @p next is left
       * at the row the next cross would take. */
      void
      add_crosses_until_small(unsigned int &next, const double tolerance)
      {
        unsigned int n_small = 0;
        while (us.size() < max_rank() && n_small < 2)
        {
          if (!add_cross(next))
          {
            const auto unused =
              std::find(row_used.begin(), row_used.end(), false);
            if (unused == row_used.end())
              break;
            next = unused - row_used.begin();
            continue;
          }
          n_small     = (squared_norm(us.back()) * squared_norm(vs.back()) <=
                     tolerance * tolerance * norm2)
                          ? n_small + 1
                          : 0;
          double best = -1;
          for (unsigned int r = 0; r < m; ++r)
            if (!row_used[r] && std::abs(us.back()[r]) > best)
            {
              best = std::abs(us.back()[r]);
              next = r;
            }
          if (best < 0)
            break;
        }
      }

      /** The unused row where the residual of the sample rows and columns,
       * scaled to the whole block, is largest, or m if there is none;
       * @p worst is that estimate of the squared residual norm. */
      unsigned int
      worst_sampled_row(double &worst)
      {
        worst                  = 0;
        unsigned int worst_row = m;
        for (const unsigned int i : sample_indices(m))
        {
          residual_row(i, row);
          const double estimate = squared_norm(row) * m;
          if (estimate > worst && !row_used[i])
          {
            worst     = estimate;
            worst_row = i;
          }
        }
        for (const unsigned int j : sample_indices(n))
        {
          residual_column(j, column);
          const unsigned int i        = index_of_largest(column);
          const double       estimate = squared_norm(column) * n;
          if (estimate > worst && !row_used[i])
          {
            worst     = estimate;
            worst_row = i;
          }
        }
        return worst_row;
      }

      unsigned int
      max_rank() const
      {
        return std::min(m, n);
      }

      unsigned int
      rank() const
      {
        return us.size();
      }

      /** Squared Frobenius norm of the approximation. */
      double
      squared_norm_of_approximation() const
      {
        return norm2;
      }

      /** The crosses as the columns of U (m x rank) and V (n x rank). */
      void
      copy_to(FullMatrix<double> &U, FullMatrix<double> &V) const
      {
        const unsigned int rank = us.size();
        U.reinit(m, rank);
        V.reinit(n, rank);
        for (unsigned int l = 0; l < rank; ++l)
        {
          for (unsigned int r = 0; r < m; ++r)
            U(r, l) = us[l][r];
          for (unsigned int j = 0; j < n; ++j)
            V(j, l) = vs[l][j];
        }
      }

    private:
      /** Entry (i, j) of the residual. */
      double
      residual(const unsigned int i, const unsigned int j) const
      {
        double value = matrix(row_begin + i, column_begin + j);
        for (std::size_t l = 0; l < us.size(); ++l)
          value -= us[l][i] * vs[l][j];
        return value;
      }

      void
      residual_row(const unsigned int i, std::vector<double> &r) const
      {
        r.resize(n);
        for (unsigned int j = 0; j < n; ++j)
          r[j] = residual(i, j);
      }

      void
      residual_column(const unsigned int j, std::vector<double> &c) const
      {
        c.resize(m);
        for (unsigned int i = 0; i < m; ++i)
          c[i] = residual(i, j);
      }

      /** One cross through row i of the residual; false if that row is
       * zero. */
      bool
      add_cross(const unsigned int i)
      {
        row_used[i] = true;
        residual_row(i, row);
        const unsigned int pivot = index_of_largest(row);
        if (row[pivot] == 0.)
          return false;
        residual_column(pivot, column);
        std::vector<double> v(n);
        for (unsigned int j = 0; j < n; ++j)
          v[j] = row[j] / row[pivot];
        double cross = 0;
        for (std::size_t l = 0; l < us.size(); ++l)
        {
          double uu = 0, vv = 0;
          for (unsigned int r = 0; r < m; ++r)
            uu += column[r] * us[l][r];
          for (unsigned int j = 0; j < n; ++j)
            vv += v[j] * vs[l][j];
          cross += uu * vv;
        }
        const double u2v2 = squared_norm(column) * squared_norm(v);
        norm2 += u2v2 + 2 * cross;
        us.push_back(column);
        vs.push_back(std::move(v));
        return true;
      }

      const FullMatrix<double>        &matrix;
      const unsigned int               row_begin, column_begin;
      const unsigned int               m, n;
      std::vector<std::vector<double>> us, vs;
      std::vector<bool>                row_used;
      double                           norm2 = 0;
      // Work space for one row and one column of the residual.
      std::vector<double> row, column;
    };
  } // namespace

  void
  HodlrMatrix::compress(const FullMatrix<double> &matrix,
                        const unsigned int        row_begin,
                        const unsigned int        row_end,
                        const unsigned int        column_begin,
                        const unsigned int        column_end,
                        const double              tolerance,
                        FullMatrix<double>       &U,
                        FullMatrix<double>       &V) const
  {
    // Adaptive cross approximation with partial pivoting: every step takes
    // one row and one column of the residual block, so the block is never
    // formed; the Frobenius norm of the approximation is tracked to stop
    // once two successive crosses are below the tolerance. Partial
    // pivoting can miss a part of the block that none of its rows
    // reached (typically the near-singular corner where two pieces of the
    // boundary meet), so the result is then checked on sample rows and
    // columns (the first and last few, and a stride), and the
    // approximation continues from the worst one until they pass.
    CrossApproximation approximation(
      matrix, row_begin, row_end, column_begin, column_end);
    const unsigned int m    = row_end - row_begin;
    unsigned int       next = 0;
    while (approximation.rank() < approximation.max_rank())
    {
      approximation.add_crosses_until_small(next, tolerance);

      double             worst     = 0;
      const unsigned int worst_row = approximation.worst_sampled_row(worst);
      if (worst_row == m ||
          worst <= tolerance * tolerance *
                     approximation.squared_norm_of_approximation())
        break;
      next = worst_row;
    }
    approximation.copy_to(U, V);
  }

  void
  HodlrMatrix::factorize_node(const int                 index,
                              const FullMatrix<double> &matrix,
                              const double              tolerance)
  {
    Node &node = nodes[index];
    if (node.children[0] < 0)
    {
      const unsigned int m = node.end - node.begin;
      node.leaf_inverse.reinit(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          node.leaf_inverse(i, j) = matrix(node.begin + i, node.begin + j);
      node.leaf_inverse.gauss_jordan();
      return;
    }

    for (const int child : node.children)
      factorize_node(child, matrix, tolerance);
    const Node &first  = nodes[node.children[0]],
               &second = nodes[node.children[1]];
    compress(matrix,
             first.begin,
             first.end,
             second.begin,
             second.end,
             tolerance,
             node.U[0],
             node.V[0]);
    compress(matrix,
             second.begin,
             second.end,
             first.begin,
             first.end,
             tolerance,
             node.U[1],
             node.V[1]);
    for (unsigned int s = 0; s < 2; ++s)
    {
      node.Y[s] = node.U[s];
      if (node.U[s].n() > 0)
        solve_node(node.children[s], node.Y[s]);
    }

    // [I, V1^T Y0; V0^T Y1, I] for the unknowns [c; a] = [V1^T x1; V0^T x2].
    const unsigned int r0 = node.U[0].n(), r1 = node.U[1].n();
    node.coupling_inverse.reinit(r1 + r0, r1 + r0);
    for (unsigned int l = 0; l < r1 + r0; ++l)
      node.coupling_inverse(l, l) = 1.;
    for (unsigned int l = 0; l < r1; ++l)
      for (unsigned int k = 0; k < r0; ++k)
      {
        double value = 0;
        for (unsigned int i = 0; i < node.V[1].m(); ++i)
          value += node.V[1](i, l) * node.Y[0](i, k);
        node.coupling_inverse(l, r1 + k) = value;
      }
    for (unsigned int k = 0; k < r0; ++k)
      for (unsigned int l = 0; l < r1; ++l)
      {
        double value = 0;
        for (unsigned int i = 0; i < node.V[0].m(); ++i)
          value += node.V[0](i, k) * node.Y[1](i, l);
        node.coupling_inverse(r1 + k, l) = value;
      }
    if (r0 + r1 > 0)
      node.coupling_inverse.gauss_jordan();
  }

  void
  HodlrMatrix::solve_node(const int index, FullMatrix<double> &X) const
  {
    // X holds the rows [begin, end) of this node, for X.n() right-hand
    // sides.
    const Node        &node = nodes[index];
    const unsigned int m = node.end - node.begin, k = X.n();
    AssertDimension(X.m(), m);
    if (node.children[0] < 0)
    {
      FullMatrix<double> result(m, k);
      node.leaf_inverse.mmult(result, X);
      X = result;
      return;
    }

    const Node &first       = nodes[node.children[0]],
               &second      = nodes[node.children[1]];
    const unsigned int m0   = first.end - first.begin,
                       m1   = second.end - second.begin;
    FullMatrix<double> z[2] = {FullMatrix<double>(m0, k),
                               FullMatrix<double>(m1, k)};
    z[0].fill(X, 0, 0, 0, 0);
    z[1].fill(X, 0, 0, m0, 0);
    solve_node(node.children[0], z[0]);
    solve_node(node.children[1], z[1]);

    const unsigned int r0 = node.U[0].n(), r1 = node.U[1].n();
    if (r0 + r1 > 0)
    {
      // w = [V1^T z1; V0^T z2], then [c; a] = coupling^{-1} w.
      FullMatrix<double> w(r1 + r0, k), ca(r1 + r0, k);
      for (unsigned int j = 0; j < k; ++j)
      {
        for (unsigned int l = 0; l < r1; ++l)
          for (unsigned int i = 0; i < m0; ++i)
            w(l, j) += node.V[1](i, l) * z[0](i, j);
        for (unsigned int l = 0; l < r0; ++l)
          for (unsigned int i = 0; i < m1; ++i)
            w(r1 + l, j) += node.V[0](i, l) * z[1](i, j);
      }
      node.coupling_inverse.mmult(ca, w);
      // x1 = z1 - Y0 a, x2 = z2 - Y1 c.
      for (unsigned int j = 0; j < k; ++j)
      {
        for (unsigned int i = 0; i < m0; ++i)
          for (unsigned int l = 0; l < r0; ++l)
            z[0](i, j) -= node.Y[0](i, l) * ca(r1 + l, j);
        for (unsigned int i = 0; i < m1; ++i)
          for (unsigned int l = 0; l < r1; ++l)
            z[1](i, j) -= node.Y[1](i, l) * ca(l, j);
      }
    }
    for (unsigned int j = 0; j < k; ++j)
    {
      for (unsigned int i = 0; i < m0; ++i)
        X(i, j) = z[0](i, j);
      for (unsigned int i = 0; i < m1; ++i)
        X(m0 + i, j) = z[1](i, j);
    }
  }

  void
  HodlrMatrix::vmult(Vector<double> &x, const Vector<double> &b) const
  {
    Assert(root >= 0, ExcMessage("Call factorize() first."));
    FullMatrix<double> X(b.size(), 1);
    for (unsigned int i = 0; i < b.size(); ++i)
      X(i, 0) = b(i);
    solve_node(root, X);
    x.reinit(b.size());
    for (unsigned int i = 0; i < b.size(); ++i)
      x(i) = X(i, 0);
  }

  unsigned int
  HodlrMatrix::max_rank() const
  {
    unsigned int rank = 0;
    for (const auto &node : nodes)
      rank = std::max<std::size_t>({rank, node.U[0].n(), node.U[1].n()});
    return rank;
  }

  std::size_t
  HodlrMatrix::n_stored_entries() const
  {
    std::size_t n = 0;
    for (const auto &node : nodes)
    {
      n += node.leaf_inverse.n_elements() + node.coupling_inverse.n_elements();
      for (unsigned int s = 0; s < 2; ++s)
        n += node.U[s].n_elements() + node.V[s].n_elements() +
             node.Y[s].n_elements();
    }
    return n;
  }
} // namespace ddcontact
