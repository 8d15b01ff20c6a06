#include <ddcontact/contact/zone_extent.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{

  double
  ZoneExtent::edge_between(const double    s_prev,
                           const double    p_prev,
                           const double    s_in,
                           const double    p_in,
                           const double    s_out,
                           const EdgeModel model)
  {
    // A sharp edge: the pressure does not fall towards it.
    if (model == EdgeModel::midpoint || !(p_in < p_prev) || !(p_in > 0))
      return 0.5 * (s_in + s_out);
    // p^2 is linear in s under p = C sqrt(e - s).
    const double e =
      s_in + p_in * p_in * (s_in - s_prev) / (p_prev * p_prev - p_in * p_in);
    return std::clamp(e, s_in, s_out);
  }

  ZoneExtent::ZoneExtent(const ZoneArcLength &arcs,
                         std::vector<Sample>  samples,
                         const EdgeModel      model)
  {
    double largest = 0;
    for (const auto &x : samples)
      largest = std::max(largest, x.value);
    const double threshold = 1e-12 * largest;
    if (!(largest > 0))
      return;

    std::vector<std::vector<Sample>> by_curve(arcs.n_curves());
    for (const auto &x : samples)
      by_curve[x.curve].push_back(x);
    for (unsigned int c = 0; c < by_curve.size(); ++c)
    {
      auto &list = by_curve[c];
      if (list.empty())
        continue;
      std::sort(list.begin(),
                list.end(),
                [](const Sample &a, const Sample &b) { return a.s < b.s; });
      const double L    = arcs.length(c);
      const auto inside = [&](const Sample &x) { return x.value > threshold; };
      const bool closed = arcs.is_closed(c);
      if (closed)
      {
        // Start the list at a sample outside the zone (then no run
        // crosses the list's ends) and continue the arc length past L.
        const auto out = std::find_if_not(list.begin(), list.end(), inside);
        if (out == list.end())
        {
          // The whole closed curve is in contact.
          total_extent += L;
          total_length += L;
          continue;
        }
        for (auto x = list.begin(); x != out; ++x)
          x->s += L;
        std::rotate(list.begin(), out, list.end());
        // That sample again at the far end: every run has both neighbours.
        list.push_back({c, list.front().s + L, list.front().value});
      }

      // The runs of samples inside, and their edges.
      const unsigned int                     n          = list.size();
      double                                 first_edge = 0, last_edge = 0;
      std::vector<std::pair<double, double>> runs;
      for (unsigned int i = 0; i < n;)
      {
        if (!inside(list[i]))
        {
          ++i;
          continue;
        }
        unsigned int j = i;
        while (j + 1 < n && inside(list[j + 1]))
          ++j;
        // The edge beyond sample k (inside) in direction dir (+1: to
        // larger s): mirrored to the right-hand case by s -> -dir s.
        const auto edge = [&](const unsigned int k, const int dir) -> Edge
        {
          const int out = int(k) + dir;
          if (out < 0 || out >= int(n))
            return {c, dir > 0 ? L : 0., true};
          const double s_in = dir * list[k].s, s_out = dir * list[out].s;
          const int    prev = int(k) - dir;
          const bool   has_prev =
            prev >= 0 && prev < int(n) && inside(list[prev]);
          edge_resolution = std::max(edge_resolution, s_out - s_in);
          if (!has_prev)
            return {c, dir * 0.5 * (s_in + s_out), false};
          return {c,
                  dir * edge_between(dir * list[prev].s,
                                     list[prev].value,
                                     s_in,
                                     list[k].value,
                                     s_out,
                                     model),
                  false};
        };
        const Edge left = edge(i, -1), right = edge(j, +1);
        zone_edges.push_back(left);
        zone_edges.push_back(right);
        runs.emplace_back(left.s, right.s);
        total_length += right.s - left.s;
        i = j + 1;
      }
      if (runs.empty())
        continue;
      first_edge = runs.front().first;
      last_edge  = runs.back().second;
      if (!closed)
      {
        total_extent += last_edge - first_edge;
        continue;
      }
      // The complement of the largest gap between runs, the one across the
      // list's ends included.
      double gap = first_edge + L - last_edge;
      for (unsigned int r = 1; r < runs.size(); ++r)
        gap = std::max(gap, runs[r].first - runs[r - 1].second);
      total_extent += L - gap;
    }
  }
} // namespace ddcontact
