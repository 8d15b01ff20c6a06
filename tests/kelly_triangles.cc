// DESCRIPTION: Kelly's indicator on triangle bodies, face_jump_indicators():
// (a) on a quadrilateral mesh with hanging nodes (Q1, Q2) and (b) on a
// conforming triangle mesh (P1, P2), where deal.II's KellyErrorEstimator
// runs, it equals deal.II's cell by cell; (c) on a locally refined triangle
// mesh (hanging nodes) it vanishes for a field of the space and decreases
// like h^p for a smooth one under uniform refinement; (d) the paper scene
// adapts both bodies, the triangle body Omega_1 included, with Kelly
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/affine_constraints.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <ddcontact/adaptivity/kelly_estimator.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** A smooth field that no finite element space holds. */
  const std::vector<std::string> smooth = {"sin(2*x + y) * exp(0.5*y)",
                                           "cos(3*x*y) + 0.2*x^3"};

  /** A field of degree @p p, held by P_p and Q_p. */
  std::vector<std::string>
  polynomial(const unsigned int p)
  {
    if (p == 1)
      return {"1 + 2*x - y", "0.5*x + 3*y"};
    return {"x^2 - 2*x*y + 0.5*y^2 + x", "3*x*y - y^2 + 1"};
  }

  /** The coarse mesh: 4 x 3 rectangles (quadrilaterals, or each cut into
   * two triangles) on (0, 1.5) x (0, 1), bent by a smooth map so that the
   * cells are general; refined afterwards, the children are straight. */
  void
  make_coarse(Triangulation<2> &tria, const bool simplex)
  {
    const Point<2> a(0, 0), b(1.5, 1);
    if (simplex)
      GridGenerator::subdivided_hyper_rectangle_with_simplices(
        tria, {4, 3}, a, b);
    else
      GridGenerator::subdivided_hyper_rectangle(tria, {4, 3}, a, b);
    GridTools::transform(
      [](const Point<2> &p)
      {
        return Point<2>(p[0] + 0.1 * std::sin(2 * p[1]),
                        p[1] + 0.08 * p[0] * p[0]);
      },
      tria);
  }

  /** Cells within @p radius of the corner (0, 0) refined once. */
  void
  refine_corner(Triangulation<2> &tria, const double radius)
  {
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center().norm() < radius)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
  }

  unsigned int
  n_hanging_faces(const Triangulation<2> &tria)
  {
    unsigned int n = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        n += !cell->at_boundary(f) && cell->neighbor(f)->has_children();
    return n;
  }

  /** @p field interpolated into @p dofs, hanging nodes constrained. */
  BodyVector
  interpolant(const Mapping<2>               &mapping,
              const DoFHandler<2>            &dofs,
              const std::vector<std::string> &field)
  {
    FunctionParser<2> f(2);
    f.initialize("x,y", field, {});
    BodyVector u(dofs.n_dofs());
    VectorTools::interpolate(mapping, dofs, f, u);
    AffineConstraints<double> constraints;
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();
    constraints.distribute(u);
    return u;
  }

  /** (a), (b): the indicator of the smooth field against deal.II's
   * KellyErrorEstimator (default strategy) on @p tria, cell by cell. */
  void
  compare_with_deal_ii(const Triangulation<2> &tria,
                       const FiniteElement<2> &fe,
                       const Mapping<2>       &mapping,
                       const std::string      &label)
  {
    DoFHandler<2> dofs(tria);
    dofs.distribute_dofs(fe);
    const BodyVector u = interpolant(mapping, dofs, smooth);
    const QGauss<1>  quadrature(fe.degree + 1);
    Vector<float>    reference(tria.n_active_cells());
    KellyErrorEstimator<2>::estimate(
      mapping, dofs, quadrature, {}, u, reference);
    Vector<double> eta;
    face_jump_indicators(mapping, dofs, quadrature, u, eta);
    double worst = 0;
    for (unsigned int c = 0; c < eta.size(); ++c)
      worst = std::max(worst, relative(eta(c), reference(c)));
    std::cout << label << ": " << tria.n_active_cells() << " cells, "
              << n_hanging_faces(tria) << " hanging faces, largest eta "
              << eta.linfty_norm() << std::endl;
    // deal.II stores eta_K^2 in a Vector<float> and adds the face terms
    // and takes the root in float: a few roundings of 2^-24 = 6e-8 each,
    // against our double. 1e-6 is 16 of them; a wrong face, factor or
    // sub-face would be off by O(1).
    check(
      label + ": eta against deal.II, cell by cell (relative)", worst, 1e-6);
  }

  void
  test_quadrilaterals(const unsigned int p)
  {
    Triangulation<2> tria;
    make_coarse(tria, false);
    tria.refine_global(1);
    refine_corner(tria, 0.5);
    refine_corner(tria, 0.25);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] > 1.1 && cell->center()[1] > 0.6)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    check(n_hanging_faces(tria) > 0, "Q mesh has hanging nodes");
    compare_with_deal_ii(tria,
                         FESystem<2>(FE_Q<2>(p), 2),
                         MappingQ<2>(1),
                         "(a) Q" + std::to_string(p) + ", hanging nodes");
  }

  void
  test_conforming_triangles(const unsigned int p)
  {
    Triangulation<2> tria;
    make_coarse(tria, true);
    tria.refine_global(1);
    compare_with_deal_ii(tria,
                         FESystem<2>(FE_SimplexP<2>(p), 2),
                         MappingFE<2>(FE_SimplexP<2>(1)),
                         "(b) P" + std::to_string(p) + ", conforming");
  }

  /** sqrt(sum eta^2) of @p field on @p tria. */
  double
  global_estimate(const Triangulation<2>         &tria,
                  const FiniteElement<2>         &fe,
                  const Mapping<2>               &mapping,
                  const std::vector<std::string> &field)
  {
    DoFHandler<2> dofs(tria);
    dofs.distribute_dofs(fe);
    Vector<double> eta;
    face_jump_indicators(mapping,
                         dofs,
                         QGauss<1>(fe.degree + 1),
                         interpolant(mapping, dofs, field),
                         eta);
    return eta.l2_norm();
  }

  /** (c): the locally refined triangle mesh. */
  void
  test_refined_triangles(const unsigned int p)
  {
    const std::string label = "(c) P" + std::to_string(p);
    Triangulation<2>  tria;
    make_coarse(tria, true);
    tria.refine_global(1);
    refine_corner(tria, 0.6);
    refine_corner(tria, 0.3);
    const FESystem<2>  fe(FE_SimplexP<2>(p), 2);
    const MappingFE<2> mapping(FE_SimplexP<2>(1));
    check(n_hanging_faces(tria) > 0, label + ": hanging nodes");

    // A field of the space: every gradient jump vanishes. Relative to the
    // estimate of the smooth field of similar size, round-off is ~1e-15
    // times the conditioning of the gradients (h ~ 1/16).
    const double zero  = global_estimate(tria, fe, mapping, polynomial(p));
    const double scale = global_estimate(tria, fe, mapping, smooth);
    std::cout << label << ": " << tria.n_active_cells() << " cells, "
              << n_hanging_faces(tria) << " hanging faces; estimate of the "
              << "degree-" << p << " field " << zero << ", of the smooth field "
              << scale << std::endl;
    check(label + ": estimate of a field of the space (relative)",
          zero / scale,
          1e-12);

    // The smooth field under uniform refinement of the locally refined
    // mesh: the normal-derivative jumps of the interpolant are O(h^p), so
    // eta_K^2 ~ h * h (h^p)^2 over h^-2 cells gives eta ~ h^p. The next
    // term is O(h) relative, at h <= 1/32 a shift of the rate below 0.3.
    std::vector<double> estimates = {scale};
    for (unsigned int k = 0; k < 2; ++k)
    {
      tria.refine_global(1);
      estimates.push_back(global_estimate(tria, fe, mapping, smooth));
    }
    const double rate = std::log2(estimates[1] / estimates[2]);
    std::cout << label << ": estimates " << estimates[0] << ", " << estimates[1]
              << ", " << estimates[2] << " (rates "
              << std::log2(estimates[0] / estimates[1]) << ", " << rate << ")"
              << std::endl;
    check(
      label + ": rate of the estimate, |rate - p|", std::abs(rate - p), 0.3);
  }

  /** (d): the paper scene, both bodies adapted by Kelly. */
  void
  test_scene(const std::string &source_dir)
  {
    const auto run = [&](const std::string &mode)
    {
      return run_coarse_paper_scene(source_dir,
                                    "kelly_triangles_output",
                                    0,
                                    {"Adaptation/Mode=" + mode,
                                     "Adaptation/Bodies=omega1, omega2",
                                     "Adaptation/Estimator=kelly",
                                     "Adaptation/Marking=fraction",
                                     "Adaptation/Fraction=0.2",
                                     "Adaptation/Max cycles=2"},
                                    {});
    };
    const auto                initial = run("none");
    const auto                adapted = run("nested");
    std::vector<unsigned int> before, after;
    for (const auto &body : initial->get_bodies())
      before.push_back(body->get_triangulation().n_active_cells());
    for (const auto &body : adapted->get_bodies())
      after.push_back(body->get_triangulation().n_active_cells());
    const auto &omega1 = adapted->get_bodies()[0]->get_triangulation();
    std::cout << "(d) paper scene, Kelly nested, 2 cycles of 20 %: Omega_1 "
              << before[0] << " -> " << after[0] << " triangles (levels 0.."
              << omega1.n_levels() - 1 << "), Omega_2 " << before[1] << " -> "
              << after[1] << " quadrilaterals" << std::endl;
    check(after[0] > before[0], "(d) Omega_1 (triangles) refined");
    check(after[1] > before[1], "(d) Omega_2 (quadrilaterals) refined");
    int coarsest = omega1.n_levels(), finest = 0;
    for (const auto &cell : omega1.active_cell_iterators())
    {
      coarsest = std::min(coarsest, cell->level());
      finest   = std::max(finest, cell->level());
    }
    check(finest > coarsest,
          "(d) Omega_1 refined locally (active cells of several levels)");
    check(one_irregular(omega1), "(d) adapted Omega_1 is one-irregular");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  for (const unsigned int p : {1u, 2u})
  {
    test_quadrilaterals(p);
    test_conforming_triangles(p);
    test_refined_triangles(p);
  }
  test_scene(source_dir);
  return report();
}
