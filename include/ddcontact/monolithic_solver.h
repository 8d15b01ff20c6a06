#ifndef ddcontact_monolithic_solver_h
#define ddcontact_monolithic_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <ddcontact/contact_pair.h>
#include <ddcontact/elastic_body.h>
#include <ddcontact/parameters.h>

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
    MonolithicContactSolver(const std::vector<ElasticBody<2> *> &bodies,
                            const std::vector<ContactPair *>    &pairs,
                            unsigned int                         max_iterations,
                            ConditionalOStream                  &pcout);

    /** Solve from the bodies' current solutions (the initial active set);
     * writes the result into them and returns the Newton iterations. With
     * the augmented Lagrangian's multipliers lambda (one vector per pair,
     * empty for none) the pressure is min(0, lambda + g/theta), i.e. the
     * penalty problem with the gap shifted to f_n + theta lambda. */
    unsigned int
    run(const std::vector<std::vector<double>> &multipliers = {});

  private:
    std::vector<ElasticBody<2> *> bodies;
    std::vector<ContactPair *>    pairs;
    const unsigned int            max_iterations;
    ConditionalOStream           &pcout;
  };
} // namespace ddcontact

#endif
