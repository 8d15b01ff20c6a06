// DESCRIPTION: Contact pair/Gap evaluation: a gap expression interpolated
// from the nodes of S_1 (the default) is met exactly by linear elements in
// exact contact, where the expression at every contact point leaves the
// penetration k h^2 / 12 of a parabola between its chords; and on the
// paper's scene (penalty, linear elements) the nodal gap's peak pressure is
// much closer to the independent reference
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // 1. The uniaxial scene on matching meshes (16 faces of h = 0.25 on both
  //    zones) with the gap f = k x^2, small enough that the whole zone
  //    stays in contact, solved as exact contact (nodal multipliers, one
  //    per node of S_1 and as many as the normal displacements there).
  //    Nodes: the weak gaps vanish for u_1n + u_2n - I_h f, linear on every
  //    face, so it vanishes at the nodes and everywhere: the penetration
  //    at the contact points is round-off (the Newton tolerance 1e-10 of
  //    the overlap times the condition of S, ~10: 1e-9 Delta). Points: the
  //    weak gaps vanish for u_1n + u_2n - f; on a face in the interior
  //    the linear trace then sits at -k h^2 / 6 at the nodes, and the
  //    parabola penetrates it by k h^2 / 12 at the middle of every face.
  const double Delta = 1.366e-3, k = 2e-5, h = 0.25;
  for (const std::string evaluation : {"nodes", "points"})
  {
    const auto sim   = run_scene(source_dir + "/prm/stability/uniaxial.prm",
                               {"Output directory=gap_evaluation_output",
                                  "Contact solver/Solver=dd-newton",
                                  "Contact pair S/Formulation=exact"},
                               {"Body omega2/Mesh/Subdivisions=16, 4",
                                  "Constants=Delta=1.366e-3, k=2e-5",
                                  "Contact pair S/Gap=k*x^2",
                                  "Contact pair S/Gap evaluation=" + evaluation});
    const auto state = sim->get_contact_solver().contact_state(0);
    std::cout << "exact contact, gap k x^2 at the " << evaluation
              << ": max penetration " << state.max_penetration
              << " (k h^2 / 12 = " << k * h * h / 12 << "), contact length "
              << state.contact_length << std::endl;
    check(state.contact_length > 4 - 1e-12,
          evaluation + ": the whole zone is in contact");
    if (evaluation == "nodes")
      check(state.max_penetration <= 1e-9 * Delta,
            "nodes: the linear elements meet the interpolated gap exactly");
    else
      check("points: the parabola penetrates by k h^2 / 12 between nodes",
            relative(state.max_penetration, k * h * h / 12),
            1e-5);
  }

  // 2. The paper's scene (penalty c = 0.05, monolithic Newton solver, both
  //    bodies at refinement 1, h = 1/8) against the penalised reference
  //    peak pressure 186.75209 (doc/error-vs-time.md: degree 2,
  //    extrapolated in h, uncertainty 3e-7). With the gap at the points the
  //    pointwise penetration carries the error r0 h^2 / 12 of item 1,
  //    which the penalty turns into r0 h^2 / (12 theta) = 5.5 MPa, 3 % of
  //    the peak; the nodal gap leaves the elements' own error (0.4 %
  //    measured). The test asks for a factor of 4 between them.
  double error[2];
  for (const unsigned int i : {0u, 1u})
  {
    const std::string evaluation = (i == 0) ? "nodes" : "points";
    const auto        sim = run_scene(source_dir + "/prm/paper_two_bodies.prm",
                               {"Output directory=gap_evaluation_output",
                                       "Adaptation/Mode=none",
                                       "Contact solver/Solver=monolithic"},
                               {"Body omega1/Mesh/Initial refinement=1",
                                       "Body omega2/Mesh/Initial refinement=1",
                                       "Contact pair S/Gap evaluation=" + evaluation});
    const double peak = sim->get_contact_solver().contact_state(0).max_pressure;
    error[i]          = relative(peak, 186.75209);
    std::cout << "paper scene, r = 1, gap at the " << evaluation
              << ": peak pressure " << std::setprecision(8) << peak
              << std::setprecision(3) << ", " << error[i]
              << " from the reference" << std::endl;
  }
  check(error[0] < error[1] / 4,
        "paper scene: the nodal gap's peak pressure is at least 4 times "
        "closer to the reference");
  return report();
}
