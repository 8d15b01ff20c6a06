// DESCRIPTION: FEM-BEM estimator (24), (27): on a block loaded on its top
// like a contact (the exact Kelvin field of a point force just above the
// block, given to FEM and BEM as traction samples), ||sigma_B - sigma_F||
// tracks the true stress error (effectivity in a fixed band, tending to 1),
// the scaled indicator shrinks under refinement while the printed one does
// not, the largest indicators sit under the load, and the element
// diameters of Definitions 1-2 are right
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/adaptivity/adaptive_refinement.h>
#include <ddcontact/adaptivity/fem_bem_estimator.h>
#include <ddcontact/body/elastic_body.h>

#include "scene_tools.h"
#include "test_tools.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  // The Kelvin solution (plane strain) of a force (0, -P) at x0 = (0, y0),
  // y0 above the block (-2, 2) x (0, 1): smooth in the block, with a
  // traction on the top face concentrated under the force, of width about
  // y0 - 1, like a contact pressure.
  const double E = 1., nu = 0.3, P = 1., y0 = 1.25;
  const double mu = E / (2. * (1. + nu));

  /** Stress sigma_ij = P/(4 pi (1-nu) r) [(1-2nu)(delta_i2 r_j + delta_j2
   * r_i - delta_ij r_2) + 2 r_i r_j r_2], r = (x - x0)/|x - x0|. */
  SymmetricTensor<2, 2>
  exact_stress(const Point<2> &x)
  {
    const double          dx = x[0], dy = x[1] - y0, r2 = dx * dx + dy * dy;
    const double          c = P / (4. * M_PI * (1. - nu));
    SymmetricTensor<2, 2> s;
    s[0][0] = c * ((1. - 2. * nu) * (-dy) / r2 + 2. * dx * dx * dy / (r2 * r2));
    s[1][1] = c * ((1. - 2. * nu) * dy / r2 + 2. * dy * dy * dy / (r2 * r2));
    s[0][1] = c * ((1. - 2. * nu) * dx / r2 + 2. * dx * dy * dy / (r2 * r2));
    return s;
  }

  /** Displacement u_j = -P c_U [(3-4nu) ln r delta_2j - r_2 r_j], c_U =
   * -1/(8 pi mu (1-nu)). */
  Tensor<1, 2>
  exact_displacement(const Point<2> &x)
  {
    const double dx = x[0], dy = x[1] - y0, r2 = dx * dx + dy * dy;
    const double c = -1. / (8. * M_PI * mu * (1. - nu));
    Tensor<1, 2> u;
    u[0] = -P * c * (-dy * dx / r2);
    u[1] = -P * c * ((3. - 4. * nu) * 0.5 * std::log(r2) - dy * dy / r2);
    return u;
  }

  /** The same fields as parser expressions for the body's data. */
  std::string
  constants()
  {
    std::ostringstream s;
    s << std::setprecision(17) << "P=" << P << ", y0=" << y0
      << ", cs=" << P / (4. * M_PI * (1. - nu))
      << ", cu=" << -1. / (8. * M_PI * mu * (1. - nu)) << ", k=" << 3 - 4 * nu
      << ", m=" << 1 - 2 * nu;
    return s.str();
  }

  const std::string r2 = "(x^2 + (y-y0)^2)";
  const std::string sxx =
    "cs*(m*(-(y-y0))/" + r2 + " + 2*x^2*(y-y0)/" + r2 + "^2)";
  const std::string sxy = "cs*(m*x/" + r2 + " + 2*x*(y-y0)^2/" + r2 + "^2)";
  const std::string syy = "cs*(m*(y-y0)/" + r2 + " + 2*(y-y0)^3/" + r2 + "^2)";
  const std::string u_expr = "-P*cu*(-(y-y0)*x/" + r2 + "); -P*cu*(k*0.5*log(" +
                             r2 + ") - (y-y0)^2/" + r2 + ")";

  /** sigma : C^{-1} sigma in plane strain, written out independently of
   * the estimator: eps = ((1+nu) sigma - nu (1+nu) tr(sigma) I) / E. */
  double
  energy(const SymmetricTensor<2, 2> &s)
  {
    const auto strain =
      ((1 + nu) * s - nu * (1 + nu) * trace(s) * unit_symmetric_tensor<2>()) /
      E;
    return s * strain;
  }

  /** The block with the exact traction of the Kelvin field on its free
   * sides and top and its displacement on the bottom, adapted with the
   * scaled FEM-BEM indicators and Doerfler marking until the estimate of
   * the relative energy-norm error is below @p target. Returns the
   * estimate and the true relative energy-norm error of the last mesh. */
  std::pair<double, double>
  adapt_to_target(const double target, unsigned int &cycles)
  {
    std::ofstream prm("fem_bem_target.prm");
    prm << "set Scene name = fem_bem_target\n"
        << "set Output directory = output/fem_bem_target\n"
        << "set Bodies = block\n"
        << "set Constants = " << constants() << "\n"
        << "subsection Adaptation\n  set Mode = nested\n"
        << "  set Bodies = block\n  set Estimator = fem-bem-scaled\n"
        << "  set Marking = doerfler\n  set Fraction = 0.5\n"
        << "  set Target error = " << target << "\n  set Max cycles = 12\n"
        << "end\n"
        << "subsection Body block\n  subsection Mesh\n"
        << "    set Corner 1 = -2, 0\n    set Corner 2 = 2, 1\n"
        << "    set Subdivisions = 16, 4\n  end\n"
        << "  subsection Material\n    set Young's modulus = " << E
        << "\n    set Poisson's ratio = " << nu << "\n  end\n"
        << "  subsection Boundary conditions\n"
        << "    set Dirichlet = 2: xy: " << u_expr << "\n"
        << "    set Neumann = 0: -(" << sxx << "); -(" << sxy
        << ") | 1: " << sxx << "; " << sxy << " | 3: " << sxy << "; " << syy
        << "\n  end\nend\n";
    prm.close();
    const auto simulation = run_scene("fem_bem_target.prm", {}, {});
    cycles                = simulation->n_adaptation_cycles();

    const auto &body    = *simulation->get_bodies()[0];
    const auto  sigma_F = body.stresses().at_quadrature_points();
    FEValues<2> fe_values(body.get_mapping(),
                          body.get_fe(),
                          body.get_cell_quadrature(),
                          update_quadrature_points | update_JxW_values);
    double      error2 = 0, norm2 = 0;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
    {
      fe_values.reinit(cell);
      const unsigned int c = cell->active_cell_index();
      for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const auto exact = exact_stress(fe_values.quadrature_point(q));
        error2 += energy(sigma_F[c][q] - exact) * fe_values.JxW(q);
        norm2 += energy(exact) * fe_values.JxW(q);
      }
    }
    return {relative_energy_error_estimate(simulation->get_adaptations()),
            std::sqrt(error2 / norm2)};
  }

  struct Result
  {
    double h, true_error, estimate, bem_error, eta_max_printed, eta_max_scaled;
    // Relative energy-norm error of sigma_F and its FEM-BEM estimate.
    double true_energy_error, energy_estimate;
    // ||sigma_B interpolated from the support points - sigma_B at the
    // quadrature points||, the shortcut the estimator takes on one process.
    double   interpolation_error;
    Point<2> worst_cell;
  };

  Result
  solve(const unsigned int refinement, const unsigned int degree = 1)
  {
    BodyParameters prm;
    prm.name                    = "block";
    prm.corner_1                = Point<2>(-2., 0.);
    prm.corner_2                = Point<2>(2., 1.);
    prm.subdivisions            = {16, 4};
    prm.initial_refinement      = refinement;
    prm.degree                  = degree;
    prm.material.youngs_modulus = E;
    prm.material.poisson_ratio  = nu;
    prm.dirichlet               = "2: xy: " + u_expr;
    prm.neumann = "0: -(" + sxx + "); -(" + sxy + ") | 1: " + sxx + "; " + sxy;
    prm.contact_ids    = "3";
    Constants      cst = parse_constants(constants(), "test");
    ElasticBody<2> body(prm, cst);
    body.make_mesh();
    body.setup_and_factorize();

    // The top face is loaded like a contact zone: the traction at face
    // quadrature points, assembled into the FEM load and handed to the
    // BEM as samples, as the DD does with the penalty pressure.
    BoundaryTractionSamples              samples;
    BodyVector                           load(body.n_dofs());
    const QGauss<1>                      face_quadrature(3);
    FEFaceValues<2>                      fe_face(body.get_mapping(),
                            body.get_fe(),
                            face_quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values | update_normal_vectors);
    std::vector<types::global_dof_index> dofs(body.get_fe().dofs_per_cell);
    Vector<double>                       local(body.get_fe().dofs_per_cell);
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 3)
        {
          fe_face.reinit(cell, f);
          local = 0;
          for (const unsigned int q : fe_face.quadrature_point_indices())
          {
            const Tensor<1, 2> t = exact_stress(fe_face.quadrature_point(q)) *
                                   fe_face.normal_vector(q);
            samples.points.push_back(fe_face.quadrature_point(q));
            samples.weights.push_back(fe_face.JxW(q));
            samples.traction.push_back(t);
            for (unsigned int i = 0; i < local.size(); ++i)
              local(i) += fe_face.shape_value(i, q) *
                          t[body.get_fe().system_to_component_index(i).first] *
                          fe_face.JxW(q);
          }
          cell->get_dof_indices(dofs);
          body.get_constraints().distribute_local_to_global(local, dofs, load);
        }
    BodyVector u;
    body.solve(load, u);

    FemBemEstimator printed(body, EstimatorType::fem_bem),
      scaled(body, EstimatorType::fem_bem_scaled);
    printed.estimate(u, samples);
    scaled.estimate(u, samples);

    // True errors of the FEM and of the BEM stresses at the same points.
    const auto sigma_F = body.stresses(u).at_quadrature_points();
    const auto sigma_B = printed.get_bem().stress_at_quadrature_points(
      body.get_dof_handler(), body.get_mapping(), body.get_cell_quadrature());
    FEValues<2> fe_values(body.get_mapping(),
                          body.get_fe(),
                          body.get_cell_quadrature(),
                          update_quadrature_points | update_JxW_values);
    const auto  sigma_I =
      printed.get_bem().interpolated_stress_at_quadrature_points(
        body.get_dof_handler(), body.get_mapping(), body.get_cell_quadrature());
    double fem2 = 0, bem2 = 0, energy_error2 = 0, energy_norm2 = 0, int2 = 0;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
    {
      fe_values.reinit(cell);
      const unsigned int c = cell->active_cell_index();
      for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const auto exact = exact_stress(fe_values.quadrature_point(q));
        fem2 +=
          (sigma_F[c][q] - exact) * (sigma_F[c][q] - exact) * fe_values.JxW(q);
        bem2 +=
          (sigma_B[c][q] - exact) * (sigma_B[c][q] - exact) * fe_values.JxW(q);
        energy_error2 += energy(sigma_F[c][q] - exact) * fe_values.JxW(q);
        energy_norm2 += energy(exact) * fe_values.JxW(q);
        int2 += (sigma_I[c][q] - sigma_B[c][q]) *
                (sigma_I[c][q] - sigma_B[c][q]) * fe_values.JxW(q);
      }
    }

    Result r;
    r.interpolation_error = std::sqrt(int2);
    r.h                   = body.get_mesh().min_cell_diameter();
    r.true_error          = std::sqrt(fem2);
    r.bem_error           = std::sqrt(bem2);
    r.estimate            = printed.global_error();
    r.true_energy_error   = std::sqrt(energy_error2 / energy_norm2);
    r.energy_estimate =
      printed.energy_norm_error() / printed.energy_norm_of_stress();
    r.eta_max_printed = printed.indicators().linfty_norm();
    r.eta_max_scaled  = scaled.indicators().linfty_norm();
    for (const auto &cell : body.get_triangulation().active_cell_iterators())
      if (scaled.indicators()(cell->active_cell_index()) == r.eta_max_scaled)
        r.worst_cell = cell->center();
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 0. The exact field is what it claims: Hooke's law of the gradient of
  //    u (central differences, error O(eps^2) ~ 1e-8 relative) gives the
  //    stress formula.
  {
    double worst = 0;
    for (const Point<2> x : {Point<2>(0.3, 0.7), Point<2>(-1.2, 0.1)})
    {
      const double       eps = 1e-5;
      Tensor<2, 2>       grad;
      const Tensor<1, 2> ex({eps, 0.}), ey({0., eps});
      for (unsigned int d = 0; d < 2; ++d)
      {
        const Tensor<1, 2> step = (d == 0) ? ex : ey;
        const auto         du =
          exact_displacement(x + step) - exact_displacement(x - step);
        for (unsigned int i = 0; i < 2; ++i)
          grad[i][d] = du[i] / (2 * eps);
      }
      const auto   strain = symmetrize(grad);
      const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
      const auto   s =
        lambda * trace(strain) * unit_symmetric_tensor<2>() + 2 * mu * strain;
      worst =
        std::max(worst, (s - exact_stress(x)).norm() / exact_stress(x).norm());
    }
    check(worst < 1e-7,
          "Kelvin stress = Hooke(grad u) (" + std::to_string(worst) + ")");
  }

  // 1. Effectivity under uniform refinement. The BEM stress error is
  //    O(h^2) and the Q1 stress error O(h) (doc/bem-method.md §6), so
  //    |effectivity - 1| <= ||sigma_B - sigma||/||sigma_F - sigma|| (the
  //    triangle inequality, Theorem 6) must shrink like h; a band of
  //    [0.8, 1.25] holds from the coarsest mesh on.
  std::vector<Result> results;
  for (const unsigned int r : {0u, 1u, 2u})
    results.push_back(solve(r));
  std::cout << "      h    true error    estimate   effectivity  BEM error "
               "   eta_max (27)  eta_max scaled"
            << std::endl;
  for (const auto &r : results)
    std::cout << std::setw(8) << r.h << std::scientific << std::setprecision(3)
              << "  " << r.true_error << "  " << r.estimate << "  "
              << r.estimate / r.true_error << "  " << r.bem_error << "  "
              << r.eta_max_printed << "  " << r.eta_max_scaled
              << std::defaultfloat << std::endl;
  for (const auto &r : results)
  {
    const double eff = r.estimate / r.true_error;
    check(eff > 0.8 && eff < 1.25,
          "effectivity " + std::to_string(eff) + " in [0.8, 1.25]");
  }
  // The same for the relative energy-norm error, the estimate that
  // Adaptation/Target error is held against (same argument, same band).
  for (const auto &r : results)
  {
    const double eff = r.energy_estimate / r.true_energy_error;
    std::cout << "relative energy-norm error " << r.true_energy_error
              << ", estimate " << r.energy_estimate << std::endl;
    check(eff > 0.8 && eff < 1.25,
          "energy-norm effectivity " + std::to_string(eff) + " in [0.8, 1.25]");
  }

  // 1b. Degree 2: Q2 body, quadratic boundary elements (the trace of Q2,
  //    (22)-(23)). The Q2 stress error is O(h^2); the BEM's is of higher
  //    order (bem_quadratic), so again |effectivity - 1| <=
  //    ||sigma_B - sigma|| / ||sigma_F - sigma|| -> 0; on these coarse
  //    meshes, where the load (width 0.25) is barely resolved, we ask for
  //    the band [0.5, 2] (doc/error-vs-time.md).
  std::cout << "degree 2:" << std::endl;
  std::vector<double> interpolation_errors, q2_errors;
  for (const unsigned int r : {0u, 1u, 2u})
  {
    const Result q2 = solve(r, 2);
    interpolation_errors.push_back(q2.interpolation_error);
    q2_errors.push_back(q2.true_error);
    const double eff = q2.energy_estimate / q2.true_energy_error;
    std::cout << "  h " << q2.h << ": relative energy-norm error "
              << q2.true_energy_error << ", estimate " << q2.energy_estimate
              << ", FEM stress error " << q2.true_error << ", BEM stress error "
              << q2.bem_error << ", sigma_B interpolated - direct "
              << q2.interpolation_error << std::endl;
    check(eff > 0.5 && eff < 2.,
          "Q2 energy-norm effectivity " + std::to_string(eff) + " in [0.5, 2]");
    check(q2.bem_error < 0.5 * q2.true_error,
          "Q2: BEM stress error below half the FEM's");
  }
  // The Q2 interpolant of sigma_B from the support points of the inner
  // cells (the estimator's shortcut on one process) against sigma_B at the
  // quadrature points: for a smooth field O(h^3), but near the boundary
  // sigma_B carries the BEM's own error, O(h^2) on the Dirichlet side
  // (bem_quadratic) and varying on the element scale, so we measured rate
  // ~2 (1.6, 2.1) at 5 % of the Q2 stress error. What the estimator needs:
  // the shortcut moves the estimate by well under the effectivity band,
  // i.e. at most 10 % of the FEM stress error on every mesh.
  for (std::size_t i = 0; i < interpolation_errors.size(); ++i)
    check(interpolation_errors[i] < 0.1 * q2_errors[i],
          "Q2: interpolated - direct sigma_B below 10 % of the FEM error (" +
            std::to_string(interpolation_errors[i] / q2_errors[i]) + ")");

  const double rate_fem =
    std::log2(results[1].true_error / results[2].true_error);
  const double rate_bem =
    std::log2(results[1].bem_error / results[2].bem_error);
  check(rate_fem > 0.8 && rate_bem > rate_fem + 0.5,
        "FEM stress error rate " + std::to_string(rate_fem) +
          " ~ 1, BEM rate " + std::to_string(rate_bem) + " clearly higher");
  check(std::abs(results[2].estimate / results[2].true_error - 1) <
          std::abs(results[0].estimate / results[0].true_error - 1),
        "effectivity tends to 1");

  // 2. The printed (27) divides the cell norm by the area: with a first-
  //    order error it scales like h^{-1} h = O(1) and does not shrink (here
  //    it even grows, the peak cell's error not yet being O(h)); the scaled
  //    form shrinks with the local error. The peak sits under a load of
  //    width 0.25 that these meshes (h = 0.25 ... 0.0625) only start to
  //    resolve, so its observed rate is below the asymptotic 1: we ask for
  //    a monotone decrease at a rate above 1/2 on the finest pair.
  check(results[2].eta_max_printed > results[1].eta_max_printed &&
          results[1].eta_max_printed > results[0].eta_max_printed,
        "printed eta_max does not decrease with h");
  check(results[1].eta_max_scaled < results[0].eta_max_scaled &&
          std::log2(results[1].eta_max_scaled / results[2].eta_max_scaled) >
            0.5,
        "scaled eta_max decreases (rate " +
          std::to_string(
            std::log2(results[1].eta_max_scaled / results[2].eta_max_scaled)) +
          ")");

  // 3. Adaptation/Target error: the adaptive loop refines until the
  //    estimate is at most the target and then stops; with the
  //    effectivity band of part 1 the true error is then at most 1.25
  //    times the target.
  {
    const double target               = 0.03;
    unsigned int cycles               = 0;
    const auto [estimate, true_error] = adapt_to_target(target, cycles);
    std::cout << "target " << target << ": " << cycles << " cycles, estimate "
              << estimate << ", true error " << true_error << std::endl;
    check(cycles > 0, "the first mesh misses the target: refined");
    check(estimate <= target, "stopped with the estimate within the target");
    check(true_error <= 1.25 * target, "true error within the target");
    check(true_error > 0.5 * target,
          "stopped at the first mesh within the target, not later");
    // The estimate of every cycle (last column of statistics.csv): above
    // the target on every mesh but the last.
    std::ifstream       statistics("output/fem_bem_target/statistics.csv");
    std::string         line;
    std::vector<double> history;
    std::getline(statistics, line); // header
    while (std::getline(statistics, line))
      history.push_back(std::stod(line.substr(line.rfind(',') + 1)));
    bool earlier_above = history.size() == cycles + 1;
    for (std::size_t c = 0; c + 1 < history.size(); ++c)
      earlier_above = earlier_above && history[c] > target;
    check(earlier_above && !history.empty() && history.back() <= target,
          "statistics.csv: every earlier estimate above the target");
  }

  // 4. The largest indicator sits under the load (0, 1).
  for (const auto &r : results)
    check(r.worst_cell.distance(Point<2>(0., 1.)) < 0.5,
          "largest eta under the load");

  // 5. Definitions 1-2 on a unit square cell: each of the four triangles
  //    of three vertices is a right isosceles triangle with legs 1, so
  //    D = sqrt 2 and d = 2 - sqrt 2, K = D/d.
  {
    Triangulation<2> tria;
    GridGenerator::hyper_cube(tria);
    const auto diam = element_diameters(tria);
    check(std::abs(diam.D(0) - std::sqrt(2.)) < 1e-14 &&
            std::abs(diam.d(0) - (2. - std::sqrt(2.))) < 1e-14 &&
            std::abs(diam.K(0) - std::sqrt(2.) / (2. - std::sqrt(2.))) < 1e-13,
          "element diameters of the unit square");
  }

  return report();
}
