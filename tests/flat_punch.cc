// DESCRIPTION: A flat punch on a wider block: contact only under the punch
// whichever body comes first in the pair (both orders give the same
// pressures), and the pressure converges to the half-plane closed form
// p(x) = P / (pi sqrt(a^2 - x^2)) of a rigid flat punch
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const double a = 0.5; // half-width of the punch in prm/flat_punch.prm

  /** The pressure -sigma_n of pair 0 by the position x_1 of its points. */
  std::map<double, double>
  pressure_profile(const Simulation &simulation)
  {
    const auto  state = simulation.get_contact_solver().contact_state(0);
    const auto &pts   = simulation.get_contact_pairs()[0]->points();
    std::map<double, double> profile;
    for (unsigned int q = 0; q < pts.size(); ++q)
      profile[pts[q].x[0]] = -state.sigma_n[q];
    return profile;
  }

  /** The scene with the pair written the other way round: the block's
   * zone (16 wide) as S_1, the punch's (1 wide) as S_2. */
  const std::vector<std::string> block_first = {
    "Contact pair S/Body 1=block",
    "Contact pair S/Boundary id 1=3",
    "Contact pair S/Body 2=punch",
    "Contact pair S/Boundary id 2=2"};

  /** Errors of the pressure against the closed form at the computed force
   * P: the largest pointwise error over |x| < a/2, relative to the closed
   * form's centre value P/(pi a), and the integral of |p - p_exact| over
   * |x| < 0.9 a relative to P (the edges carry the r^(-1/2) singularity,
   * which a mesh resolves only in an integral sense). */
  std::pair<double, double>
  closed_form_errors(const Simulation &simulation)
  {
    const auto   state  = simulation.get_contact_solver().contact_state(0);
    const auto  &pts    = simulation.get_contact_pairs()[0]->points();
    const double P      = state.force_1.norm();
    double       centre = 0, integral = 0;
    for (unsigned int q = 0; q < pts.size(); ++q)
    {
      const double x     = pts[q].x[0];
      const double exact = P / (M_PI * std::sqrt(a * a - x * x));
      const double error = std::abs(-state.sigma_n[q] - exact);
      if (std::abs(x) < 0.5 * a)
        centre = std::max(centre, error / (P / (M_PI * a)));
      if (std::abs(x) < 0.9 * a)
        integral += error * pts[q].JxW / P;
    }
    return {centre, integral};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  const std::string                scene = source_dir + "/prm/flat_punch.prm";

  // 1. Both orders of the pair, with the DD at a penalty it converges for.
  // On flat zones the common refinement of the two zones is the same set
  // of pieces in either order and the absolute penalty is the same, so
  // both runs solve the same discrete problem: the pressures agree to the
  // DD's stopping tolerance. The points of the block's zone beyond the
  // punch's ends must have dropped out (they have no orthogonal
  // projection on the punch).
  std::cout << "Both orders of the pair (DD, theta = 1e-7):" << std::endl;
  const std::vector<std::string> dd = {"Output directory=flat_punch_output",
                                       "Contact solver/Solver=dd",
                                       "Contact solver/Tolerance=1e-10",
                                       "Contact pair S/Penalty=1e-7",
                                       "Body block/Mesh/Box refinement=5"};
  const auto                     punch_first_run = run_scene(scene, dd, {});
  auto                           overrides       = block_first;
  const auto block_first_run = run_scene(scene, dd, overrides);

  overrides.push_back("Contact pair S/Gap type=geometric");
  const auto geometric_run = run_scene(scene, dd, overrides);

  const auto p_punch     = pressure_profile(*punch_first_run);
  const auto p_block     = pressure_profile(*block_first_run);
  const auto p_geometric = pressure_profile(*geometric_run);
  check(p_geometric == p_block,
        "the geometric gap (zero on flat zones) gives the same pressures");
  double outside = 0;
  for (const auto &[x, p] : p_block)
    outside = std::max(outside, std::abs(x));
  check("every point of the block's zone lies under the punch",
        std::max(0., outside - a),
        1e-12);
  check(p_punch.size() == p_block.size(),
        "as many contact points in both orders (" +
          std::to_string(p_punch.size()) + ", " +
          std::to_string(p_block.size()) + ")");
  const double peak = std::max_element(p_punch.begin(),
                                       p_punch.end(),
                                       [](const auto &l, const auto &r)
                                       { return l.second < r.second; })
                        ->second;
  double difference = 0;
  for (auto i = p_punch.begin(), j = p_block.begin();
       i != p_punch.end() && j != p_block.end();
       ++i, ++j)
    difference = std::max(difference,
                          std::abs(i->first - j->first) +
                            std::abs(i->second - j->second) / peak);
  // The DD stops at a relative residual of 1e-10 per iteration; the
  // contraction near the penalty limit amplifies it by 1/(1 - rho), so
  // 1e-6 of the peak pressure leaves room for rho up to 0.9999.
  check("pressures of the two orders, relative to the peak", difference, 1e-6);
  check(
    "contact force of the two orders",
    relative(contact_force(*block_first_run), contact_force(*punch_first_run)),
    1e-6);

  // 2. The closed form, with the monolithic solver (Newton on (16)) at a
  // penalty whose penetration theta p stays far below h. The block's mesh
  // is refined toward the punch and the punch's mesh halves with it;
  // theta halves with h, so the penalty error falls with the
  // discretisation error. The r^(-1/2) edge singularity limits the
  // integral error to O(h^(1/2)), at least a factor 2 over two halvings;
  // away from the edges the pressure is smooth and the error at a/2 falls
  // to the floor of the model, a punch 1e4 times stiffer than the block on
  // a block 16 punch widths wide (measured: 0.33 % at level 7 with the
  // punch 1e4 times stiffer, 1.2 % with it 100 times stiffer).
  std::cout << "Closed form of a rigid flat punch on a half-plane:"
            << std::endl;
  std::vector<double> centre_errors, integral_errors;
  for (const unsigned int level : {5u, 6u, 7u})
  {
    const unsigned int n = 3u << (level - 3); // punch cells across a
    const auto         run =
      run_scene(scene,
                {"Output directory=flat_punch_output",
                 "Contact solver/Solver=monolithic",
                 "Contact pair S/Penalty=" +
                   Utilities::to_string(2e-8 / (1u << (level - 5))),
                 "Body block/Mesh/Box refinement=" + std::to_string(level),
                 "Body punch/Mesh/Subdivisions=" + std::to_string(2 * n) +
                   ", " + std::to_string(n)},
                {});
    const auto [centre, integral] = closed_form_errors(*run);
    std::cout << "  level " << level << ": error at |x| < a/2 " << centre
              << ", integral error " << integral << std::endl;
    centre_errors.push_back(centre);
    integral_errors.push_back(integral);
  }
  check("integral error falls by 2 over two halvings of h",
        integral_errors.back() / integral_errors.front(),
        0.5);
  check("pressure error at |x| < a/2 on the finest mesh (model floor 0.5 %)",
        centre_errors.back(),
        0.01);

  return report();
}
