#ifndef ddcontact_monolithic_solver_h
#define ddcontact_monolithic_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/contact/contact_interface.h>
#include <ddcontact/contact/friction_history.h>
#include <ddcontact/solvers/contact_solver.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Contact solver/Solver = monolithic, the reference for the domain
   * decomposition: the penalised problem (16)
   * for all bodies at once,
   *   A(u, v) + J'_theta(u, v) - L(v) = 0,
   * solved by a semismooth (active-set) Newton method. The penalty is
   *   J_theta(u) = sum_i m_i / (2 theta_i) max(0, d_i(u))^2
   * over the unknowns i of a ContactInterface, each with an affine
   * penetration d_i = g_i . u - f_i and pressure p_i = max(0, d_i) / theta_i:
   *
   * - **points** (the paper's (20)): one term per contact point, m_i its
   *   weight w_q, g_i the normal shape values of both bodies there, f_i
   *   the gap shifted by the augmented Lagrangian's multiplier;
   * - **nodes** (Contact solver/Contact pressure = nodes, the
   *   nodal penalty of dd-newton, doc/contact-solvers.md section 6): one
   *   term per node of S_1 for the averaged gap d_i = (1/m_i) int_S1 psi_i d,
   *   i.e. g_i = sum_q (w_q psi_i(x_q) / m_i) g_q over all dofs of both
   *   bodies in the node's support.
   *
   * J_theta is piecewise quadratic: on a fixed active set one Newton step
   * is one linear solve with the Hessian blockdiag(K_a) + sum_active
   * (m_i / theta_i) g_i g_i^T. On the points that matrix is assembled as it
   * is. On the nodes the same step is solved in its mixed form, with the
   * pressures as unknowns,
   *   K u + sum_active m_i p_i g_i = L,  m_i (g_i . u - theta_i p_i) = m_i f_i
   * (p_i = 0 off the active set): eliminating p gives the Hessian, but the
   * mixed matrix does not degrade like 1/theta, since the nodal pressure is
   * determined by body 1's trace also for theta = 0 (p from d/theta has
   * the round-off eps |u| / (theta p): the Hessian form is 4e-8 off the
   * uniaxial closed form at c = 1e-8, the mixed one 6e-15). The
   * active set is that of dd-newton, {d_i + (c_i - theta_i) p_i > 0} with
   * c_i = ContactInterface::complementarity_scale() (on the points, where
   * p = max(0, d)/theta, it is {d_i > 0}).
   *
   * The method stops when the active set of the solution is the one it was
   * computed with: the exact minimiser of (15). Should the active set
   * return to an earlier one without settling (it cycles), the following
   * steps are damped: (u, p) + tau (u_new - u, p_new - p) with the largest
   * tau = 1, 1/2, ... that reduces the Euclidean norm of the Newton
   * residual (K u - L + sum_i m_i p_i g_i on the unconstrained dofs, and
   * m_i min(p_i, (theta_i p_i - d_i) / c_i), both forces).
   *
   * **Friction** (Contact pair/Friction = tresca or coulomb, on the nodes
   * only; doc/friction.md) adds a tangential multiplier t_i per node, the
   * traction -t_i tau on body 1 (tau = n_1 turned by +90 degrees, t_i >= 0
   * opposing a positive slip of body 1), with the averaged slip s_i(u) =
   * (1/m_i) int_S1 psi_i (u_1 - u_2) . tau = h_i . u and its increment
   * over the load step, ds_i = s_i(u) - s_i,old. Every node is open (p_i =
   * t_i = 0), sticks (ds_i = theta_i (t_i - t_i,old): no slip for exact
   * contact, the penalty's elastic slip otherwise) or slips (t_i =
   * sigma_i b_i, sigma_i = +-1, with the bound b_i = g_i for Tresca and
   * mu_i p_i for Coulomb), decided as in the primal-dual active-set
   * method of Hueber, Stadler and Wohlmuth from the trial traction
   *   t_i + (ds_i - theta_i (t_i - t_i,old)) / c_i
   * against b_i (for Coulomb with the trial pressure p_i + (d_i - theta_i
   * p_i) / c_i). The Newton step of a given set of states is one linear
   * solve, the force rows gaining m_i t_i h_i and each node a row for t_i:
   * symmetric for stick and Tresca's slip, the row t_i - sigma_i mu_i p_i =
   * 0 of Coulomb's slip is not (UMFPACK takes either). The method stops,
   * as without friction, when the states of the solution are those it was
   * computed with: then it solves the discrete problem exactly. With
   * friction Formulation = exact is theta = 0 on the nodes (no Uzawa loop).
   */
  class MonolithicContactSolver : public ContactSolver
  {
  public:
    /** Contact solver/Contact pressure = nodes gives the nodal
     * penalty, otherwise the points; Max Newton iterations limits a
     * solve. */
    MonolithicContactSolver(const ContactSolverParameters       &parameters,
                            const std::vector<ElasticBody<2> *> &bodies,
                            const std::vector<ContactPair *>    &pairs,
                            const BodyDistribution              &distribution,
                            ConditionalOStream                  &pcout);

    /** ContactSolver::initialize() and Contact solver/Initial guess,
     * which gives the first active set. */
    void
    initialize() override;

    /**
     * The whole Newton solve on the current multipliers, from the bodies'
     * current solutions (the initial active set); writes the result into
     * them and records one row of the history. The law of each pair gives
     * the gap shifted by its multipliers, f_n + theta lambda (the
     * augmented Lagrangian's pressure min(0, lambda + g/theta) is the
     * penalty pressure of that gap). On the nodes the pressure p is handed
     * to the pairs' laws (ContactLaw::set_contact_pressure()) for the
     * output, the force and the estimator, as dd-newton does. Returns
     * true (converged) or throws.
     */
    bool
    step() override;

    /** Reached only by Uzawa updates beyond Contact solver/Max
     * iterations (each step is a whole solve), whatever loop the caller
     * names. */
    [[noreturn]] void
    stop_at_iteration_limit(const std::string &what) const override;

    std::string
    name() const override
    {
      return "monolithic";
    }

    /** The converged slip and tangential traction of every node become
     * the history (s_i,old, t_i,old) of the next step. */
    void
    start_load_step() override;

    /** New points: no warm start from the last multipliers. */
    void
    reinit_after_refinement() override;

    /** The Newton steps of all solves; no body solves. */
    SolverCounts
    counts() const override;

    /** No DD iterations: the bodies are solved together. */
    unsigned int
    n_dd_iterations() const override
    {
      return 0;
    }

  private:
    /** The load steps' history (ContactSolver::load_step_start()). */
    FrictionHistory *
    friction_history() override
    {
      return &history;
    }

    /** One term of J_theta: d = sum_j g[j] u(dofs[j]) - f (global dofs);
     * with friction the slip s = sum_j h[j] u(dofs[j]) on the same dofs
     * and the slip and traction at the start of the load step. */
    struct Penetration
    {
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  g, h;
      double                               f      = 0;
      double                               weight = 0; // m_i
      double                               theta  = 0;
      double                               scale  = 0; // c_i
      double                               s_old = 0, t_old = 0;

      double
      operator()(const Vector<double> &u) const;

      double
      slip(const Vector<double> &u) const;
    };

    /** The bodies' constraints in the global numbering, and the offsets. */
    void
    setup_constraints();

    /** The terms of the interface's unknowns, in the global numbering. */
    void
    setup_penetrations();

    /** The couplings of the bodies and of every term's support (and of
     * its pressure, on the nodes). */
    void
    setup_sparsity();

    /** max(0, d_i(@p u)) / theta_i: the pressure of the points. */
    PointVector
    penalty_pressure(const Vector<double> &u) const;

    /** The states of the nodes at (@p u, @p p) in the law
     * (ContactInterface::law()), or, with @p stick, all closed nodes
     * sticking (the first step, whose u and t are no Newton iterate:
     * sticking, the zone finds the direction of every slip from its
     * traction). @p p holds the pressures and, with friction, the
     * tangential tractions after them. */
    std::vector<NodeStatus>
    active_set(const Vector<double> &u,
               const PointVector    &p,
               bool                  stick = false) const;

    /** The trial values of node @p i at (@p u, @p p) for the law. */
    NodalContactLaw::Trial
    trial(unsigned int i, const Vector<double> &u, const PointVector &p) const;

    /** Node @p i's rows and columns in the Newton system on the states
     * @p active at (@p u, @p p): its pressure p_i and, with friction, its
     * tangential traction t_i, with their coupling to the displacements. */
    void
    add_node_rows(unsigned int                   i,
                  const std::vector<NodeStatus> &active,
                  const Vector<double>          &u,
                  const PointVector             &p,
                  SparseMatrix<double>          &matrix,
                  Vector<double>                &rhs) const;

    /** One Newton step on the states @p active: the new @p u and, on
     * the nodes, @p p. */
    void
    solve_linearised(const std::vector<NodeStatus> &active,
                     Vector<double>                &u,
                     PointVector                   &p) const;

    /** The Euclidean norm of the Newton residual of (@p u, @p p). */
    double
    residual_norm(const Vector<double> &u, const PointVector &p) const;

    /** The largest tau = 1, 1/2, ... for which (u, p) + tau (u_new - u,
     * p_new - p) reduces residual_norm(); 1 if none does. */
    double
    damping(const Vector<double> &u,
            const PointVector    &p,
            const Vector<double> &u_new,
            const PointVector    &p_new) const;

    /** Hand the iterate (@p u, @p p) to the bodies and, on the nodes, the
     * pressure and its peak to the contact laws. */
    void
    store_iterate(const Vector<double> &u, const PointVector &p);

    /** The Newton method to a settled active set; returns its steps. */
    unsigned int
    solve_newton();

    /** Prints Newton step @p iteration's counts of closed (and slipping)
     * nodes or points of @p active. */
    void
    print_active_set(unsigned int                   iteration,
                     const std::vector<NodeStatus> &active) const;

    /** The error of an active set not settled in Max Newton iterations:
     * moving still (no set met twice, not @p cycled), or cycling. */
    [[noreturn]] void
    stop_unsettled(bool cycled) const;

    const bool                           on_nodes;
    const bool                           friction; // tangential unknowns
    const unsigned int                   max_iterations;
    unsigned int                         n_newton_steps = 0;
    double                               final_residual = 0;
    ContactInterface                     interface;
    std::vector<types::global_dof_index> offset;
    AffineConstraints<double>            constraints;
    std::vector<Penetration>             penetrations;
    PointVector     last_multipliers;   // p and t of the last solve, on nodes
    bool            warm_start = false; // from last_multipliers (a load step)
    FrictionHistory history;

    SparsityPattern sparsity;
  };
} // namespace ddcontact

#endif
