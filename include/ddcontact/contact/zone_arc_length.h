#ifndef ddcontact_zone_arc_length_h
#define ddcontact_zone_arc_length_h

#include <deal.II/base/point.h>

#include <array>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The arc length along a contact zone S_1 given as its faces (straight
   * segments), so that the measures of a contact set hold for any shape
   * and origin: a pin in a hole, a roller, a whole closed surface.
   *
   * The faces are joined into curves at their shared end points (a curve
   * is closed if it returns to its start). A point x on face f has the arc
   * length s(x) from the start of its curve. The extent of a set of points
   * on a curve is max s - min s on an open curve, and on a closed curve of
   * length L the length L minus the largest gap between neighbours (so
   * that a set across the curve's start is measured the short way round).
   * On a straight zone the extent is that of the projections on its
   * tangent.
   */
  class ZoneArcLength
  {
  public:
    ZoneArcLength() = default;

    /** The curves of @p faces; adjacent faces share an end point exactly
     * (ContactPair::zone_faces_1()). */
    explicit ZoneArcLength(const std::vector<std::array<Point<2>, 2>> &faces);

    /** The curve of face @p face and the arc length of @p x on it. */
    std::pair<unsigned int, double>
    position(unsigned int face, const Point<2> &x) const;

    /** The point at arc length @p s of curve @p curve (modulo its length
     * on a closed curve); the inverse of position(). */
    Point<2>
    point(unsigned int curve, double s) const;

    /** Half the sum over the curves of the extent of the points @p x
     * (on faces @p faces): the half-width of a contact or stick set. */
    double
    half_extent(const std::vector<unsigned int> &faces,
                const std::vector<Point<2>>     &x) const;

    /** The number of curves, and whether curve @p c is closed. */
    unsigned int
    n_curves() const
    {
      return curve_length.size();
    }

    bool
    is_closed(const unsigned int c) const
    {
      return closed[c];
    }

    double
    length(const unsigned int c) const
    {
      return curve_length[c];
    }

  private:
    // Per face: the end points, its curve, the arc length at the end it
    // is entered from, and whether it runs from its first end point.
    std::vector<std::array<Point<2>, 2>> faces;
    std::vector<unsigned int>            curve;
    std::vector<double>                  start;
    std::vector<bool>                    forward;
    // Per curve.
    std::vector<double> curve_length;
    std::vector<bool>   closed;
  };
} // namespace ddcontact

#endif
