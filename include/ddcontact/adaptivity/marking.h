#ifndef ddcontact_marking_h
#define ddcontact_marking_h

#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/adaptivity/adaptation_parameters.h>

#include <mpi.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Set the refine flags of the cells of @p triangulation whose indicator
   * (27) @p eta (one value per active cell) is above Adaptation/Delta: the
   * rule of the paper (Marking = threshold). Other flags are cleared
   * first; a distributed mesh flags its own cells.
   */
  void
  mark_above_delta(Triangulation<2>           &triangulation,
                   const Vector<double>       &eta,
                   const AdaptationParameters &parameters);

  /**
   * Fraction or Doerfler marking over the cells of all adapted bodies at
   * once: the value at and above which a cell's error contribution
   * (ErrorEstimator::error_contributions(), in common units) is refined,
   * so that the error is balanced between the bodies instead of each body
   * refining the same share of its own error. Infinity when no cell is to
   * be refined.
   *  - fraction: the round(Fraction N) largest of the N contributions;
   *  - doerfler: the fewest cells whose squared contributions sum to the
   *    Fraction of the total (bulk marking: the error is the l2 sum of the
   *    cells').
   *
   * @p counted_here are the contributions this process counts, and
   * @p communicator the processes that together count every cell once. On
   * one process the values are sorted; over several the same value is
   * found by bisection on the bit patterns of the (non-negative)
   * contributions with exact global counts, about 64 reductions and no
   * gather: fraction marking selects the same cells as on one process,
   * Doerfler's sums differ by round-off in the order of summation.
   */
  double
  joint_marking_threshold(const std::vector<double>  &counted_here,
                          const AdaptationParameters &parameters,
                          MPI_Comm                    communicator);

  /**
   * Which of @p values (this process's, one per cell @p cells) are among
   * the @p n largest over all processes of @p communicator: those above
   * the n-th largest value, and of the cells at it as many as are
   * missing, in the order of their CellId (a cell's place in the
   * hierarchy, the same on one process and on a p4est mesh, where cell
   * indices differ). Used to keep the flagged cells that fit in
   * Adaptation/Max cells. The n-th largest is found as in
   * joint_marking_threshold(); the tied cells' ids are gathered.
   */
  std::vector<bool>
  keep_largest(const std::vector<double> &values,
               const std::vector<CellId> &cells,
               unsigned long long         n,
               MPI_Comm                   communicator);
} // namespace ddcontact

#endif
