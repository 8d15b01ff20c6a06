#include <ddcontact/contact/contact_law.h>

#include <cmath>

namespace ddcontact
{
  ContactLaw::ContactLaw(const ContactPair &pair)
    : pair(pair)
  {
    reset();
  }

  void
  ContactLaw::reset()
  {
    lambda.assign(pair.points().size(), 0.);
    lambda_points.clear();
    for (const auto &p : pair.points())
      lambda_points.push_back(p.x);
  }

  std::vector<double>
  nearest_point_values(const std::vector<Point<2>> &from,
                       const std::vector<double>   &values,
                       const std::vector<Point<2>> &to)
  {
    std::vector<double> moved(to.size(), 0.);
    if (!from.empty() && values.size() == from.size())
      for (unsigned int q = 0; q < to.size(); ++q)
      {
        unsigned int nearest = 0;
        for (unsigned int i = 1; i < from.size(); ++i)
          if (to[q].distance_square(from[i]) <
              to[q].distance_square(from[nearest]))
            nearest = i;
        moved[q] = values[nearest];
      }
    return moved;
  }

  std::vector<double>
  interpolated_node_values(const std::vector<Point<2>> &from,
                           const std::vector<double>   &values,
                           const std::vector<Point<2>> &to)
  {
    if (from.size() < 2 || values.size() != from.size())
      return nearest_point_values(from, values, to);
    std::vector<double> moved(to.size());
    for (unsigned int q = 0; q < to.size(); ++q)
    {
      // The nearest old node a and the second nearest b, in one pass.
      unsigned int a = 0, b = 1;
      double       da = to[q].distance_square(from[0]),
             db       = to[q].distance_square(from[1]);
      if (db < da)
      {
        std::swap(a, b);
        std::swap(da, db);
      }
      for (unsigned int i = 2; i < from.size(); ++i)
      {
        const double di = to[q].distance_square(from[i]);
        if (di < da)
        {
          b  = a;
          db = da;
          a  = i;
          da = di;
        }
        else if (di < db)
        {
          b  = i;
          db = di;
        }
      }
      // Between a and b: its projection on the chord falls inside it, and
      // it lies near the chord (a curved zone bows by ~ h^2 / (8 R)).
      const Tensor<1, 2> ab = from[b] - from[a];
      const double       t  = ((to[q] - from[a]) * ab) / ab.norm_square();
      const double       off =
        (to[q] - (from[a] + t * ab)).norm() / std::sqrt(ab.norm_square());
      moved[q] = (t > 0 && t < 1 && off < 0.1)
                   ? (1 - t) * values[a] + t * values[b]
                   : values[a];
    }
    return moved;
  }

  void
  ContactLaw::transfer_to_new_points()
  {
    std::vector<Point<2>> points;
    for (const auto &p : pair.points())
      points.push_back(p.x);
    lambda        = nearest_point_values(lambda_points, lambda, points);
    lambda_points = std::move(points);
  }

  std::vector<double>
  ContactLaw::pressure(const std::vector<double> &g) const
  {
    AssertDimension(g.size(), lambda.size());
    std::vector<double> sigma(g.size());
    for (unsigned int q = 0; q < g.size(); ++q)
      sigma[q] = pressure(q, g[q]);
    return sigma;
  }

  void
  ContactLaw::set_multipliers(const std::vector<double> &sigma_n)
  {
    AssertDimension(sigma_n.size(), lambda.size());
    lambda = sigma_n;
  }

  void
  ContactLaw::set_contact_pressure(const std::vector<double> &sigma_n)
  {
    Assert(from_solver, ExcMessage("only with set_solver_pressure()"));
    set_multipliers(sigma_n);
  }
} // namespace ddcontact
