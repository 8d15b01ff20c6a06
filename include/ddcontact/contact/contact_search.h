#ifndef ddcontact_contact_search_h
#define ddcontact_contact_search_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <ddcontact/contact/segment_search.h>

#include <array>
#include <optional>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** The partner of a point x of S_1 on the candidate surface S_2. */
  struct FacingPoint
  {
    unsigned int segment = 0; // index of the face of S_2
    Point<2>     point;       // P(x), on that face
    double       gap = 0;     // signed distance from x to P(x) along n_1
  };

  /**
   * What the contact search of ContactPair::setup() found (the setup report
   * of a pair, doc/output.md): how many points of S_1 have a partner on
   * S_2, the range of their initial gaps, the deepest initial overlap, and,
   * for an expression gap, where it falls short of the distance between the
   * meshes by the most.
   */
  struct ContactSearchReport
  {
    double       search_distance = 0;
    unsigned int n_examined      = 0; // integration points of S_1
    unsigned int n_points        = 0; // of them with a partner on S_2
    /** Of the gap in use (f_n), over the points with a partner. */
    double   min_gap = 0, max_gap = 0;
    Point<2> min_gap_at;
    /** Whether the gap is an expression; then the largest excess of the
     * geometric distance over it beyond the tolerance, and where. */
    bool     expression_gap   = false;
    double   worst_excess     = 0;
    double   worst_expression = 0;
    double   worst_geometric  = 0;
    Point<2> worst_excess_at;
    double   worst_excess_length = 0; // face length there
    /** With an expression gap: the deepest overlap of the meshes
     * (geometric gap < 0 beyond the tolerance) that the expression leaves
     * out (its gap above the geometric one), and where (issue 59: a hub
     * meshed 0.02 into its shaft ran silently). */
    double   hidden_overlap    = 0;
    double   hidden_expression = 0;
    Point<2> hidden_overlap_at;
    /** Length of the face of S_1 at the deepest overlap. */
    double min_gap_face_length = 0;
    /** Contact pair/Interference delta, taken off the gaps after they
     * were recorded (the meshes' overlap is judged without it): the gap in
     * use is min_gap - interference to max_gap - interference. */
    double interference = 0;

    /** Take the point @p x with the gap in use @p gap and the geometric
     * gap @p geometric, on a face of S_1 of length @p length, into
     * account. */
    void
    record(const Point<2> &x, double gap, double geometric, double length);

    /** An overlap deeper than this fraction of the face length at its
     * point is reported (round-off and faceting stay below it). */
    static constexpr double overlap_per_face = 1e-3;
  };

  /**
   * The contact search of a pair (doc/method.md, section 1.1): for a point
   * x of the candidate surface S_1 with outward normal n_1, the point P(x)
   * of the candidate surface S_2 that x can touch. P(x) is where the normal
   * line x + t n_1 meets a face of S_2, and it counts only if
   * - the face's outward normal n_2 opposes n_1 within 60 degrees
   *   (n_1 . n_2 <= -1/2): a face that looks away, or sideways, cannot be
   *   touched by x (the small-gap assumption n_2 ~ -n_1 of (3)-(5));
   * - it lies within the search distance d along the normal, in front
   *   (0 <= t <= d: a gap) or behind (-d <= t < 0: x lies inside body 2,
   *   an initial overlap);
   * - it falls on the face, not beyond its ends (a point beyond the end of
   *   S_2 has no partner).
   * Of several such faces the nearest along the normal (smallest |t|, the
   * first index of equal ones) wins. The gap is t: the signed distance to
   * the facing part of S_2 along n_1. Where the faces of S_2 are straight
   * and parallel to those of S_1 it is the paper's f_n(x) = |x - P(x)| of
   * the orthogonal projection; on curved zones the two differ by
   * O(f_n |n_1 + n_2|^2).
   *
   * The normal line meets a given face of S_2 at a point that is affine in
   * x along a face of S_1, and switches faces exactly where the normal
   * lines through S_2's vertices cross S_1 -- the breaks of the common
   * refinement (SegmentSearch::end_points_over()), so u_2n(P(x)) is a
   * polynomial on every piece.
   *
   * The faces near x come from the R-tree of SegmentSearch: O(log n) per
   * point.
   */
  class ContactSearch
  {
  public:
    /** n_1 . n_2 at most this: the normals are opposed (60 degrees). */
    static constexpr double max_normal_cosine = -0.5;

    /** The faces of S_2 (end points) with their outward normals; the
     * search distance d > 0. */
    ContactSearch(const std::vector<std::array<Point<2>, 2>> &faces,
                  const std::vector<Tensor<1, 2>>            &normals,
                  double                                      distance);

    /** The partner of @p x with outward normal @p n_1, if it has one. */
    std::optional<FacingPoint>
    facing_point(const Point<2> &x, const Tensor<1, 2> &n_1) const;

    /** Whether some face of S_2 has a normal opposed to @p n_1, wherever
     * it is (whether S_1 and S_2 can face each other at all). */
    bool
    has_opposed_normal(const Tensor<1, 2> &n_1) const;

    /** The search distance d. */
    double
    distance() const
    {
      return search_distance;
    }

    /** The segment search of the faces (closest points, end points). */
    const SegmentSearch &
    segments() const
    {
      return search;
    }

  private:
    std::vector<std::array<Point<2>, 2>> faces;
    std::vector<Tensor<1, 2>>            normals;
    double                               search_distance;
    SegmentSearch                        search;
    /** The directions of the normals of S_2 in 360 sectors of one degree
     * (for has_opposed_normal() without a loop over all faces). */
    std::array<bool, 360> sector_has_normal{};
  };
} // namespace ddcontact

#endif
