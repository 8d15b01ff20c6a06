// DESCRIPTION: local refinement of triangle bodies (P1 and P2), refined
// around a corner through ElasticBody::refine_and_transfer(): the patch test
// is exact, the mesh stays one-irregular, the transfer is exact for a field
// the coarse space holds, the BEM built on the refined triangle mesh (the
// FEM-BEM estimator) reproduces the patch stress; Mesh/Refinement box
// refines triangles locally; and the paper scene with its triangle body
// adapted by fem-bem-scaled refines it locally and gives the contact force
// of the quadrilateral-only adaptation
#include <deal.II/base/function_parser.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include "plane_strain_hooke.h"
#include <ddcontact/adaptivity/fem_bem_estimator.h>
#include <ddcontact/body/elastic_body.h>

#include "scene_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const Constants constants = {
    {"g11", 1e-3}, {"g12", 2e-3}, {"g21", -5e-4}, {"g22", 1.5e-3}, {"q", 4e-4}};

  /** The patch field u = G x of tests/patch_test.cc. */
  const std::vector<std::string> linear = {"g11*x + g12*y", "g21*x + g22*y"};

  /** A quadratic field, held by P2 but not by P1. */
  const std::vector<std::string> quadratic = {"g11*x + q*x*y + q*y*y",
                                              "g22*y - q*x*x + 2*q*x*y"};

  ElasticConstants
  steel()
  {
    ElasticConstants material;
    material.youngs_modulus = 2.1e5;
    material.poisson_ratio  = 0.3;
    return material;
  }

  /** A triangle body on (0, 2) x (0, 1), 6 x 3 squares of two triangles,
   * with @p field as Dirichlet data on the left (0) and bottom (2) and the
   * tractions @p neumann on the others. */
  BodyParameters
  parameters(const unsigned int              degree,
             const std::vector<std::string> &field,
             const std::string              &neumann)
  {
    BodyParameters p;
    p.name              = "triangles";
    p.cell_type         = CellType::triangle;
    p.degree            = degree;
    p.corner_1          = Point<2>(0, 0);
    p.corner_2          = Point<2>(2, 1);
    p.subdivisions      = {6, 3};
    p.material          = steel();
    const std::string u = field[0] + "; " + field[1];
    p.dirichlet         = "0: xy: " + u + " | 2: xy: " + u;
    p.neumann           = neumann;
    return p;
  }

  /** The initial mesh refined once and distorted (as tests/patch_test.cc),
   * and the system. */
  void
  make_mesh(ElasticBody<2> &body)
  {
    body.make_mesh();
    body.get_triangulation().refine_global(1);
    GridTools::distort_random(0.25, body.get_triangulation(), true, 42);
    body.setup_and_factorize();
  }

  BodyVector
  interpolant(const ElasticBody<2> &body, const std::vector<std::string> &field)
  {
    FunctionParser<2> f(2);
    f.initialize("x,y", field, constants);
    BodyVector v(body.n_dofs());
    VectorTools::interpolate(body.get_mapping(), body.get_dof_handler(), f, v);
    return v;
  }

  /** One round of refinement around the corner (0, 0): the cells within
   * 0.6 / 2^round of it, through the adaptive step's refine_and_transfer().
   * Returns whether the mesh is one-irregular afterwards. */
  bool
  refine_around_corner(ElasticBody<2> &body, const unsigned int round)
  {
    const double radius = 0.6 / std::pow(2., round);
    for (const auto &cell : body.get_triangulation().active_cell_iterators())
      if (cell->center().norm() < radius)
        cell->set_refine_flag();
    body.refine_and_transfer();
    return one_irregular(body.get_triangulation());
  }

  unsigned int
  n_hanging_constraints(const ElasticBody<2> &body)
  {
    unsigned int n = 0;
    for (const auto &line : body.get_constraints().get_lines())
      n += !line.entries.empty();
    return n;
  }

  /** (a), (b) and the BEM: the patch test on the locally refined body. */
  void
  patch_test(const unsigned int degree)
  {
    SymmetricTensor<2, 2> strain;
    strain[0][0] = constants.at("g11");
    strain[1][1] = constants.at("g22");
    strain[0][1] = 0.5 * (constants.at("g12") + constants.at("g21"));
    const auto         sigma = test::hooke(steel(), strain);
    std::ostringstream n;
    n << std::setprecision(17) << "1: " << sigma[0][0] << "; " << sigma[0][1]
      << " | 3: " << sigma[0][1] << "; " << sigma[1][1];
    const auto p    = parameters(degree, linear, n.str());
    const auto body = std::make_unique<ElasticBody<2>>(p, constants);
    make_mesh(*body);

    bool irregular_once = false;
    for (unsigned int round = 0; round < 4; ++round)
      irregular_once |= !refine_around_corner(*body, round);
    body->solve();

    // Every element holds linear fields: the solution is the exact one up
    // to round-off (condition numbers ~1e3-1e4 here; any discretisation
    // error would be O(h) or larger), as in tests/patch_test.cc.
    BodyVector error = interpolant(*body, linear);
    error -= body->get_solution();
    const double u_error =
      error.linfty_norm() / body->get_solution().linfty_norm();
    double s_error = 0;
    for (const auto &cell_stress : body->stresses().at_quadrature_points())
      for (const auto &s : cell_stress)
        s_error = std::max(s_error, (s - sigma).norm() / sigma.norm());

    const auto       &tria  = body->get_triangulation();
    const std::string label = "P" + std::to_string(degree);
    std::cout << label << " patch test: " << tria.n_active_cells()
              << " cells on levels 0.." << tria.n_levels() - 1 << ", "
              << n_hanging_constraints(*body)
              << " hanging-node constraints; max nodal error " << u_error
              << ", max stress error " << s_error << std::endl;
    check(tria.n_levels() >= 5, label + ": refined four times at the corner");
    check(n_hanging_constraints(*body) > 0, label + ": hanging nodes");
    check(!irregular_once, label + ": one-irregular after every round");
    check(label + ": max nodal error", u_error, 1e-10);
    check(label + ": max stress error", s_error, 1e-10);

    if (degree != 1)
      return; // the BEM has linear elements (26)
    // The BEM's boundary mesh of the refined triangle mesh: boundary faces
    // carry no hanging nodes in 2D, so one element per active boundary
    // face, and the BEM reproduces the patch stress to its quadrature
    // accuracy (~1e-8 per element, tests/bem_patch.cc): the FEM-BEM
    // estimate of the exact FEM solution is that small.
    unsigned int boundary_faces = 0;
    for (const auto &face : tria.active_face_iterators())
      boundary_faces += face->at_boundary();
    FemBemEstimator estimator(*body, EstimatorType::fem_bem_scaled);
    estimator.estimate(body->get_solution(), {});
    const double relative = estimator.global_error() / estimator.stress_norm();
    std::cout << "P1 FEM-BEM: " << estimator.get_bem().n_elements()
              << " boundary elements for " << boundary_faces
              << " boundary faces; ||sigma_B - sigma_F|| / ||sigma_B|| = "
              << relative << ", max eta "
              << estimator.indicators().linfty_norm() << std::endl;
    check(estimator.get_bem().n_elements() == boundary_faces,
          "one boundary element per active boundary face");
    check("FEM-BEM relative error of the exact patch solution", relative, 1e-6);
  }

  /** (c): the transfer of a field the coarse space holds is exact. */
  void
  transfer_test(const unsigned int degree)
  {
    const auto &field = degree == 1 ? linear : quadratic;
    const auto  p     = parameters(degree, field, "");
    const auto  body  = std::make_unique<ElasticBody<2>>(p, constants);
    make_mesh(*body);
    body->get_solution() = interpolant(*body, field);
    double max_error     = 0;
    for (unsigned int round = 0; round < 4; ++round)
    {
      refine_around_corner(*body, round);
      BodyVector error = interpolant(*body, field);
      error -= body->get_solution();
      max_error = std::max(
        max_error, error.linfty_norm() / body->get_solution().linfty_norm());
    }
    const std::string label = "P" + std::to_string(degree) + " transfer of a " +
                              (degree == 1 ? "linear" : "quadratic") + " field";
    std::cout << label << ": " << body->get_triangulation().n_active_cells()
              << " cells, max nodal error (relative) " << max_error
              << std::endl;
    check(label + ", max nodal error (relative)", max_error, 1e-12);
  }

  /** Mesh/Refinement box on a triangle body: local, one-irregular. */
  void
  box_test()
  {
    auto p           = parameters(1, linear, "");
    p.refinement_box = {0., 0., 0.3, 0.3};
    p.box_refinement = 3;
    ElasticBody<2> body(p, constants);
    body.make_mesh();
    const auto &tria = body.get_triangulation();
    std::cout << "Refinement box, 3 times: " << tria.n_active_cells()
              << " triangles on levels 0.." << tria.n_levels() - 1 << std::endl;
    check(tria.n_levels() == 4 && tria.n_active_cells() < 36 * 64,
          "Refinement box refines triangles locally");
    check(one_irregular(tria), "box-refined triangle mesh is one-irregular");
  }

  /** (d): the paper scene, coarse, adapted by fem-bem-scaled. */
  void
  scene_test(const std::string &source_dir)
  {
    const auto run = [&](const std::string &bodies, const std::string &mode)
    {
      return run_coarse_paper_scene(source_dir,
                                    "triangle_adaptivity_output",
                                    0,
                                    {"Adaptation/Mode=" + mode,
                                     "Adaptation/Bodies=" + bodies,
                                     "Adaptation/Estimator=fem-bem-scaled",
                                     "Adaptation/Marking=fraction",
                                     "Adaptation/Fraction=0.2",
                                     "Adaptation/Max cycles=3"},
                                    {});
    };
    const auto quads = run("omega2", "nested");
    const auto both  = run("omega1, omega2", "nested");
    // A reference: both bodies refined uniformly once more than the
    // adaptive runs start (h = 1/16 above, 1/8 below).
    const auto reference = run_coarse_paper_scene(
      source_dir,
      "triangle_adaptivity_output",
      1,
      {"Adaptation/Mode=none", "Body omega1/Mesh/Initial refinement=2"},
      {});

    const auto &omega1   = both->get_bodies()[0]->get_triangulation();
    int         coarsest = omega1.n_levels(), finest = 0;
    for (const auto &cell : omega1.active_cell_iterators())
    {
      coarsest = std::min(coarsest, cell->level());
      finest   = std::max(finest, cell->level());
    }
    const double f_quads = contact_force(*quads), f_both = contact_force(*both),
                 f_ref = contact_force(*reference);
    std::cout << std::setprecision(8)
              << "paper scene, nested, 3 cycles of 20 %:"
              << "\n  Omega_1 adapted: " << omega1.n_active_cells()
              << " triangles on levels " << coarsest << ".." << finest
              << ", one-irregular " << one_irregular(omega1)
              << "\n  contact force: Omega_2 adapted " << f_quads
              << ", both adapted " << f_both << ", uniform reference (h = "
              << "1/16, 1/8) " << f_ref << std::endl;
    check(finest > coarsest,
          "Omega_1 refined locally (active cells of several levels)");
    check(one_irregular(omega1), "adapted Omega_1 is one-irregular");
    // Adapting Omega_1 as well (its cells ranked with Omega_2's by their
    // error contributions) must bring the force at least as close to the
    // finer uniform reference as adapting Omega_2 alone, whose distance
    // (2.6e-3 relative) is what Omega_1's coarse mesh leaves; F converges
    // like the energy, O(h^2) for P1/Q1.
    const double tolerance = std::abs(f_quads - f_ref) / std::abs(f_ref);
    check("contact force, both adapted against the uniform reference "
          "(relative)",
          std::abs(f_both - f_ref) / std::abs(f_ref),
          tolerance);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  for (const unsigned int degree : {1u, 2u})
  {
    patch_test(degree);
    transfer_test(degree);
  }
  box_test();
  scene_test(source_dir);
  return report();
}
