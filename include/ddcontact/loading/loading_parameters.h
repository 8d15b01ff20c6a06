#ifndef ddcontact_loading_parameters_h
#define ddcontact_loading_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The subsection Loading: the load parameter t of the boundary data runs
   * from 0 to 1 in quasi-static load steps. A fixed number of steps
   * (t = k / Steps), or Steps = auto, where LoadStepControl chooses the
   * steps so that the estimated load-path error of a path-dependent
   * (frictional) solution stays below Path tolerance.
   */
  struct LoadingParameters
  {
    /** Steps = auto. */
    bool automatic = false;
    /** Steps = N: the number of steps (1 with auto until it chooses). */
    unsigned int n_steps = 1;
    /** Path tolerance: the load-path error allowed in a step, relative
     * (LoadPathMeasures::difference()). */
    double path_tolerance = 1e-3;
    /** Check path: with a fixed number of steps, estimate each step's
     * load-path error as well (two half steps beside it). */
    bool check_path = false;
    /** Max splits: Steps = auto halves a step of the whole path at most
     * this often (the smallest step is 2^-max_splits). */
    unsigned int max_splits = 10;

    static void
    declare(ParameterHandler &prm);

    /** Throws InputError naming the entry. */
    void
    parse(const ParameterHandler &prm);

    /** "auto" or the number of steps, as Loading/Steps writes it. */
    std::string
    steps_text() const;

    /** The load times at which the bodies check their boundary data when
     * they are set up: every k / Steps, or with auto every multiple of
     * 1/64 (the steps it may choose are dyadic; a finer check would cost
     * more than the setup). */
    unsigned int
    n_checked_load_times() const
    {
      return automatic ? 64 : n_steps;
    }
  };
} // namespace ddcontact

#endif
