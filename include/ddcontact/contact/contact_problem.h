#ifndef ddcontact_contact_problem_h
#define ddcontact_contact_problem_h

#include <deal.II/base/tensor.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_distribution.h>
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/contact/contact_law.h>
#include <ddcontact/contact/contact_pair.h>

#include <utility>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** A frictional solver's results on a pair: at every point the
   * tangential traction t (the traction -t tau on body 1, see
   * ContactPoint), the slip increment of the load step, the slip since the
   * start, and the state; over the pair the energy dissipated in the step,
   * int_S1 t . slip increment >= 0. */
  struct FrictionResults
  {
    std::vector<double>    t, slip_increment, slip;
    std::vector<NodeState> state; // open, stick or slip
    double                 dissipation = 0;
    /** The law holds node by node for the averaged slip (doc/friction.md,
     * section 3): the multipliers t_i, the averaged slip increments ds_i
     * and the bounds (g_i or mu_i p_i) of the pair's nodes. */
    std::vector<double> nodal_t, nodal_slip_increment, nodal_bound;
    /** ds_i - theta_i (t_i - t_i,old): the slip increment beyond the
     * penalty's elastic slip, nonzero only where the node slips at its
     * bound (0 for every sticking node). */
    std::vector<double> nodal_inelastic_slip;
  };

  /**
   * What a contact solver computes on a pair beyond its iterate. The
   * displacements are the bodies' and the pressure the pair's law's
   * (ContactProblem::contact_state() computes forces, zone and
   * penetration from them); the solver publishes the rest here
   * (ContactSolver::solution_of()) for the report, the load steps and
   * the estimators: the frictional results (empty vectors until a solver
   * with friction has published them) and the peak of a nodal pressure
   * (0 for a pressure at the points).
   */
  struct PairSolution
  {
    FrictionResults friction;
    /** The largest nodal value of p: the peak of the piecewise linear
     * pressure, at a node, which the points between the nodes miss. */
    double peak_nodal_pressure = 0;
    /** The normal stress and the tangential traction at the points that
     * the bodies were loaded with, sum_i p_i phi_i with the test
     * functions phi_i (ContactInterface): with the dual basis not the
     * reported field sum_i p_i psi_i, though of the same resultant; the
     * reactions are computed from these (empty: the reported field, as
     * for a pressure at the points). */
    std::vector<double> load_sigma_n, load_t;
    /** The nodal multipliers p_i, the weak gaps d_i = (1/m_i) int phi_i
     * (u_1n + u_2n - g) of the bodies' displacements (> 0: penetration)
     * and the nodes' theta_i (0 for exact contact): the law (20) at the
     * nodes, p_i >= 0, d_i <= theta_i p_i, p_i (d_i - theta_i p_i) = 0,
     * which SelfChecks verifies (empty for a pressure at the points). */
    std::vector<double> nodal_pressure, nodal_gap, nodal_penalty;
  };

  /** Contact results of one pair for one iterate. */
  struct ContactState
  {
    std::vector<double> u_1n, u_2n, sigma_n; // at every contact point
    Tensor<1, 2>        force_1, force_2;
    double              max_pressure = 0; // over the contact points
    double max_nodal_pressure        = 0; // over the nodal multipliers, 0: none
    // The length of the zone along S_1, its gaps left out (ZoneExtent).
    double contact_length = 0;
    // The integral of the pressure along S_1 (each point's own normal).
    double normal_force = 0;
    // Half the extent of the zone along S_1, its edges placed inside their
    // cells (ZoneExtent); a zone that reaches the axis counts its mirror
    // image (then the contact radius).
    double half_width = 0;
    // The largest cell at an edge of the zone, and of the stick zone, not
    // at an end of S_1 (ZoneExtent::resolution()): how far an edge may be
    // off when the profile is not the assumed one.
    double extent_resolution = 0;
    double stick_resolution  = 0;
    // Axisymmetric zones (Geometry): the largest r of the zone's edges and
    // of the stick zone's, the contact and stick radii of a zone about the
    // axis (Hertz's a); -1 in plane strain.
    double contact_radius  = -1;
    double stick_radius    = -1;
    double max_penetration = 0;
    // With friction (PairSolution::friction; empty or 0 without): the
    // tangential traction t at the points (the traction -t tau on body 1),
    // the slip increment and state, the tangential force on body 1 along
    // each point's tau (included in force_1; the integral of -t), the
    // half-width of the stick zone (by arc length) and the
    // energy dissipated in the load step.
    std::vector<double>    t, slip_increment, slip;
    std::vector<NodeState> slip_state;
    double                 tangential_force = 0;
    double                 stick_half_width = 0;
    double                 dissipation      = 0;
  };

  /**
   * The contact problem (16) of several bodies, as the solvers see it: the
   * bodies with their factorized stiffness, the contact pairs with their
   * points, and the law (20) of every pair. It provides what the physics
   * gives -- normal displacements, gaps, pressures, contact loads, the
   * solution of every body problem for given loads -- and nothing of how
   * to iterate (that is the solvers').
   *
   * An iterate is one displacement vector per body (BodyVector: all dofs
   * on every process as BodyDistribution shares them, or a distributed
   * body's owned dofs plus ghosts, the contact traces among them).
   */
  class ContactProblem
  {
  public:
    using Iterate = std::vector<BodyVector>;

    /** What the processes that do not solve a body receive of its
     * solution: the whole vector, or only its values at trace_dofs() (zero
     * elsewhere), enough for every contact evaluation. */
    enum class Exchange
    {
      whole,
      traces
    };

    ContactProblem(const std::vector<ElasticBody<2> *> &bodies,
                   const std::vector<ContactPair *>    &pairs,
                   const BodyDistribution              &distribution);

    const std::vector<ElasticBody<2> *> &
    get_bodies() const
    {
      return bodies;
    }

    const std::vector<ContactPair *> &
    get_pairs() const
    {
      return pairs;
    }

    unsigned int
    body_index(const ElasticBody<2> &body) const;

    /** Whether a body has a nonlinear material law. */
    bool
    has_nonlinear_bodies() const;

    /** Where the bodies are solved (for other solves than solve_all()). */
    const BodyDistribution &
    get_distribution() const
    {
      return distribution;
    }

    /** The law of pair @p p (its multipliers can be updated). */
    ContactLaw &
    law(const unsigned int p)
    {
      return laws[p];
    }

    const ContactLaw &
    law(const unsigned int p) const
    {
      return laws[p];
    }

    /** New laws with zero multipliers (after setup of the pairs). */
    void
    reset_laws();

    /** The pressure is the solver's nodal multiplier
     * (ContactLaw::set_solver_pressure()), for the laws of reset_laws()
     * on. */
    void
    set_pressure_from_solver(bool from_solver);

    /** The bodies' current solutions. */
    Iterate
    current_iterate() const;

    /** Zero vectors of the bodies' layouts, their ghosts valid. */
    Iterate
    zero_iterate() const;

    /** @p to = @p from, vector by vector with copy_stored(), ghosts
     * included (std::vector's assignment may copy construct, which drops
     * them). */
    static void
    assign(Iterate &to, const Iterate &from)
    {
      to.resize(from.size());
      for (unsigned int b = 0; b < from.size(); ++b)
        copy_stored(from[b], to[b]);
    }

    /** Solve every body b with the extra load loads[b] (empty: none), each
     * on its process, concurrently; every process receives all u[b].
     * A non-finite load is refused naming the pairs' Gap and Penalty.
     * With @p homogeneous, the bodies' own data are left out
     * (ElasticBody::solve_homogeneous(): with a nonlinear law, the tangent
     * of its last solve). Otherwise a body of a nonlinear law runs its
     * Newton loop (ElasticBody::solve_nonlinear()) warm-started from u[b]
     * (zero if empty). */
    void
    solve_all(const Iterate &loads,
              Iterate       &u,
              bool           homogeneous = false,
              Exchange       exchange    = Exchange::whole) const;

    /** Solve all bodies loaded by the normal stresses sigma_n (one vector
     * per pair) on their contact zones: one step of (20); with
     * @p homogeneous, the response to sigma_n alone. */
    void
    solve_bodies(const std::vector<std::vector<double>> &sigma_n,
                 Iterate                                &u,
                 bool                                    homogeneous = false,
                 Exchange exchange = Exchange::whole) const;

    /** The same with the tangential tractions @p t as well (the traction
     * -t tau on body 1 and +t tau on body 2, ContactPair's friction
     * loads; one vector per pair). */
    void
    solve_bodies(const std::vector<std::vector<double>> &sigma_n,
                 const std::vector<std::vector<double>> &t,
                 Iterate                                &u,
                 bool                                    homogeneous = false,
                 Exchange exchange = Exchange::whole) const;

    /** Per body, the dofs (sorted) that the contact evaluations read:
     * those of the pairs' points, for the normal displacements and for the
     * loads with the constraints resolved. Exchange::traces sends these. */
    std::vector<std::vector<types::global_dof_index>>
    trace_dofs() const;

    /** Give every body with distributed vectors the current trace_dofs()
     * as ghosts (ElasticBody::distribute_vectors()): after the pairs were
     * set up on new meshes. Collective. */
    void
    update_vector_layouts() const;

    /** g = f_n - u_1n - u_2n of pair @p p at its points. */
    std::vector<double>
    gaps(unsigned int p, const Iterate &u) const;

    /** The pressure (20) of pair @p p for the iterate @p u. */
    std::vector<double>
    pressure(unsigned int p, const Iterate &u) const;

    /** Normal displacements on S of all pairs, both sides, body by body. */
    std::vector<std::vector<double>>
    normal_displacements_by_body(const Iterate &u) const;

    /** Forces, pressure, active set and penetration of pair @p p; with
     * what the solver published on the pair (@p published, if given) its
     * friction and nodal peak too. */
    ContactState
    contact_state(unsigned int        p,
                  const Iterate      &u,
                  const PairSolution *published = nullptr) const;

    /** The largest penetration u_1n + u_2n - f_n over all pairs, and its
     * ratio to the largest approach |u_1n| + |u_2n| (the measure of the
     * augmented Lagrangian's tolerance). */
    std::pair<double, double>
    penetration(const Iterate &u) const;

  private:
    std::vector<ElasticBody<2> *> bodies;
    std::vector<ContactPair *>    pairs;
    const BodyDistribution       &distribution;
    std::vector<ContactLaw>       laws;
    bool                          solver_pressure = false;
  };
} // namespace ddcontact

#endif
