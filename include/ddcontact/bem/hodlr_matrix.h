#ifndef ddcontact_hodlr_matrix_h
#define ddcontact_hodlr_matrix_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * A hierarchically off-diagonal low-rank (HODLR) approximation of a dense
   * square matrix, with its fast direct solve. The index range is halved
   * recursively down to small leaves; on every level the two off-diagonal
   * blocks are replaced by low-rank products U V^T, found by adaptive
   * cross approximation (ACA with partial pivoting) to a relative
   * tolerance. The solve uses, on every level,
   *   [A11 U1 V1^T; U2 V2^T A22] x = b  ->  x1 = z1 - Y1 a, x2 = z2 - Y2 c,
   * with z = the children's solves of b, Y1 = A11^{-1} U1, Y2 = A22^{-1} U2
   * and the small coupling system [I, V2^T Y1; V1^T Y2, I] [c; a] =
   * [V2^T z1; V1^T z2] (the Sherman-Morrison-Woodbury formula).
   *
   * For a boundary element matrix whose rows and columns are ordered
   * along the boundary, the off-diagonal blocks couple two pieces of the
   * boundary through a kernel that is smooth away from their common end
   * points, so their ranks grow only like log N: the factorization costs
   * O(N r^2 log N) after an O(N r log N) compression, instead of the
   * LU's O(N^3).
   */
  class HodlrMatrix
  {
  public:
    /** Compress and factorize @p matrix (held by the caller; only read
     * here). Blocks are compressed to @p tolerance relative to the
     * largest entry of their first cross; leaves have at most @p leaf_size
     * rows. */
    void
    factorize(const FullMatrix<double> &matrix,
              const double              tolerance,
              const unsigned int        leaf_size = 64);

    /** x = the HODLR solve of b, an approximation of A^{-1} b to about the
     * compression tolerance times the condition number (used as the
     * preconditioner of GMRES, which makes it exact). */
    void
    vmult(Vector<double> &x, const Vector<double> &b) const;

    /** Largest rank of an off-diagonal block. */
    unsigned int
    max_rank() const;

    /** Stored numbers (low-rank factors, leaves, coupling systems), to
     * compare with the N^2 of the dense matrix. */
    std::size_t
    n_stored_entries() const;

  private:
    struct Node
    {
      unsigned int begin = 0, end = 0;
      int          children[2] = {-1, -1};
      // Leaf: the inverse of the diagonal block.
      FullMatrix<double> leaf_inverse;
      // A12 = U[0] V[0]^T, A21 = U[1] V[1]^T.
      FullMatrix<double> U[2], V[2];
      // Y[0] = A11^{-1} U[0], Y[1] = A22^{-1} U[1].
      FullMatrix<double> Y[2];
      // Inverse of the coupling system [I, V[1]^T Y[0]; V[0]^T Y[1], I].
      FullMatrix<double> coupling_inverse;
    };

    int
    build(unsigned int begin, unsigned int end, unsigned int leaf_size);

    void
    compress(const FullMatrix<double> &matrix,
             unsigned int              row_begin,
             unsigned int              row_end,
             unsigned int              column_begin,
             unsigned int              column_end,
             double                    tolerance,
             FullMatrix<double>       &U,
             FullMatrix<double>       &V) const;

    void
    factorize_node(int node, const FullMatrix<double> &matrix, double tol);

    /** @p X holds the rows [begin, end) of node @p node for X.n()
     * right-hand sides; overwrite them by the node's solve. */
    void
    solve_node(int node, FullMatrix<double> &X) const;

    std::vector<Node> nodes;
    int               root = -1;
  };
} // namespace ddcontact

#endif
