// DESCRIPTION: ZoneArcLength (the half-widths of contact and stick sets)
// measures by arc length along S_1 for any shape and origin: on a polygon
// inscribed in a circle (a pin in a hole) of N faces, given in shuffled
// order and with faces reversed, the extent of the vertices k1..k2 is
// (k2 - k1) times the chord 2 R sin(pi/N), also across the curve's start,
// at two centres (the origin and far from it); an open arc (a roller) the
// same; a straight zone gives the extent of the projections on its
// tangent (the former definition); two separate curves add up
#include <deal.II/base/point.h>

#include <ddcontact/contact/zone_arc_length.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  using Faces = std::vector<std::array<Point<2>, 2>>;

  /** The vertices of a regular N-gon of radius R about @p centre, from
   * angle @p from over @p n_faces faces (all N for the closed one). */
  std::vector<Point<2>>
  polygon(const Point<2>    &centre,
          const double       R,
          const unsigned int N,
          const unsigned int n_faces)
  {
    std::vector<Point<2>> v;
    for (unsigned int k = 0; k <= n_faces; ++k)
    {
      const double phi = -0.5 * M_PI + 2 * M_PI * (k % N) / N;
      v.push_back(centre + R * Point<2>(std::cos(phi), std::sin(phi)));
    }
    return v;
  }

  /** The faces between consecutive vertices, shuffled, every third one
   * reversed, as a mesh hands them over; @p face_of[k] is the face that
   * starts or ends at vertex k (for the points at the vertices). */
  Faces
  faces_of(const std::vector<Point<2>> &v, std::vector<unsigned int> &face_of)
  {
    std::vector<unsigned int> order(v.size() - 1);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    Faces faces;
    face_of.assign(v.size(), 0);
    for (unsigned int i = 0; i < order.size(); ++i)
    {
      const unsigned int k = order[i];
      if (i % 3 == 0)
        faces.push_back({{v[k + 1], v[k]}});
      else
        faces.push_back({{v[k], v[k + 1]}});
      face_of[k] = i; // vertex k lies on face i (its first end along v)
    }
    face_of.back() = face_of[v.size() - 2];
    return faces;
  }

  double
  half_extent_of(const ZoneArcLength             &arc,
                 const std::vector<Point<2>>     &v,
                 const std::vector<unsigned int> &face_of,
                 const std::vector<unsigned int> &vertices)
  {
    std::vector<unsigned int> faces;
    std::vector<Point<2>>     x;
    for (const unsigned int k : vertices)
    {
      faces.push_back(face_of[k]);
      x.push_back(v[k]);
    }
    return arc.half_extent(faces, x);
  }
} // namespace

int
main()
{
  const double       R     = 1.5;
  const unsigned int N     = 64;
  const double       chord = 2 * R * std::sin(M_PI / N);
  for (const Point<2> centre : {Point<2>(0, 0), Point<2>(37.5, -12.25)})
  {
    std::cout << "centre (" << centre << ")" << std::endl;
    // The closed curve: a pin in a hole, the whole circle as S_1.
    {
      const auto                v = polygon(centre, R, N, N);
      std::vector<unsigned int> face_of;
      const ZoneArcLength       arc(faces_of(v, face_of));
      check(arc.n_curves() == 1 && arc.is_closed(0), "one closed curve");
      check("its length against N chords",
            relative(arc.length(0), N * chord),
            1e-13);
      std::vector<unsigned int> set;
      for (unsigned int k = 5; k <= 17; ++k)
        set.push_back(k);
      check("half-width of vertices 5..17 against 6 chords",
            relative(half_extent_of(arc, v, face_of, set), 6 * chord),
            1e-12);
      // Across the start of the curve: vertices N-7 .. N-1, 0 .. 9.
      set.clear();
      for (unsigned int k = N - 7; k < N; ++k)
        set.push_back(k);
      for (unsigned int k = 0; k <= 9; ++k)
        set.push_back(k);
      check("... across the curve's start, 16 vertices: 8 chords",
            relative(half_extent_of(arc, v, face_of, set), 8 * chord),
            1e-12);
      // A point inside a face (its midpoint).
      const unsigned int f     = face_of[20];
      const auto         faces = arc.half_extent(
        {f, face_of[10]}, {Point<2>(0.5 * (v[20] + v[21])), v[10]});
      check("a face's midpoint: 10.5 chords / 2",
            relative(faces, 5.25 * chord),
            1e-12);
    }
    // An open arc: a roller's lower half.
    {
      const auto                v = polygon(centre, R, N, N / 2);
      std::vector<unsigned int> face_of;
      const ZoneArcLength       arc(faces_of(v, face_of));
      check(arc.n_curves() == 1 && !arc.is_closed(0), "one open curve");
      check(
        "half-width of the whole arc against N/4 chords",
        relative(half_extent_of(arc, v, face_of, {0, 3, N / 2}), N / 4 * chord),
        1e-12);
    }
  }

  // A straight zone: the extent of the projections on the tangent, as
  // before arc lengths.
  {
    std::vector<Point<2>> v;
    const Tensor<1, 2>    tau({0.6, 0.8});
    for (unsigned int k = 0; k <= 40; ++k)
      v.push_back(Point<2>(3, -4) + (0.1 * k * k / 40.) * tau);
    std::vector<unsigned int> face_of;
    const ZoneArcLength       arc(faces_of(v, face_of));
    const double              expected = 0.5 * (v[33] - v[7]) * tau;
    check("straight zone: half the extent of the projections",
          relative(half_extent_of(arc, v, face_of, {7, 12, 33}), expected),
          1e-12);

    // Two separate curves: the extents add.
    Faces               two = {{{Point<2>(0, 0), Point<2>(1, 0)}},
                               {{Point<2>(1, 0), Point<2>(2, 0)}},
                               {{Point<2>(5, 5), Point<2>(5, 7)}}};
    const ZoneArcLength arcs(two);
    check(arcs.n_curves() == 2, "two separate curves");
    check("their extents add",
          relative(arcs.half_extent({0, 1, 2, 2},
                                    {Point<2>(0.5, 0),
                                     Point<2>(1.5, 0),
                                     Point<2>(5, 5.5),
                                     Point<2>(5, 6.5)}),
                   1.),
          1e-15);
  }
  return report();
}
