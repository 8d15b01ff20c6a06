#ifndef ddcontact_friction_history_h
#define ddcontact_friction_history_h

#include <ddcontact/contact/contact_interface.h>
#include <ddcontact/contact/contact_problem.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The frictional state that a load step hands to the next (friction is
   * path dependent, doc/friction.md section 2): the averaged slip s_i,old
   * and the tangential multiplier t_i,old of every node of S_1 at the end
   * of the last step, and the slip at the pairs' points. It also turns an
   * iterate of nodal multipliers into the frictional results of the
   * pairs (PairSolution::friction): the traction, slip and state
   * at the points, the nodal values and the dissipated energy. Shared by
   * the monolithic solver and dd-newton, whose nodes are the same
   * (ContactInterface).
   */
  class FrictionHistory
  {
  public:
    /** No history: the undeformed, traction-free state (a new run). */
    void
    clear();

    /** The last published iterate (publish()) becomes the history of the
     * next load step, on the nodes of @p interface and the pairs' points.
     * After continue_load_step(), the next solve is the second part of the
     * same load step: the law's history moves on, but the slip increment
     * and the dissipated energy that publish() reports still count from
     * the start of the load step. */
    void
    start_load_step(const ContactProblem   &problem,
                    const ContactInterface &interface);

    /** The next start_load_step() starts a part of the current load step
     * (Loading/Steps = auto solves a step in two halves). */
    void
    continue_load_step()
    {
      continuing = true;
    }

    /** After a refinement (@p interface reinitialised on the new nodes):
     * the history moves to the new nodes, linearly between the old ones
     * (interpolated_node_values(): exact for the hat functions of a
     * bisected face), and the slip at the points to the new points (the
     * nearest old one). */
    void
    transfer(const ContactProblem &problem, const ContactInterface &interface);

    /** s_i,old of node @p i of the current nodes (transfer() keeps the
     * history on them), 0 without history (the first load step). */
    double
    old_slip(const unsigned int i) const
    {
      if (slips.empty())
        return 0.;
      AssertIndexRange(i, slips.size());
      return slips[i];
    }

    /** t_i,old, 0 without history. */
    double
    old_traction(const unsigned int i) const
    {
      if (tractions.empty())
        return 0.;
      AssertIndexRange(i, tractions.size());
      return tractions[i];
    }

    /**
     * Hand the frictional results of the nodal pressures @p p, tangential
     * multipliers @p t and averaged slips @p nodal_slips (interface.size()
     * values each) into @p published, per pair, for the frictional pairs; @p
     * sigma_n is the normal stress at the points (per pair), @p sticking the
     * nodes that stick in the solver's states. A point in contact sticks where
     * one of its nodes does, else it slips (between slipping or open nodes,
     * where t = sigma b): the solver's states, not a comparison of |t| with the
     * bound, which an iterative solver meets only to its tolerance. The energy
     * dissipated at node i is m_i t_i (ds_i - theta_i (t_i - t_i,old)): the
     * slip beyond the penalty's elastic part, zero where the node sticks.
     */
    void
    publish(const ContactProblem                   &problem,
            const ContactInterface                 &interface,
            const PointVector                      &p,
            const PointVector                      &t,
            const PointVector                      &nodal_slips,
            const std::vector<bool>                &sticking,
            const std::vector<std::vector<double>> &sigma_n,
            std::vector<PairSolution>              &published);

  private:
    std::vector<Point<2>>              nodes; // where slips and tractions live
    PointVector                        slips, tractions; // of the last step
    PointVector                        last_slips, last_tractions; // published
    std::vector<std::vector<double>>   point_slips; // per pair, last step
    std::vector<std::vector<Point<2>>> points;      // where point_slips live
    // Per pair as last published: the slip at the points (the next
    // step's point_slips; kept here, not read back from the laws, so that
    // a copy of the history is a whole state to go back to), and the
    // energy dissipated since the load step started.
    std::vector<std::vector<double>> last_point_slips;
    std::vector<double>              last_dissipation;
    // The dissipation of the earlier parts of the current load step, per
    // pair, and whether the next start_load_step() continues it.
    std::vector<double> carried_dissipation;
    bool                continuing = false;
  };
} // namespace ddcontact

#endif
