// DESCRIPTION: SegmentSearch (the R-tree searches of ContactPair::setup())
// gives the same answers, bit for bit, as the loops over all segments it
// replaced: the closest segment and point (the first of equally close
// ones) and the end points that project onto a face, for a closed polygon,
// a zig-zag with coinciding vertices and a straight zone of 2000 segments,
// at random points near and far, on the vertices and on the segments
#include <deal.II/base/point.h>

#include <ddcontact/contact/segment_search.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  using Segments = std::vector<std::array<Point<2>, 2>>;

  /** The loop of ContactPair::setup() before the R-tree: every segment,
   * the first of the closest. */
  std::pair<unsigned int, Point<2>>
  closest_by_loop(const Segments &segments, const Point<2> &x)
  {
    double                            best = std::numeric_limits<double>::max();
    std::pair<unsigned int, Point<2>> closest;
    for (unsigned int i = 0; i < segments.size(); ++i)
    {
      const auto        &f = segments[i];
      const Tensor<1, 2> d = f[1] - f[0];
      const double   r = std::clamp((x - f[0]) * d / d.norm_square(), 0., 1.);
      const Point<2> candidate = f[0] + r * d;
      const double   distance  = candidate.distance(x);
      if (distance < best)
      {
        best    = distance;
        closest = {i, candidate};
      }
    }
    return closest;
  }

  /** The parameters s in (1e-10, 1 - 1e-10) along [a, b] of the end points
   * of @p points, sorted: what splits a face of S_1. */
  std::vector<double>
  breaks(const std::vector<Point<2>> &points,
         const Point<2>              &a,
         const Point<2>              &b)
  {
    const Tensor<1, 2>  t = b - a;
    std::vector<double> s;
    for (const auto &v : points)
    {
      const double r = (v - a) * t / t.norm_square();
      if (r > 1e-10 && r < 1. - 1e-10)
        s.push_back(r);
    }
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
  }

  void
  compare(const std::string &name, const Segments &segments)
  {
    const SegmentSearch   search(segments);
    std::vector<Point<2>> all_ends, probes;
    for (const auto &[a, b] : segments)
    {
      all_ends.push_back(a);
      all_ends.push_back(b);
      probes.push_back(a);
      probes.push_back(a + 0.5 * (b - a));
    }
    // Random points in a box twice the zone's size around it.
    const BoundingBox<2> box(all_ends);
    const double   size  = std::max(box.side_length(0), box.side_length(1));
    const Point<2> lower = box.get_boundary_points().first;
    std::mt19937   random(7);
    std::uniform_real_distribution<double> u(-0.5, 1.5);
    for (unsigned int i = 0; i < 2000; ++i)
      probes.push_back(lower +
                       Tensor<1, 2>({u(random) * size, u(random) * size}));

    unsigned int closest_differ = 0;
    for (const auto &x : probes)
    {
      const auto loop = closest_by_loop(segments, x);
      const auto tree = search.closest_point(x);
      if (loop.first != tree.first || !(loop.second == tree.second))
        ++closest_differ;
    }
    unsigned int ends_differ = 0;
    for (unsigned int i = 0; i < segments.size(); i += 7)
    {
      // Faces of a zone S_1 near the segments, shifted and tilted.
      const Point<2> a = segments[i][0] + Tensor<1, 2>({1e-3, 2e-2});
      const Point<2> b = segments[i][1] + Tensor<1, 2>({-2e-3, 1e-2});
      if (breaks(all_ends, a, b) != breaks(search.end_points_over(a, b), a, b))
        ++ends_differ;
    }
    std::cout << name << ": " << segments.size() << " segments, "
              << probes.size() << " points" << std::endl;
    check(closest_differ == 0,
          name + ": closest segment and point as the loop's, bit for bit");
    check(ends_differ == 0, name + ": the breaks of every face as the loop's");
  }
} // namespace

int
main()
{
  // A closed 97-gon of radius 1 (every point has far-side vertices in its
  // slab too).
  Segments circle;
  for (unsigned int i = 0; i < 97; ++i)
  {
    const double t0 = 2 * numbers::PI * i / 97,
                 t1 = 2 * numbers::PI * (i + 1) / 97;
    circle.push_back({{Point<2>(std::cos(t0), std::sin(t0)),
                       Point<2>(std::cos(t1), std::sin(t1))}});
  }
  compare("circle", circle);

  // A zig-zag whose vertices every probe at a vertex has two equally close
  // segments, and a segment given twice (a tie broken by the index).
  Segments zigzag;
  for (unsigned int i = 0; i < 50; ++i)
    zigzag.push_back({{Point<2>(0.1 * i, (i % 2) * 0.05),
                       Point<2>(0.1 * (i + 1), ((i + 1) % 2) * 0.05)}});
  zigzag.push_back(zigzag[10]);
  compare("zig-zag", zigzag);

  // A long straight zone as the benchmark's, of 2000 faces.
  Segments line;
  for (unsigned int i = 0; i < 2000; ++i)
    line.push_back({{Point<2>(i / 2e3, 0.01), Point<2>((i + 1) / 2e3, 0.01)}});
  compare("straight zone", line);

  return report();
}
