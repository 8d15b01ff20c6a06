#include <ddcontact/contact/penalty_law.h>

namespace ddcontact
{
  PenaltyLaw::PenaltyLaw(const ContactPair &pair)
    : pair(pair)
  {
    reset();
  }

  void
  PenaltyLaw::reset()
  {
    lambda.assign(pair.points().size(), 0.);
    lambda_points.clear();
    for (const auto &p : pair.points())
      lambda_points.push_back(p.x);
  }

  void
  PenaltyLaw::transfer_to_new_points()
  {
    const auto         &points = pair.points();
    std::vector<double> moved(points.size(), 0.);
    if (!lambda_points.empty() && lambda.size() == lambda_points.size())
      for (unsigned int q = 0; q < points.size(); ++q)
      {
        unsigned int nearest = 0;
        for (unsigned int i = 1; i < lambda_points.size(); ++i)
          if (points[q].x.distance_square(lambda_points[i]) <
              points[q].x.distance_square(lambda_points[nearest]))
            nearest = i;
        moved[q] = lambda[nearest];
      }
    lambda = std::move(moved);
    lambda_points.clear();
    for (const auto &p : points)
      lambda_points.push_back(p.x);
  }

  std::vector<double>
  PenaltyLaw::pressure(const std::vector<double> &g) const
  {
    AssertDimension(g.size(), lambda.size());
    std::vector<double> sigma(g.size());
    for (unsigned int q = 0; q < g.size(); ++q)
      sigma[q] = pressure(q, g[q]);
    return sigma;
  }

  void
  PenaltyLaw::set_multipliers(const std::vector<double> &sigma_n)
  {
    AssertDimension(sigma_n.size(), lambda.size());
    lambda = sigma_n;
  }
} // namespace ddcontact
