// DESCRIPTION: the contact law (20), sigma_n = min(0, lambda + g/theta), of
// ContactLaw against values worked out by hand: no pressure where the gap
// is open, slope 1/theta where it is closed, continuity at the kink, the
// multiplier's shift of the kink and the shifted gap (augmented
// Lagrangian), the Uzawa update, reset, and the piecewise constant
// transfer of the multipliers to the points of a refined zone
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/contact/contact_law.h>
#include <ddcontact/contact/contact_pair.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** A steel block (0, 4) x (y0, y0 + 1) of 4 x 1 quadrilaterals, held on the
   * side @p dirichlet_id, with its contact zone on @p contact_id (ids of
   * the rectangle: 2 bottom, 3 top). */
  BodyParameters
  block(const std::string &name,
        const double       y0,
        const std::string &dirichlet_id,
        const std::string &contact_id)
  {
    BodyParameters p;
    p.name                    = name;
    p.corner_1                = Point<2>(0, y0);
    p.corner_2                = Point<2>(4, y0 + 1);
    p.subdivisions            = {4, 1};
    p.dirichlet               = dirichlet_id + ": xy: 0; 0";
    p.contact_ids             = contact_id;
    p.material.youngs_modulus = 2.1e5;
    p.material.poisson_ratio  = 0.3;
    return p;
  }

  /** The pair "S": the bottom of the upper block on the top of the lower
   * one, initial gap f_n = 0.01 x, penalty @p penalty of @p type. */
  ContactPairParameters
  pair_parameters(const PenaltyType type, const double penalty)
  {
    ContactPairParameters p;
    p.name           = "S";
    p.body_1         = "upper";
    p.boundary_id_1  = 2;
    p.body_2         = "lower";
    p.boundary_id_2  = 3;
    p.gap_expression = "0.01*x";
    p.penalty_type   = type;
    p.penalty        = penalty;
    return p;
  }

  /** Whether every multiplier of @p law is @p left at x < 2 and @p right
   * at x > 2 (no contact point lies at x = 2: Gauss points only). */
  bool
  is_step(const ContactLaw  &law,
          const ContactPair &pair,
          const double       left,
          const double       right)
  {
    const auto &lambda = law.multipliers();
    if (lambda.size() != pair.points().size())
      return false;
    for (unsigned int q = 0; q < lambda.size(); ++q)
      if (lambda[q] != (pair.points()[q].x[0] < 2 ? left : right))
        return false;
    return true;
  }

  /** The multipliers -0.1 at x < 2 and -0.3 at x > 2. */
  std::vector<double>
  step(const ContactPair &pair)
  {
    std::vector<double> lambda;
    for (const auto &p : pair.points())
      lambda.push_back(p.x[0] < 2 ? -0.1 : -0.3);
    return lambda;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  ElasticBody<2> upper(block("upper", 1, "3", "2"), Constants());
  ElasticBody<2> lower(block("lower", 0, "2", "3"), Constants());
  for (ElasticBody<2> *body : {&upper, &lower})
  {
    body->make_mesh();
    body->setup_and_factorize();
  }
  // theta = 0.5 given as is: round numbers for the values below.
  ContactPair pair(
    pair_parameters(PenaltyType::absolute, 0.5), upper, lower, Constants());
  pair.setup();
  ContactLaw  law(pair);
  const auto &points = pair.points();

  std::cout << "Setup:" << std::endl;
  // Both zones are x in (0, 4) with vertices at 0, 1, 2, 3, 4: four
  // pieces of three Gauss points each.
  check(points.size() == 12, "12 contact points (4 pieces x 3)");
  check(law.theta() == 0.5, "theta is the absolute penalty 0.5");
  {
    // Relative penalty: theta = c H / E_1 with H = 1 (the upper block's
    // height) and E_1 = 2.1e5: 0.05 / 2.1e5.
    ContactPair relative_pair(
      pair_parameters(PenaltyType::relative, 0.05), upper, lower, Constants());
    relative_pair.setup();
    check("relative penalty: theta = 0.05 H / E_1 = 2.381e-7",
          relative(ContactLaw(relative_pair).theta(), 0.05 / 2.1e5),
          1e-14);
  }
  check(std::all_of(law.multipliers().begin(),
                    law.multipliers().end(),
                    [](const double l) { return l == 0; }) &&
          law.multipliers().size() == points.size(),
        "lambda = 0 at every point to start with");

  // Without a multiplier, sigma_n = min(0, g / 0.5) = min(0, 2 g).
  std::cout << "Penalty law, lambda = 0:" << std::endl;
  check(law.pressure(0, 0.3) == 0, "open gap g = 0.3: no pressure");
  check(law.pressure(0, 1e-12) == 0, "open gap g = 1e-12: no pressure");
  check("closed gap g = -0.2: sigma_n = -0.2/0.5 = -0.4",
        std::abs(law.pressure(0, -0.2) + 0.4),
        1e-15);
  check("closed gap g = -1e-3: sigma_n = -2e-3",
        std::abs(law.pressure(0, -1e-3) + 2e-3),
        1e-18);
  check("slope 1/theta = 2 between g = -0.2 and g = -0.1",
        std::abs((law.pressure(0, -0.2) - law.pressure(0, -0.1)) / -0.1 - 2.),
        1e-14);
  check(law.pressure(0, 0.) == 0, "at the kink g = 0: sigma_n = 0");
  // Continuity: on either side of the kink the values differ by the slope
  // times the distance, 2 * 2e-9.
  check(
    "continuous at the kink: |sigma(-1e-9) - sigma(1e-9)| = 2e-9",
    std::abs(std::abs(law.pressure(0, -1e-9) - law.pressure(0, 1e-9)) - 2e-9),
    1e-22);
  {
    // The vector form at every point, with g = f_n - 0.02 = 0.01 x - 0.02:
    // open beyond x = 2, and 2 (0.01 x - 0.02) = 0.02 x - 0.04 before.
    std::vector<double> g;
    for (const auto &p : points)
      g.push_back(p.gap - 0.02);
    const auto sigma = law.pressure(g);
    double     error = 0;
    for (unsigned int q = 0; q < points.size(); ++q)
    {
      const double x = points[q].x[0];
      error =
        std::max(error, std::abs(sigma[q] - (x < 2 ? 0.02 * x - 0.04 : 0.)));
    }
    check("every point, g = 0.01 x - 0.02: sigma_n = min(0, 0.02 x - 0.04)",
          error,
          1e-16);
  }

  // lambda = -0.1: sigma_n = min(0, -0.1 + 2 g), the kink moves to the
  // open gap g = -theta lambda = 0.05.
  std::cout << "Augmented law, lambda = -0.1:" << std::endl;
  law.set_multipliers(std::vector<double>(points.size(), -0.1));
  check(law.multipliers() == std::vector<double>(points.size(), -0.1),
        "set_multipliers() stores lambda");
  check(law.pressure(3, 0.3) == 0, "g = 0.3: -0.1 + 0.6 > 0, no pressure");
  check("g = 0.04 (open): still pressed, -0.1 + 0.08 = -0.02",
        std::abs(law.pressure(3, 0.04) + 0.02),
        1e-16);
  check("g = 0.05 = -theta lambda: the kink, sigma_n = 0",
        std::abs(law.pressure(3, 0.05)),
        1e-16);
  check("g = -0.2: -0.1 - 0.4 = -0.5",
        std::abs(law.pressure(3, -0.2) + 0.5),
        1e-15);
  {
    // shifted_gap = f_n + theta lambda = 0.01 x - 0.05, and the law
    // presses exactly where u_1n + u_2n (= f_n - g) exceeds it.
    double error        = 0;
    bool   active_where = true;
    for (unsigned int q = 0; q < points.size(); ++q)
    {
      const double shifted = 0.01 * points[q].x[0] - 0.05;
      error = std::max(error, std::abs(law.shifted_gap(q) - shifted));
      for (const double approach : {shifted + 1e-6, shifted - 1e-6})
      {
        const double g = points[q].gap - approach;
        active_where =
          active_where && ((law.pressure(q, g) < 0) == (approach > shifted));
      }
    }
    check("shifted_gap = 0.01 x - 0.05 at every point", error, 1e-16);
    check(active_where,
          "sigma_n < 0 exactly where u_1n + u_2n exceeds the shifted gap");
  }
  // Multipliers that differ between points: at g = 0 the law gives the
  // multiplier itself (lambda <= 0).
  law.set_multipliers(step(pair));
  {
    bool ok = true;
    for (unsigned int q = 0; q < points.size(); ++q)
      ok = ok && law.pressure(q, 0.) == (points[q].x[0] < 2 ? -0.1 : -0.3);
    check(ok, "lambda -0.1 / -0.3 left / right of x = 2: sigma_n(0) = lambda");
  }

  // Uzawa: lambda <- sigma_n. At g = -0.2 the first solve gives
  // 2 (-0.2) = -0.4; with lambda = -0.4 the same gap gives -0.4 - 0.4.
  std::cout << "Uzawa update and reset:" << std::endl;
  law.reset();
  check(law.multipliers() == std::vector<double>(points.size(), 0.),
        "reset(): lambda = 0 again");
  {
    const std::vector<double> g(points.size(), -0.2);
    law.set_multipliers(law.pressure(g));
    check("after lambda <- sigma_n(g = -0.2): sigma_n(-0.2) = -0.8",
          std::abs(law.pressure(5, -0.2) + 0.8),
          1e-15);
  }

  // Transfer. Without new points nothing moves.
  std::cout << "Transfer of lambda to new points:" << std::endl;
  law.set_multipliers(step(pair));
  law.transfer_to_new_points();
  check(is_step(law, pair, -0.1, -0.3), "the same points: lambda unchanged");

  // A smooth lambda = -0.01 x and the step, on the upper block refined
  // once: its zone has 8 faces of 3 Gauss points. Each new point takes
  // the value of the nearest old point. The step stays where it was: the
  // old points nearest x = 2 are 2 -+ 0.1127 (the Gauss point (1 -
  // sqrt(3/5))/2 of the faces (1, 2) and (2, 3)), so no new point is
  // nearer one on the other side. The smooth lambda is off most at the
  // new points 0.25 + k/2, the midpoints of the new faces: their nearest
  // old point is the Gauss point (1 - sqrt(3/5))/2 = 0.1127 (+ k/2) of
  // the old face, at (sqrt(3/5) - 1/2)/2 = 0.1373; all other new points
  // are 0.0563 from an old one. So the largest error is 0.01 * 0.1373.
  std::vector<double> smooth;
  for (const auto &p : points)
    smooth.push_back(-0.01 * p.x[0]);
  ContactLaw smooth_law(pair);
  smooth_law.set_multipliers(smooth);

  upper.get_triangulation().refine_global(1);
  upper.setup_and_factorize();
  pair.setup();
  law.transfer_to_new_points();
  smooth_law.transfer_to_new_points();
  check(pair.points().size() == 24 && law.multipliers().size() == 24,
        "refined zone: 24 points (8 pieces x 3), 24 multipliers");
  check(is_step(law, pair, -0.1, -0.3),
        "the step of lambda at x = 2 stays at x = 2");
  {
    double error   = 0;
    bool   old_one = true;
    for (unsigned int q = 0; q < pair.points().size(); ++q)
    {
      const double l = smooth_law.multipliers()[q];
      error = std::max(error, std::abs(l + 0.01 * pair.points()[q].x[0]));
      old_one =
        old_one && std::find(smooth.begin(), smooth.end(), l) != smooth.end();
    }
    check(old_one, "lambda = -0.01 x: every new value is an old one");
    check("lambda = -0.01 x: largest error 0.01 (sqrt(3/5) - 1/2)/2",
          std::abs(error - 0.01 * (std::sqrt(0.6) - 0.5) / 2),
          1e-15);
  }

  return report();
}
