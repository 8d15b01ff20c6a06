#ifndef ddcontact_collocation_system_h
#define ddcontact_collocation_system_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/bem/hodlr_matrix.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The dense, unsymmetric collocation system A x = b of the boundary
   * element method (doc/bem.md), solved in one of two ways:
   *  - dense LU (LAPACK): O(N^3) once per boundary mesh, then O(N^2) per
   *    right-hand side; cheapest for small N, and used whenever the system
   *    is bordered with rigid modes (a floating body);
   *  - GMRES with the dense matrix-vector product (O(N^2), in parallel
   *    over rows), preconditioned by a HodlrMatrix of A, with rows and
   *    columns ordered along the boundary: the HODLR solve is nearly
   *    exact, so GMRES needs a few iterations, and its tolerance, not the
   *    compression's, sets the accuracy. Compression and factorization
   *    cost O(N r^2 log N); repeated solves on the same mesh start from
   *    the previous solution.
   * The automatic choice takes the LU below a size where both cost about
   * the same. If GMRES does not reach its tolerance, the dense LU is
   * computed and used: the answer never depends on the method beyond the
   * GMRES tolerance.
   */
  class CollocationSystem
  {
  public:
    enum class Method
    {
      automatic,
      dense_lu,
      hierarchical
    };

    /** Take the assembled matrix and prepare the solver chosen by
     * @p method (automatic: by size). @p row_keys and @p column_keys give
     * the position along the boundary of each row's collocation point and
     * each column's unknown (for the hierarchical ordering); either empty
     * forces the dense LU. */
    void
    initialize(FullMatrix<double>       &&matrix,
               const std::vector<double> &row_keys,
               const std::vector<double> &column_keys,
               const Method               method = Method::automatic);

    bool
    initialized() const
    {
      return matrix.m() > 0;
    }

    /** Overwrite @p b by the solution of A x = b. */
    void
    solve(Vector<double> &b);

    /** Whether the dense LU is in use (else hierarchical GMRES). */
    bool
    uses_dense_lu() const
    {
      return dense_lu_ready;
    }

    /** GMRES iterations of the last solve (0 with the LU). */
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

    /** The hierarchical preconditioner (empty with the LU). */
    const HodlrMatrix &
    get_hierarchical_matrix() const
    {
      return hodlr;
    }

    /** y = A x (in the original ordering), in parallel over blocks of
     * rows, each row summed in a fixed order so that the result does not
     * depend on the thread count. */
    void
    vmult(Vector<double> &y, const Vector<double> &x) const;

    /** Relative residual at which GMRES stops. */
    static constexpr double tolerance = 1e-12;

    /** Relative tolerance of the low-rank blocks of the preconditioner. */
    static constexpr double compression_tolerance = 1e-8;

    /** Below this many unknowns the automatic choice is the dense LU
     * (doc/bem.md measures the crossover). */
    static constexpr unsigned int dense_lu_limit = 800;

  private:
    void
    compute_dense_lu();

    /** The HODLR solve in the original ordering. */
    struct Preconditioner
    {
      const CollocationSystem &system;
      void
      vmult(Vector<double> &x, const Vector<double> &b) const;
    };

    FullMatrix<double>       matrix;
    LAPACKFullMatrix<double> lu;
    bool                     dense_lu_ready = false;

    // Position along the boundary -> index: row_order[i] is the row of A
    // that is row i of the HODLR matrix, likewise for the columns.
    std::vector<unsigned int> row_order, column_order;
    HodlrMatrix               hodlr;

    Vector<double> previous_solution;
    unsigned int   iterations = 0;
  };
} // namespace ddcontact

#endif
