#include <ddcontact/contact/segment_search.h>

#include <boost/geometry/algorithms/append.hpp>
#include <boost/geometry/algorithms/correct.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/geometries/segment.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace ddcontact
{
  namespace
  {
    namespace bg  = boost::geometry;
    namespace bgi = boost::geometry::index;

    std::vector<BoundingBox<2>>
    boxes_of(const std::vector<std::array<Point<2>, 2>> &segments)
    {
      std::vector<BoundingBox<2>> boxes;
      boxes.reserve(segments.size());
      for (const auto &[a, b] : segments)
        boxes.emplace_back(std::vector<Point<2>>{a, b});
      return boxes;
    }

    std::vector<Point<2>>
    end_points_of(const std::vector<std::array<Point<2>, 2>> &segments)
    {
      std::vector<Point<2>> points;
      points.reserve(2 * segments.size());
      for (const auto &[a, b] : segments)
      {
        points.push_back(a);
        points.push_back(b);
      }
      return points;
    }
  } // namespace

  SegmentSearch::SegmentSearch(
    const std::vector<std::array<Point<2>, 2>> &segments)
    : segments(segments)
    , boxes(boxes_of(segments))
    , end_points(end_points_of(segments))
    , extent(end_points)
    , box_tree(pack_rtree_of_indices(boxes))
    , point_tree(pack_rtree_of_indices(end_points))
  {
    AssertThrow(!segments.empty(), ExcMessage("SegmentSearch: no segments"));
    for (const auto &x : end_points)
      scale = std::max({scale, std::abs(x[0]), std::abs(x[1])});
  }

  Point<2>
  closest_point_on_segment(const Point<2> &a,
                           const Point<2> &b,
                           const Point<2> &x)
  {
    const Tensor<1, 2> d = b - a;
    const double       r = std::clamp((x - a) * d / d.norm_square(), 0., 1.);
    return a + r * d;
  }

  Point<2>
  SegmentSearch::closest_point_on(const unsigned int i, const Point<2> &x) const
  {
    return closest_point_on_segment(segments[i][0], segments[i][1], x);
  }

  std::pair<unsigned int, Point<2>>
  SegmentSearch::closest_point(const Point<2> &x) const
  {
    // The segment of the nearest box is at some distance d0 from x; every
    // segment at most d0 away has its box in the square of half-width d0
    // around x. The margin covers the round-off of the computed distances
    // (a few units in the last place of the coordinates), so that no
    // segment the full loop could pick is missed.
    std::vector<std::size_t> found;
    box_tree.query(bgi::nearest(x, 1), std::back_inserter(found));
    const double d0 = closest_point_on(found[0], x).distance(x);
    const double h =
      d0 + 1e-10 * (d0 + scale + std::max(std::abs(x[0]), std::abs(x[1])));
    const BoundingBox<2> square(
      std::make_pair(x - Tensor<1, 2>({h, h}), x + Tensor<1, 2>({h, h})));
    found.clear();
    box_tree.query(bgi::intersects(square), std::back_inserter(found));

    // As the loop over all segments: the first of equally close ones.
    std::sort(found.begin(), found.end());
    double                            best = std::numeric_limits<double>::max();
    std::pair<unsigned int, Point<2>> closest;
    for (const auto i : found)
    {
      const Point<2> candidate = closest_point_on(i, x);
      const double   distance  = candidate.distance(x);
      if (distance < best)
      {
        best    = distance;
        closest = {i, candidate};
      }
    }
    return closest;
  }

  std::vector<unsigned int>
  SegmentSearch::segments_crossed(const Point<2> &p, const Point<2> &q) const
  {
    const bg::model::segment<Point<2>> line(p, q);
    std::vector<std::size_t>           found;
    box_tree.query(bgi::intersects(line), std::back_inserter(found));
    std::vector<unsigned int> indices(found.begin(), found.end());
    std::sort(indices.begin(), indices.end());
    return indices;
  }

  std::vector<Point<2>>
  SegmentSearch::end_points_over(const Point<2> &a, const Point<2> &b) const
  {
    // The slab over [a, b], widened by 1e-6 of its length along it and cut
    // off beyond the zone's box across it: a long thin parallelogram that
    // crosses the zone where it faces [a, b].
    const Tensor<1, 2> t      = b - a;
    const Tensor<1, 2> normal = Tensor<1, 2>({t[1], -t[0]}) / t.norm();
    double             reach  = 0;
    for (unsigned int v = 0; v < 4; ++v)
      reach = std::max(reach, std::abs((extent.vertex(v) - a) * normal));
    const Tensor<1, 2> along  = 1e-6 * t,
                       across = (1.01 * reach + t.norm()) * normal;
    bg::model::polygon<Point<2>> slab;
    for (const Point<2> &corner : {a - along - across,
                                   b + along - across,
                                   b + along + across,
                                   a - along + across,
                                   a - along - across})
      bg::append(slab.outer(), corner);
    bg::correct(slab);

    std::vector<std::size_t> found;
    point_tree.query(bgi::intersects(slab), std::back_inserter(found));
    std::vector<Point<2>> points;
    points.reserve(found.size());
    for (const auto i : found)
      points.push_back(end_points[i]);
    return points;
  }
} // namespace ddcontact
