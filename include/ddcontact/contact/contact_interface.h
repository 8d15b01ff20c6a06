#ifndef ddcontact_contact_interface_h
#define ddcontact_contact_interface_h

#include <deal.II/base/point.h>

#include <ddcontact/contact/contact_problem.h>
#include <ddcontact/contact/nodal_contact_law.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** A value for every unknown of the contact interface (ContactInterface):
   * at every contact point, or at every node of S_1, of all pairs, the
   * pairs one after the other (the contact pressure p = -sigma_n, a
   * penetration, ...). */
  using PointVector = std::vector<double>;

  /**
   * The contact pressure as the unknown of the contact problem, for
   * DDNewtonSolver, in one of two discrete spaces:
   *
   * - **points** (the penalty (20), as the paper and the other solvers):
   *   one value at every contact point of ContactPair;
   * - **nodes** (exact contact, or Contact pressure = nodes,
   *   ContactSolverParameters::multipliers_on_nodes()): one
   *   multiplier per vertex of the faces of S_1, the pressure
   *   p(x) = sum_i p_i psi_i(x) piecewise linear (psi_i the hat functions
   *   of the zone mesh of body 1) as reported, and the contact condition
   *   tested with functions phi_i: the weak gap of node i is the average
   *   d_i = (1/m_i) int_S1 phi_i d, m_i = int_S1 psi_i = int_S1 phi_i,
   *   and the load of the pressure is sum_i p_i phi_i. With Contact
   *   solver/Multiplier basis = standard phi_i = psi_i; with dual (the
   *   default) phi_i is Wohlmuth's dual basis, 2 psi_i - psi_j on every
   *   face of S_1 wholly facing S_2 (j the face's other vertex), so that
   *   int phi_i psi_j = m_i delta_ij: on matching meshes d_i and the slip
   *   s_i are the values at node i, and the state of a node (open, stick,
   *   slip) does not reach its neighbours through the mass matrix int
   *   psi_i psi_j, which with the hat functions made the tangential
   *   traction oscillate before the stick edge (doc/friction.md 5.2). The
   *   force sum_i m_i p_i is the same either way; the moments of the
   *   reported field and of the load differ at the ends of a zone by
   *   O(h^2) with the dual basis (tests/floating_body.cc). As many
   *   multipliers
   *   as normal displacements of body 1 on S_1 (no boundary vertex hangs in
   *   2D), so that the trace of body 1 determines them (the mortar method's
   *   choice of the slave side). The integrals use the pair's points (the
   *   common refinement of the two zone meshes, doc/method.md section 7).
   *
   * Both are written with Psi, phi_i at the points (the identity for
   * points): the load of p at the points = Psi^T p. With the bodies solved
   * under p the penetration is d(p) = M^{-1} Psi W (u_1n + u_2n - f~_n) = d_0 -
   * S p, affine in p: d_0 that of the bodies without contact load, and S p =
   * M^{-1} Psi W B K^{-1} B^T W Psi^T p the averaged approach of the bodies
   * loaded by p alone (homogeneous data): B evaluates both bodies' normal
   * displacements at the points, B^T W Psi^T p is the load (20) of the pressure
   * p (W the weights of the contact integral), K = blockdiag(K_a), M =
   * diag(m_i) (M = W for points). f~_n = f_n + theta lambda is the gap shifted
   * by the augmented Lagrangian's multipliers (ContactLaw::shifted_gap()).
   *
   * M S is symmetric positive semidefinite: S is self-adjoint in the inner
   * product (x, y)_M = sum_i m_i x_i y_i. Every application of S is one set
   * of body solves (all bodies at once, each reusing its factorization),
   * counted here.
   *
   * **Friction** (constructed with friction, doc/friction.md section 4.2):
   * every node i also carries a tangential multiplier t_i, the unknown
   * size() + i, with the traction -t(x) tau on body 1 (t(x) = sum_i t_i
   * psi_i(x)) and the averaged slip s_i = (1/m_i) int_S1 psi_i (u_1 - u_2)
   * . tau in the place of the penetration. The tangential load and the
   * slip use the same coefficients as the normal load and the approach
   * (ContactPoint::load_t1, at), so S = M^{-1} Psi W B K^{-1} B^T W Psi^T
   * with B = (B_n; B_t) stays self-adjoint and positive semidefinite in
   * (.,.)_M on the 2 size() unknowns (p, t): d(p, t) = d_0 - S_nn p -
   * S_nt t, s(p, t) = s_0 - S_tn p - S_tt t. A tangential unknown has the
   * pair's own theta (no continuation) and the weight of its node.
   */
  class ContactInterface
  {
  public:
    /** With @p on_nodes the nodal space, otherwise the points; theta = 0
     * with @p exact_contact, otherwise the pairs' penalties; with
     * @p friction (on the nodes) a tangential multiplier per node; with
     * @p dual_basis the nodes' test and load functions are the dual
     * basis phi_i, otherwise the hat functions psi_i. */
    ContactInterface(const ContactProblem &problem,
                     bool                  on_nodes,
                     bool                  exact_contact,
                     bool                  friction   = false,
                     bool                  dual_basis = false);

    /** The share of point @p point of pair @p pair in an unknown: the hat
     * function psi_i(x_q) (the reported field) and the test and load
     * function phi_i(x_q) (psi_i, or the dual basis). */
    struct PointShare
    {
      unsigned int pair;
      unsigned int point;
      double       psi;
      double       phi;
    };

    /** The unknowns, their weights, penalties and shares of the pairs'
     * current points. */
    void
    reinit();

    /** The number of nodes (or points) of all pairs: the normal
     * unknowns. */
    unsigned int
    size() const
    {
      return weights.size();
    }

    /** All unknowns: size(), and as many tangential ones with friction. */
    unsigned int
    n_unknowns() const
    {
      return (tangential ? 2 : 1) * size();
    }

    /** Whether the unknowns include the tangential multipliers. */
    bool
    has_friction() const
    {
      return tangential;
    }

    /** Whether unknown @p q is a tangential multiplier. */
    bool
    is_tangential(const unsigned int q) const
    {
      return q >= size();
    }

    /** The node (or point) of unknown @p q. */
    unsigned int
    node(const unsigned int q) const
    {
      return is_tangential(q) ? q - size() : q;
    }

    /** The contact law of the nodes: the friction law of each node's pair
     * and its slip bound g_i (Tresca) or coefficient mu_i (Coulomb),
     * averaged like the gap: (1/m_i) sum_q w_q psi_i(x_q) g(x_q). */
    const NodalContactLaw &
    law() const
    {
      return nodal_law;
    }

    /** Whether the unknowns are the nodal multipliers of exact contact. */
    bool
    on_nodes() const
    {
      return nodal;
    }

    /** m_i = sum_q w_q psi_i(x_q), the weight of unknown @p i in (.,.)_M. */
    double
    weight(const unsigned int i) const
    {
      return weights[node(i)];
    }

    /** The points that unknown @p i spreads to, with psi_i there. */
    const std::vector<PointShare> &
    shares(const unsigned int i) const
    {
      return point_shares[node(i)];
    }

    /** (x, y)_M, summed in index order. */
    double
    inner(const PointVector &x, const PointVector &y) const;

    /** sqrt((x, x)_M). */
    double
    norm(const PointVector &x) const;

    /** theta of the pair of unknown q (0 for exact contact), plus the
     * continuation's t theta_ref,q on a normal unknown. */
    double
    penalty(const unsigned int q) const
    {
      return is_tangential(q) ? thetas[node(q)]
                              : thetas[q] + continuation * references[q];
    }

    /** The pair's own theta of unknown @p q (0 for exact contact), without
     * the continuation. */
    double
    target_penalty(const unsigned int q) const
    {
      return thetas[node(q)];
    }

    /** theta_ref,q = sum_a (1 - nu_a^2) min(H_a, L) / E_a over both bodies
     * of the pair of unknown @p q: the compliance of the bodies across
     * their thicknesses H_a (c = 1 of a relative penalty, for equal
     * bodies), or across the length L of the zone where that is shorter
     * (set_reference_lengths()). */
    double
    reference_penalty(const unsigned int q) const
    {
      return references[node(q)];
    }

    /** The lengths L of theta_ref, one per pair (infinite if not set),
     * kept through reinit(). */
    void
    set_reference_lengths(const std::vector<double> &lengths);

    /** The compliance m_q (c_1 + c_2) of unknown @p q's own surface (an
     * element's, of the order of the diagonal of S). */
    double
    element_compliance(const unsigned int q) const
    {
      return scales[node(q)];
    }

    /** Penalty continuation (DDNewtonSolver): theta_q + @p t theta_ref,q
     * in penalty() and complementarity_scale(), kept through reinit(). */
    void
    set_continuation(const double t)
    {
      continuation = t;
    }

    double
    get_continuation() const
    {
      return continuation;
    }

    /** c_q = theta_q + m_q (c_1 + c_2), c_a = (1 - nu_a^2) / E_a: the
     * compliance of the unknown q (of the order of the diagonal of S) plus
     * the penalty. It scales the pressure in the complementarity function
     * min(c p, lambda) of DDNewtonSolver, so that a wrong sign of p counts
     * as much as the penetration it would cause, also for theta -> 0. */
    double
    complementarity_scale(const unsigned int q) const
    {
      return penalty(q) + scales[node(q)];
    }

    /** Position of every unknown on S_1 (to move a pressure to new
     * points). */
    const std::vector<Point<2>> &
    positions() const
    {
      return points;
    }

    /** The normal stresses sigma_n = -Psi^T p at the points, one vector
     * per pair (the loads of ContactProblem::solve_bodies()), from the
     * first size() values of @p p. */
    std::vector<std::vector<double>>
    normal_stresses(const PointVector &p) const;

    /** The tangential tractions t = Psi^T t at the points, one vector per
     * pair, from the tangential unknowns of @p x (n_unknowns() values). */
    std::vector<std::vector<double>>
    tangential_tractions(const PointVector &x) const;

    /** The field @p factor sum_i x_i psi_i of the first size() values of
     * @p x at the points, one vector per pair: with the hat functions also
     * for dual multipliers, what the reports show (factor -1 for the
     * normal stress of a pressure). */
    std::vector<std::vector<double>>
    reported_field(const PointVector &x, double factor = 1.) const;

    /** The largest value of @p p on every pair (the peak of the piecewise
     * linear pressure of the nodes, which the points between them miss; 0
     * for a pair without positive value). */
    std::vector<double>
    peak_pressures(const PointVector &p) const;

    /** The penetration d = M^{-1} Psi W (u_1n + u_2n - f~_n) of the
     * displacements @p u (f~_n with the current multipliers); with
     * friction followed by the slips (slip_average()). */
    PointVector
    penetration(const ContactProblem::Iterate &u) const;

    /** The averaged slips s_i = M^{-1} Psi W (u_1 - u_2) . tau of @p u at
     * the nodes (zero on a pair without friction). */
    PointVector
    slip_average(const ContactProblem::Iterate &u) const;

    /** The averaged approach M^{-1} Psi W (u_1n + u_2n) of @p u, without
     * the gap: the linear part of penetration(). */
    PointVector
    normal_approach(const ContactProblem::Iterate &u) const
    {
      return average(jump(u));
    }

    /** Sx = S @p x, and the displacements @p u of the bodies loaded by the
     * pressure @p x alone (with friction: and its tangential traction,
     * n_unknowns() values): one set of homogeneous body solves. */
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
    /** u_1n + u_2n of @p u at every point, one vector per pair. */
    std::vector<std::vector<double>>
    jump(const ContactProblem::Iterate &u) const;

    /** @p normal (normal values of the nodes), followed with friction by
     * the averaged slips of @p u. */
    PointVector
    with_slips(PointVector normal, const ContactProblem::Iterate &u) const;

    /** @p factor Psi^T of the size() values of @p x from index @p first:
     * the field sum_i x_i psi_i at the points, one vector per pair. */
    std::vector<std::vector<double>>
    at_points(const PointVector &x,
              unsigned int       first,
              double             factor,
              bool               load) const;

    /** M^{-1} Psi W @p values (values at the points, per pair). */
    PointVector
    average(const std::vector<std::vector<double>> &values) const;

    /** Per node [@p first, @p last) of pair @p k (with friction on the
     * nodes): whether the Dirichlet conditions of both bodies fix its
     * tangential motion, at the node on body 1 and at a held vertex of
     * body 2 on its normal (NodalContactLaw::slip_prescribed()). The same
     * on every process (collective). */
    std::vector<bool>
    prescribed_slips(unsigned int k,
                     unsigned int first,
                     unsigned int last) const;

    /** theta_ref of pair @p k. */
    double
    reference_of_pair(unsigned int k) const;

    /** One unknown per vertex of the faces of S_1 of pair @p k (in the
     * order the points meet them). */
    void
    add_nodes(unsigned int k);

    const ContactProblem                &problem;
    const bool                           nodal, exact, tangential, dual;
    PointVector                          weights, thetas, scales, references;
    NodalContactLaw                      nodal_law;
    std::vector<double>                  reference_lengths; // per pair
    double                               continuation = 0;
    std::vector<Point<2>>                points;
    std::vector<std::vector<PointShare>> point_shares;
    mutable unsigned int                 applications = 0;
  };

  /** x += a y, for the interface unknowns of dd-newton. */
  inline void
  add(PointVector &x, const double a, const PointVector &y)
  {
    for (unsigned int q = 0; q < x.size(); ++q)
      x[q] += a * y[q];
  }

  /** u += a v for the bodies' responses. */
  inline void
  add(ContactProblem::Iterate       &u,
      const double                   a,
      const ContactProblem::Iterate &v)
  {
    for (unsigned int b = 0; b < u.size(); ++b)
      u[b].add(a, v[b]);
  }

  /** x <- (1 - tau) x + tau y. */
  inline void
  blend(PointVector &x, const double tau, const PointVector &y)
  {
    for (unsigned int q = 0; q < x.size(); ++q)
      x[q] = (1 - tau) * x[q] + tau * y[q];
  }

  inline void
  blend(ContactProblem::Iterate       &u,
        const double                   tau,
        const ContactProblem::Iterate &v)
  {
    for (unsigned int b = 0; b < u.size(); ++b)
      u[b].sadd(1 - tau, tau, v[b]);
  }
} // namespace ddcontact

#endif
