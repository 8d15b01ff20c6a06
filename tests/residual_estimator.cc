// DESCRIPTION: the residual estimator's data (Adaptation/Estimator =
// residual) on the frictional patch test (prm/friction_patch.prm, uniform
// pressure and shear on non-matching meshes, which both bodies' FE spaces
// solve exactly): with the whole contact traction as Neumann data the
// estimate vanishes to round-off on both bodies, with either solver, and
// it does not when the contact traction lacks its tangential part or is
// left out (the errors such data would make); the rates and the bounded
// ratio to the energy error are tests/manufactured_solution's
#include <ddcontact/adaptivity/residual_estimator.h>
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <iostream>
#include <string>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** The global estimate sqrt(sum eta_K^2) of @p u on @p body. */
  double
  estimate(const ElasticBody<2>          &body,
           const BodyVector              &u,
           const BoundaryTractionSamples &contact)
  {
    ResidualEstimator estimator(body);
    estimator.estimate(u, contact);
    return estimator.indicators().l2_norm();
  }

  void
  run(const std::string &source_dir, const std::string &solver)
  {
    const auto sim = run_scene(
      source_dir + "/prm/friction_patch.prm",
      {"Contact solver/Solver=" + solver, "Contact solver/Tolerance=1e-12"},
      {});
    const auto &contact_solver = sim->get_contact_solver();
    for (const auto &body : sim->get_bodies())
    {
      const std::string label = solver + ", " + body->name();
      const auto       &u     = contact_solver.last_body_solution(*body);
      const auto        full  = contact_solver.last_contact_traction(*body);
      check(full.points.size() > 0, label + ": the contact load has samples");

      // The scale: the estimate of u = 0, the norm of the data (the
      // Neumann tractions and the contact traction) in the estimator's
      // own weights.
      const double data = estimate(*body, BodyVector(u.size()), full);

      // The tangential part removed: t tau = g - (g . n) n with n the
      // pair's normal, which for these flat faces is +-e_y.
      auto normal_only = full;
      for (auto &g : normal_only.traction)
        g[0] = 0;
      BoundaryTractionSamples none;

      const double eta_full   = estimate(*body, u, full);
      const double eta_normal = estimate(*body, u, normal_only);
      const double eta_none   = estimate(*body, u, none);
      std::cout << label << ": data " << data << ", eta/data with the whole "
                << "traction " << eta_full / data << ", normal part only "
                << eta_normal / data << ", none " << eta_none / data
                << std::endl;
      // Round-off: the FEM solution is exact to the solver's tolerance
      // 1e-12 and the face projections of a constant traction are exact;
      // 1e-9 leaves room for the conditioning of the bodies' systems.
      check(label + ": eta/data with the whole contact traction",
            eta_full / data,
            1e-9);
      // Without it the residual is the missing traction itself: the shear
      // S = 20.2 against the pressure P = 141 (relative 0.14 of the
      // contact data), and all of it.
      check(eta_normal / data > 0.05,
            label + ": without the shear the estimate sees it");
      check(eta_none / data > 0.5,
            label + ": without the contact traction the estimate sees it");
    }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = argc > 1 ? argv[1] : "..";
  for (const std::string solver : {"monolithic", "dd-newton"})
    run(source_dir, solver);
  return report();
}
