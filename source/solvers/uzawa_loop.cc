#include <ddcontact/solvers/uzawa_loop.h>

#include <iomanip>
#include <sstream>

namespace ddcontact
{
  UzawaLoop::UzawaLoop(const ContactSolverParameters &parameters,
                       ConditionalOStream            &pcout)
    : parameters(parameters)
    , pcout(pcout)
  {
  }

  void
  UzawaLoop::start_mesh()
  {
    n_mesh           = 0;
    last_penetration = std::numeric_limits<double>::max();
    mesh_limited     = false;
  }

  bool
  UzawaLoop::update(ContactProblem &problem)
  {
    // Exact contact solved directly (dd-newton) needs no updates.
    if (!parameters.exact_formulation || parameters.exact_contact() ||
        n_mesh >= parameters.uzawa.max_updates)
      return false;

    const auto u                        = problem.current_iterate();
    const auto [max_penetration, ratio] = problem.penetration(u);
    pcout << "  Uzawa check " << n_mesh + 1 << ": max penetration "
          << max_penetration << " (" << ratio << " of the approach)"
          << std::endl;
    mesh_limited = false;
    if (ratio <= parameters.uzawa.tolerance)
      return false;
    if (n_mesh == 0)
      first_penetration = max_penetration;
    // With non-matching meshes the pointwise condition at every contact
    // point cannot hold exactly for the discrete displacements: stop when
    // the penetration no longer shrinks, after the updates have removed
    // most of it (a tenth or less of the first check's). A penetration
    // that shrinks slowly from the start (a soft penalty, e.g. c = 100:
    // 3 % per update) is not that limit: the updates go on, up to AL max
    // updates.
    if (max_penetration > 0.9 * last_penetration &&
        max_penetration <= 0.1 * first_penetration)
    {
      mesh_limited = true;
      pcout << "  Uzawa: the penetration no longer decreases (" << ratio
            << " of the approach, Uzawa/Tolerance "
            << parameters.uzawa.tolerance
            << "): the limit of the non-matching zone meshes; stopping"
            << std::endl;
      return false;
    }
    last_penetration = max_penetration;

    // lambda <- min(0, lambda + g/theta) for every pair.
    for (unsigned int p = 0; p < problem.get_pairs().size(); ++p)
      problem.law(p).set_multipliers(problem.pressure(p, u));
    ++n_total;
    ++n_mesh;
    return true;
  }

  std::string
  UzawaLoop::shortfall(const ContactProblem &problem) const
  {
    if (!parameters.exact_formulation || parameters.exact_contact())
      return "";
    const double ratio = problem.penetration(problem.current_iterate()).second;
    if (ratio <= parameters.uzawa.tolerance)
      return "";
    std::ostringstream s;
    if (mesh_limited)
    {
      // Pointwise conditions at the contact points of non-matching meshes
      // cannot all hold: the tolerance is out of reach on this mesh.
      s << std::setprecision(3)
        << "the augmented Lagrangian stopped with a penetration of " << ratio
        << " of the approach, above Contact solver/Uzawa/Tolerance = "
        << parameters.uzawa.tolerance
        << ": the penetration no longer decreases (the limit of pointwise "
           "contact on non-matching zone meshes); results are written with "
           "status \"stalled\". For exact contact use Contact "
           "solver/Solver = dd-newton (multipliers on the nodes of "
           "S_1), or raise Contact solver/Uzawa/Tolerance above "
        << ratio;
      return s.str();
    }
    s << std::setprecision(3)
      << "the augmented Lagrangian stopped with a penetration of " << ratio
      << " of the approach, above Contact solver/Uzawa/Tolerance = "
      << parameters.uzawa.tolerance << ", after " << n_mesh
      << " Uzawa updates on the last mesh (Uzawa/Max updates = "
      << parameters.uzawa.max_updates
      << "); results are written with status \"stalled\". Make the "
         "penalty stiffer (smaller Contact pair/Penalty) so that each "
         "update removes more of the penetration, or raise Contact "
         "solver/Uzawa/Max updates";
    return s.str();
  }
} // namespace ddcontact
