#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/grid/grid_refinement.h>

#include <ddcontact/adaptivity/marking.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace ddcontact
{
  namespace
  {
    /**
     * Flag the cells with the largest @p criteria: a fixed fraction of the
     * cells (@p by_number) or of the sum of the criteria. On a distributed
     * mesh over all processes' cells (deal.II searches the threshold in
     * parallel).
     */
    void
    refine_fixed(Triangulation<2>     &tria,
                 const Vector<double> &criteria,
                 const double          fraction,
                 const bool            by_number)
    {
      namespace distributed = parallel::distributed::GridRefinement;
      if (auto *forest =
            dynamic_cast<parallel::distributed::Triangulation<2> *>(&tria))
      {
        if (by_number)
          distributed::refine_and_coarsen_fixed_number(
            *forest, criteria, fraction, 0.);
        else
          distributed::refine_and_coarsen_fixed_fraction(
            *forest, criteria, fraction, 0.);
      }
      else if (by_number)
        GridRefinement::refine_and_coarsen_fixed_number(
          tria, criteria, fraction, 0.);
      else
        GridRefinement::refine_and_coarsen_fixed_fraction(
          tria, criteria, fraction, 0.);
    }
  } // namespace

  void
  mark_cells(Triangulation<2>           &tria,
             const Vector<double>       &eta,
             const AdaptationParameters &parameters)
  {
    AssertDimension(eta.size(), tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      cell->clear_refine_flag();

    switch (parameters.marking)
    {
      case MarkingType::threshold:
      {
        // p4est takes the flags of the owned cells only.
        const bool forest =
          dynamic_cast<parallel::distributed::Triangulation<2> *>(&tria) !=
          nullptr;
        for (const auto &cell : tria.active_cell_iterators())
          if ((!forest || cell->is_locally_owned()) &&
              eta(cell->active_cell_index()) > parameters.delta)
            cell->set_refine_flag();
        break;
      }
      case MarkingType::fraction:
        refine_fixed(tria, eta, parameters.fraction, true);
        break;
      case MarkingType::doerfler:
      {
        Vector<double> eta2(eta.size());
        for (unsigned int c = 0; c < eta.size(); ++c)
          eta2(c) = eta(c) * eta(c);
        refine_fixed(tria, eta2, parameters.fraction, false);
        break;
      }
    }
  }

  double
  joint_marking_threshold(
    const std::vector<const Vector<double> *> &contributions,
    const AdaptationParameters                &parameters)
  {
    Assert(parameters.marking != MarkingType::threshold, ExcInternalError());
    std::vector<double> values;
    for (const auto *c : contributions)
      values.insert(values.end(), c->begin(), c->end());
    std::sort(values.begin(), values.end(), std::greater<double>());
    if (values.empty())
      return std::numeric_limits<double>::infinity();

    if (parameters.marking == MarkingType::fraction)
    {
      const auto n = static_cast<std::size_t>(
        std::round(parameters.fraction * values.size()));
      return n == 0 ? std::numeric_limits<double>::infinity() : values[n - 1];
    }
    // Doerfler: the fewest cells whose squared contributions reach the
    // Fraction of the total (summed largest first, a fixed order).
    double total = 0;
    for (const double v : values)
      total += v * v;
    double sum = 0;
    for (const double v : values)
    {
      sum += v * v;
      if (sum >= parameters.fraction * total)
        return v > 0 ? v : std::numeric_limits<double>::infinity();
    }
    return values.back();
  }
} // namespace ddcontact
