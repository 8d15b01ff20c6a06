// DESCRIPTION: the hierarchical (HODLR) solver of the BEM collocation
// system: on a log-kernel matrix along a closed curve the HODLR solve
// inverts to its compression tolerance with ranks far below N; on the
// paper's Omega_2 the GMRES solve it preconditions equals the dense LU to
// the GMRES tolerance in a few iterations; the BEM keeps its system when
// only the interior is refined and rebuilds it when the boundary changes
#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/bem/collocation_system.h>
#include <ddcontact/bem/hodlr_matrix.h>

#include "bem_test_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** The single-layer-like matrix of @p n points on the unit circle,
   * A_ij = -log|x_i - x_j| h + delta_ij: smooth off the diagonal, singular
   * where the points meet, as the BEM's kernels are. */
  FullMatrix<double>
  log_kernel_matrix(const unsigned int n)
  {
    const double       h = 2 * numbers::PI / n;
    FullMatrix<double> A(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
      {
        const double d = 2 * std::abs(std::sin((i - double(j)) * h / 2));
        A(i, j)        = (i == j) ? 1. - h * std::log(h / 2) : -h * std::log(d);
      }
    return A;
  }

  /** The HODLR solve of the log-kernel matrix. */
  void
  check_log_kernel(const unsigned int n, const double tolerance)
  {
    const double       h = 2 * numbers::PI / n;
    FullMatrix<double> A = log_kernel_matrix(n);
    HodlrMatrix        hodlr;
    hodlr.factorize(A, tolerance, 32);
    Vector<double> x(n), b(n), y(n);
    for (unsigned int i = 0; i < n; ++i)
      x(i) = std::sin(3. * i * h) + std::cos(17. * i * h) + 0.1 * (i % 7);
    A.vmult(b, x);
    hodlr.vmult(y, b);
    y -= x;
    const double error = y.l2_norm() / x.l2_norm();
    std::cout << "log kernel, N = " << n << ", tolerance " << tolerance
              << ": solve error " << error << ", largest rank "
              << hodlr.max_rank() << ", stored " << hodlr.n_stored_entries()
              << " of N^2 = " << n * n << std::endl;
    // The condition number of this matrix is small (about 10): the solve
    // is accurate to a modest multiple of the block tolerance.
    check("HODLR solve error", error, 100 * tolerance);
    check(hodlr.max_rank() < n / 8, "ranks far below N");
  }

  /** CollocationSystem on the same kind of matrix, hierarchical: the
   * GMRES solve satisfies A x = b to its tolerance, and a zero load after a
   * solve gives zero (the warm start must not leak into the answer). */
  void
  check_collocation_system(const unsigned int n)
  {
    const double        h = 2 * numbers::PI / n;
    FullMatrix<double>  A = log_kernel_matrix(n);
    std::vector<double> keys(n);
    for (unsigned int i = 0; i < n; ++i)
      keys[i] = i;
    const FullMatrix<double> copy(A);
    CollocationSystem        system;
    system.initialize(
      std::move(A), keys, keys, CollocationSystem::Method::hierarchical);
    Vector<double> b(n), x(n), residual(n);
    for (unsigned int i = 0; i < n; ++i)
      b(i) = std::cos(5. * i * h);
    x = b;
    system.solve(x);
    copy.vmult(residual, x);
    residual -= b;
    check(!system.uses_dense_lu(), "CollocationSystem: hierarchical");
    // GMRES stops when its (recursively updated) residual is 1e-12
    // relative; the residual recomputed here may differ by round-off
    // growth over the iterations, hence 1e-11.
    check("CollocationSystem: relative residual",
          residual.l2_norm() / b.l2_norm(),
          1e-11);
    x = 0.;
    system.solve(x);
    check("CollocationSystem: zero load after a solve", x.linfty_norm(), 0.);
  }

  /** The paper's Omega_2 = (-2,2) x (0,1): bottom clamped (id 2), a
   * varying pressure and shear on top (id 3), sides free. Mixed data give
   * both kinds of unknowns (displacements and tractions) and D-D corner
   * rows. */
  BoundaryConditions<2>
  scene()
  {
    BoundaryConditions<2> bc;
    bc.dirichlet[2] = {ComponentMask(2, true),
                       std::make_shared<Functions::ZeroFunction<2>>(2)};
    auto top        = std::make_shared<FunctionParser<2>>(2);
    top->initialize("x,y", "0.3*x; -(1 + 0.5*x - 0.2*x^2)", {});
    bc.neumann[3] = top;
    return bc;
  }

  /** Largest nodal displacement and element-end traction difference of
   * two solves on the same boundary mesh, relative to the largest value. */
  double
  difference(const BoundaryElementSolver &a, const BoundaryElementSolver &b)
  {
    double du = 0, u = 0, dt = 0, t = 0;
    for (unsigned int i = 0; i < a.n_nodes(); ++i)
    {
      du =
        std::max(du, (a.node_displacement(i) - b.node_displacement(i)).norm());
      u = std::max(u, a.node_displacement(i).norm());
    }
    for (unsigned int e = 0; e < a.n_elements(); ++e)
      for (unsigned int k = 0; k < 2; ++k)
      {
        dt = std::max(
          dt, (a.element_traction(e, k) - b.element_traction(e, k)).norm());
        t = std::max(t, a.element_traction(e, k).norm());
      }
    return std::max(du / u, dt / t);
  }

  void
  check_against_dense_lu()
  {
    // 1040 boundary elements, about 2100 unknowns.
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_rectangle(
      tria, {416, 104}, Point<2>(-2, 0), Point<2>(2, 1), true);
    const Q1Displacement space(tria);

    BoundaryElementSolver dense(steel(), scene()), fast(steel(), scene());
    dense.set_solver_method(CollocationSystem::Method::dense_lu);
    fast.set_solver_method(CollocationSystem::Method::hierarchical);
    for (auto *bem : {&dense, &fast})
    {
      bem->setup(space.dof_handler, space.mapping);
      bem->solve();
    }
    const double error = difference(dense, fast);
    std::cout
      << "Omega_2, " << fast.n_unknowns() << " unknowns: hierarchical GMRES in "
      << fast.timings().iterations << " iterations, largest rank "
      << fast.get_collocation_system().get_hierarchical_matrix().max_rank()
      << ", difference to the dense LU " << error << std::endl;
    check(!fast.uses_dense_lu() && dense.uses_dense_lu(), "methods as chosen");
    // GMRES stops at a relative residual of 1e-12; the collocation matrix
    // of this mixed problem has a condition number of order 1e3 (its
    // first-kind part grows like 1/h), so 1e-8 bounds the difference.
    check("hierarchical vs dense LU, u and t", error, 1e-8);
    // The preconditioner is a solve to the compression tolerance 1e-8:
    // GMRES needs it only to reach 1e-12.
    check(fast.timings().iterations <= 4, "at most 4 GMRES iterations");
  }

  void
  check_reuse()
  {
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_rectangle(
      tria, {16, 4}, Point<2>(-2, 0), Point<2>(2, 1), true);
    BoundaryElementSolver bem(steel(), scene());
    {
      const Q1Displacement space(tria);
      bem.setup(space.dof_handler, space.mapping);
      bem.solve();
    }
    std::vector<std::pair<Point<2>, Tensor<1, 2>>> before;
    double                                         u_max = 0;
    for (unsigned int i = 0; i < bem.n_nodes(); ++i)
    {
      before.emplace_back(bem.node_position(i), bem.node_displacement(i));
      u_max = std::max(u_max, bem.node_displacement(i).norm());
    }

    // Refine a cell that touches no boundary: same boundary mesh.
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->at_boundary())
      {
        cell->set_refine_flag();
        break;
      }
    tria.execute_coarsening_and_refinement();
    {
      const Q1Displacement space(tria);
      bem.setup(space.dof_handler, space.mapping);
      bem.solve();
      BoundaryElementSolver fresh(steel(), scene());
      fresh.setup(space.dof_handler, space.mapping);
      fresh.solve();
      check(bem.n_system_setups() == 1, "interior refinement keeps the system");
      check("reused vs fresh system", difference(bem, fresh), 1e-14);
      // The nodes may be numbered differently: match them by position.
      double change = 0;
      for (const auto &[x, u] : before)
        for (unsigned int i = 0; i < bem.n_nodes(); ++i)
          if (bem.node_position(i).distance(x) < 1e-12)
            change = std::max(change, (bem.node_displacement(i) - u).norm());
      check("same boundary, same answer", change / u_max, 1e-14);
    }

    // Refine a boundary cell: the system is rebuilt.
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->at_boundary())
      {
        cell->set_refine_flag();
        break;
      }
    tria.execute_coarsening_and_refinement();
    const Q1Displacement space(tria);
    bem.setup(space.dof_handler, space.mapping);
    check(bem.n_system_setups() == 2, "boundary refinement rebuilds it");
  }
} // namespace

int
main()
{
  check_log_kernel(512, 1e-8);
  check_log_kernel(2048, 1e-8);
  check_log_kernel(2048, 1e-12);
  check_collocation_system(1024);
  check_against_dense_lu();
  check_reuse();
  return report();
}
