#include <ddcontact/contact/zone_arc_length.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace ddcontact
{
  ZoneArcLength::ZoneArcLength(
    const std::vector<std::array<Point<2>, 2>> &faces)
    : faces(faces)
    , curve(faces.size(), 0)
    , start(faces.size(), 0.)
    , forward(faces.size(), true)
  {
    // The faces at each end point (shared end points are bitwise equal).
    const auto key = [](const Point<2> &p)
    { return std::make_pair(p[0], p[1]); };
    std::map<std::pair<double, double>, std::vector<unsigned int>> at;
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (const auto &p : faces[f])
        at[key(p)].push_back(f);
    // The other face at end point @p p of face @p f, if the curve goes
    // on there (exactly two faces meet).
    const auto next = [&](const unsigned int f, const Point<2> &p) -> int
    {
      const auto &here = at[key(p)];
      if (here.size() != 2)
        return -1;
      return here[0] == f ? here[1] : here[0];
    };

    std::vector<bool> visited(faces.size(), false);
    for (unsigned int first = 0; first < faces.size(); ++first)
    {
      if (visited[first])
        continue;
      // Walk back from the first end point to the curve's start (or once
      // round a closed curve).
      unsigned int f     = first;
      bool         ahead = true; // f is entered at faces[f][0]
      bool         loop  = false;
      while (true)
      {
        const Point<2> &entry = faces[f][ahead ? 0 : 1];
        const int       g     = next(f, entry);
        if (g < 0)
          break;
        if (static_cast<unsigned int>(g) == first)
        {
          loop = true;
          break;
        }
        // g is left at `entry`: it runs towards it.
        ahead = (faces[g][1] == entry);
        f     = g;
      }
      if (loop)
      {
        f     = first;
        ahead = true;
      }
      // Walk forward along the curve, accumulating the length.
      const unsigned int c = curve_length.size();
      double             s = 0;
      while (true)
      {
        visited[f] = true;
        curve[f]   = c;
        start[f]   = s;
        forward[f] = ahead;
        s += faces[f][0].distance(faces[f][1]);
        const Point<2> &exit = faces[f][ahead ? 1 : 0];
        const int       g    = next(f, exit);
        if (g < 0 || visited[g])
          break;
        ahead = (faces[g][0] == exit);
        f     = g;
      }
      curve_length.push_back(s);
      closed.push_back(loop);
    }
  }

  std::pair<unsigned int, double>
  ZoneArcLength::position(const unsigned int face, const Point<2> &x) const
  {
    const auto &ends = faces[face];
    return {curve[face], start[face] + x.distance(ends[forward[face] ? 0 : 1])};
  }

  Point<2>
  ZoneArcLength::point(const unsigned int c, double s) const
  {
    if (closed[c] && curve_length[c] > 0)
      s -= curve_length[c] * std::floor(s / curve_length[c]);
    // The face of the curve that holds s (the nearest one past an end).
    int    best     = -1;
    double distance = 0;
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (curve[f] == c)
      {
        const double length = faces[f][0].distance(faces[f][1]);
        const double d = std::max({start[f] - s, s - start[f] - length, 0.});
        if (best < 0 || d < distance)
        {
          best     = f;
          distance = d;
        }
      }
    Assert(best >= 0, ExcMessage("A curve without faces"));
    const auto  &ends   = faces[best];
    const double length = ends[0].distance(ends[1]);
    const double along =
      std::clamp((s - start[best]) / std::max(length, 1e-300), 0., 1.);
    const Point<2> &from = ends[forward[best] ? 0 : 1];
    const Point<2> &to   = ends[forward[best] ? 1 : 0];
    return from + along * (to - from);
  }

  double
  ZoneArcLength::half_extent(const std::vector<unsigned int> &on_faces,
                             const std::vector<Point<2>>     &x) const
  {
    std::vector<std::vector<double>> s(curve_length.size());
    for (unsigned int i = 0; i < x.size(); ++i)
    {
      const auto [c, arc] = position(on_faces[i], x[i]);
      s[c].push_back(arc);
    }
    double extent = 0;
    for (unsigned int c = 0; c < s.size(); ++c)
    {
      if (s[c].empty())
        continue;
      std::sort(s[c].begin(), s[c].end());
      if (!closed[c])
      {
        extent += s[c].back() - s[c].front();
        continue;
      }
      // The complement of the largest gap, counting the one across the
      // curve's start.
      double gap = s[c].front() + curve_length[c] - s[c].back();
      for (unsigned int i = 1; i < s[c].size(); ++i)
        gap = std::max(gap, s[c][i] - s[c][i - 1]);
      extent += curve_length[c] - gap;
    }
    return 0.5 * extent;
  }
} // namespace ddcontact
