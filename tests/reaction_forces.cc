// DESCRIPTION: reaction forces per Dirichlet id (summary.json bodies[].
// reactions): against the closed form of a block in uniaxial strain (each
// id's share, hanging nodes on the supports, quadrilaterals of degree 1
// and 2 and triangles), against the resultant of polynomial loads, and on
// contact scenes against the load carried through the contact (blocks in
// uniaxial stress, the paper's scene adapted with hanging nodes, Hertz
// with a floating cylinder), where reactions + loads + contact forces sum
// to zero
#include <deal.II/grid/grid_tools.h>

#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/reaction_forces.h>

#include "scene_tools.h"
#include "test_tools.h"

#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  std::string
  number(const double v)
  {
    std::ostringstream s;
    s << std::setprecision(17) << v;
    return s.str();
  }

  /** The block (0, 2) x (0, 1) (ids 0 left, 1 right, 2 bottom, 3 top),
   * refined once, distorted, with two layers of hanging nodes on the
   * left and bottom supports, solved. */
  std::unique_ptr<ElasticBody<2>>
  solved_block(const BodyParameters &p)
  {
    auto body = std::make_unique<ElasticBody<2>>(p, Constants());
    body->make_mesh();
    auto &tria = body->get_triangulation();
    tria.refine_global(1);
    GridTools::distort_random(0.2, tria, true, 3);
    if (p.cell_type == CellType::quadrilateral)
      for (unsigned int round = 0; round < 2; ++round)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->center()[0] + cell->center()[1] < 0.7 - 0.2 * round)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    body->setup_and_factorize();
    body->solve();
    return body;
  }

  /** The hanging dofs with a parent on a Dirichlet face (in 2D a hanging
   * node lies inside the body): their residual is a share of the support
   * reaction that must be handed to the parent. */
  unsigned int
  hanging_dofs_with_parents_on_supports(const ElasticBody<2> &body)
  {
    std::set<types::global_dof_index>    on_support;
    std::vector<types::global_dof_index> dofs(body.get_fe().n_dofs_per_face());
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() &&
            body.get_boundary_conditions().dirichlet.count(face->boundary_id()))
        {
          face->get_dof_indices(dofs);
          on_support.insert(dofs.begin(), dofs.end());
        }
    unsigned int n = 0;
    for (const auto &line : body.get_hanging_node_constraints().get_lines())
      for (const auto &[parent, weight] : line.entries)
        if (on_support.count(parent))
        {
          ++n;
          break;
        }
    return n;
  }

  void
  check_block(const std::string &cell_type, const unsigned int degree)
  {
    const std::string label = cell_type + " degree " + std::to_string(degree);
    ElasticConstants  material;
    material.youngs_modulus = 2.1e5;
    material.poisson_ratio  = 0.3;
    const double lambda = material.lambda(), mu = material.mu();

    BodyParameters p;
    p.name         = "block";
    p.cell_type    = parse_selection<CellType>(cell_type);
    p.degree       = degree;
    p.corner_1     = Point<2>(0, 0);
    p.corner_2     = Point<2>(2, 1);
    p.subdivisions = {6, 3};
    p.material     = material;

    // (a) Rollers on every side, the top pressed by q: uniaxial strain,
    // sigma_yy = -q, sigma_xx = -lambda q / (lambda + 2 mu), sigma_xy = 0,
    // reproduced exactly. The force of a support is the integral of
    // sigma n over its side: left (lambda q / (lambda + 2 mu), 0) per unit
    // height, right the opposite, bottom (0, 2 q), and the top's held x
    // component 0 (sigma_xy = 0). A corner node of two ids counts for the
    // lower one, which prescribes the same component here only at (0, 1)
    // and (2, 1), where sigma_xy = 0 leaves the split unchanged.
    const double q = 10.;
    p.dirichlet    = "0: x: 0; 0 | 1: x: 0; 0 | 2: y: 0; 0 | 3: x: 0; 0";
    p.neumann      = "3: 0; " + number(-q);
    {
      const auto              body = solved_block(p);
      const ReactionForces<2> r(*body, body->get_solution(), {});
      const double            side = lambda * q / (lambda + 2 * mu);
      const std::map<types::boundary_id, Tensor<1, 2>> exact = {
        {0, Tensor<1, 2>({side, 0})},
        {1, Tensor<1, 2>({-side, 0})},
        {2, Tensor<1, 2>({0, 2 * q})},
        {3, Tensor<1, 2>({0, 0})}};
      check(r.supports().size() == 4, label + ": four supports");
      double error = 0;
      for (const auto &s : r.supports())
        error = std::max(error, (s.force - exact.at(s.id)).norm() / (2 * q));
      if (p.cell_type == CellType::quadrilateral)
      {
        const unsigned int n = hanging_dofs_with_parents_on_supports(*body);
        check(n > 0,
              label + ": hanging dofs with a parent on a support (" +
                std::to_string(n) + ")");
      }
      // A linear field: exact up to round-off (condition ~1e3).
      check(label + ", uniaxial strain: each support's force", error, 1e-10);
      check(!r.supports()[0].prescribed[1] && r.supports()[0].prescribed[0] &&
              r.supports()[0].force[1] == 0.,
            label + ": the left roller prescribes x only, and carries no y");
      check(label + ", uniaxial strain: applied load (0, -2 q)",
            (r.applied_load() - Tensor<1, 2>({0, -2 * q})).norm() / (2 * q),
            1e-12);
    }

    // (b) Clamped at the bottom, a roller on the left; the top sheared by
    // tau and pressed by q, the right side loaded by (s y, 0), a body
    // force (0, -g). The field is not polynomial, but the supports balance
    // the resultant of the loads, (2 tau + s / 2, -2 q - 2 g), which every
    // rule here integrates exactly: to round-off, whatever the mesh.
    const double tau = 3., s = 4., g = 5.;
    p.dirichlet = "2: xy: 0; 0 | 0: x: 0; 0";
    p.neumann =
      "3: " + number(tau) + "; " + number(-q) + " | 1: " + number(s) + "*y; 0";
    p.body_force = "0; " + number(-g);
    {
      const auto              body = solved_block(p);
      const ReactionForces<2> r(*body, body->get_solution(), {});
      const Tensor<1, 2>      load({2 * tau + s / 2, -2 * q - 2 * g});
      Tensor<1, 2>            supports;
      for (const auto &support : r.supports())
        supports += support.force;
      check(label + ", clamped and loaded: applied load",
            (r.applied_load() - load).norm() / load.norm(),
            1e-12);
      check(label + ", clamped and loaded: supports + load",
            (supports + load).norm() / load.norm(),
            1e-10);
      check(label + ", clamped and loaded: imbalance",
            r.imbalance().norm() / load.norm(),
            1e-10);
    }
  }

  /** The reactions of summary.json, per body, as (id -> force). */
  std::map<std::string, std::map<int, Tensor<1, 2>>>
  reactions(const Simulation &s)
  {
    std::map<std::string, std::map<int, Tensor<1, 2>>> all;
    for (const auto &b : s.summary().at("bodies"))
      for (const auto &r : b.at("reactions"))
        all[b.at("name").get<std::string>()][r.at("boundary_id").get<int>()] =
          Tensor<1, 2>(
            {r.at("force")[0].get<double>(), r.at("force")[1].get<double>()});
    return all;
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  for (const std::string cell_type : {"quadrilateral", "triangle"})
    for (const unsigned int degree : {1u, 2u})
      check_block(cell_type, degree);

  // Two blocks in uniaxial stress (prm/stability/uniaxial.prm), exact
  // contact by dd-newton: the top support pushes body 1 down by the
  // contact force p L of the closed form (tests/scene_tools.h), the bottom
  // support pushes body 2 up by it, and the rollers carry nothing
  // (sigma_xx = 0). The Newton solve is exact on this linear field.
  {
    const auto   sim = run_scene(source_dir + "/prm/stability/uniaxial.prm",
                               {"Output directory=reaction_uniaxial"},
                               {"Contact pair S/Formulation=exact",
                                  "Contact solver/Solver=dd-newton",
                                  "Contact solver/Contact pressure=auto"});
    const double PL  = uniaxial_pressure(0.) * 4.;
    const auto   r   = reactions(*sim);
    const double error =
      std::max({(r.at("omega1").at(3) - Tensor<1, 2>({0, -PL})).norm(),
                (r.at("omega2").at(2) - Tensor<1, 2>({0, PL})).norm(),
                r.at("omega1").at(0).norm(),
                r.at("omega2").at(0).norm()}) /
      PL;
    check("uniaxial blocks, exact contact: reactions against p L", error, 1e-8);
    check("uniaxial blocks: imbalance", largest_imbalance(*sim), 1e-8);
  }

  // The paper's scene, adapted by the combined algorithm (hanging nodes in
  // Omega_2, triangles in Omega_1): body 1 is held by its top alone, body
  // 2 by its base, so both supports carry the contact force, equal and
  // opposite, as the contact points sum it.
  {
    const auto sim = run_coarse_paper_scene(
      source_dir, "reaction_paper", 1, {}, {"Adaptation/Max cycles=3"});
    const auto   r     = reactions(*sim);
    const auto   state = sim->get_contact_solver().contact_state(0);
    const double F     = state.force_1.norm();
    const double error =
      std::max((r.at("omega1").at(3) + state.force_1).norm(),
               (r.at("omega2").at(2) + state.force_2).norm()) /
      F;
    std::cout << "paper scene: contact force " << F << ", reaction of omega2 "
              << r.at("omega2").at(2) << ", "
              << sim->get_bodies()[1]->n_active_cells() << " cells"
              << std::endl;
    // The DD converged to Tolerance 1e-10.
    check(
      "paper scene, adapted: reactions against the contact force", error, 1e-6);
    check("paper scene: imbalance", largest_imbalance(*sim), 1e-6);
  }

  // Hertz (prm/hertz_force.prm, half model): the cylinder floats, pressed
  // by q on its flat top of width R; the base's supports carry q R up.
  {
    const auto   sim = run_scene(source_dir + "/prm/hertz_force.prm",
                               {"Output directory=reaction_hertz"},
                               {});
    const double qR  = 0.19139 * 5;
    const auto   r   = reactions(*sim);
    const double y   = r.at("block").at(2)[1] + r.at("block").at(0)[1];
    std::cout << "Hertz: base reaction " << y << " against q R = " << qR
              << std::endl;
    check("Hertz: the base carries q R", std::abs(y - qR) / qR, 1e-6);
    check("Hertz: imbalance", largest_imbalance(*sim), 1e-6);
  }
  return report();
}
