#ifndef ddcontact_robin_preconditioner_h
#define ddcontact_robin_preconditioner_h

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <ddcontact/body/body_linear_solver.h>
#include <ddcontact/contact/contact_interface.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The preconditioner of DDNewtonSolver's linear systems
   * (Theta + S_AA) p_A = d_A on an active set A (ContactInterface for S):
   * an approximate inverse of Theta + S that is exact for one body in the
   * limits theta -> 0 and theta -> infinity alike.
   *
   * For one body with compliance S_b = C_b K_b^{-1} C_b^T W on its points,
   * (Theta + S_b)^{-1} r is one solve with the body's stiffness plus springs
   * of stiffness w_q / theta_q at its contact points (a Robin problem):
   *   (K_b + C_b^T W Theta^{-1} C_b) v = C_b^T W Theta^{-1} r,
   *   z = Theta^{-1} (r - C_b v).
   * For theta -> 0 this is the Dirichlet preconditioner of FETI (the
   * stiffness of the body with its zone clamped), for theta -> infinity it
   * is Theta^{-1}, and in between it is still exact. A pair adds the
   * compliances of its two bodies in series; each body b takes the share
   * alpha_b = c_b / (c_1 + c_2), c = (1 - nu^2) / E, of the penalty and of
   * the residual, z = sum_b alpha_b (alpha_b Theta + S_b)^{-1} alpha_b r,
   * which is exact when the two compliances are in that ratio. Summed:
   *   (K_b + C_b^T W (alpha_b Theta)^{-1} C_b) v_b = C_b^T W Theta^{-1} r,
   *   z = Theta^{-1} (r - sum_b C_b v_b),
   * self-adjoint and positive definite in (.,.)_W. On an active set A the
   * springs sit on the points of A only, so that z is exact for
   * (Theta + S_AA)^{-1} r: the rest of the zone is free, as in S_AA. (With
   * springs on the whole zone the inactive part is clamped for small theta,
   * and CG needed 20 to 60 iterations per Newton step on the paper's scene
   * at c = 1e-8.) This costs a factorization of every body whenever the
   * active set changes, about once per Newton step.
   *
   * With the nodal multipliers of exact contact (theta = 0,
   * ContactInterface::on_nodes()) theta is replaced by 1e-3 of the
   * unknown's compliance m (c_1 + c_2) in the preconditioner only: the
   * springs are then a thousand times stiffer than the surface, and the
   * preconditioner is the Dirichlet one of FETI to 1e-3. Both bodies of a
   * pair precondition it when every vertex of S_1 is a vertex of S_2
   * (body 2's trace then contains body 1's and determines the multipliers
   * too): the sum is FETI's, closer to (S_1 + S_2)^{-1} than either share
   * when the bodies differ, and the bodies' work is balanced. Otherwise
   * (a coarser body 2 leaves modes of the multiplier that it does not
   * feel, on which its share alpha_2 Theta^{-1} would blow up) only body 1
   * preconditions: z = alpha_1 (alpha_1 Theta + S_1)^{-1} r, exact when
   * S_2 = (c_2 / c_1) S_1. A body that is body 1 of one pair and body 2
   * of another (the middle body of a stack) holds the zone of the second
   * pair by the same springs at its active nodes in its solve for the
   * first: the other body of that pair is the stiff side of the series.
   * Three bodies: 57 to 59 sets of body solves down to 34 to 39.
   *
   * With friction (ContactInterface::has_friction()) the tangential
   * multiplier of a node of a frictional pair has a row of its own, with
   * the tangential load coefficients (ContactPoint::load_t1, load_t2):
   * on the sticking nodes the bodies get springs along tau beside those
   * along n, and the same formulas precondition (Theta + S_AA) on the
   * unknowns (p, t).
   *
   * One application is one set of body solves with these factorizations,
   * concurrently and on the bodies' processes, like the DD's solves.
   */
  class RobinPreconditioner
  {
  public:
    explicit RobinPreconditioner(const ContactProblem &problem);

    /** Take the points and penalties of @p interface (after the pairs were
     * set up). */
    void
    setup(const ContactInterface &interface);

    /** The springs and loads for the interface's current theta (after
     * ContactInterface::set_continuation()); the bodies are factorized
     * again at the next update(). The rows and sparsity of setup() do not
     * depend on theta and are kept. */
    void
    update_penalties();

    /** Assemble and factorize the Robin matrix of every body solved here
     * with springs on the unknowns with @p active (nothing if the last
     * factorization has springs on a superset of them, at most a tenth
     * more). */
    void
    update(const std::vector<bool> &active);

    /** z = P_A r on the unknowns with @p active (those of the last
     * update()), zero elsewhere. */
    void
    vmult(PointVector             &z,
          const PointVector       &r,
          const std::vector<bool> &active) const;

    /** Sets of body solves done by vmult(). */
    unsigned int
    n_applications() const
    {
      return applications;
    }

    /** Pairs that both their bodies precondition (the others: body 1). */
    unsigned int
    pairs_with_both_bodies() const
    {
      return std::count(both_bodies.begin(), both_bodies.end(), true);
    }

    /** Factorizations of all bodies since setup(). */
    unsigned int
    factorizations() const
    {
      return n_factorizations;
    }

  private:
    /**
     * An unknown i of the interface as body b sees it: the load
     * coefficients c_i = (1/m_i) sum_q w_q psi_i(x_q) c_q of its points q
     * (constraints resolved) on the body, so that C_b x = c_i . x is the
     * body's part of the averaged normal displacement of i; the spring
     * m_i / (alpha theta_i) and the factor of r_i in the right-hand side.
     */
    struct Row
    {
      unsigned int                         unknown;
      double                               alpha, beta; // shares, make_row()
      double                               spring;
      double                               load;
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  c;
      /** False for a spring only: body 2 of a pair with nodal multipliers,
       * held at the pair's active nodes while it preconditions another
       * pair as body 1 (the middle body of a stack). */
      bool preconditions = true;
    };

    /** The Robin matrix of one body and its factorization: UMFPACK on
     * one process, or MUMPS over the body's process group (group). */
    struct BodyFactor
    {
      SparsityPattern                      sparsity;
      SparseMatrix<double>                 matrix;
      SparseDirectUMFPACK                  direct;
      std::unique_ptr<SpringFactorization> group;
    };

    /** The theta of unknown @p i in the preconditioner: the interface's,
     * or 1e-3 of its compliance where that is 0 (exact contact). */
    double
    penalty(unsigned int i) const;

    /** The rows of unknown @p i on the side @p body_1 of its pair, with
     * the share @p alpha of the pair's compliance and the share @p beta of
     * the residual (alpha when both bodies precondition the pair, 1 for
     * body 1 alone). */
    Row
    make_row(unsigned int i, bool body_1, double alpha, double beta) const;

    /** The spring m / (alpha theta) and load factor (m / theta)(beta /
     * alpha) of @p row for the interface's current theta. */
    void
    set_penalty(Row &row) const;

    /** Whether the trace of body 2 of pair @p k determines the nodal
     * multipliers: every vertex of S_1 is a vertex of S_2 (S_2 as fine or
     * finer, nested). */
    bool
    body_2_determines_nodes(unsigned int k) const;

    /** The sparsity of the Robin matrix of body @p b. */
    void
    make_pattern(unsigned int b);

    /** Assemble and factorize the Robin matrix of body @p b with springs
     * on the current active unknowns. */
    void
    factorize(unsigned int b);

    const ContactProblem                    &problem;
    const ContactInterface                  *interface = nullptr;
    std::vector<std::vector<Row>>            rows; // per body
    std::vector<std::unique_ptr<BodyFactor>> factors;
    std::vector<bool>                        springs; // of the factors
    std::vector<bool>    both_bodies; // per pair: body 2 preconditions too
    unsigned int         n_factorizations = 0;
    mutable unsigned int applications     = 0;
  };
} // namespace ddcontact

#endif
