// DESCRIPTION: penalty contact by the Neumann DD (20)-(21) on the paper's
// scene: equal and opposite forces, symmetry, no contact, penalty error ~
// theta, augmented Lagrangian, divergence reported
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** Run the paper's scene on coarse fixed meshes with extra overrides. */
  std::unique_ptr<Simulation>
  run(const std::string &source_dir, const std::vector<std::string> &overrides)
  {
    return run_coarse_paper_scene(
      source_dir, "contact_dd_output", 1, {"Adaptation/Mode=none"}, overrides);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // 1. Momentum: the two contact forces are assembled from the same points
  //    and weights but from different shape functions (body 1 at x, body 2
  //    at P(x)); partition of unity makes them equal and opposite up to
  //    round-off.
  {
    const auto   sim      = run(source_dir, {});
    const auto   state    = sim->get_contact_solver().contact_state(0);
    const double f        = state.force_1.norm();
    const double mismatch = (state.force_1 + state.force_2).norm() / f;
    std::cout << "force on body 1 = " << state.force_1
              << ", on body 2 = " << state.force_2 << ", relative mismatch "
              << mismatch << std::endl;
    check(f > 0 && mismatch < 1e-12, "forces equal and opposite to 1e-12");
    check(std::abs(state.force_1[0]) < 1e-10 * f,
          "no tangential force (frictionless, flat zone)");
  }

  // 1b. The DD and the monolithic semismooth Newton solver minimise the
  //     same penalised energy (15) on the same meshes and contact points, so
  //     with a residual tolerance of 1e-13 (error ~ tolerance x condition of
  //     the iteration, ~40 here) their contact displacements agree to 1e-8.
  {
    const auto dd     = run(source_dir, {"Contact solver/Tolerance=1e-13"});
    const auto newton = run(source_dir, {"Contact solver/Solver=monolithic"});
    const auto s_dd   = dd->get_contact_solver().contact_state(0);
    const auto s_nt   = newton->get_contact_solver().contact_state(0);
    double     diff = 0, scale = 0;
    for (unsigned int q = 0; q < s_dd.u_1n.size(); ++q)
    {
      diff  = std::max({diff,
                        std::abs(s_dd.u_1n[q] - s_nt.u_1n[q]),
                        std::abs(s_dd.u_2n[q] - s_nt.u_2n[q])});
      scale = std::max({scale, std::abs(s_nt.u_1n[q]), std::abs(s_nt.u_2n[q])});
    }
    std::cout << "DD vs monolithic Newton: max contact displacement difference "
              << diff / scale << " relative" << std::endl;
    check(diff < 1e-8 * scale, "DD equals the monolithic solver to 1e-8");
  }

  // 1c. The iterative body solver (CG with Trilinos AMG, relative residual
  //     1e-12) gives the direct solver's contact displacements to well
  //     within 1e-8 (error ~ tolerance x condition number ~1e4 here).
  {
    const auto direct = run(source_dir, {});
    const auto amg =
      run(source_dir,
          {"Body omega1/Solver/Type=cg-amg", "Body omega2/Solver/Type=cg-amg"});
    const auto s_d  = direct->get_contact_solver().contact_state(0);
    const auto s_a  = amg->get_contact_solver().contact_state(0);
    double     diff = 0, scale = 0;
    for (unsigned int q = 0; q < s_d.u_1n.size(); ++q)
    {
      diff  = std::max(diff, std::abs(s_d.u_2n[q] - s_a.u_2n[q]));
      scale = std::max(scale, std::abs(s_d.u_2n[q]));
    }
    std::cout << "cg-amg against direct: " << diff / scale << " relative"
              << std::endl;
    check(diff < 1e-8 * scale, "cg-amg body solver equals the direct solver");
  }

  // 2. Symmetry about x1 = 0 on quad/quad meshes, which are mirror
  //    symmetric (the triangle mesh of a rectangle is not: its diagonals
  //    all lean one way). Converged to 1e-10, so the mirrored pressures
  //    agree to about that relative to the peak.
  {
    const auto sim =
      run(source_dir, {"Body omega1/Element/Cell type=quadrilateral"});
    const auto  state = sim->get_contact_solver().contact_state(0);
    const auto &pts   = sim->get_contact_pairs()[0]->points();
    double      worst = 0;
    for (unsigned int i = 0; i < pts.size(); ++i)
      for (unsigned int j = 0; j < pts.size(); ++j)
        if (std::abs(pts[i].x[0] + pts[j].x[0]) < 1e-12)
          worst =
            std::max(worst, std::abs(state.sigma_n[i] - state.sigma_n[j]));
    std::cout << "largest asymmetry of the pressure " << worst << " (peak "
              << state.max_pressure << ")" << std::endl;
    check(worst < 1e-7 * state.max_pressure, "pressure symmetric about x1 = 0");
  }

  // 2b. Non-matching meshes: triangles above (P1) against quadrilaterals
  //     below, compared with quadrilaterals on both sides at the same
  //     resolution. The contact integral on the common refinement of the
  //     two zones keeps the peak pressure within 0.5 % and the profile (L2
  //     over S) within 0.5 %; what remains is the different stiffness of P1
  //     and Q1 elements, largest at the edges of the contact area, and it
  //     halves with each refinement (0.34 % here, 0.16 % one level finer).
  {
    const std::vector<std::string> fine = {
      "Body omega1/Mesh/Initial refinement=2",
      "Body omega2/Mesh/Initial refinement=2"};
    auto with = [&](std::vector<std::string> extra)
    {
      extra.insert(extra.end(), fine.begin(), fine.end());
      return extra;
    };
    const auto tri = run(source_dir, with({}));
    const auto quad =
      run(source_dir, with({"Body omega1/Element/Cell type=quadrilateral"}));
    const auto  s_t   = tri->get_contact_solver().contact_state(0);
    const auto  s_q   = quad->get_contact_solver().contact_state(0);
    const auto &pts   = tri->get_contact_pairs()[0]->points();
    double      diff2 = 0, norm2 = 0;
    for (unsigned int q = 0; q < pts.size(); ++q)
    {
      diff2 += pts[q].JxW * std::pow(s_t.sigma_n[q] - s_q.sigma_n[q], 2);
      norm2 += pts[q].JxW * std::pow(s_q.sigma_n[q], 2);
    }
    const double peak =
      std::abs(s_t.max_pressure - s_q.max_pressure) / s_q.max_pressure;
    const double profile = std::sqrt(diff2 / norm2);
    std::cout << "triangle/quad against quad/quad: peak pressure "
              << s_t.max_pressure << " vs " << s_q.max_pressure << " (" << peak
              << " relative), profile L2 difference " << profile << std::endl;
    check(peak < 5e-3 && profile < 5e-3,
          "non-matching pair agrees with the quad/quad pair to 0.5 %");
  }

  // 2c. Geometric gap: with flat zones a distance s apart, the distance
  //     to the projection on S_2 is s everywhere, so the geometric gap and
  //     the expression "s" define the same problem, to round-off.
  {
    const std::vector<std::string> apart = {
      "Constants=r0=0, Delta=3e-4, s=1e-4",
      "Body omega1/Mesh/Corner 1=-2, 1.0001",
      "Body omega1/Mesh/Corner 2=2, 2.0001"};
    auto with = [&](std::vector<std::string> extra)
    {
      extra.insert(extra.end(), apart.begin(), apart.end());
      return extra;
    };
    const auto expression = run(source_dir, with({"Contact pair S/Gap=s"}));
    const auto geometric =
      run(source_dir, with({"Contact pair S/Gap type=geometric"}));
    const auto s_e  = expression->get_contact_solver().contact_state(0);
    const auto s_g  = geometric->get_contact_solver().contact_state(0);
    double     diff = 0;
    for (unsigned int q = 0; q < s_e.sigma_n.size(); ++q)
      diff = std::max(diff, std::abs(s_e.sigma_n[q] - s_g.sigma_n[q]));
    std::cout << "geometric against expression gap: max pressure difference "
              << diff / s_e.max_pressure << " of the peak " << s_e.max_pressure
              << std::endl;
    check(s_e.max_pressure > 0 && diff < 1e-8 * s_e.max_pressure,
          "geometric gap equals the expression gap for parallel zones");
  }

  // 3. No contact: without approach the gap r0 x1^2 >= 0 never closes; the
  //    Winkler initial guess is then the contact-free solution and the
  //    first iteration has a zero residual.
  {
    const auto sim   = run(source_dir, {"Constants=r0=1e-3, Delta=0"});
    const auto state = sim->get_contact_solver().contact_state(0);
    const auto n     = sim->get_contact_solver().history().size();
    std::cout << "no contact: " << n << " iteration(s), peak pressure "
              << state.max_pressure << std::endl;
    check(n == 1 && state.max_pressure == 0.,
          "no contact: zero pressure, stops at once");
  }

  // 4. Penalty error: the overlap is about theta * pressure, so halving
  //    theta halves it. The pressure itself changes by O(theta) relative
  //    (theta E/H = 0.05 here), so the ratio is 2 to within a few percent.
  double penetration_c = 0;
  {
    const auto s1   = run(source_dir, {});
    const auto s2   = run(source_dir, {"Contact pair S/Penalty=0.025"});
    penetration_c   = s1->get_contact_solver().contact_state(0).max_penetration;
    const double p2 = s2->get_contact_solver().contact_state(0).max_penetration;
    std::cout << "penetration c = 0.05: " << penetration_c
              << ", c = 0.025: " << p2 << ", ratio " << penetration_c / p2
              << std::endl;
    check(std::abs(penetration_c / p2 - 2.) < 0.1,
          "penetration scales with theta");
  }

  // 5. Augmented Lagrangian: the penetration falls below 1e-3 of the
  //    approach Delta without changing theta. (Pointwise contact on these
  //    non-matching meshes stops at 9.7e-4: a tolerance below that ends
  //    "stalled", see tests/dd_newton.cc.)
  {
    const auto   sim = run(source_dir,
                         {"Contact pair S/Formulation=exact",
                            "Contact solver/Uzawa/Tolerance=1e-3"});
    const double p = sim->get_contact_solver().contact_state(0).max_penetration;
    std::cout << "augmented Lagrangian: penetration " << p << " = "
              << p / 1.366e-3 << " of the approach, after "
              << sim->get_contact_solver().n_uzawa_updates() << " updates"
              << std::endl;
    check(p < 1e-3 * 1.366e-3 && p < 0.1 * penetration_c,
          "augmented Lagrangian removes the penalty penetration");
  }

  // 6. A gamma far above gamma* is reported as divergence, not looped on.
  check_divergence_reported(
    [&](const std::vector<std::string> &overrides)
    { return run(source_dir, overrides); },
    "0.9",
    "gamma above gamma* reported as divergence naming Gamma");

  return report();
}
