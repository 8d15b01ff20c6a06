#ifndef ddcontact_self_checks_h
#define ddcontact_self_checks_h

#include <ddcontact/io/json.h>
#include <ddcontact/io/run_report.h>

#include <string>
#include <vector>

namespace ddcontact
{
  /** One check of SelfChecks: a measured, dimensionless @p value that
   * passes when it is at most @p limit (a NaN fails), where it is worst
   * and what to change when it fails. */
  struct SelfCheck
  {
    std::string name;
    double      value = 0;
    double      limit = 0;
    std::string where;
    std::string advice;

    bool
    passed() const
    {
      return value <= limit;
    }
  };

  /**
   * What a run checks of its own answer before it writes `converged`
   * (issue 59), without a reference solution:
   *
   * - `finite`: the bodies' displacements and the contact forces are
   *   finite numbers (the count of those that are not; limit 0);
   * - `equilibrium`: every body balances its reactions, loads and contact
   *   tractions (force_imbalance: the largest of |sum| / the largest
   *   force, or a millionth of E max|u| (ReactionForces::force_scale());
   *   axial only in axisymmetry), the reactions taken from the tractions
   *   the bodies were loaded with (PairSolution::load_sigma_n). A
   *   pressure at the points, p = max(0, d) / theta of the displacements,
   *   carries the solvers' residual into the forces amplified by
   *   sqrt(N) A / (theta p_mean) (N points, A the zone's displacement,
   *   p_mean the force over the closed area), and the relaxed DD's
   *   iterate trails its last body solves by 1 / gamma: the
   *   limit is that much larger there, and never below 1e-6 (the
   *   round-off that many damped Newton steps leave);
   * - on the nodal multipliers (PairSolution::nodal_pressure) the law (20)
   *   node by node, against the bodies' own weak gaps d_i:
   *   `contact_sign` max (-p_i)+ / max |p|, `contact_gap` max (d_i -
   *   theta_i p_i)+ / A and `complementarity` max p_i (theta_i p_i -
   *   d_i)+ / (max |p| A), A the largest |u_1n| + |u_2n| or slip on the
   *   zone;
   * - with friction at the nodes: `friction_bound` max (|t_i| - b_i)+ /
   *   max b and `slip_at_bound` max |r_i| (b_i - sign(r_i) t_i)+ /
   *   (A max b), r_i the slip beyond the penalty's elastic slip
   *   (FrictionResults::nodal_inelastic_slip): slip only at the bound and
   *   against the traction;
   * - `inner_solves`: 1 when the contact solver's last inner linear solve
   *   stopped above its tolerance (ContactSolver::inner_solve_converged()).
   *
   * The limit of the relative measures is limit_factor times Contact
   * solver/Tolerance (at least round-off): the solvers stop on a relative
   * residual of that size, measured in a norm that sums over the nodes,
   * so no node of a converged answer is far off it.
   */
  class SelfChecks
  {
  public:
    /** The factor on Contact solver/Tolerance of the relative checks. */
    static constexpr double limit_factor = 100;

    /** The checks of the current state of @p results, a run of Contact
     * solver/Tolerance @p tolerance. Collective (the reactions). */
    SelfChecks(const RunReport::Results &results, double tolerance);

    /** The same on the states and reactions @p answer of @p results
     * (RunReport::fix_answer()), computed once for the checks and the
     * report. Collective. */
    SelfChecks(const RunReport::Results &results,
               const RunReport::Answer  &answer,
               double                    tolerance);

    /** Checks built one by one (tests). */
    explicit SelfChecks(std::vector<SelfCheck> checks);

    /** The nodal law's checks of @p solution (sign, gap, complementarity;
     * with friction the bound and the slip) on pair @p pair with the
     * displacements of size @p displacement (the largest |u_1n| + |u_2n|
     * or slip), to @p limit. Empty without nodal
     * multipliers. */
    static std::vector<SelfCheck>
    nodal_law(const PairSolution &solution,
              const std::string  &pair,
              double              displacement,
              double              limit);

    bool
    passed() const;

    /** One line for the first failed check: its name, value, limit, where
     * and what to change; "" when all pass. */
    std::string
    failure() const;

    /** summary.json's `self_checks`: passed, and every check. */
    Json
    json() const;

    const std::vector<SelfCheck> &
    get() const
    {
      return checks;
    }

  private:
    std::vector<SelfCheck> checks;
  };
} // namespace ddcontact

#endif
