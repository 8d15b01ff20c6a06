#ifndef ddcontact_zone_extent_h
#define ddcontact_zone_extent_h

#include <ddcontact/contact/zone_arc_length.h>

#include <vector>

namespace ddcontact
{
  /**
   * Where a contact zone (or a stick zone) ends along S_1, to a fraction of
   * a cell (issue 60): the extents that the report gives (half-width,
   * contact length, contact radius) from samples of a field that is
   * positive inside the zone, on the curves of a ZoneArcLength.
   *
   * Between the last sample inside and the first outside, the edge is
   *
   * - at a smooth edge (EdgeModel::square_root, a pressure that falls
   *   towards it), where the square-root profile p = C sqrt(e - s) through
   *   the last two samples inside vanishes: the edge of Hertz's and every
   *   smooth elastic contact (Johnson, Contact Mechanics, 4.2). Nodal
   *   multipliers are taken as point values of p there: on the Hertz
   *   cylinder they follow the closed form node by node up to the zone's
   *   last node, which lies inside the edge (doc/verification.md);
   * - otherwise (a sharp edge, a pressure that does not fall towards it, or
   *   the stick zone's EdgeModel::midpoint) halfway between them.
   *
   * A zone that reaches the end of its curve ends there exactly (a closed
   * end: a shrink fit's zone is the whole fit). resolution() is the
   * largest cell at an edge of the first kinds: how far the edge may be
   * from the estimate when the profile is not the assumed one.
   */
  class ZoneExtent
  {
  public:
    /** A value of the field at arc length @p s of curve @p curve. */
    struct Sample
    {
      unsigned int curve = 0;
      double       s     = 0;
      double       value = 0;
    };

    enum class EdgeModel
    {
      square_root,
      midpoint
    };

    /** An end of the zone: curve, arc length, and whether it is an end of
     * the curve (exact). */
    struct Edge
    {
      unsigned int curve      = 0;
      double       s          = 0;
      bool         at_the_end = false;
    };

    /** The zone of the samples @p samples whose value exceeds a 1e-12th
     * of the largest (round-off of the samples' reconstruction), on the
     * curves @p arcs. */
    ZoneExtent(const ZoneArcLength &arcs,
               std::vector<Sample>  samples,
               EdgeModel            model);

    /** The sum over the curves of the extent from the first edge to the
     * last (on a closed curve the complement of the largest gap between
     * the runs of the zone): twice the half-width. */
    double
    extent() const
    {
      return total_extent;
    }

    /** The sum of the lengths of the zone's runs (without its gaps). */
    double
    length() const
    {
      return total_length;
    }

    /** Every edge of the zone (two per run, none on a whole closed
     * curve). */
    const std::vector<Edge> &
    edges() const
    {
      return zone_edges;
    }

    /** The extent of the runs that reach an end of a curve at which
     * @p on_axis(curve, s) holds (the part mirrored by an axis of
     * symmetry). */
    template <typename OnAxis>
    double
    extent_at(const OnAxis &on_axis) const
    {
      double extent = 0;
      for (unsigned int r = 0; r + 1 < zone_edges.size(); r += 2)
        for (const auto &e : {zone_edges[r], zone_edges[r + 1]})
          if (e.at_the_end && on_axis(e.curve, e.s))
          {
            extent += zone_edges[r + 1].s - zone_edges[r].s;
            break;
          }
      return extent;
    }

    /** The largest cell (sample spacing) at an edge not at a curve's end;
     * 0 when every edge is one. */
    double
    resolution() const
    {
      return edge_resolution;
    }

    /** The edge between the last sample inside, at @p s_in with value
     * @p p_in, and the next outside at @p s_out, the one before inside at
     * @p s_prev with @p p_prev (s_prev < s_in < s_out), by @p model. */
    static double
    edge_between(double    s_prev,
                 double    p_prev,
                 double    s_in,
                 double    p_in,
                 double    s_out,
                 EdgeModel model);

  private:
    std::vector<Edge> zone_edges;
    double            total_extent    = 0;
    double            total_length    = 0;
    double            edge_resolution = 0;
  };
} // namespace ddcontact

#endif
