// DESCRIPTION: ZoneExtent places a contact zone's edges inside their cells
// (issue 60). On samples of p = sqrt(e - s), the profile it assumes, the
// edge is exact to round-off at any offset in the cell; on Hertz's
// ellipse p0 sqrt(1 - x^2/a^2) its error is that of the chord of p^2, at
// most h^2 / a; a zone that reaches an end of its curve ends there
// exactly; a sharp edge (p not falling) and the stick zone's indicator
// are put halfway; on a closed curve a zone across the curve's start is
// measured the short way round, and a zone over the whole curve is the
// curve; extent_at() counts the runs that reach a marked end
#include <deal.II/base/point.h>

#include <ddcontact/contact/zone_extent.h>

#include "test_tools.h"

#include <cmath>
#include <functional>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  using Faces = std::vector<std::array<Point<2>, 2>>;

  /** n faces of length h along the x axis from 0. */
  Faces
  straight(const unsigned int n, const double h)
  {
    Faces faces;
    for (unsigned int k = 0; k < n; ++k)
      faces.push_back({{Point<2>(k * h, 0), Point<2>((k + 1) * h, 0)}});
    return faces;
  }

  /** @p p at the nodes k h, k = 0..n, of curve 0. */
  std::vector<ZoneExtent::Sample>
  nodes(const unsigned int                   n,
        const double                         h,
        const std::function<double(double)> &p)
  {
    std::vector<ZoneExtent::Sample> samples;
    for (unsigned int k = 0; k <= n; ++k)
      samples.push_back({0, k * h, p(k * h)});
    return samples;
  }
} // namespace

int
main()
{
  const double        h = 0.5;
  const ZoneArcLength line(straight(20, h));
  const auto          root = ZoneExtent::EdgeModel::square_root;

  // The assumed profile, from the curve's start (an exact end) to e, at
  // offsets across a cell.
  for (const double e : {3.01, 3.2, 3.37, 3.49})
  {
    const ZoneExtent zone(
      line,
      nodes(
        20, h, [&](const double s) { return std::sqrt(std::max(0., e - s)); }),
      root);
    check("square-root profile to e = " + std::to_string(e) + ", relative",
          relative(zone.extent(), e),
          1e-12);
    check(zone.edges().size() == 2 && zone.edges()[0].at_the_end &&
            !zone.edges()[1].at_the_end,
          "the zone's start is the curve's end, its edge is not");
    check("resolution: the cell at the edge",
          relative(zone.resolution(), h),
          1e-12);
    check("length = extent for one run",
          relative(zone.length(), zone.extent()),
          1e-15);
  }

  // Hertz's ellipse about c, at a / h = 5.3: the chord of p^2 through the
  // last two nodes misses its root by at most h^2 / a on each side.
  {
    const double     a = 2.65, c = 5.1;
    const ZoneExtent zone(line,
                          nodes(20,
                                h,
                                [&](const double s)
                                {
                                  const double x = (s - c) / a;
                                  return 3. *
                                         std::sqrt(std::max(0., 1. - x * x));
                                }),
                          root);
    check("Hertz's ellipse: |extent - 2a| / (2 h^2 / a)",
          std::abs(zone.extent() - 2 * a) / (2 * h * h / a),
          1.);
    check(!zone.edges()[0].at_the_end && !zone.edges()[1].at_the_end,
          "an interior zone has no exact end");
  }

  // A sharp edge (a punch: p rises towards it, or stays flat) is put
  // halfway; so is every edge of the stick indicator.
  {
    const ZoneExtent punch(
      line,
      nodes(20,
            h,
            [](const double s)
            { return (s > 1.2 && s < 3.7) ? 1. + std::abs(s - 2.5) : 0.; }),
      root);
    // Nodes inside: 1.5 .. 3.5; halfway to 1.0 and to 4.0.
    check("sharp edges halfway", relative(punch.extent(), 2.5), 1e-12);
    const ZoneExtent stick(
      line,
      nodes(
        20, h, [](const double s) { return (s > 1.2 && s < 3.7) ? 1. : -1.; }),
      ZoneExtent::EdgeModel::midpoint);
    check("stick indicator halfway", relative(stick.extent(), 2.5), 1e-12);
  }

  // Two runs on an open curve: the extent spans both, the length does not;
  // extent_at() counts the run that reaches the marked end s = 0.
  {
    const ZoneExtent two(line,
                         nodes(20,
                               h,
                               [](const double s) {
                                 return (s < 1.2 || (s > 6.2 && s < 7.7)) ? 1.
                                                                          : 0.;
                               }),
                         root);
    // Run 1: 0 .. 1.0 (end) .. halfway to 1.5 = 1.25; run 2: 6.25 .. 7.75.
    check("two runs: extent", relative(two.extent(), 7.75), 1e-12);
    check("two runs: length", relative(two.length(), 1.25 + 1.5), 1e-12);
    check("the run at the marked end",
          relative(
            two.extent_at([](unsigned int, const double s) { return s == 0.; }),
            1.25),
          1e-12);
    check(two.extent_at([](unsigned int, double) { return false; }) == 0.,
          "no marked end, nothing mirrored");
  }

  // A closed curve (a square of side 4, faces of 0.5): a zone across its
  // start measured the short way round, the whole curve, nothing.
  {
    Faces                 square;
    std::vector<Point<2>> v;
    for (unsigned int k = 0; k < 32; ++k)
    {
      const double t = 0.5 * k;
      v.push_back(t < 4    ? Point<2>(t, 0)
                  : t < 8  ? Point<2>(4, t - 4)
                  : t < 12 ? Point<2>(12 - t, 4)
                           : Point<2>(0, 16 - t));
    }
    for (unsigned int k = 0; k < 32; ++k)
      square.push_back({{v[k], v[(k + 1) % 32]}});
    const ZoneArcLength loop(square);
    check(loop.n_curves() == 1 && loop.is_closed(0), "the square is closed");
    // The zone |s| < 2.2 about the start (s = 0 and s = 16 are the same
    // node), the square-root profile towards both edges.
    const auto across = [](const double s)
    {
      const double d = std::min(s, 16. - s);
      return std::sqrt(std::max(0., 2.2 - d));
    };
    const ZoneExtent zone(loop, nodes(31, 0.5, across), root);
    check("across the start, the short way round",
          relative(zone.extent(), 4.4),
          1e-12);
    const ZoneExtent whole(
      loop, nodes(31, 0.5, [](double) { return 1.; }), root);
    check("the whole closed curve", relative(whole.extent(), 16.), 1e-15);
    check(whole.resolution() == 0., "a whole curve has no edge to resolve");
    const ZoneExtent none(
      loop, nodes(31, 0.5, [](double) { return 0.; }), root);
    check(none.extent() == 0. && none.edges().empty(), "no zone, no extent");
    // The point at an arc length, the inverse of position().
    check("ZoneArcLength::point past the start",
          loop.point(0, 16.75).distance(Point<2>(0.75, 0)),
          1e-12);
  }
  return report();
}
