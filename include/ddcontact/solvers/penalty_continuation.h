#ifndef ddcontact_penalty_continuation_h
#define ddcontact_penalty_continuation_h

#include <deal.II/base/conditional_ostream.h>

#include <ddcontact/contact/contact_interface.h>
#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/solvers/robin_preconditioner.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The penalty continuation of dd-newton (DD-Newton/Penalty
   * continuation): started from the overlap, a primal-dual active-set
   * method releases about one unknown at each end of a zone per step,
   * because the tension of a too-wide zone sits in a layer of about an
   * element, so its steps grow like 1/h. The stages theta + t theta_ref,
   * t = 1, 1e-2, ... (theta_ref the compliance of both bodies across their
   * thickness, or across the overlap where that is shorter) spread that
   * layer: each stage's active set settles in a few steps and starts the
   * next, down to the pairs' own theta once t theta_ref is below an
   * element's compliance (the path following of Hintermueller and Kunisch
   * for the Moreau-Yosida regularised problem, here the penalty (15)
   * itself). Only on the nodes, and on zones that overlap on at least 100
   * unknowns. Counts: doc/contact-solvers.md.
   *
   * The stage lives in the interface (ContactInterface::set_continuation()),
   * its springs in the preconditioner.
   */
  class PenaltyContinuation
  {
  public:
    PenaltyContinuation(ContactInterface    &interface,
                        RobinPreconditioner &preconditioner,
                        ConditionalOStream  &pcout);

    /** No stage; with @p enabled the first stage starts at the next
     * start(). */
    void
    reset(bool enabled);

    /** Whether start() is still to come. */
    bool
    is_pending() const
    {
      return pending;
    }

    /** The first stage, once the overlap @p d_0 of the unknowns is known
     * (@p pairs: the contact pairs, for the lengths of their overlaps). */
    void
    start(const PointVector &d_0, const std::vector<ContactPair *> &pairs);

    /** After a step whose active set of @p n_active unknowns changed in
     * @p n_changed: the next stage if at most 1 % changed. Returns whether
     * the stage moved on (the active set is then to be taken again). */
    bool
    advance(unsigned int n_changed, unsigned int n_active);

    /** Whether the continuation's theta dominates S so much that
     * Theta^{-1} preconditions better than the Robin problems (soft
     * stages). */
    bool
    penalty_dominates() const;

  private:
    /** Go on to stage @p t (0: the pairs' own theta). */
    void
    enter_stage(double t);

    /** @p t if that stage is still much softer than the pairs' own theta
     * and than an element's compliance somewhere (t theta_ref,q larger
     * than ten times the first and than the second), else 0: below, the
     * springs' boundary layer at the zone's ends is narrower than an
     * element, and the active set is that of the pairs' theta to a
     * node. */
    double
    stage_after(double t) const;

    ContactInterface    &interface;
    RobinPreconditioner &preconditioner;
    ConditionalOStream  &pcout;
    bool                 pending = false;
  };
} // namespace ddcontact

#endif
