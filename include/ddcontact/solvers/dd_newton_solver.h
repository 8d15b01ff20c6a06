#ifndef ddcontact_dd_newton_solver_h
#define ddcontact_dd_newton_solver_h

#include <ddcontact/contact/contact_interface.h>
#include <ddcontact/contact/friction_history.h>
#include <ddcontact/solvers/contact_solver.h>
#include <ddcontact/solvers/interface_krylov_solver.h>
#include <ddcontact/solvers/penalty_continuation.h>
#include <ddcontact/solvers/rigid_mode_coarse_space.h>
#include <ddcontact/solvers/robin_preconditioner.h>

#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Contact solver/Solver = dd-newton: contact solved body by body by a
   * semismooth Newton method on the contact multipliers (ContactInterface:
   * one pressure per node of S_1 for exact contact, or per contact point
   * for the penalty (20)).
   *
   * With the penetration d(p) = d_0 - S p of the bodies solved under p,
   * the law is the complementarity problem p >= 0, lambda = (Theta + S) p
   * - d_0 >= 0, p lambda = 0 (the dual of (15)); Newton's method on
   * Phi(p) = min(c p, lambda) (NodalContactLaw, c the complementarity
   * scale) is a primal-dual active-set method. On the active set A it
   * solves (Theta + S_AA) p_A = d_0,A by a Krylov method in which every
   * iteration is one set of independent body solves, the "DD iteration"
   * of the paper's structure (InterfaceKrylovSolver, preconditioned by the
   * bodies' Robin problems). A step that does not reduce ||Phi|| is
   * damped; the stopping test is ||Phi(p)||_W <= Tolerance ||max(0,
   * d_0)||_W. step() is one Newton step, what the combined algorithm of
   * Fig. 2 calls between two adaptation steps.
   *
   * Its parts: the law of the nodes (NodalContactLaw: states, bounds,
   * residuals), the interface Krylov solver, the penalty continuation
   * (PenaltyContinuation), the floating bodies' coarse problem
   * (RigidModeCoarseSpace, FETI: every step solves for p and the rigid
   * modes' amplitudes with the bodies' equilibrium as a constraint) and,
   * with friction, the load steps' history (FrictionHistory: a tangential
   * multiplier per node beside p; the first step of a load step lets every
   * closed node stick or keep its last state). Floating bodies are
   * refused with friction.
   *
   * The method, its choices and measured counts: doc/contact-solvers.md
   * (frictionless) and doc/friction.md section 4.2 (friction).
   */
  class DDNewtonSolver : public ContactSolver
  {
  public:
    using ContactSolver::ContactSolver;

    /** Zero pressure; resets the history and the multipliers. */
    void
    initialize() override;

    /** One Newton step; returns true when ||Phi(p)||_W is below the
     * tolerance. Throws NotConvergedError or DivergenceError after Max
     * Newton iterations on one mesh and multiplier. */
    bool
    step() override;

    [[noreturn]] void
    stop_at_iteration_limit(const std::string &what) const override;

    /** The pressure moves to the new points (nearest old point); the
     * preconditioner and the data are set up again at the next step. */
    void
    reinit_after_refinement() override;

    /** With friction the converged slip and traction of every node
     * become the history of the next step; then as after a refinement. */
    void
    start_load_step() override;

    std::string
    name() const override
    {
      return "dd-newton";
    }

    SolverCounts
    counts() const override;

    bool
    inner_solve_converged() const override
    {
      return krylov.met_tolerance();
    }

    /** Sets of solves with the bodies' stiffness: the bodies' data, and
     * one per application of S. */
    unsigned int
    n_dd_iterations() const override
    {
      return n_data_solves + interface.n_applications();
    }

  private:
    /** The load steps' history (ContactSolver::load_step_start()). */
    FrictionHistory *
    friction_history() override
    {
      return &history;
    }

    /** The data d_0 change with the multipliers: recomputed (without
     * solves) at the next step. */
    void
    start_phase() override;

    /** For new meshes, once the interface has been set up for them
     * (initialize(), reinit_after_refinement()): the preconditioner, the
     * bodies without contact load u_0 (one set of solves), and S p for the
     * transferred pressure. */
    void
    setup_mesh();

    /** Phi(p) = min(c p, Theta p - d) with the penetration d = d_0 - S p +
     * G alpha, for @p p, @p Sp = S p and @p Ga = G alpha; with friction
     * followed by c t - clamp(c t + ds - theta (t - t_old), -c b, c b) at
     * closed nodes of frictional pairs (the trial traction cut to the
     * bound b), c t elsewhere. */
    PointVector
    newton_residual(const PointVector &p,
                    const PointVector &Sp,
                    const PointVector &Ga) const;

    /** The tolerance of ||Phi||_W at the iterate @p x: Tolerance of the
     * overlap, and on the points at most 1e-3 of ||Theta x||_W (the
     * pressure to 0.1 %). */
    double
    stopping_tolerance(const PointVector &x) const;

    /** The unknowns A of the Newton step, from the current iterate;
     * @p n_changed counts those that changed since the last step;
     * `forced` marks those added only to hold the floating modes. With
     * friction the sticking nodes' tangential unknowns are active (with
     * @p stick, the first step of a phase: all closed ones, or those that
     * stuck at the end of the last load step), `slip_directions` holds
     * sigma_i of the slipping ones and `slip_values` sigma_i b_i. */
    std::vector<bool>
    active_set(unsigned int &n_changed, bool stick = false);

    /** The trial values of node @p i at (@p x, @p Sx, @p Gx) for the
     * law (ContactInterface::law()): the penetration d_i = d_0,i - (S x)_i
     * + (G x)_i and, with friction, the slip increment beyond the
     * penalty's ds_i - theta_i (t_i - t_i,old). */
    NodalContactLaw::Trial
    trial(unsigned int       i,
          const PointVector &x,
          const PointVector &Sx,
          const PointVector &Gx) const;

    /** u_p and S p of the current p (one set of homogeneous body solves,
     * none for p = 0). */
    void
    respond_to_pressure();

    /** u_0 + u_p: the bodies' displacement under p by the current model
     * (with a nonlinear body, the warm start of its next Newton loop). */
    ContactProblem::Iterate
    prediction() const;

    /**
     * Bodies of a nonlinear law (plasticity): the affine model d(x) = d_0 -
     * S x of the interface problem, taken at the pressure p. Every body is
     * solved under p (a nonlinear body by its Newton loop, warm-started
     * from @p warm_start, the model's prediction), which leaves its
     * consistent tangent factorized; S is then the Schur complement of the
     * tangents and d_0 = d(u(p)) + S p, so that the model is exact at p
     * and the semismooth Newton step on it is a Newton step of the
     * nonlinear problem. u_p = S-response to p, u_0 = u(p) - u_p.
     */
    void
    relinearize(const ContactProblem::Iterate &warm_start);

    /** For floating bodies: the amplitudes alpha that fit the gaps where
     * the pressure is positive, for the pressure of another mesh or
     * phase (zero if these do not hold the modes). */
    void
    estimate_amplitudes();

    /** alpha = H^{-1} G_A^T M ((Theta + S) x - d_0) on the coarse space's
     * active set, for @p x and @p Sx = S x: the amplitudes that close the
     * gaps there in the least-squares sense. */
    std::vector<double>
    fitted_amplitudes(const PointVector &x, const PointVector &Sx) const;

    /** d_0, its scale and with friction the history's part, for a new
     * phase or linearization (phase_ready false). */
    void
    update_data();

    /** What a step needs before its active set: the data d_0 of a new
     * phase, the continuation's first stage, the floating modes'
     * amplitudes; stops at Max Newton iterations. */
    void
    prepare_step();

    /** DivergenceError where only tension holds the floating modes: the
     * same active set again (@p n_changed = 0), completed by unknowns
     * that pull. */
    void
    check_mechanism(unsigned int n_changed) const;

    /** The start (@p x, @p Sx, @p u_x) of the step's Krylov solve: p,
     * with the unknowns off @p active at their fixed values. */
    void
    warm_start(const std::vector<bool> &active,
               PointVector             &x,
               PointVector             &Sx,
               ContactProblem::Iterate &u_x) const;

    /** The step length tau toward (@p x, @p Sx, @p Gx) from the iterate of
     * residual @p psi: the largest 1, 1/2, ... that reduces ||Phi||_W, 1
     * with @p full_step; @p psi_new the residual there. */
    double
    damping(double             psi,
            bool               full_step,
            const PointVector &x,
            const PointVector &Sx,
            const PointVector &Gx,
            double            &psi_new) const;

    /** p + tau (x - p) with S p, u_p, G alpha and alpha alike; the bodies'
     * solutions and the step's record. With nonlinear bodies relinearized
     * at the new p, and @p psi_new (the model's residual there) replaced
     * by the true one; @p tau halved where a body's Newton loop fails
     * under the step's pressure, or (unless @p full_step) where the true
     * residual does not fall below @p psi, the step's start. */
    IterationRecord
    take_step(double                        &tau,
              const PointVector             &x,
              const PointVector             &Sx,
              const ContactProblem::Iterate &u_x,
              const PointVector             &Gx,
              const std::vector<double>     &alpha_x,
              double                        &psi_new,
              double                         psi,
              bool                           full_step);

    /** The step's line of progress; DivergenceError on a non-finite
     * residual, or where the step's CG stopped at its iteration limit
     * above its tolerance (no Newton step: a singular system). */
    void
    print_step(const IterationRecord   &record,
               const std::vector<bool> &active,
               unsigned int             n_changed,
               unsigned int             cg) const;

    /** The value of the unknown @p q off the active set for the iterate
     * @p x: zero, or a slipping node's sigma b (Coulomb linearization =
     * newton: sigma mu x_i of its pressure). */
    double
    fixed_value(unsigned int q, const PointVector &x) const;

    /** The bodies' solutions u_0 + u_p, and the last loads and body
     * solutions for the estimator (on the processes that do not solve a
     * body only its traces, until complete_iterate()). */
    void
    store_iterate();

    /** The body solves send the other processes only the traces that
     * S x reads (ContactInterface::apply()); here the owners send the
     * whole u~ once, for the estimator, the output and the report. */
    void
    complete_iterate() override;

    /** Whether last_u_tilde is whole on every process: false from
     * store_iterate() until complete_iterate() has sent it, which a second
     * call (the iteration callback, then the end of the step) skips. */
    bool iterate_complete = true;

    ContactInterface interface {
      problem, parameters.multipliers_on_nodes(), parameters.exact_contact(),
        parameters.friction, parameters.dual_multipliers
    };
    FrictionHistory history;

    RobinPreconditioner   preconditioner{problem};
    RigidModeCoarseSpace  coarse{problem, interface};
    PenaltyContinuation   continuation{interface, preconditioner, pcout};
    InterfaceKrylovSolver krylov{interface, preconditioner, coarse};
    bool                  mesh_ready = false; // interface, u_0, S p
    bool same_mesh     = false; // a load step: the preconditioner is kept
    bool phase_ready   = false; // d_0 with the multipliers
    bool nonlinear     = false; // a body of a nonlinear law: relinearize()
    bool keep_scale    = false; // d_0 of a new linearization, not a new phase
    bool tangent_start = false; // nonlinear, from p = 0: no relinearize() yet

    ContactProblem::Iterate u_0;       // the bodies under their data alone
    PointVector             d_0;       // its penetration
    double                  scale = 0; // ||max(0, d_0)||_W
    PointVector             p, Sp;     // the pressure and S p
    ContactProblem::Iterate u_p;       // the bodies' response to p
    std::vector<bool>       last_active;
    PointVector             slip_values;     // sigma_i b_i, 0: not slipping
    PointVector             slip_coupling;   // sigma_i mu_i (newton), or 0
    std::vector<int>        slip_directions; // sigma_i, 0: not slipping
    std::vector<int>        last_slip_directions;
    std::vector<int>        step_slip_directions; // end of the last step
    std::vector<bool>       forced; // active only to hold floating modes
    std::vector<double>     alpha;  // floating modes' amplitudes
    PointVector             Ga;     // G alpha
    bool                    alpha_stale = false; // estimate_amplitudes()
    bool                    balanced    = true;  // p in equilibrium

    unsigned int n_data_solves     = 0;
    unsigned int n_factorizations  = 0; // of the preconditioner, all meshes
    unsigned int krylov_iterations = 0;
  };
} // namespace ddcontact

#endif
