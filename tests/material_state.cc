// DESCRIPTION: The quadrature-point state of a path-dependent material law
// (QuadraturePointHistory, issue 61), with a law of one state variable
// defined here: new cells start from the law's initial state; a trial
// state is committed, restored, and a snapshot (committed and trial) taken
// and returned to; under refinement a child takes its parent's mean state
// and a coarsened parent the mean of its children's, so that the
// area-weighted mean of the state over the mesh is conserved exactly
// through a refinement and a coarsening (children of equal area); cells a
// process does not hold have no state.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <ddcontact/body/quadrature_point_history.h>

#include "test_tools.h"

#include <cmath>
#include <numeric>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** A law with one state variable, initially 7 (only its state matters
   * here). */
  class OneVariableLaw : public MaterialLaw
  {
  public:
    std::string
    name() const override
    {
      return "one-variable";
    }
    bool
    is_linear() const override
    {
      return false;
    }
    bool
    is_path_dependent() const override
    {
      return true;
    }
    unsigned int
    n_state_variables() const override
    {
      return 1;
    }
    void
    initial_state(const ArrayView<double> &state) const override
    {
      for (double &s : state)
        s = 7.;
    }
    const ElasticConstants &
    elastic_constants() const override
    {
      return constants;
    }
    void
    evaluate(const ArrayView<const SymmetricTensor<2, 3>> &,
             const ArrayView<const double> &,
             const ArrayView<SymmetricTensor<2, 3>> &,
             std::vector<MaterialTangent> *,
             const ArrayView<double> &) const override
    {
    }

  private:
    ElasticConstants constants;
  };

  using History = QuadraturePointHistory<2>;

  /** The area-weighted mean of the committed state over the mesh. */
  double
  mean_state(const Triangulation<2> &tria, const History &history)
  {
    double              sum = 0, area = 0;
    std::vector<double> values;
    for (const auto &cell : tria.active_cell_iterators())
    {
      history.get_committed(cell, values);
      double cell_mean = 0;
      for (const double v : values)
        cell_mean += v / values.size();
      sum += cell_mean * cell->measure();
      area += cell->measure();
    }
    return sum / area;
  }
} // namespace

int
main()
{
  Triangulation<2> tria;
  GridGenerator::hyper_cube(tria, 0., 1.);
  tria.refine_global(2);
  const OneVariableLaw law;
  const unsigned int   n_points = 4;
  History              history;
  const auto           all = [](const History::CellIterator &cell)
  { return cell->is_active(); };
  history.setup(tria, law, n_points, all);
  check(!history.empty(), "a law with state has a history");

  std::vector<double> values;
  bool                initial = true;
  for (const auto &cell : tria.active_cell_iterators())
  {
    history.get_committed(cell, values);
    for (const double v : values)
      initial = initial && v == 7.;
  }
  check(initial, "every point starts from the law's initial state");

  // A trial state that differs per cell and point: v = index + q / 10.
  const auto trial_of = [&](const History::CellIterator &cell)
  {
    std::vector<double> v(n_points);
    for (unsigned int q = 0; q < n_points; ++q)
      v[q] = cell->active_cell_index() + 0.1 * q;
    return v;
  };
  for (const auto &cell : tria.active_cell_iterators())
    history.set_trial(cell, make_array_view(trial_of(cell)));
  bool committed_kept = true;
  for (const auto &cell : tria.active_cell_iterators())
  {
    history.get_committed(cell, values);
    committed_kept = committed_kept && values[0] == 7.;
  }
  check(committed_kept, "an iterate's trial state leaves the committed one");

  const History::Snapshot before_commit = history.snapshot();
  history.commit();
  bool committed = true;
  for (const auto &cell : tria.active_cell_iterators())
  {
    history.get_committed(cell, values);
    committed = committed && values == trial_of(cell);
  }
  check(committed, "commit(): the trial state becomes the committed one");

  // A new trial, then restore(): back to the committed state.
  for (const auto &cell : tria.active_cell_iterators())
    history.set_trial(cell,
                      make_array_view(std::vector<double>(n_points, -1.)));
  history.restore();
  bool restored = true;
  for (const auto &cell : tria.active_cell_iterators())
  {
    history.get_trial(cell, values);
    restored = restored && values == trial_of(cell);
  }
  check(restored, "restore(): the trial state back to the committed one");

  // The snapshot taken before the commit: committed 7, trial as set.
  history.restore(before_commit);
  bool returned = true;
  for (const auto &cell : tria.active_cell_iterators())
  {
    history.get_committed(cell, values);
    returned = returned && values == std::vector<double>(n_points, 7.);
    history.get_trial(cell, values);
    returned = returned && values == trial_of(cell);
  }
  check(returned, "restore(snapshot): committed and trial states as taken");
  history.commit();

  // Refine two cells: their children take the parent's mean.
  const double             mean_0 = mean_state(tria, history);
  std::map<CellId, double> parent_mean;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->active_cell_index() % 7 == 3)
    {
      cell->set_refine_flag();
      history.get_committed(cell, values);
      parent_mean[cell->id()] =
        std::accumulate(values.begin(), values.end(), 0.) / n_points;
    }
  tria.prepare_coarsening_and_refinement();
  history.prepare_for_refinement();
  tria.execute_coarsening_and_refinement();
  history.transfer_after_refinement();
  history.setup(tria, law, n_points, all);
  double child_error = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->level() == 3)
    {
      history.get_committed(cell, values);
      for (const double v : values)
        child_error = std::max(
          child_error, std::abs(v - parent_mean.at(cell->parent()->id())));
      history.get_trial(cell, values);
      for (const double v : values)
        child_error = std::max(
          child_error, std::abs(v - parent_mean.at(cell->parent()->id())));
    }
  check("children take their parent's mean state", child_error, 0.);
  check("refinement conserves the mean state",
        std::abs(mean_state(tria, history) - mean_0) / mean_0,
        1e-14);

  // Give the children distinct states, then coarsen them again.
  for (const auto &cell : tria.active_cell_iterators())
    history.set_trial(cell, make_array_view(trial_of(cell)));
  history.commit();
  const double mean_1 = mean_state(tria, history);
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->level() == 3)
      cell->set_coarsen_flag();
  tria.prepare_coarsening_and_refinement();
  history.prepare_for_refinement();
  tria.execute_coarsening_and_refinement();
  history.transfer_after_refinement();
  history.setup(tria, law, n_points, all);
  check(tria.n_levels() == 3, "the refined cells are coarsened again");
  check("coarsening conserves the mean state",
        std::abs(mean_state(tria, history) - mean_1) / mean_1,
        1e-14);

  // Cells a process does not hold get no state.
  Triangulation<2> other;
  GridGenerator::hyper_cube(other, 0., 1.);
  other.refine_global(1);
  History    half;
  const auto left = [](const History::CellIterator &cell)
  { return cell->is_active() && cell->center()[0] < 0.5; };
  half.setup(other, law, n_points, left);
  bool only_left = true;
  for (const auto &cell : other.active_cell_iterators())
    if (left(cell))
    {
      half.get_committed(cell, values);
      only_left = only_left && values.size() == n_points;
    }
  half.commit();
  half.restore();
  check(only_left && half.snapshot().committed.size() == 2,
        "a history of the cells a process holds only");
  return report();
}
