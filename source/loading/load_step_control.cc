#include <deal.II/base/exceptions.h>

#include <ddcontact/loading/load_step_control.h>

namespace ddcontact
{
  LoadStepControl::LoadStepControl(const double       tolerance,
                                   const unsigned int max_splits)
    : tolerance(tolerance)
    , max_splits(max_splits)
    , n_step(n_total()) // the whole path first
  {
    Assert(max_splits < 8 * sizeof(unsigned long) - 1,
           dealii::ExcIndexRange(max_splits, 0, 8 * sizeof(unsigned long)));
    Assert(tolerance > 0, dealii::ExcMessage("the tolerance must be positive"));
  }

  double
  LoadStepControl::start() const
  {
    return double(n_done) / n_total();
  }

  double
  LoadStepControl::end() const
  {
    return double(n_done + n_step) / n_total();
  }

  double
  LoadStepControl::length() const
  {
    return double(n_step) / n_total();
  }

  double
  LoadStepControl::allowed_error() const
  {
    return tolerance;
  }

  bool
  LoadStepControl::judge(const double error)
  {
    Assert(!finished(), dealii::ExcInternalError());
    // A NaN error is never within the tolerance (!(error <= ...)).
    const bool within = (error <= allowed_error());
    if (!within && n_step > 1)
    {
      n_step /= 2;
      ++rejected;
      return false;
    }
    steps.push_back({start(), end(), error, !within});
    n_done += n_step;
    if (finished())
      return true;
    // Double the next step where the error leaves room for it (a step's
    // error grows at least like h: like h where a node enters the contact
    // within the step, faster along a smooth slip) and the doubled step
    // starts on its own dyadic grid; never past t = 1.
    if (error <= allowed_error() / 4 && n_done % (2 * n_step) == 0)
      n_step *= 2;
    while (n_done + n_step > n_total())
      n_step /= 2; // ends at 1 at the latest: n_done < n_total
    return true;
  }

  double
  LoadStepControl::path_error() const
  {
    double sum = 0;
    for (const auto &step : steps)
      sum += step.error;
    return sum;
  }
} // namespace ddcontact
