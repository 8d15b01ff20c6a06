#include <ddcontact/contact/contact_law.h>

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
    peak = 0;
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
  ContactLaw::set_contact_pressure(const std::vector<double> &sigma_n,
                                   const double               peak_pressure)
  {
    Assert(from_solver, ExcMessage("only with set_solver_pressure()"));
    set_multipliers(sigma_n);
    peak = peak_pressure;
  }
} // namespace ddcontact
