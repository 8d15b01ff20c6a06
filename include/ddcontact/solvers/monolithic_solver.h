#ifndef ddcontact_monolithic_solver_h
#define ddcontact_monolithic_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <ddcontact/contact/contact_problem.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The reference for the domain decomposition: the penalised problem (16)
   * for all bodies at once,
   *   A(u, v) + J'_theta(u, v) - L(v) = 0,
   * solved by a semismooth (active-set) Newton method. J_theta is piecewise
   * quadratic, so on a fixed active set (the contact points with
   * f_n - u_1n - u_2n < 0) one Newton step is one linear solve with the
   * matrix blockdiag(K_a) + (1/theta) sum_active w c c^T, where c holds the
   * normal shape values of both bodies at the point; the method stops when
   * the active set no longer changes, at the exact minimiser of (15).
   */
  class MonolithicContactSolver
  {
  public:
    MonolithicContactSolver(const ContactProblem &problem,
                            unsigned int          max_iterations,
                            ConditionalOStream   &pcout);

    /** Solve from the bodies' current solutions (the initial active set);
     * writes the result into them and returns the Newton iterations. The
     * law of each pair gives the gap shifted by its multipliers,
     * f_n + theta lambda (the augmented Lagrangian's pressure
     * min(0, lambda + g/theta) is the penalty pressure of that gap). */
    unsigned int
    run();

  private:
    const ContactProblem &problem;
    const unsigned int    max_iterations;
    ConditionalOStream   &pcout;
  };
} // namespace ddcontact

#endif
