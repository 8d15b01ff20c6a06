#ifndef ddcontact_nodal_contact_law_h
#define ddcontact_nodal_contact_law_h

#include <ddcontact/contact/contact_pair_parameters.h>

#include <algorithm>
#include <string>
#include <vector>

namespace ddcontact
{
  class ContactPair;

  /** Where a node of S_1 (or a point) is in the contact law. The values
   * are those the reports write (slip_state in the CSV and VTU files). */
  enum class NodeState : unsigned char
  {
    open  = 0, // no contact: p = 0 and t = 0
    stick = 1, // in contact, the slip increment is the penalty's (frictional)
    slip  = 2  // in contact, t at its bound along the slip (0 frictionless)
  };

  /** A node's state in a Newton step: its NodeState and, slipping, the
   * direction sigma = +-1 of t (0 for a frictionless node in contact). */
  struct NodeStatus
  {
    NodeState state     = NodeState::open;
    int       direction = 0;

    bool
    closed() const
    {
      return state != NodeState::open;
    }

    bool
    operator==(const NodeStatus &other) const
    {
      return state == other.state && direction == other.direction;
    }
  };

  /**
   * The contact law of the nodes of S_1 in the form both Newton solvers
   * (dd-newton and the monolithic one) solve, doc/friction.md section 3:
   * the law holds node by node for the averaged gap and slip.
   *
   * Normal: min(c p, theta p - d) = 0, d the node's averaged penetration,
   * theta its penalty (0 for exact contact) and c = theta + the
   * compliance of its surface (ContactInterface::complementarity_scale());
   * the node is in contact (closed) where d + (c - theta) p > 0.
   *
   * Tangential, at a closed node of a frictional pair: t = the trial
   * traction t + r / c_t cut to [-b, b], r = ds - theta (t - t_old) the
   * slip increment beyond the penalty's elastic slip; b = g (Tresca) or
   * mu max(0, p + (d - theta p) / c) (Coulomb, at the pressure the normal
   * law's trial gives). The node sticks where |trial| <= b, else it slips
   * with t = sigma b. t = 0 at open and frictionless nodes.
   *
   * The solvers compute d, r and the scales from their own unknowns; this
   * class owns the per-node law and bound coefficient (g_i or mu_i,
   * averaged like the gap) and answers everything the law decides: the
   * state, the bound, the residual and, on a slipping node, the linear
   * equation for t. A new law is a new FrictionLaw here.
   */
  class NodalContactLaw
  {
  public:
    /** One node's trial values. */
    struct Trial
    {
      double p     = 0; // the pressure multiplier p_i
      double d     = 0; // the averaged penetration d_i (data less S p)
      double theta = 0; // the normal penalty theta_i
      double c     = 0; // the normal complementarity scale c_i
      double t     = 0; // the tangential multiplier t_i
      double r     = 0; // ds_i - theta (t_i - t_i,old)
      double c_t   = 0; // the tangential complementarity scale
    };

    /** On a slipping node t = value + coupling p. */
    struct SlipEquation
    {
      double value    = 0;
      double coupling = 0;
    };

    /** No nodes. */
    void
    clear();

    /** Appends a node of a pair with law @p law and bound coefficient
     * @p coefficient (g_i or mu_i); @p prescribed_slip where the Dirichlet
     * conditions of both bodies fix the node's tangential motion. */
    void
    add_node(FrictionLaw law, double coefficient, bool prescribed_slip = false);

    /** Whether both bodies' Dirichlet conditions fix node @p i's slip
     * (a contact zone ending at nodes held on both sides): its slip is
     * data, r of its trial, and its traction follows from the law alone.
     * A closed node slips at its bound along r (t = 0 where r = 0),
     * never sticks: a stick condition there asks for the slip the
     * conditions forbid, and its row of the Newton system is singular
     * (issue 59: a push-out written "converged" with a force of 9.7e19). */
    bool
    slip_prescribed(const unsigned int i) const
    {
      return prescribed[i];
    }

    /** Whether node @p i has a frictional law. */
    bool
    frictional(const unsigned int i) const
    {
      return laws[i] != FrictionLaw::none;
    }

    /** The node is in contact: d + (c - theta) p > 0. */
    static bool
    closed(const Trial &x)
    {
      return x.d + (x.c - x.theta) * x.p > 0;
    }

    /** The normal law's residual min(c p, theta p - d). */
    static double
    normal_residual(const Trial &x)
    {
      return std::min(x.c * x.p, x.theta * x.p - x.d);
    }

    /** The trial traction t + r / c_t. */
    static double
    trial_traction(const Trial &x)
    {
      return x.t + x.r / x.c_t;
    }

    /** The slip bound b of node @p i at @p x (0 without friction). */
    double
    bound(unsigned int i, const Trial &x) const;

    /** The bound of node @p i at the converged pressure @p p, for the
     * reports: g_i or mu_i p. */
    double
    converged_bound(unsigned int i, double p) const;

    /** The state of node @p i at @p x. */
    NodeStatus
    status(unsigned int i, const Trial &x) const;

    /** The state of node @p i at @p x when the tangential traction is not
     * yet a Newton iterate (the first step of a load step): closed nodes
     * stick, or slip along @p direction where it is not 0. */
    NodeStatus
    prescribed_status(unsigned int i, const Trial &x, int direction) const;

    /** The tangential residual t - proj_[-b,b](trial) at a closed
     * frictional node, t elsewhere. */
    double
    tangential_residual(unsigned int i, const Trial &x) const;

    /** The equation t = value + coupling p of a slipping node @p i in
     * state @p s with bound @p b. With @p linearise_coulomb a Coulomb node
     * takes t = sigma mu p (coupled to the pressure, Newton's
     * linearisation), without it t = sigma b (a fixed point in the
     * pressure). */
    SlipEquation
    slip_equation(unsigned int      i,
                  const NodeStatus &s,
                  double            b,
                  bool              linearise_coulomb) const;

  private:
    /** The state of a closed frictional node whose slip is prescribed
     * (slip_prescribed()): slip along r, or with t = 0 where r vanishes
     * against the elastic slip c_t b of the bound. */
    NodeStatus
    prescribed_slip_status(unsigned int i, const Trial &x) const;

    std::vector<FrictionLaw> laws;         // per node
    std::vector<double>      coefficients; // g_i or mu_i per node
    std::vector<bool>        prescribed;   // slip_prescribed() per node
  };

  /** The explanation appended to a message on an active set that cycles
   * when a pair of @p pairs has Tresca friction (empty otherwise): g does
   * not vanish with the pressure. */
  std::string
  tresca_lift_off_note(const std::vector<ContactPair *> &pairs);
} // namespace ddcontact

#endif
