#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <ddcontact/adaptivity/marking.h>
#include <ddcontact/tasks.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>

namespace ddcontact
{
  void
  mark_above_delta(Triangulation<2>           &tria,
                   const Vector<double>       &eta,
                   const AdaptationParameters &parameters)
  {
    AssertDimension(eta.size(), tria.n_active_cells());
    Assert(parameters.marking == MarkingType::threshold, ExcInternalError());
    // p4est takes the flags of the owned cells only.
    const bool forest =
      dynamic_cast<parallel::distributed::Triangulation<2> *>(&tria) != nullptr;
    for (const auto &cell : tria.active_cell_iterators())
    {
      cell->clear_refine_flag();
      if ((!forest || cell->is_locally_owned()) &&
          eta(cell->active_cell_index()) > parameters.delta)
        cell->set_refine_flag();
    }
  }

  namespace
  {
    /** The threshold from all contributions, sorted (one process). */
    double
    sorted_threshold(std::vector<double>         values,
                     const AdaptationParameters &parameters)
    {
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

    std::uint64_t
    bits_of(const double x)
    {
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      return b;
    }

    double
    value_of(const std::uint64_t b)
    {
      double x;
      std::memcpy(&x, &b, sizeof x);
      return x;
    }

    /**
     * The largest t in [0, @p largest] with @p measure(t) >= @p target,
     * for a measure that does not grow with t and that changes only at the
     * values (so t is one of them, or 0): a bisection over the bit
     * patterns of non-negative doubles, which are ordered as the doubles
     * are. measure(0) >= target is assumed. Every process computes the
     * same measures (exact counts, or ordered_sum()), hence the same t.
     */
    double
    largest_value_with(const std::function<double(double)> &measure,
                       const double                         target,
                       const double                         largest)
    {
      std::uint64_t lo = 0, hi = bits_of(largest);
      if (measure(largest) >= target)
        return largest;
      // measure(lo) >= target > measure(hi)
      while (hi - lo > 1)
      {
        const std::uint64_t mid = lo + (hi - lo) / 2;
        if (measure(value_of(mid)) >= target)
          lo = mid;
        else
          hi = mid;
      }
      return value_of(lo);
    }

    /** The largest of all processes' (non-negative) @p values, 0 for
     * none. */
    double
    largest_over(const std::vector<double> &values, const MPI_Comm comm)
    {
      return Utilities::MPI::max(
        values.empty() ? 0. : *std::max_element(values.begin(), values.end()),
        comm);
    }

    /** The n-th largest of the processes' @p values (at most @p largest):
     * the largest t with n values at or above it (counts are exact, and
     * the same on every process). */
    double
    nth_largest(const std::vector<double> &values,
                const unsigned long long   n,
                const double               largest,
                const MPI_Comm             comm)
    {
      const auto count_from = [&](const double t)
      {
        const unsigned long long here = std::count_if(
          values.begin(), values.end(), [t](const double v) { return v >= t; });
        return static_cast<double>(Utilities::MPI::sum(here, comm));
      };
      return largest_value_with(count_from, static_cast<double>(n), largest);
    }

    /** The threshold of sorted_threshold() from the processes' values,
     * by bisection (see joint_marking_threshold()). */
    double
    distributed_threshold(const std::vector<double>  &values,
                          const AdaptationParameters &parameters,
                          const MPI_Comm              comm)
    {
      const auto n_values =
        Utilities::MPI::sum<unsigned long long>(values.size(), comm);
      const double largest = largest_over(values, comm);
      if (n_values == 0)
        return std::numeric_limits<double>::infinity();

      if (parameters.marking == MarkingType::fraction)
      {
        const auto n = static_cast<unsigned long long>(
          std::round(parameters.fraction * n_values));
        if (n == 0)
          return std::numeric_limits<double>::infinity();
        return nth_largest(values, n, largest, comm);
      }
      // Doerfler: the largest t whose values at or above it carry the
      // Fraction of the squared total.
      const auto squares_from = [&](const double t)
      {
        double here = 0;
        for (const double v : values)
          if (v >= t)
            here += v * v;
        return ordered_sum(here, comm);
      };
      const double total = squares_from(0.);
      if (!(total > 0))
        return std::numeric_limits<double>::infinity();
      const double t =
        largest_value_with(squares_from, parameters.fraction * total, largest);
      return t > 0 ? t : std::numeric_limits<double>::infinity();
    }
  } // namespace

  double
  joint_marking_threshold(const std::vector<double>  &counted_here,
                          const AdaptationParameters &parameters,
                          const MPI_Comm              communicator)
  {
    Assert(parameters.marking != MarkingType::threshold, ExcInternalError());
    return Utilities::MPI::n_mpi_processes(communicator) == 1
             ? sorted_threshold(counted_here, parameters)
             : distributed_threshold(counted_here, parameters, communicator);
  }

  std::vector<bool>
  keep_largest(const std::vector<double> &values,
               const std::vector<CellId> &cells,
               const unsigned long long   n,
               const MPI_Comm             comm)
  {
    AssertDimension(values.size(), cells.size());
    const auto n_values =
      Utilities::MPI::sum<unsigned long long>(values.size(), comm);
    if (n_values <= n)
      return std::vector<bool>(values.size(), true);
    std::vector<bool> keep(values.size(), false);
    if (n == 0)
      return keep;
    const double largest = largest_over(values, comm);
    const double t       = nth_largest(values, n, largest, comm);
    // Every value above t is kept (fewer than n); of those at t, the
    // first in CellId order make up the n.
    unsigned long long  above = 0;
    std::vector<CellId> tied_here;
    for (unsigned int i = 0; i < values.size(); ++i)
      if (values[i] > t)
      {
        keep[i] = true;
        ++above;
      }
      else if (values[i] == t)
        tied_here.push_back(cells[i]);
    above = Utilities::MPI::sum(above, comm);
    std::vector<CellId> tied;
    for (const auto &from : Utilities::MPI::all_gather(comm, tied_here))
      tied.insert(tied.end(), from.begin(), from.end());
    std::sort(tied.begin(), tied.end());
    Assert(above < n && above + tied.size() >= n, ExcInternalError());
    tied.resize(n - above);
    for (unsigned int i = 0; i < values.size(); ++i)
      if (values[i] == t &&
          std::binary_search(tied.begin(), tied.end(), cells[i]))
        keep[i] = true;
    return keep;
  }
} // namespace ddcontact
