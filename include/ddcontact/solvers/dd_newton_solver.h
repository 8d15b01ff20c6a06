#ifndef ddcontact_dd_newton_solver_h
#define ddcontact_dd_newton_solver_h

#include <ddcontact/solvers/contact_interface.h>
#include <ddcontact/solvers/contact_solver.h>
#include <ddcontact/solvers/friction_history.h>
#include <ddcontact/solvers/rigid_mode_coarse_space.h>
#include <ddcontact/solvers/robin_preconditioner.h>

#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Contact solver/Solver = dd-newton: the penalty contact (20)
   * solved body by body by a semismooth Newton method on the contact
   * pressure p = -sigma_n at the contact points (ContactInterface).
   *
   * With the penetration d(p) = d_0 - S p of the bodies solved under p,
   * the law (20), theta p = max(0, d(p)), is the complementarity problem
   *   p >= 0,  lambda = (Theta + S) p - d_0 >= 0,  p lambda = 0,
   * the optimality system of the dual of (15), min_{p >= 0}
   * (1/2) (p, (Theta + S) p)_W - (d_0, p)_W. The semismooth Newton method on
   * Phi(p) = min(c p, lambda) = 0 (c = theta + w (1 - nu^2)/E summed over
   * both bodies, ContactInterface::complementarity_scale(): with c = theta
   * a tension p < 0 at a point counted only theta |p|, invisible for small
   * theta) is a primal-dual active-set method: on the active set
   * A = {d(p) + (c - theta) p > 0} solve
   *   (Theta + S_AA) p_A = d_0,A,   p = 0 off A,
   * by conjugate gradients in (.,.)_W, preconditioned by the bodies' Robin
   * problems (RobinPreconditioner), warm-started from the last p. Every CG
   * iteration applies S once: one set of body solves, each body on its own
   * (concurrently, on its process) with its factorization, loaded on its
   * contact zones -- the structure of the paper's DD, whose "DD iteration"
   * is that set of solves. d(p) and the bodies' displacements follow from
   * the CG recursions by linearity, without further solves. The inner
   * tolerance is 0.1 of the Newton residual while the active set changes
   * and the final one once it has settled. A step that does not reduce
   * ||Phi||_W is damped (p + tau (p_new - p), tau halved; free, since d is
   * affine in p).
   *
   * step() is one Newton step, what the combined algorithm of Fig. 2 calls
   * between two adaptation steps; the stopping test is ||Phi(p)||_W <=
   * Tolerance ||max(0, d_0)||_W (the overlap of the bodies without
   * contact pressure).
   *
   * With Contact pair/Formulation = exact the solver takes exact contact
   * directly: theta = 0 and the unknowns are one multiplier per node of
   * S_1 (ContactInterface's nodal space, W replaced by the lumped weights
   * M), so that S_AA is positive definite and the same Newton steps
   * converge; no Uzawa loop runs. The pressure is then the piecewise
   * linear multiplier field, handed to the pairs' laws
   * (ContactLaw::set_contact_pressure()) for the output and the
   * estimator.
   *
   * Penalty continuation (Penalty continuation = true, from zero pressure
   * on zones that overlap on at least 100 unknowns): started from the
   * overlap, a primal-dual active-set method releases about one unknown at
   * each end of a zone per step, because the tension of a too-wide zone
   * sits in a layer of about an element; the steps grow like 1/h (paper
   * scene, exact contact: 19 sets of body solves at refinement 2, 50 at
   * 5). The stages theta + t theta_ref, t = 1, 1e-2, ... (theta_ref the
   * compliance of both bodies across their thickness, or across the
   * overlap where that is shorter), spread that layer over t theta_ref E:
   * each stage's active set settles in a few steps and starts the next,
   * down to the pairs' own theta once t theta_ref is below an element's
   * compliance (the path following of Hintermueller and Kunisch for the
   * Moreau-Yosida regularised problem, here the penalty (15) itself).
   * A stage ends when at most 1 % of its active set changes, with loose
   * inner solves; only the last one is converged. Paper scene, exact
   * contact, refinement 3, 4, 5: 26, 24, 25 sets (without: 35, 39, 50).
   *
   * Floating bodies (held only by contact, ElasticBody::is_floating()) are
   * solved with a few components clamped, and their rigid modes enter as a
   * coarse problem (RigidModeCoarseSpace): the penetration is d_0 - S p +
   * G alpha, and every Newton step solves for p and the modes' amplitudes
   * alpha with the bodies' equilibrium as a constraint, by projected CG
   * (FETI). An active set too small to hold the modes is completed by the
   * unknowns nearest to contact.
   *
   * **Friction** (Contact pair/Friction = tresca or coulomb,
   * doc/friction.md section 4.2): a tangential multiplier t_i per node
   * beside p_i (ContactInterface with friction: the unknowns (p, t), S
   * the response of the normal approach and of the slip to both). Every
   * node is open, sticks or slips, decided from the trial traction as in
   * MonolithicContactSolver: a sticking node's row is
   * S_tn p + (Theta + S_tt) t = s_0 - s_old + theta t_old (the slip
   * increment is the penalty's elastic slip, zero for exact contact), a
   * slipping node's t_i is fixed at sigma_i times its bound. On a set of
   * states the step is again (Theta + S_AA) x_A = b_A - (Theta + S)_AF x_F
   * on the active unknowns A (closed normals and sticking tangentials),
   * x_F fixed: symmetric, solved by the same preconditioned CG (the Robin
   * problems get springs along tau at the sticking nodes), one set of body
   * solves per iteration. Tresca's bound g_i is a datum. Coulomb's
   * mu_i p_i is taken at the current iterate's trial pressure and updated
   * at every Newton step (a fixed point on the slip bound inside the
   * semismooth Newton method): the operator stays symmetric, and for
   * elastically similar bodies (S_nt = 0) p does not depend on t, so the
   * fixed point is exact once p has converged. The first step of a load
   * step lets every closed node stick. Floating bodies are refused with
   * friction (the coarse space carries the normal approach only).
   */
  class DDNewtonSolver : public ContactSolver
  {
  public:
    using ContactSolver::ContactSolver;

    /** dd-newton solves floating bodies too (its coarse space), but not
     * with friction: InputError then. */
    static void
    check_scene(const ContactSolverParameters       &parameters,
                const std::vector<ElasticBody<2> *> &bodies);

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

    /** The continuation's stage @p t if it is still much softer than the
     * pairs' own theta and than an element's compliance somewhere
     * (t theta_ref,q larger than ten times the first and than the second),
     * else 0: below, the springs' boundary layer at the zone's ends is
     * narrower than an element, and the active set is that of the pairs'
     * theta to a node. */
    double
    continuation_stage(double t) const;

    /** The first stage of the penalty continuation, once d_0 is known. */
    void
    start_continuation();

    /** Go on to the continuation's stage @p t (0: the pairs' own theta):
     * the interface's theta and the preconditioner's springs. */
    void
    enter_stage(double t);

    /** The tolerance of ||Phi||_W at the iterate @p x: Tolerance of the
     * overlap, and on the points at most 1e-3 of ||Theta x||_W (the
     * pressure to 0.1 %). */
    double
    stopping_tolerance(const PointVector &x) const;

    /** Whether the continuation's theta dominates S so much that Theta^{-1}
     * preconditions better than the Robin problems (soft stages). */
    bool
    penalty_dominates() const;

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

    /**
     * Preconditioned CG on (Theta + S_AA) x_A = d_0,A from x (zero off
     * @p active) until ||r||_W <= @p tolerance; @p Sx = S x and @p u_x,
     * the bodies' response to x, follow x. Returns the iterations. With
     * floating bodies x is first put in equilibrium, and the CG is
     * projected (RigidModeCoarseSpace).
     */
    unsigned int
    solve_active_system(const std::vector<bool> &active,
                        double                   tolerance,
                        PointVector             &x,
                        PointVector             &Sx,
                        ContactProblem::Iterate &u_x);

    /**
     * The Newton step with Coulomb linearization = newton: as
     * solve_active_system(), but a slipping Coulomb node's t follows its
     * pressure, t_i = sigma_i mu_i p_i (`slip_coupling`), instead of
     * being fixed. The rows of the active set then see the slipping
     * tangentials through S: the step's operator R_A (Theta + S) E (E
     * extends y on the active set by the coupled tangentials) is not
     * symmetric. GMRES solves it, right preconditioned by the Robin
     * problems of the active set, in the inner product of M. It is our
     * own (deal.II's SolverGMRES does not hand out its Krylov basis): each
     * direction keeps the bodies' response, so the increment comes with S
     * x and the displacements without another set of body solves. Returns
     * the sets of body solves.
     */
    unsigned int
    solve_coupled_system(const std::vector<bool> &active,
                         double                   tolerance,
                         PointVector             &x,
                         PointVector             &Sx,
                         ContactProblem::Iterate &u_x);

    /** (Theta + S) y on the rows of @p active, zero on the others, from y
     * and S y: the operator of a Newton step. */
    PointVector
    operator_on_active(const std::vector<bool> &active,
                       const PointVector       &y,
                       const PointVector       &Sy) const;

    /** The step's residual d_0 - (Theta + S) x on the rows of @p active,
     * zero on the others. */
    PointVector
    active_residual(const std::vector<bool> &active,
                    const PointVector       &x,
                    const PointVector       &Sx) const;

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

    RobinPreconditioner  preconditioner{problem};
    RigidModeCoarseSpace coarse{problem, interface};
    bool                 mesh_ready = false; // interface, u_0, S p
    bool same_mesh   = false; // a load step: the preconditioner is kept
    bool phase_ready = false; // d_0 with the multipliers

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
    bool continuation_pending = false; // start_continuation() at next step

    unsigned int n_data_solves     = 0;
    unsigned int n_factorizations  = 0; // of the preconditioner, all meshes
    unsigned int krylov_iterations = 0;
  };
} // namespace ddcontact

#endif
