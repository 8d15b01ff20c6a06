// DESCRIPTION: a shrink fit of two thick cylinders, axisymmetric
// (prm/shrink_fit.prm): the pair's Interference gives Lamé's interface
// pressure (to 0.1 %, converging at O(h^2)), the hub's hoop stress at the
// bore, and the normal force p 2 pi b L over the ring; the same overlap
// written as the Gap expression (Gap = -delta) gives the same numbers and
// the initial-overlap warning, which the Interference (meant) does not
#include <ddcontact/simulation.h>

#include "scene_tools.h"
#include "test_tools.h"

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

  // Lamé with eps_zz = 0: a solid shaft r < b under the outer pressure p,
  // u_r(b) = -p b / (2 (l + m)); a hub b < r < c under the inner pressure
  // p, u_r(b) = A b + B / b with A = p b^2 / (2 (l + m)(c^2 - b^2)) and
  // B = p b^2 c^2 / (2 m (c^2 - b^2)). The interference delta is their
  // difference.
  const double E = 200e3, nu = 0.3, b = 1, c = 2, L = 0.5, delta = 1e-3;
  const double l = E * nu / ((1 + nu) * (1 - 2 * nu)), m = E / (2 * (1 + nu));
  const double p =
    delta /
    (b * (1. / (2. * (l + m)) +
          (b * b / (2. * (l + m)) + c * c / (2. * m)) / (c * c - b * b)));
  const double hoop = p * (c * c + b * b) / (c * c - b * b);

  std::vector<double> errors, averaged_rr, averaged_tt, raw_rr;
  for (const unsigned int n : {8u, 16u})
  {
    const std::string cells      = std::to_string(n) + ", 4";
    const auto        simulation = run_scene(source_dir + "/prm/shrink_fit.prm",
                                      {"Output directory=shrink_fit_output"},
                                      {"Body shaft/Mesh/Subdivisions=" + cells,
                                              "Body hub/Mesh/Subdivisions=" + cells,
                                              "Output/Points=hub: 1.5, 0.5"});
    const auto        state = simulation->get_contact_solver().contact_state(0);
    const auto        bore =
      simulation->get_bodies()[1]->stresses().at_point(Point<2>(b, L / 2));
    std::cout << std::setprecision(8) << "\n"
              << n << " cells across each cylinder: pressure "
              << state.max_pressure << ", Lamé " << p
              << "; hoop stress at the bore " << bore.out_of_plane << ", Lamé "
              << hoop << std::endl;
    errors.push_back(relative(state.max_pressure, p));
    // The pressure is uniform along the fit: every point carries it.
    double spread = 0;
    for (const double s : state.sigma_n)
      spread = std::max(spread, std::abs(-s - state.max_pressure));
    check("pressure uniform along the fit, / p", spread / p, 1e-10);
    check("normal force = p 2 pi b L over the ring, relative",
          relative(state.normal_force,
                   state.max_pressure * 2. * numbers::PI * b * L),
          1e-12);
    // The hoop stress at the bore, from the hub's first cell: O(h) (the
    // stress of Q1 is O(h) accurate; h = 1/n, d sigma_tt/dr / sigma_tt is
    // 2 c^2 / (b (c^2 + b^2)) = 1.6 at the bore).
    check("hub's hoop stress at the bore, relative, / (1.6 h)",
          relative(bore.out_of_plane, hoop) / (1.6 / n),
          1.);

    // Output/Points at a vertex inside the hub (r = 1.5): the stress of
    // the cell that holds it is O(h) off (the jump between cells: 4.5 %
    // of p in sigma_rr on 16 cells), the mean over the cells around it
    // O(h^2) (issue 60: summary.json's stress_averaged, sigma_hoop_averaged).
    const auto  &point = simulation->summary().at("points").at(0);
    const double r = 1.5, A = p * b * b / (c * c - b * b);
    const double rr = A * (1 - c * c / (r * r)), tt = A * (1 + c * c / (r * r));
    averaged_rr.push_back(
      std::abs(point.at("stress_averaged")[0].get<double>() - rr) / p);
    averaged_tt.push_back(
      std::abs(point.at("sigma_hoop_averaged").get<double>() - tt) / p);
    raw_rr.push_back(std::abs(point.at("stress")[0].get<double>() - rr) / p);
  }
  check("interface pressure within 0.1 % on 16 cells", errors.back(), 1e-3);
  // O(h^2): a factor 4 per halving (measured 4.02 and 4.01), asked at
  // least 3; and far below the cell's own stress, O(h) (measured 28 times
  // below it on 16 cells), asked 10 times.
  check("Points: averaged sigma_rr at a vertex, rate against Lamé",
        2. - std::log2(averaged_rr[0] / averaged_rr[1]),
        2. - std::log2(3.));
  check("Points: averaged hoop stress at a vertex, rate against Lamé",
        2. - std::log2(averaged_tt[0] / averaged_tt[1]),
        2. - std::log2(3.));
  check("Points: averaged sigma_rr against the cell's own, 16 cells",
        10. * averaged_rr[1] / raw_rr[1],
        1.);

  // Interference = delta against Gap = -delta: the same gap, so the same
  // solution; only the gap expression's overlap is warned about.
  const auto overlap_warnings = [](const Simulation &simulation)
  {
    unsigned int n = 0;
    for (const auto &w : simulation.summary().at("warnings"))
      n += w.get<std::string>().find("initial overlap") != std::string::npos;
    return n;
  };
  std::vector<std::unique_ptr<Simulation>> fits;
  for (const auto &gap :
       {std::vector<std::string>{},
        std::vector<std::string>{"Contact pair fit/Interference=0",
                                 "Contact pair fit/Gap=-1e-3"}})
  {
    auto entries = gap;
    entries.push_back("Body shaft/Mesh/Subdivisions=8, 4");
    entries.push_back("Body hub/Mesh/Subdivisions=8, 4");
    fits.push_back(run_scene(source_dir + "/prm/shrink_fit.prm",
                             {"Output directory=shrink_fit_output"},
                             entries));
  }
  const auto by_interference = fits[0]->get_contact_solver().contact_state(0);
  const auto by_gap          = fits[1]->get_contact_solver().contact_state(0);
  std::cout << std::setprecision(8) << "\nInterference = 1e-3: pressure "
            << by_interference.max_pressure
            << "; Gap = -1e-3: " << by_gap.max_pressure << std::endl;
  check("Interference = delta and Gap = -delta: the same pressure, relative",
        relative(by_interference.max_pressure, by_gap.max_pressure),
        1e-12);
  check(overlap_warnings(*fits[0]) == 0 && overlap_warnings(*fits[1]) == 1,
        "the initial overlap is warned about for the Gap, not for the "
        "Interference");
  // O(h^2): the error falls by about 4 per halving (measured 0.20 % and
  // 0.05 %, then 0.013 % on 32 cells).
  check("interface pressure error falls by at least 3 per halving",
        errors[0] / errors[1] >= 3. ? 0. : 1.,
        0.);
  return report();
}
