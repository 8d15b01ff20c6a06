// DESCRIPTION: fraction and Doerfler marking with the caps Max level and
// Max cells, on the paper scene with both bodies adapted by Kelly: cells
// at Max level are not ranked, so they never use up the fraction (no cell
// is flagged and then capped for its level); a step that would exceed Max
// cells refines the cells with the largest contributions that fit instead
// of none, so both bodies end near the cap instead of one stalling far
// below it; and uniform refinement still refines all or nothing.
#include "scene_tools.h"

#include <fstream>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** Column @p name of every row of @p file (a CSV with a header). */
  std::vector<double>
  csv_column(const std::string &file, const std::string &name)
  {
    std::ifstream in(file);
    std::string   line, cell;
    std::getline(in, line);
    std::istringstream header(line);
    int                column = -1;
    for (int c = 0; std::getline(header, cell, ','); ++c)
      if (cell == name)
        column = c;
    std::vector<double> values;
    while (column >= 0 && std::getline(in, line))
    {
      std::istringstream row(line);
      for (int c = 0; std::getline(row, cell, ','); ++c)
        if (c == column)
          values.push_back(std::stod(cell));
    }
    return values;
  }

  unsigned int
  cells(const Simulation &simulation, const unsigned int body)
  {
    return simulation.get_bodies()[body]->get_triangulation().n_active_cells();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  const std::vector<std::string>   kelly = {"Adaptation/Bodies=omega1, omega2",
                                            "Adaptation/Mode=nested",
                                            "Adaptation/Estimator=kelly",
                                            "Adaptation/Marking=fraction",
                                            "Adaptation/Fraction=0.3",
                                            "Adaptation/Write every mesh=false"};

  // 1. Max level 4 (Omega_2 starts at level 1, Omega_1 at level 1): after
  // a few cycles the corner and contact-edge cells sit at level 4, and
  // the 30 % go to cells that can still be refined.
  {
    auto overrides = kelly;
    overrides.insert(overrides.end(),
                     {"Adaptation/Max level=4", "Adaptation/Max cycles=5"});
    const auto sim = run_coarse_paper_scene(
      source_dir, "output/marking_level", 1, overrides, {});
    const auto capped =
      csv_column("output/marking_level/statistics.csv", "capped");
    const auto marked =
      csv_column("output/marking_level/statistics.csv", "marked");
    double total_capped = 0, total_marked = 0;
    for (const double c : capped)
      total_capped += c;
    for (const double m : marked)
      total_marked += m;
    std::cout << "Max level 4: " << marked.size() << " cycles, " << total_marked
              << " cells marked, " << total_capped << " capped; cells "
              << cells(*sim, 0) << ", " << cells(*sim, 1) << std::endl;
    check(marked.size() == 6, "six rows (cycles 0 to 5) in statistics.csv");
    check(total_marked > 0 && total_capped == 0,
          "no cell is flagged and then capped for its level");
    unsigned int at_max_level = 0;
    for (const auto &cell :
         sim->get_bodies()[1]->get_triangulation().active_cell_iterators())
      at_max_level += (cell->level() == 4);
    check(at_max_level > 0, "the cap was reached (cells at level 4)");
  }

  // 2. Max cells 1500: both bodies end between 90 % of the cap (the last
  // step may leave up to a refined cell's 3 new cells per flagged cell
  // unused) and the cap plus the one-irregularity closure (10 %).
  {
    auto overrides = kelly;
    overrides.insert(overrides.end(),
                     {"Adaptation/Max cells=1500", "Adaptation/Max cycles=8"});
    const auto sim = run_coarse_paper_scene(
      source_dir, "output/marking_cells", 1, overrides, {});
    for (const unsigned int b : {0u, 1u})
    {
      std::cout << "Max cells 1500: body " << b << " has " << cells(*sim, b)
                << " cells" << std::endl;
      check(cells(*sim, b) >= 1350 && cells(*sim, b) <= 1650,
            "body " + std::to_string(b) + " refined up to the cap");
    }
  }

  // 3. Uniform refinement refines every cell or none: Max cells 5000
  // stops at 4096 quadrilaterals of Omega_2 (64 cells refined three
  // times; a fourth step would give 16384).
  {
    const auto sim = run_coarse_paper_scene(source_dir,
                                            "output/marking_uniform",
                                            0,
                                            {"Adaptation/Mode=uniform",
                                             "Adaptation/Max cycles=6",
                                             "Adaptation/Max level=10",
                                             "Adaptation/Max cells=5000"},
                                            {});
    std::cout << "uniform, Max cells 5000: Omega_2 has " << cells(*sim, 1)
              << " cells" << std::endl;
    check(cells(*sim, 1) == 4096, "uniform refinement stops whole at 4096");
  }
  return report();
}
