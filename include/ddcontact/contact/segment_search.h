#ifndef ddcontact_segment_search_h
#define ddcontact_segment_search_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>

#include <deal.II/numerics/rtree.h>

#include <array>
#include <utility>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** The closest point of the segment [@p a, @p b] to @p x. */
  Point<2>
  closest_point_on_segment(const Point<2> &a,
                           const Point<2> &b,
                           const Point<2> &x);

  /**
   * The geometric searches of ContactPair::setup() on the faces of a zone
   * S_2, given as straight segments: the closest point P(x) of the zone to
   * a point x (the orthogonal projection of section 1 of doc/method.md),
   * and the segment end points that project onto a face of S_1 (where the
   * common refinement splits that face).
   *
   * Both are R-tree queries (Boost.Geometry through deal.II's
   * pack_rtree_of_indices()): the tree of the segments' bounding boxes and
   * the tree of their end points are packed once, in O(n log n), and each
   * query visits O(log n) nodes plus the few segments near the point,
   * instead of every segment. The candidates the trees return are then
   * judged by the same arithmetic, and in the same order, as a loop over
   * all segments: the answers are the same to the last bit, including
   * which of two equally close segments wins (the first).
   */
  class SegmentSearch
  {
  public:
    /** Pack the trees of @p segments (end points a, b). */
    explicit SegmentSearch(
      const std::vector<std::array<Point<2>, 2>> &segments);

    /** The trees refer to the members: no copies. */
    SegmentSearch(const SegmentSearch &) = delete;
    SegmentSearch &
    operator=(const SegmentSearch &) = delete;

    /**
     * The segment closest to @p x and its closest point on it: of equally
     * close segments, the one with the smallest index.
     */
    std::pair<unsigned int, Point<2>>
    closest_point(const Point<2> &x) const;

    /**
     * The end points of the segments whose orthogonal projection on the
     * line through @p a and @p b falls on the segment [a, b] (and possibly
     * a few just beyond its ends, within 1e-6 of its length: the caller
     * decides with its own tolerance). Each point once per segment that
     * has it, in no particular order.
     */
    std::vector<Point<2>>
    end_points_over(const Point<2> &a, const Point<2> &b) const;

    /** The segments whose bounding boxes meet the straight line from
     * @p p to @p q (a superset of the segments it crosses), in increasing
     * order. */
    std::vector<unsigned int>
    segments_crossed(const Point<2> &p, const Point<2> &q) const;

    /** The closest point of segment @p i to @p x. */
    Point<2>
    closest_point_on(const unsigned int i, const Point<2> &x) const;

  private:
    std::vector<std::array<Point<2>, 2>> segments;
    std::vector<BoundingBox<2>>          boxes;
    std::vector<Point<2>>                end_points;
    /** The box of all end points. */
    BoundingBox<2> extent;
    /** The largest coordinate magnitude of the zone: the scale of the
     * round-off of a computed distance. */
    double scale = 0;

    template <typename Container>
    using IndexTree = RTree<typename Container::size_type,
                            boost::geometry::index::linear<16>,
                            IndexableGetterFromIndices<Container>>;
    IndexTree<std::vector<BoundingBox<2>>> box_tree;
    IndexTree<std::vector<Point<2>>>       point_tree;
  };
} // namespace ddcontact

#endif
