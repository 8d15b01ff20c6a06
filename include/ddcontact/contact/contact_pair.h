#ifndef ddcontact_contact_pair_h
#define ddcontact_contact_pair_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/elastic_body.h>
#include <ddcontact/contact/contact_pair_parameters.h>
#include <ddcontact/contact/contact_search.h>
#include <ddcontact/contact/zone_arc_length.h>
#include <ddcontact/parameter_tools.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** "(x1, x2)" in full precision, for messages. */
  std::string
  point_coordinates(const Point<2> &x);

  /**
   * One integration point of the contact integral over S_1 (15)-(16). It
   * carries everything an iteration needs, so that the point-to-cell search
   * is done once per mesh and never per iteration: the position x on S_1,
   * the weight, the outward normal n_1 of body 1, the initial gap f_n(x),
   * and, for both bodies, the dofs of the cell that holds x (body 1) or its
   * projection P(x) (body 2) together with the normal component of each
   * shape function there: u_1n(x) = sum_i a_i u_1[dofs_1[i]] and
   * u_2n(P(x)) = sum_i b_i u_2[dofs_2[i]], with n_2 = -n_1 (small-gap
   * assumption of section 1 of doc/method.md).
   *
   * The load of the point, the same coefficients with the body's
   * constraints resolved (hanging and Dirichlet dofs replaced by their
   * masters, as AffineConstraints::distribute_local_to_global() would),
   * is kept too (load_dofs_1, load_1 and the same for body 2): then adding
   * the contact load needs no constraints, which a process of a
   * distributed mesh knows only for its own cells.
   *
   * For the output of the zone (ContactZoneWriter), a point also knows the
   * face of S_1 that holds it (an index into ContactPair::zone_faces_1())
   * and the value of each shape function of dofs_1 at x (of its one
   * nonzero component), from which u_1(x) is summed.
   *
   * With friction (ContactPair::has_friction()) the point carries the same
   * coefficients for the tangent tau = n_1 turned by +90 degrees: the slip
   * s = (u_1 - u_2) . tau = sum_i at_i u_1[dofs_1[i]] + sum_i bt_i
   * u_2[dofs_2[i]] (tau_2 = -tau, as n_2 = -n_1), the loads load_t1 and
   * load_t2 on load_dofs_1 and load_dofs_2, and the slip bound g (Tresca)
   * or the coefficient mu (Coulomb) at x.
   */
  struct ContactPoint
  {
    Point<2> x;
    Point<2> projection;
    /** The weight of the point: ds of the zone times the section's
     * measure (2 pi r for an axisymmetric body, Geometry); ds alone for
     * lengths. */
    double                               JxW = 0;
    double                               ds  = 0;
    Tensor<1, 2>                         normal;
    double                               gap = 0;
    std::vector<types::global_dof_index> dofs_1, dofs_2;
    std::vector<double>                  a, b;
    std::vector<types::global_dof_index> load_dofs_1, load_dofs_2;
    std::vector<double>                  load_1, load_2;
    unsigned int                         face = 0;
    std::vector<double>                  values_1;
    std::vector<double>                  at, bt, load_t1, load_t2;
    double                               friction = 0;
  };

  /**
   * A possible contact zone S_1 of body 1 facing a zone S_2 of body 2, with
   * independent (non-matching) meshes.
   *
   * The contact integral is computed on the common refinement of the two
   * meshes: each face of S_1 is split where the projections of the
   * vertices of S_2 fall, and each piece gets its own Gauss rule. Both
   * normal displacements are then polynomials on every piece, so the
   * integral of (20) is exact up to the kink of min(0, .) at the edge of
   * the contact area; a rule on the faces of S_1 alone would integrate
   * across the kinks of u_2n and lose accuracy at the peak pressure.
   *
   * A body on a distributed mesh (p4est) holds only its own cells: its
   * zone faces are gathered from all processes, the points are found in
   * the owned cells by Utilities::MPI::RemotePointEvaluation, and their
   * owners send the dofs, shape values and constraints of each point to
   * every process. setup() is then collective; the iterations are not.
   */
  class ContactPair
  {
  public:
    ContactPair(const ContactPairParameters &parameters,
                const ElasticBody<2>        &body_1,
                const ElasticBody<2>        &body_2,
                const Constants             &constants);

    /** Build the contact points; call again after either mesh changed
     * (refined or repartitioned). */
    void
    setup();

    const std::string &
    name() const
    {
      return parameters.name;
    }

    const ElasticBody<2> &
    get_body_1() const
    {
      return body_1;
    }

    const ElasticBody<2> &
    get_body_2() const
    {
      return body_2;
    }

    const std::vector<ContactPoint> &
    points() const
    {
      return contact_points;
    }

    /** The faces of S_1 (end points, in the order of ContactPoint::face);
     * adjacent faces share an end point exactly. */
    const std::vector<std::array<Point<2>, 2>> &
    zone_faces_1() const
    {
      return zone_1;
    }

    /** The arc length along S_1 (its faces joined into curves): where
     * the half-widths of contact and stick sets are measured. */
    const ZoneArcLength &
    zone_arc_length() const
    {
      return arc_length;
    }

    /** u_1n and u_2n at every contact point. */
    void
    normal_displacements(const BodyVector    &u_1,
                         const BodyVector    &u_2,
                         std::vector<double> &u_1n,
                         std::vector<double> &u_2n) const;

    /**
     * Add the Neumann load of the normal traction sigma_n (one value per
     * contact point, <= 0 for compression) to both bodies: on body 1
     * int_S1 sigma_n n_1 . v_1, on body 2 int_S1 sigma_n n_2 . v_2(P(x)),
     * with the same points and weights, so the two forces are equal and
     * opposite. Constraints of each body are applied. Returns the force on
     * body 1 and on body 2, each summed from the assembled entries (not
     * from sigma_n), as a check of the assembly.
     */
    std::pair<Tensor<1, 2>, Tensor<1, 2>>
    add_contact_loads(const std::vector<double> &sigma_n,
                      BodyVector                &load_1,
                      BodyVector                &load_2) const;

    /**
     * Add the load of the normal stress @p sigma_n on @p body (either side
     * of the pair) to @p load, as add_contact_loads() does but with no
     * constraints applied: the contact's share in the residual of a
     * Dirichlet node (ReactionForces).
     */
    void
    add_unconstrained_contact_load(const std::vector<double> &sigma_n,
                                   const ElasticBody<2>      &body,
                                   BodyVector                &load) const;

    /** The tangential traction's share, as add_friction_loads() but on
     * @p body alone and with no constraints applied (@p t empty: none). */
    void
    add_unconstrained_friction_load(const std::vector<double> &t,
                                    const ElasticBody<2>      &body,
                                    BodyVector                &load) const;

    /**
     * Append the traction sigma_n n_a that the normal stress @p sigma_n
     * (one value per contact point) exerts on @p body (either side of the
     * pair) to @p samples: at x with n_1 on body 1, at P(x) with n_2 = -n_1
     * on body 2, with the weights of S_1 -- the same points and weights
     * that add_contact_loads() uses, so that a BEM loaded by the samples
     * sees the load of the FEM problem (20). With friction @p t (empty:
     * none) adds the tangential traction -t tau on body 1, +t tau on body
     * 2.
     */
    void
    add_traction_samples(const std::vector<double> &sigma_n,
                         const ElasticBody<2>      &body,
                         BoundaryTractionSamples   &samples,
                         const std::vector<double> &t = {}) const;

    /** The friction law (Contact pair/Friction). */
    FrictionLaw
    friction_law() const
    {
      return parameters.friction;
    }

    bool
    has_friction() const
    {
      return parameters.friction != FrictionLaw::none;
    }

    /** The slip s = (u_1 - u_2) . tau at every contact point (see
     * ContactPoint; zero without friction). */
    std::vector<double>
    slips(const BodyVector &u_1, const BodyVector &u_2) const;

    /**
     * Add the load of the tangential traction: -@p t tau on body 1 and
     * +@p t tau on body 2 at every contact point (t >= 0 opposes a positive
     * slip of body 1 along tau), as add_contact_loads() does for the
     * normal stress. Returns the forces on both bodies.
     */
    std::pair<Tensor<1, 2>, Tensor<1, 2>>
    add_friction_loads(const std::vector<double> &t,
                       BodyVector                &load_1,
                       BodyVector                &load_2) const;

    /** What the contact search found at the last setup(). */
    const ContactSearchReport &
    search_report() const
    {
      return report;
    }

    /** The warnings of the last setup(), one sentence each: a zone that
     * faces away, an initial overlap, an expression gap that contradicts
     * the meshes (empty: none). */
    std::vector<std::string>
    setup_warnings() const;

    /** How many faces of S_1 meet the points for every cell of body 2 that
     * their projections meet: above 1, S_1 is the finer side where the
     * zones face each other (0 without points). Multipliers on the nodes
     * of a much finer S_1 oscillate (the mortar inf-sup condition). */
    double
    multiplier_side_ratio() const;

    /** The penalty parameter theta of (15) for this pair. */
    double
    penalty() const
    {
      return theta;
    }

    /** Thickness of body 1 across the contact zone (for theta = c H/E_1),
     * and of body 2 along the same direction. */
    double
    thickness_of_body_1() const
    {
      return thickness_1;
    }

    double
    thickness_of_body_2() const
    {
      return thickness_2;
    }

  private:
    const ContactPairParameters          parameters;
    const ElasticBody<2>                &body_1;
    const ElasticBody<2>                &body_2;
    std::shared_ptr<Function<2>>         gap_function;
    std::shared_ptr<Function<2>>         friction_function; // g or mu
    std::vector<ContactPoint>            contact_points;
    std::vector<std::array<Point<2>, 2>> zone_1;     // faces of S_1
    ZoneArcLength                        arc_length; // along zone_1
    double                               theta       = 0;
    double                               thickness_1 = 0, thickness_2 = 0;
    ContactSearchReport                  report;

    /** Search distance = auto: a tenth of the smaller body's diameter (a
     * gap wider than that cannot close under small strains), at least
     * twice the longest zone face @p h_max. */
    double
    default_search_distance(double h_max) const;

    /** The thickness of both bodies along the mean normal of S_1 and
     * theta (end of setup()), with the checks of the overlap and of the
     * penalty. */
    void
    set_penalty();
  };
} // namespace ddcontact

#endif
