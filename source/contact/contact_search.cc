#include <ddcontact/contact/contact_search.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  namespace
  {
    /** The sector (of 360, one degree each) of the direction @p n. */
    unsigned int
    sector_of(const Tensor<1, 2> &n)
    {
      const double degrees = std::atan2(n[1], n[0]) * 180. / M_PI + 180.;
      return static_cast<unsigned int>(std::floor(degrees)) % 360;
    }
  } // namespace

  void
  ContactSearchReport::record(const Point<2> &x,
                              const double    gap,
                              const double    geometric,
                              const double    length)
  {
    if (n_points == 0 || gap < min_gap)
    {
      min_gap             = gap;
      min_gap_at          = x;
      min_gap_face_length = length;
    }
    max_gap = (n_points == 0) ? gap : std::max(max_gap, gap);
    ++n_points;
    if (!expression_gap)
      return;
    // An expression gap below the distance between the meshes lets the
    // bodies touch across empty space. The tolerance admits the usual
    // approximations: 5 % of the distance (a parabola for a circle) plus
    // 1 % of the face (the faceting of a curved mesh). The opposite, an
    // expression above the meshes' distance, is the classical curved gap
    // on flat meshes (the paper's scene) and no contradiction.
    const double excess    = geometric - gap;
    const double tolerance = 0.05 * std::abs(geometric) + 0.01 * length;
    // The meshes overlap, and the expression does not say so.
    if (geometric < -ContactSearchReport::overlap_per_face * length &&
        -excess > tolerance && -geometric > hidden_overlap)
    {
      hidden_overlap    = -geometric;
      hidden_expression = gap;
      hidden_overlap_at = x;
    }
    if (excess > tolerance && excess > worst_excess)
    {
      worst_excess        = excess;
      worst_expression    = gap;
      worst_geometric     = geometric;
      worst_excess_at     = x;
      worst_excess_length = length;
    }
  }

  ContactSearch::ContactSearch(
    const std::vector<std::array<Point<2>, 2>> &faces,
    const std::vector<Tensor<1, 2>>            &normals,
    const double                                distance)
    : faces(faces)
    , normals(normals)
    , search_distance(distance)
    , search(faces)
  {
    AssertDimension(faces.size(), normals.size());
    Assert(distance > 0, ExcMessage("the search distance must be positive"));
    for (const auto &n : normals)
      sector_has_normal[sector_of(n)] = true;
  }

  std::optional<FacingPoint>
  ContactSearch::facing_point(const Point<2> &x, const Tensor<1, 2> &n_1) const
  {
    const double               d = search_distance;
    std::optional<FacingPoint> best;
    // Only the faces whose boxes the normal segment [x - d n_1, x + d n_1]
    // crosses can be met within the search distance.
    for (const unsigned int j :
         search.segments_crossed(x - d * n_1, x + d * n_1))
    {
      const Tensor<1, 2> &n_2    = normals[j];
      const double        cosine = n_1 * n_2;
      if (cosine > max_normal_cosine)
        continue;
      // x + t n_1 on the line of face j: (x + t n_1 - a) . n_2 = 0.
      const auto &[a, b] = faces[j];
      const double t     = ((a - x) * n_2) / cosine;
      if (std::abs(t) > d)
        continue;
      const Tensor<1, 2> along = b - a;
      const double       s = (x + t * n_1 - a) * along / along.norm_square();
      // On the face: the tolerance only keeps a point whose normal line
      // passes through a vertex from falling between two faces.
      if (s < -1e-10 || s > 1. + 1e-10)
        continue;
      if (!best || std::abs(t) < std::abs(best->gap))
        best = FacingPoint{j, a + std::clamp(s, 0., 1.) * along, t};
    }
    return best;
  }

  bool
  ContactSearch::has_opposed_normal(const Tensor<1, 2> &n_1) const
  {
    // The sectors within 60 degrees of -n_1, one more on each side so that
    // no normal the exact test would accept is missed.
    const int centre = sector_of(-n_1);
    for (int k = -61; k <= 61; ++k)
      if (sector_has_normal[(centre + k + 360) % 360])
        return true;
    return false;
  }
} // namespace ddcontact
