// DESCRIPTION: Hertz contact (plane strain): half-width and peak pressure
// converge to the closed form of doc/verification.md §2.2 under refinement
// toward the contact zone
#include <deal.II/base/convergence_table.h>

#include <ddcontact/simulation.h>

#include "scene_tools.h"
#include "test_tools.h"

#include <cmath>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  const double R = 50, E = 1000, nu = 0.3;
  const double E_star = 1. / (2. * (1. - nu * nu) / E);

  ConvergenceTable    table;
  std::vector<double> error_a, error_p0, error_reported;
  for (const unsigned int level : {4u, 5u, 6u, 7u})
  {
    const std::string     levels = std::to_string(level);
    const ParameterReader reader(source_dir + "/prm/hertz.prm",
                                 {"Output directory=hertz_output",
                                  "Output/Write vtu=false",
                                  "Body upper/Mesh/Box refinement=" + levels,
                                  "Body lower/Mesh/Box refinement=" + levels});
    std::ostringstream    quiet;
    Simulation            simulation(reader.scene(), quiet);
    simulation.run();

    const auto   state = simulation.get_contact_solver().contact_state(0);
    const double P     = state.force_1.norm();

    // Closed form at the computed force (doc/verification.md §2.2: in plane
    // strain the approach does not fix P, so compare at the P the run
    // produced).
    const double a_exact  = std::sqrt(4. * P * R / (M_PI * E_star));
    const double p0_exact = std::sqrt(P * E_star / (M_PI * R));

    // Half-width from the whole profile (scene_tools.h).
    const double a = hertz_half_width(simulation);

    const double h = simulation.get_bodies()[0]->get_mesh().min_cell_diameter();
    error_a.push_back(std::abs(a - a_exact) / a_exact);
    // The half-width the run reports (summary.json, ZoneExtent): the edge
    // placed inside its cell by the square-root profile of the last two
    // nodal pressures.
    error_reported.push_back(std::abs(state.half_width - a_exact) / a_exact);
    error_p0.push_back(std::abs(state.max_pressure - p0_exact) / p0_exact);
    table.add_value("level", level);
    table.add_value("h", h);
    table.add_value("P", P);
    table.add_value("a", a);
    table.add_value("a_exact", a_exact);
    table.add_value("err_a", error_a.back());
    table.add_value("half_width", state.half_width);
    table.add_value("err_half_width", error_reported.back());
    table.add_value("p0", state.max_pressure);
    table.add_value("p0_exact", p0_exact);
    table.add_value("err_p0", error_p0.back());
  }
  for (const auto &c :
       {"h", "P", "a", "a_exact", "half_width", "p0", "p0_exact"})
    table.set_precision(c, 5);
  print_with_rates(table, {"err_a", "err_half_width", "err_p0"});

  // Both errors must fall under refinement (toward the half-plane floor,
  // which for a / L = 0.02 lies well below the 2 % asked of the finest
  // mesh), and the finest mesh must be within 2 %.
  check("half-width a on the finest mesh", error_a.back(), 0.02);
  check("peak pressure p0 on the finest mesh", error_p0.back(), 0.02);
  // The reported half-width to 2 % of a on the shipped mesh (level 7) and
  // on the meshes 2 and 4 times coarser at the contact (issue 60; before,
  // the extent of the points with p > 0 reached into the next cell: +4.5 %
  // on level 7); a / h is 18, 9 and 4.5 there.
  for (unsigned int i = 1; i < error_reported.size(); ++i)
    check("reported half-width, level " + std::to_string(4 + i),
          error_reported[i],
          0.02);
  check(error_a.back() < error_a.front(),
        "the error of a falls under refinement");
  check(error_p0.back() < error_p0.front(),
        "the error of p0 falls under refinement");
  return report();
}
