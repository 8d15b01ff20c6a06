#ifndef ddcontact_contact_interface_h
#define ddcontact_contact_interface_h

#include <deal.II/base/point.h>

#include <ddcontact/contact/contact_problem.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** A value at every contact point of all pairs, the pairs one after the
   * other (the contact pressure p = -sigma_n, a penetration, ...). */
  using PointVector = std::vector<double>;

  /**
   * The contact pressure as the unknown of the contact problem, for
   * DDNewtonSolver. On the contact points of all pairs, with the pressure
   * p = -sigma_n >= 0 (compression positive), the bodies solved under p
   * have the penetration
   *   d(p) = u_1n + u_2n - f~_n = d_0 - S p,
   * affine in p: d_0 that of the bodies without contact load, and
   * S p = B K^{-1} B^T W p the approach of the bodies loaded by p alone
   * (homogeneous data): B evaluates both bodies' normal displacements at
   * the points, B^T W p is the load (20) of the pressure p (W the weights
   * of the contact integral), K = blockdiag(K_a). f~_n = f_n + theta lambda
   * is the gap shifted by the augmented Lagrangian's multipliers
   * (PenaltyLaw::shifted_gap()).
   *
   * W S = (W B) K^{-1} (W B)^T is symmetric positive semidefinite: S is
   * self-adjoint in the inner product (x, y)_W = sum_q w_q x_q y_q. Every
   * application of S is one set of body solves (all bodies at once, each
   * reusing its factorization), counted here.
   */
  class ContactInterface
  {
  public:
    explicit ContactInterface(const ContactProblem &problem);

    /** Offsets, weights and penalties of the pairs' current points. */
    void
    reinit();

    /** The number of contact points of all pairs. */
    unsigned int
    size() const
    {
      return weights.size();
    }

    /** (x, y)_W, summed in index order. */
    double
    inner(const PointVector &x, const PointVector &y) const;

    /** sqrt((x, x)_W). */
    double
    norm(const PointVector &x) const;

    /** theta of the pair of point q. */
    double
    penalty(const unsigned int q) const
    {
      return thetas[q];
    }

    /** c_q = theta_q + w_q (c_1 + c_2), c_a = (1 - nu_a^2) / E_a: the
     * compliance of the point q (of the order of the diagonal of S) plus
     * the penalty. It scales the pressure in the complementarity function
     * min(c p, lambda) of DDNewtonSolver, so that a wrong sign of p counts
     * as much as the penetration it would cause, also for theta -> 0. */
    double
    complementarity_scale(const unsigned int q) const
    {
      return scales[q];
    }

    /** Position of every point on S_1 (to move a pressure to new points). */
    const std::vector<Point<2>> &
    positions() const
    {
      return points;
    }

    /** The normal stresses sigma_n = -p, one vector per pair (the loads of
     * ContactProblem::solve_bodies()). */
    std::vector<std::vector<double>>
    normal_stresses(const PointVector &p) const;

    /** The penetration d = u_1n + u_2n - f~_n of the displacements @p u at
     * every point (f~_n with the current multipliers). */
    PointVector
    penetration(const ContactProblem::Iterate &u) const;

    /** Sx = S @p x, and the displacements @p u of the bodies loaded by the
     * pressure @p x alone: one set of homogeneous body solves. */
    void
    apply(const PointVector       &x,
          ContactProblem::Iterate &u,
          PointVector             &Sx) const;

    /** (1 - nu^2) / E of @p body: its compliance under a load of short
     * wavelength on its surface, per unit of the load's length. */
    static double
    surface_compliance(const ElasticBody<2> &body);

    /** Sets of body solves done by apply(). */
    unsigned int
    n_applications() const
    {
      return applications;
    }

  private:
    /** u_1n + u_2n of @p u at every point. */
    PointVector
    jump(const ContactProblem::Iterate &u) const;

    const ContactProblem     &problem;
    std::vector<unsigned int> offsets; // first point of every pair, and end
    PointVector               weights, thetas, scales;
    std::vector<Point<2>>     points;
    mutable unsigned int      applications = 0;
  };
} // namespace ddcontact

#endif
