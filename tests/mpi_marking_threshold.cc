// DESCRIPTION: (run under mpirun -np 3) the joint marking threshold of
// fraction and Doerfler marking found over the processes (bisection on the
// bit patterns of the contributions with exact global counts, for p4est
// meshes) equals the threshold one process finds by sorting all values,
// for cell contributions spread over the processes unevenly, with exact
// ties, zeros and a process that holds none
#include <deal.II/base/mpi.h>

#include <ddcontact/adaptivity/marking.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <numeric>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   world = MPI_COMM_WORLD;
  const unsigned int rank    = Utilities::MPI::this_mpi_process(world);
  const unsigned int n_procs = Utilities::MPI::n_mpi_processes(world);
  const bool         root    = rank == 0;

  // 997 contributions: a smooth spread over six decades, every 7th value
  // repeated by the next cell (exact ties), every 50th zero (cells at Max
  // level). Cell i lives on process (i / 7) % P, except that the last
  // process holds none.
  std::vector<double> all(997);
  for (unsigned int i = 0; i < all.size(); ++i)
    all[i] =
      (i % 50 == 0) ? 0. : std::pow(10., -6. * std::fmod(0.618034 * i, 1.));
  for (unsigned int i = 0; i + 1 < all.size(); i += 7)
    all[i + 1] = all[i];
  std::vector<double> here;
  for (unsigned int i = 0; i < all.size(); ++i)
    if (n_procs > 1 && (i / 7) % (n_procs - 1) == rank)
      here.push_back(all[i]);

  AdaptationParameters parameters;
  for (const auto marking : {MarkingType::fraction, MarkingType::doerfler})
    for (const double fraction : {0.01, 0.3, 0.5, 0.9, 1.})
    {
      // (Doerfler at 1 is every non-zero cell, where the target is the
      // total itself: no margin to check.)
      if (marking == MarkingType::doerfler && fraction == 1.)
        continue;
      parameters.marking  = marking;
      parameters.fraction = fraction;
      const double sorted =
        joint_marking_threshold(all, parameters, MPI_COMM_SELF);
      const double distributed =
        joint_marking_threshold(here, parameters, world);
      const std::string what =
        std::string(marking == MarkingType::fraction ? "fraction "
                                                     : "doerfler ") +
        std::to_string(fraction);
      if (root)
        std::cout << what << ": threshold " << sorted << " (one process), "
                  << distributed << " (" << n_procs << " processes)"
                  << std::endl;
      // Doerfler's sums are added in another order over the processes: the
      // same cell is chosen unless a partial sum lies within round-off of
      // the target. Here the nearest one is far from it (checked), so the
      // thresholds must be the same number.
      if (marking == MarkingType::doerfler)
      {
        std::vector<double> squares(all.size());
        std::transform(all.begin(),
                       all.end(),
                       squares.begin(),
                       [](const double v) { return v * v; });
        std::sort(squares.begin(), squares.end(), std::greater<double>());
        const double total =
          std::accumulate(squares.begin(), squares.end(), 0.);
        double sum = 0, margin = total;
        for (const double s : squares)
        {
          sum += s;
          margin = std::min(margin, std::abs(sum - fraction * total));
        }
        check(margin > 1e-12 * total,
              what + ": no partial sum within round-off of the target");
      }
      check(sorted == distributed,
            what + ": the same threshold on every number of processes");
      check(Utilities::MPI::max(distributed, world) ==
              Utilities::MPI::min(distributed, world),
            what + ": the same threshold on every process");
    }
  return root ? report() : (failures == 0 ? 0 : 1);
}
