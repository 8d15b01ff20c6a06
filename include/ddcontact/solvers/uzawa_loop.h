#ifndef ddcontact_uzawa_loop_h
#define ddcontact_uzawa_loop_h

#include <deal.II/base/conditional_ostream.h>

#include <ddcontact/contact/contact_problem.h>
#include <ddcontact/solvers/contact_solver_parameters.h>

#include <limits>
#include <string>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The augmented Lagrangian's outer (Uzawa) loop around any solver of the
   * penalised problem (20): after the solver has converged for the current
   * multipliers, update(), if the penetration is still above the
   * tolerance, sets lambda <- sigma_n (the converged pressure) in every
   * pair's law, so that the penetration goes to zero without shrinking
   * theta. The DD and the monolithic Newton solver share it.
   */
  class UzawaLoop
  {
  public:
    UzawaLoop(const ContactSolverParameters &parameters,
              ConditionalOStream            &pcout);

    /** A new run: no updates yet. */
    void
    reset()
    {
      n_total = 0;
      start_mesh();
    }

    /** A new mesh: its penetration is judged anew. */
    void
    start_mesh();

    /**
     * Check the converged iterate of @p problem: returns true after
     * updating the multipliers (the solver must run again), false when the
     * penetration met the tolerance, reached the limit of non-matching
     * meshes, or the updates are used up -- then the multipliers are left
     * as they are, so that the iterate and the reported pressure stay
     * consistent. Always false with the penalty formulation.
     */
    bool
    update(ContactProblem &problem);

    /** Empty when the loop is off (or exact contact is solved directly)
     * or met its tolerance on the current iterate; otherwise the one-line
     * message that says how far it is off and what to change, also when
     * it stopped at the limit of non-matching meshes (the run must not say
     * "converged"). */
    std::string
    shortfall(const ContactProblem &problem) const;

    /** Updates over the whole run (all meshes). */
    unsigned int
    n_updates() const
    {
      return n_total;
    }

  private:
    const ContactSolverParameters &parameters;
    ConditionalOStream            &pcout;
    unsigned int                   n_total = 0, n_mesh = 0;
    double first_penetration = 0; // first check of this mesh
    double last_penetration  = std::numeric_limits<double>::max();
    bool   mesh_limited      = false; // the last check stopped there
  };
} // namespace ddcontact

#endif
