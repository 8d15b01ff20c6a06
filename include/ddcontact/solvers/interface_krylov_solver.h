#ifndef ddcontact_interface_krylov_solver_h
#define ddcontact_interface_krylov_solver_h

#include <ddcontact/contact/contact_interface.h>
#include <ddcontact/contact/contact_problem.h>
#include <ddcontact/solvers/rigid_mode_coarse_space.h>
#include <ddcontact/solvers/robin_preconditioner.h>

#include <vector>

namespace ddcontact
{
  /**
   * The linear system of one Newton step of dd-newton on its active
   * unknowns A (closed normals and sticking tangentials):
   *   (Theta + S)_AA x_A = d_0,A - (Theta + S)_AF x_F,
   * x_F fixed off A. Every iteration applies S once: one set of body
   * solves (ContactInterface::apply()), so the Krylov methods are ours:
   * each keeps the bodies' response to its directions, and the increment
   * comes with S x and the displacements without another set of solves.
   *
   * Symmetric (no coupled slip): preconditioned CG in (.,.)_M, the
   * preconditioner the bodies' Robin problems (RobinPreconditioner) or, in
   * the soft stages of the penalty continuation, Theta^{-1}; with floating
   * bodies x is first put in equilibrium and the CG is projected
   * (RigidModeCoarseSpace, FETI).
   *
   * With a slipping Coulomb node's t_i coupled to its pressure,
   * t_i = sigma_i mu_i p_i (Coulomb linearization = newton), the operator
   * R_A (Theta + S) E (E extends y on A by the coupled tangentials) is not
   * symmetric: GMRES, right preconditioned by the Robin problems, in the
   * inner product of M (deal.II's SolverGMRES does not hand out its Krylov
   * basis).
   */
  class InterfaceKrylovSolver
  {
  public:
    /** The system of a step. */
    struct Step
    {
      const std::vector<bool> &active; // A
      const PointVector       &data;   // d_0
      /** sigma_i mu_i of the nodes whose t_i follows p_i, else 0 (one per
       * node; empty without friction). */
      const PointVector &coupling;
      /** Theta^{-1} instead of the Robin problems (soft stages). */
      bool penalty_preconditioner;
    };

    /** The CG stops after at most this many iterations (a safeguard; the
     * counts are tens). */
    static constexpr unsigned int max_cg_iterations = 500;

    /** GMRES keeps at most this many directions, each with the bodies'
     * response: the step goes on with what they give (the counts are a
     * few per step). */
    static constexpr unsigned int max_gmres_directions = 50;

    InterfaceKrylovSolver(const ContactInterface &interface,
                          RobinPreconditioner    &preconditioner,
                          RigidModeCoarseSpace   &coarse);

    /** Solve @p step from @p x (which holds the fixed values off A) until
     * the residual's M-norm is at most @p tolerance; @p Sx = S x and
     * @p u_x, the bodies' response to x, follow x. Returns the CG
     * iterations, or GMRES's sets of body solves. */
    unsigned int
    solve(const Step              &step,
          double                   tolerance,
          PointVector             &x,
          PointVector             &Sx,
          ContactProblem::Iterate &u_x) const;

    /** Whether the last solve() reached its tolerance: a CG stopped at
     * max_cg_iterations above it is no Newton step (a singular or
     * indefinite system), a GMRES at max_gmres_directions an inexact one. */
    bool
    met_tolerance() const
    {
      return last_met_tolerance;
    }

    /** Whether the last solve() ran GMRES (a coupled slip), not CG. */
    bool
    used_gmres() const
    {
      return last_used_gmres;
    }

    /** The M-norm of the last solve()'s final residual. */
    double
    final_residual() const
    {
      return last_residual;
    }

  private:
    /** GMRES on the coupled system; returns its sets of body solves. */
    unsigned int
    gmres(const Step              &step,
          double                   tolerance,
          PointVector             &x,
          PointVector             &Sx,
          ContactProblem::Iterate &u_x) const;

    /** (Theta + S) y on the rows of @p active, zero on the others, from y
     * and S y: the operator of a Newton step. */
    PointVector
    operator_on_active(const std::vector<bool> &active,
                       const PointVector       &y,
                       const PointVector       &Sy) const;

    /** The step's residual d_0 - (Theta + S) x on the rows of A, zero on
     * the others. */
    PointVector
    active_residual(const Step        &step,
                    const PointVector &x,
                    const PointVector &Sx) const;

    const ContactInterface &interface;
    RobinPreconditioner    &preconditioner;
    RigidModeCoarseSpace   &coarse;
    mutable bool            last_met_tolerance = true;
    mutable double          last_residual      = 0;
    mutable bool            last_used_gmres    = false;
  };
} // namespace ddcontact

#endif
