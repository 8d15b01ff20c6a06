#ifndef ddcontact_load_step_control_h
#define ddcontact_load_step_control_h

#include <vector>

namespace ddcontact
{
  /**
   * The steps of Loading/Steps = auto: dyadic steps [t0, t0 + h] of the
   * load parameter t in [0, 1], h = 2^-m, controlled by step doubling
   * (the step is solved once and again in two halves from the same
   * history; the difference estimates the one step's load-path error e).
   * A step is accepted when e <= tol, otherwise it is halved; after a step
   * with e <= tol / 4 the next may be twice as long (where its start
   * allows a dyadic step of that length). A step of the smallest length
   * 2^-max_splits is accepted whatever its error, and counted as over the
   * tolerance. The sum of the accepted steps' errors bounds the error of
   * the whole path (path_error()).
   *
   * The tolerance holds per step, not per unit load: where a node enters
   * the contact within a step, it sticks from the step's start instead of
   * from its entry, an error of the order of h that a tolerance tol h
   * could meet only at the smallest step. Such errors sit at different
   * nodes, so that the slip's largest error over the path stays near the
   * largest step error.
   *
   * The steps stay dyadic so that a kink of the load path at a dyadic t
   * (a press-then-shear path switching at t = 1/2) is a step end.
   */
  class LoadStepControl
  {
  public:
    LoadStepControl(double tolerance, unsigned int max_splits);

    /** Whether the path has reached t = 1. */
    bool
    finished() const
    {
      return n_done == n_total();
    }

    /** The step to try next: [start(), end()]. */
    double
    start() const;
    double
    end() const;
    double
    length() const;

    /** The error that accepts a step (tol). */
    double
    allowed_error() const;

    /** Judge the current step by its estimated error @p error: returns
     * true when it is accepted (the path advances), false when it is
     * split (the next step is its first half). */
    bool
    judge(double error);

    /** The accepted steps so far. */
    struct Step
    {
      double t_start, t_end, error;
      bool   over_tolerance;
    };
    const std::vector<Step> &
    accepted() const
    {
      return steps;
    }

    unsigned int
    n_rejected() const
    {
      return rejected;
    }

    /** The sum of the accepted steps' errors: the estimated load-path
     * error of the whole path so far. */
    double
    path_error() const;

  private:
    // t and h in units of the smallest step 2^-max_splits, exactly.
    unsigned long
    n_total() const
    {
      return 1ul << max_splits;
    }

    double            tolerance;
    unsigned int      max_splits;
    unsigned long     n_done   = 0; // t0 = n_done / n_total
    unsigned long     n_step   = 0; // h = n_step / n_total
    unsigned int      rejected = 0;
    std::vector<Step> steps;
  };
} // namespace ddcontact

#endif
