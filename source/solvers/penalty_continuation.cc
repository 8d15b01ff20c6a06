#include <ddcontact/solvers/penalty_continuation.h>

#include <algorithm>
#include <limits>

namespace ddcontact
{
  namespace
  {
    /** The continuation's stages: t = 1, 1e-2, 1e-4, ... (with 1, 0.1,
     * 0.01: 30 and 32 sets at paper refinements 4 and 5, against 24 and
     * 25; the stage t = 0.1 costs more steps than it saves). */
    constexpr double continuation_factor = 1e-2;

    /** Penalty continuation only where a pair's overlap covers at least
     * this many unknowns (paper scene: 75 at refinement 2 took 19 sets
     * without and 23 with it, 150 at refinement 3 35 and 33). */
    constexpr unsigned int min_continuation_unknowns = 100;

  } // namespace

  PenaltyContinuation::PenaltyContinuation(ContactInterface    &interface,
                                           RobinPreconditioner &preconditioner,
                                           ConditionalOStream  &pcout)
    : interface(interface)
    , preconditioner(preconditioner)
    , pcout(pcout)
  {
  }

  void
  PenaltyContinuation::reset(const bool enabled)
  {
    interface.set_continuation(0.);
    pending = enabled;
  }

  void
  PenaltyContinuation::start(const PointVector                &d_0,
                             const std::vector<ContactPair *> &pairs)
  {
    // theta_ref over the length of the overlap where it is shorter than
    // the bodies are thick: a Hertzian zone is held by the compliance of
    // its own length.
    std::vector<double>       lengths(pairs.size(), 0.);
    std::vector<unsigned int> overlapping(lengths.size(), 0);
    for (unsigned int q = 0; q < interface.size(); ++q)
      if (d_0[q] > 0)
      {
        lengths[interface.shares(q)[0].pair] += interface.weight(q);
        ++overlapping[interface.shares(q)[0].pair];
      }
    for (double &L : lengths)
      if (L == 0)
        L = std::numeric_limits<double>::infinity();
    interface.set_reference_lengths(lengths);
    // An active set method takes about a step per unknown that it releases
    // at each end of a zone; on small zones that is fewer than the stages.
    // Only on the nodes: on the points S has a kernel, a stage's pressure
    // is determined only to the residual over theta, and on the slender
    // plate at c = 0.05 the last stage ended on a force 6.6 times the
    // nodes' (without stages the points do not converge there).
    const bool large_zone =
      *std::max_element(overlapping.begin(), overlapping.end()) >=
      min_continuation_unknowns;
    if (large_zone && interface.on_nodes())
      enter_stage(stage_after(1.));
    pending = false;
  }

  void
  PenaltyContinuation::enter_stage(const double t)
  {
    if (t == interface.get_continuation())
      return;
    interface.set_continuation(t);
    preconditioner.update_penalties();
    pcout << "  continuation: theta + " << t << " theta_ref" << std::endl;
  }

  bool
  PenaltyContinuation::advance(const unsigned int n_changed,
                               const unsigned int n_active)
  {
    // A stage has settled when at most 1 % of its active set changes (the
    // last changes of a stage are the node-by-node peeling that the next
    // stage does anyway); the next, stiffer one starts from it.
    if (interface.get_continuation() == 0 || 100 * n_changed > n_active)
      return false;
    enter_stage(
      stage_after(continuation_factor * interface.get_continuation()));
    return true;
  }

  bool
  PenaltyContinuation::penalty_dominates() const
  {
    // Theta^{-1} (Theta + S) has a condition number of at most
    // 1 + theta_ref / theta = 1 + 1 / t (S is at most the compliance
    // across the bodies). It is taken when that is below t theta_ref / e,
    // the stage's springs in units of an element's compliance e: such a
    // soft stage does not pay for the Robin factorization (paper scene,
    // refinement 5: the stage t = 1 in 6 sets without factorization).
    // With friction the sticking nodes' tangential unknowns have no
    // continuation: the Robin problems precondition them.
    const double t = interface.get_continuation();
    if (t == 0 || interface.has_friction())
      return false;
    double ratio = 0;
    for (unsigned int q = 0; q < interface.size(); ++q)
      ratio = std::max(ratio,
                       interface.reference_penalty(q) /
                         std::max(interface.target_penalty(q),
                                  interface.element_compliance(q)));
    return 1 / t < t * ratio;
  }

  double
  PenaltyContinuation::stage_after(const double t) const
  {
    for (unsigned int q = 0; q < interface.size(); ++q)
      if (t * interface.reference_penalty(q) >
          std::max(10 * interface.target_penalty(q),
                   interface.element_compliance(q)))
        return t;
    return 0.;
  }

} // namespace ddcontact
