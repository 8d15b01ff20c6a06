#ifndef ddcontact_marking_h
#define ddcontact_marking_h

#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/adaptivity/adaptation_parameters.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Set the refine flags of the cells of @p triangulation that the rule of
   * Adaptation/Marking selects from @p eta (one value per active cell):
   * the indicators (27) for threshold, the cells' error contributions
   * (ErrorEstimator::error_contributions()) for the others:
   *  - threshold: eta(e) > delta, the rule of (27) in the paper;
   *  - fraction: the Fraction of the cells with the largest eta;
   *  - doerfler: the fewest cells whose eta^2 sum to the Fraction of the
   *    total (bulk marking: the error is the l2 sum of the cells').
   * Other flags are cleared first. On a distributed mesh every process
   * holds eta of its own cells, and fraction and Doerfler marking search
   * their threshold over all processes. A new rule is one case here.
   */
  void
  mark_cells(Triangulation<2>           &triangulation,
             const Vector<double>       &eta,
             const AdaptationParameters &parameters);

  /**
   * Fraction or Doerfler marking over the cells of several bodies at once
   * (@p contributions: one vector per body, the cells' error
   * contributions in common units): the value at and above which a cell is
   * refined, so that the error is balanced between the bodies instead of
   * each body refining the same share of its own error. Infinity when no
   * cell is to be refined.
   */
  double
  joint_marking_threshold(
    const std::vector<const Vector<double> *> &contributions,
    const AdaptationParameters                &parameters);
} // namespace ddcontact

#endif
