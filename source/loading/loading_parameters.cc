#include <ddcontact/loading/loading_parameters.h>
#include <ddcontact/parameter_tools.h>

#include <cstdlib>

namespace ddcontact
{
  void
  LoadingParameters::declare(ParameterHandler &prm)
  {
    // Steps is "auto" or a whole number; the pattern admits any text so
    // that parse() names the entry and both forms in its message.
    prm.declare_entry(
      "Steps",
      "1",
      Patterns::Anything(),
      "Quasi-static load steps: the Dirichlet, Neumann and body-force "
      "expressions may use the load parameter t, which runs from 0 to 1. "
      "A number N (1 to 100000): the steps t = k / N, k = 1, ..., N (t = 1 "
      "with one step). auto: with friction, the steps are chosen so that "
      "the estimated load-path error stays below Path tolerance (each step "
      "is compared with two half steps and split while they differ; "
      "doc/friction.md); without friction the solution does not depend on "
      "the path and auto takes one step. Each step is solved from the "
      "last (warm start); with friction the slip and the tangential "
      "traction carry over from step to step. Every step writes its output "
      "(bodies-<step>.vtu in the PVD time series, "
      "contact_<pair>_step<k>.csv).");
    prm.declare_entry(
      "Path tolerance",
      "1e-3",
      Patterns::Double(0),
      "Steps = auto: the load-path error allowed in a step, relative: "
      "the change of the tangential traction when the step is solved in "
      "two halves, over the largest slip bound (mu p or g), and the change "
      "of the dissipated energy over the bound force times the zone's "
      "largest relative displacement (normal approach or slip). "
      "summary.json gives the sum "
      "over the steps (load_path/path_error), a bound of the whole path's "
      "error.");
    prm.declare_entry(
      "Check path",
      "false",
      Patterns::Bool(),
      "With a fixed number of Steps and friction: estimate the load-path "
      "error of every step as Steps = auto does (the step is solved again "
      "in two halves, which costs three solves per step; the halves' "
      "solution is kept) and warn where it exceeds Path tolerance.");
    prm.declare_entry("Max splits",
                      "10",
                      Patterns::Integer(1, 20),
                      "Steps = auto: the smallest step is 2^-(Max splits); "
                      "a step that still exceeds the tolerance there is "
                      "accepted with a warning. At most 20 (a million "
                      "steps of the smallest length; Steps takes 100000).");
  }

  void
  LoadingParameters::parse(const ParameterHandler &prm)
  {
    const std::string steps = prm.get("Steps");
    automatic               = (steps == "auto");
    if (!automatic)
    {
      char      *end    = nullptr;
      const long number = std::strtol(steps.c_str(), &end, 10);
      if (steps.empty() || *end != '\0' || number < 1 || number > 100000)
        throw InputError("Loading/Steps: '" + steps +
                         "' is neither auto nor a whole number of steps "
                         "from 1 to 100000");
      n_steps = static_cast<unsigned int>(number);
    }
    else
      n_steps = 1;
    path_tolerance = prm.get_double("Path tolerance");
    if (!(path_tolerance > 0))
      throw InputError("Loading/Path tolerance: must be positive (the "
                       "allowed relative load-path error), not " +
                       prm.get("Path tolerance"));
    check_path = prm.get_bool("Check path");
    max_splits = prm.get_integer("Max splits");
  }

  std::string
  LoadingParameters::steps_text() const
  {
    return automatic ? "auto" : std::to_string(n_steps);
  }
} // namespace ddcontact
