#ifndef ddcontact_contact_law_h
#define ddcontact_contact_law_h

#include <deal.II/base/point.h>

#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/nodal_contact_law.h>

#include <algorithm>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** The value at every point of @p to of a function given by its
   * @p values at the points @p from: that of the nearest point (piecewise
   * constant transfer of a pressure or multiplier to new contact points);
   * zero where @p from is empty. */
  std::vector<double>
  nearest_point_values(const std::vector<Point<2>> &from,
                       const std::vector<double>   &values,
                       const std::vector<Point<2>> &to);

  /**
   * The nodal multipliers of exact contact, or another function on S_1
   * in its hat functions (the slip history of friction), on the
   * nodes @p to of a refined zone from their values on the old nodes
   * @p from: linear between the two nearest old nodes where the new node
   * lies between them (a bisected face of S_1), else the nearest node's
   * value. The piecewise constant transfer left every new node with its
   * neighbour's value, and the first Newton step on the new mesh had to
   * be damped to 1/8.
   */
  std::vector<double>
  interpolated_node_values(const std::vector<Point<2>> &from,
                           const std::vector<double>   &values,
                           const std::vector<Point<2>> &to);

  /**
   * The contact law (20) of one pair, at its contact points:
   *   sigma_n = min(0, lambda + g / theta),  g = f_n - u_1n - u_2n,
   * with theta the pair's penalty and lambda the augmented Lagrangian's
   * multiplier of every point (zero without it). This is the only place
   * the law is written; the solvers ask it for pressures, and the Newton
   * solver for the gap that lambda shifts.
   *
   * When dd-newton takes the pressure on the nodes of S_1
   * (ContactSolverParameters::multipliers_on_nodes(): exact contact, or the
   * penalty for the averaged gap) the law holds node by node for the gap
   * averaged with the hat functions, which does not give the pressure pointwise
   * from g: lambda is then the pressure itself, set by the solver
   * (set_contact_pressure()), and the gap is not shifted.
   */
  class ContactLaw
  {
  public:
    explicit ContactLaw(const ContactPair &pair);

    /** lambda = 0 at the pair's current points. */
    void
    reset();

    /** After the pair's points moved (either mesh refined): lambda
     * approximates the contact pressure, a function on S, so each new
     * point takes the value of the nearest old one (piecewise constant
     * transfer). */
    void
    transfer_to_new_points();

    double
    theta() const
    {
      return pair.penalty();
    }

    /** The pressure is the solver's (nodal) multiplier. */
    void
    set_solver_pressure(const bool solver_pressure)
    {
      from_solver = solver_pressure;
    }

    /** (20) at point @p q for the gap function value @p g (the solver's
     * pressure with set_solver_pressure()). */
    double
    pressure(const unsigned int q, const double g) const
    {
      return from_solver ? lambda[q] : std::min(0., lambda[q] + g / theta());
    }

    /** (20) at every point. */
    std::vector<double>
    pressure(const std::vector<double> &g) const;

    /** lambda + g/theta < 0 exactly where u_1n + u_2n exceeds
     * f_n + theta lambda: the gap shifted by the multiplier, for a solver
     * that linearises (20) on its active set. */
    double
    shifted_gap(const unsigned int q) const
    {
      return pair.points()[q].gap + (from_solver ? 0. : theta() * lambda[q]);
    }

    /** The Uzawa update lambda <- sigma_n (the converged pressure). */
    void
    set_multipliers(const std::vector<double> &sigma_n);

    const std::vector<double> &
    multipliers() const
    {
      return lambda;
    }

    /** The solver's pressure: the normal stress sigma_n = -p at the
     * points (with set_solver_pressure()). */
    void
    set_contact_pressure(const std::vector<double> &sigma_n);

  private:
    const ContactPair    &pair;
    std::vector<double>   lambda;
    std::vector<Point<2>> lambda_points;       // where lambda lives
    bool                  from_solver = false; // the solver's pressure
  };
} // namespace ddcontact

#endif
