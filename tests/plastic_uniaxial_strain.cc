// DESCRIPTION: an elastoplastic body in contact (Material/Law =
// j2-plasticity) on a load path that loads, unloads and lifts off: two
// blocks in uniaxial strain (rollers on their sides), the lower one J2 with
// linear isotropic hardening, the upper one elastic, pressed by a
// prescribed displacement Delta(t) that rises and falls back to zero. Every
// field is homogeneous, so the pressure of each load step is a closed form:
// the scalar radial return of uniaxial strain below (written here from the
// yield condition, not from the code's law), the series of the two blocks
// solved by bisection. Checked: the
// pressure of every step (loading, first yield, hardening, elastic
// unloading, reverse yielding at lift-off), the largest equivalent plastic
// strain and the plastic zone (the whole lower block) in summary.json, and
// the first yield step, for dd-newton, the paper's DD and the monolithic
// solver; the same end with Loading/Steps = auto.
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  // The material: E, nu, the yield stress and the isotropic hardening.
  constexpr double E = 2.1e5, nu = 0.3, Y = 100., H_iso = 2.e4;
  constexpr double mu     = E / (2 * (1 + nu));
  constexpr double K      = E / (3 * (1 - 2 * nu)); // bulk modulus
  constexpr double M      = K + 4. / 3. * mu;       // the constrained modulus
  constexpr double height = 1.;                     // of each block
  // The scene's penalty: relative 0.05, theta = 0.05 H / E.
  constexpr double theta = 0.05 * height / E;

  /**
   * J2 in uniaxial strain: eps_yy = -e (e > 0 compresses), eps_xx =
   * eps_zz = 0. The deviatoric strain is (2e/3) d, d = (1/2, -1, 1/2), and
   * the plastic strain stays along d: eps_p = kappa d, its equivalent
   * plastic strain |d kappa| sqrt(2/3) |d| = |d kappa|. The signed von
   * Mises stress is q = 3 mu (2e/3 - kappa) = 2 mu e - 3 mu kappa, the
   * pressure p = -sigma_yy = K e + (2/3) q, and the yield condition |q| <=
   * Y + H_iso alpha. Backward Euler over a step: the trial q at the old
   * kappa, and if it exceeds the yield stress, kappa moves by f / (3 mu +
   * H_iso) in the direction of q.
   */
  struct UniaxialStrainPoint
  {
    double kappa = 0, alpha = 0;

    /** The pressure at the strain @p e from this (committed) state, and
     * the state it leads to in @p next. */
    double
    pressure(const double e, UniaxialStrainPoint &next) const
    {
      next              = *this;
      const double q_tr = 2 * mu * e - 3 * mu * kappa;
      const double f    = std::abs(q_tr) - (Y + H_iso * alpha);
      if (f > 0)
      {
        const double dk = std::copysign(f / (3 * mu + H_iso), q_tr);
        next.kappa += dk;
        next.alpha += std::abs(dk);
      }
      return K * e + 2. / 3. * (2 * mu * e - 3 * mu * next.kappa);
    }
  };

  /** The lower block's strain e and the pressure p under the prescribed
   * shortening @p delta of both blocks, from the committed state @p point
   * (advanced to the step's end): H (p / M + e) + theta p = delta while
   * p > 0 (the upper block elastic, the penalty's overlap theta p), p = 0
   * with the blocks apart. */
  double
  series_pressure(const double delta, UniaxialStrainPoint &point)
  {
    UniaxialStrainPoint next;
    // p(e) increases with e: bisection on H (p(e)/M + e) + theta p(e) -
    // delta, over a bracket far wider than the strains of the path.
    const auto solve = [&](const auto &residual)
    {
      double lo = -1., hi = 1.;
      for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid              = 0.5 * (lo + hi);
        (residual(mid) > 0 ? hi : lo) = mid;
      }
      return 0.5 * (lo + hi);
    };
    const double e = solve(
      [&](const double e)
      {
        const double p = point.pressure(e, next);
        return height * (p / M + e) + theta * p - delta;
      });
    double p = point.pressure(e, next);
    if (p < 0)
    {
      // Apart: the lower block free of load (it may yield back).
      const double e_free =
        solve([&](const double e) { return point.pressure(e, next); });
      point.pressure(e_free, next);
      p = 0;
    }
    point = next;
    return p;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // The path: up to Delta_max at t = 1/2, down to zero at t = 1, in eight
  // steps; Delta_max strains the lower block to several times its first
  // yield strain e_y = Y / (2 mu).
  const double       e_y       = Y / (2 * mu);
  const double       delta_max = 6 * e_y * height;
  std::ostringstream delta;
  delta << std::setprecision(17) << delta_max;
  const std::vector<std::string> scene = {
    "Output directory=plastic_uniaxial_strain_output",
    "Constants=Delta=" + delta.str() + ", g0=0",
    "Contact solver/Contact pressure=auto",
    "Loading/Steps=8",
    "Body omega1/Boundary conditions/Dirichlet=3: y: 0; -Delta*if(t<=0.5, "
    "2*t, 2-2*t) | 0: x: 0; 0 | 1: x: 0; 0",
    "Body omega2/Boundary conditions/Dirichlet=2: y: 0; 0 | 0: x: 0; 0 | 1: "
    "x: 0; 0",
    "Body omega2/Material/Law=j2-plasticity",
    "Body omega2/Material/Yield stress=" + std::to_string(Y),
    "Body omega2/Material/Isotropic hardening=" + std::to_string(H_iso)};

  // The closed form of every step.
  std::vector<double> reference;
  UniaxialStrainPoint point;
  unsigned int        first_yield = 0;
  for (unsigned int k = 1; k <= 8; ++k)
  {
    const double t     = k / 8.;
    const double delta = delta_max * (t <= 0.5 ? 2 * t : 2 - 2 * t);
    reference.push_back(series_pressure(delta, point));
    if (first_yield == 0 && point.alpha > 0)
      first_yield = k;
    std::cout << "  t = " << t << ": p = " << reference.back()
              << ", alpha = " << point.alpha << std::endl;
  }
  check(reference[3] > 3 * Y && reference[7] == 0. && point.alpha > 0,
        "the path yields, hardens and lifts off (closed form)");

  for (const std::string solver : {"dd-newton", "dd", "monolithic"})
  {
    const auto  sim     = run_scene(source_dir + "/prm/stability/uniaxial.prm",
                               scene,
                               {"Contact solver/Solver=" + solver});
    const auto &summary = sim->summary();
    const auto &steps   = summary.at("load_steps");
    check(steps.size() == 8, solver + ": eight load steps in summary.json");
    double error = 0;
    for (unsigned int k = 0; k < steps.size() && k < 8; ++k)
    {
      const double p = steps[k].at("pairs")[0].at("max_pressure").get<double>();
      // Relative to the peak pressure: the pressure is zero at lift-off.
      error = std::max(error, std::abs(p - reference[k]) / reference[3]);
      std::cout << "  " << solver << " step " << k + 1 << ": p = " << p
                << " (closed form " << reference[k] << ")" << std::endl;
    }
    // Homogeneous fields are exact on any mesh: what is left is the
    // solvers' tolerances (Tolerance 1e-10, the body Newton 1e-10).
    check(
      solver + ": the pressure of every step is the closed form", error, 1e-7);
    const auto &lower = summary.at("bodies")[1];
    check(solver + ": the largest equivalent plastic strain",
          relative(lower.at("largest_equivalent_plastic_strain").get<double>(),
                   point.alpha),
          1e-7);
    // The plastic zone is the whole lower block, 4 x 1.
    check(solver + ": the plastic zone is the lower block",
          relative(lower.at("plastic_zone_measure").get<double>(), 4.),
          1e-12);
    check(summary.contains("first_yield") &&
            summary.at("first_yield").at("step").get<unsigned int>() ==
              first_yield,
          solver + ": the first yield step is the closed form's (" +
            std::to_string(first_yield) + ")");
  }

  // Loading/Steps = auto: the step control measures the plastic strain and
  // the pressure too, so the path is path-dependent; step doubling returns
  // to the start of a step (the quadrature-point state with it). Uniaxial
  // strain with linear hardening is exact in one step per monotonic
  // branch: two steps, the kinks of the path, and the same end.
  {
    const auto  sim     = run_scene(source_dir + "/prm/stability/uniaxial.prm",
                               scene,
                               {"Loading/Steps=auto"});
    const auto &summary = sim->summary();
    check(summary.at("load_path").at("accepted_steps").get<unsigned int>() == 2,
          "Steps = auto: one step per monotonic branch");
    check("Steps = auto: the final equivalent plastic strain",
          relative(summary.at("bodies")[1]
                     .at("largest_equivalent_plastic_strain")
                     .get<double>(),
                   point.alpha),
          1e-7);
  }

  return report();
}
