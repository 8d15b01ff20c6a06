// DESCRIPTION: a thick hollow sphere under internal pressure, elastic-
// perfectly plastic (J2, axisymmetric, Q2, no contact: tests/
// hollow_sphere.prm), against Hill's closed form (The Mathematical Theory
// of Plasticity, ch. V): in a sphere sigma_theta = sigma_phi, so von Mises
// and Tresca agree and the solution is exact for any nu. Yield starts at
// the inner surface at p_e = (2Y/3)(1 - a^3/b^3); past it the plastic zone
// a < r < c carries p = 2Y ln(c/a) + (2Y/3)(1 - c^3/b^3), the elastic shell
// outside is Lame's under (2Y/3)(1 - c^3/b^3) at r = c, and the outer
// surface moves by u_b = Y c^3 (1 - nu) / (E b^2). Checked: the first
// yield step and where it starts; at every load step the volume of the
// plastic zone (summary.json plastic_zone_measure) against (2 pi / 3)(c^3
// - a^3) of the modelled half; u_b at the end.
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  constexpr double Y = 1, E = 1000, nu = 0.3, a = 1, b = 2;
  constexpr double p_end = 1.19635; // the scene's p: c = 1.5

  /** Hill's plastic radius c for the pressure @p p (> p_e), by
   * bisection on p(c), which increases with c. */
  double
  plastic_radius(const double p)
  {
    double lo = a, hi = b;
    for (unsigned int i = 0; i < 200; ++i)
    {
      const double c = 0.5 * (lo + hi);
      const double f =
        2 * Y * std::log(c / a) + 2 * Y / 3 * (1 - std::pow(c / b, 3)) - p;
      (f > 0 ? hi : lo) = c;
    }
    return 0.5 * (lo + hi);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  const auto  sim     = run_scene(source_dir + "/tests/hollow_sphere.prm",
                             {"Output directory=plastic_hollow_sphere_output"},
                             {});
  const auto &summary = sim->summary();
  const auto &steps   = summary.at("load_steps");
  check(steps.size() == 10, "ten load steps in summary.json");

  // The wall's 16 cells of h = 1/16, three Gauss points each across: the
  // points that tell yielded from elastic lie at most delta = 0.387 h apart
  // in r (sqrt(3/5) h / 2, between neighbouring points of one cell; 0.225 h
  // across a face), so the front is resolved to delta: the zone's volume to
  // 2 pi c^2 delta (the modelled half of the shell of that thickness).
  const double h = (b - a) / 16, delta = std::sqrt(0.6) / 2 * h;

  // First yield: the step where p t first exceeds p_e, at r = a.
  const double p_e = 2 * Y / 3 * (1 - std::pow(a / b, 3));
  const auto   k_e = static_cast<unsigned int>(std::ceil(10 * p_e / p_end));
  check(summary.contains("first_yield") &&
          summary.at("first_yield").at("step").get<unsigned int>() == k_e,
        "the first yield step is Hill's (" + std::to_string(k_e) + ")");
  if (summary.contains("first_yield"))
  {
    const auto  &x = summary.at("first_yield").at("location");
    const double r = std::hypot(x[0].get<double>(), x[1].get<double>());
    check("first yield at the inner surface, in cells", std::abs(r - a) / h, 1);
  }

  double largest = 0;
  for (unsigned int k = 0; k < steps.size(); ++k)
  {
    const double p         = p_end * steps[k].at("t").get<double>();
    const double c         = (p > p_e) ? plastic_radius(p) : a;
    const double zone_hill = 2 * M_PI / 3 * (std::pow(c, 3) - std::pow(a, 3));
    const double zone =
      steps[k].at("bodies")[0].at("plastic_zone_measure").get<double>();
    const double allowed = 2 * M_PI * c * c * delta;
    std::cout << std::setprecision(6) << "  step " << k + 1 << ": p = " << p
              << ", c = " << c << ", plastic zone " << zone << " (Hill "
              << zone_hill << ", allowed difference " << allowed << ")"
              << std::endl;
    largest = std::max(largest, std::abs(zone - zone_hill) / allowed);
  }
  check("the plastic zone of every step against Hill's, in fronts of delta",
        largest,
        1.);

  // u_b at the end: c^3 in it moves by 3 delta / c relative.
  const double c_end  = plastic_radius(p_end);
  const double u_hill = Y * std::pow(c_end, 3) * (1 - nu) / (E * b * b);
  const double u_b    = summary.at("points")[0].at("u")[0].get<double>();
  std::cout << std::setprecision(6) << "  u_b = " << u_b << " (Hill " << u_hill
            << ")" << std::endl;
  check(
    "u_b at the end against Hill's", relative(u_b, u_hill), 3 * delta / c_end);
  return report();
}
