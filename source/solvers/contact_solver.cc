#include <ddcontact/contact/elastic_layer_guess.h>
#include <ddcontact/interruption.h>
#include <ddcontact/parameter_messages.h>
#include <ddcontact/parameter_tools.h>
#include <ddcontact/solvers/contact_solver.h>
#include <ddcontact/solvers/dd_newton_solver.h>
#include <ddcontact/solvers/monolithic_solver.h>
#include <ddcontact/solvers/neumann_dd_solver.h>
#include <ddcontact/tasks.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ddcontact
{
  ContactSolver::ContactSolver(const ContactSolverParameters       &parameters,
                               const std::vector<ElasticBody<2> *> &bodies,
                               const std::vector<ContactPair *>    &pairs,
                               const BodyDistribution &distribution,
                               ConditionalOStream     &pcout)
    : parameters(parameters)
    , problem(bodies, pairs, distribution)
    , uzawa(this->parameters, pcout)
    , pcout(pcout)
    , published(pairs.size())
  {
  }

  namespace
  {
    /** A solver's factory. */
    template <typename SolverType>
    std::unique_ptr<ContactSolver>
    make_solver(const ContactSolverParameters       &parameters,
                const std::vector<ElasticBody<2> *> &bodies,
                const std::vector<ContactPair *>    &pairs,
                const BodyDistribution              &distribution,
                ConditionalOStream                  &pcout)
    {
      return std::make_unique<SolverType>(
        parameters, bodies, pairs, distribution, pcout);
    }

    using SolverFactory =
      std::unique_ptr<ContactSolver> (*)(const ContactSolverParameters &,
                                         const std::vector<ElasticBody<2> *> &,
                                         const std::vector<ContactPair *> &,
                                         const BodyDistribution &,
                                         ConditionalOStream &);

    /** A registered solver: its entry value, its factory, what it can
     * take and its description (Contact solver/Solver's documentation). */
    struct SolverEntry
    {
      const char        *name;
      SolverFactory      factory;
      SolverCapabilities can;
      const char        *description;
    };

    /** The registered solvers, one row each: a new solver is its header,
     * its source, its row here and its test. Capabilities: friction,
     * floating bodies, pressure on the nodes, exact contact on the nodes,
     * (the same only with friction), auto = points for the Uzawa loop,
     * single steps, several processes, nonlinear material laws. */
    const std::vector<SolverEntry> solvers = {
      {"dd-newton",
       &make_solver<DDNewtonSolver>,
       {true, true, true, true, true, false, true, true, true},
       "semismooth Newton on the contact pressure of (20), "
       "whose linear systems are solved by preconditioned CG with one set "
       "of body solves per iteration (doc/contact-solvers.md)"},
      {"monolithic",
       &make_solver<MonolithicContactSolver>,
       {true, false, true, false, true, true, false, false, true},
       "semismooth Newton on the penalised problem (16) for all bodies at "
       "once (the reference)"},
      {"dd",
       &make_solver<NeumannDDSolver>,
       {false, false, false, false, false, false, true, true, true},
       "the paper's parallel Neumann domain decomposition (20)-(21) with "
       "the relaxation of the subsection Domain decomposition, kept for "
       "reproducing the paper (and needed when a body is solved by a "
       "process group)"}};

    const SolverEntry &
    entry_of(const std::string &solver)
    {
      for (const auto &entry : solvers)
        if (entry.name == solver)
          return entry;
      AssertThrow(false, ExcMessage("unknown contact solver " + solver));
      return solvers.front();
    }
  } // namespace

  Patterns::Selection
  contact_solver_pattern()
  {
    std::string names;
    for (const auto &entry : solvers)
      names += (names.empty() ? "" : "|") + std::string(entry.name);
    return Patterns::Selection(names);
  }

  std::string
  contact_solver_documentation()
  {
    const std::string default_solver = ContactSolverParameters().solver;
    std::string       text;
    for (const auto &entry : solvers)
      text += (text.empty() ? "" : "; ") + std::string(entry.name) +
              (entry.name == default_solver ? " (the default): " : ": ") +
              entry.description;
    return text + ".";
  }

  const SolverCapabilities &
  capabilities_of(const std::string &solver)
  {
    return entry_of(solver).can;
  }

  std::string
  solvers_with(bool SolverCapabilities::*capability)
  {
    std::vector<std::string> names;
    for (const auto &entry : solvers)
      if (entry.can.*capability)
        names.emplace_back(entry.name);
    return parameter_messages::alternatives(names);
  }

  std::unique_ptr<ContactSolver>
  ContactSolver::create(const ContactSolverParameters       &parameters,
                        const std::vector<ElasticBody<2> *> &bodies,
                        const std::vector<ContactPair *>    &pairs,
                        const BodyDistribution              &distribution,
                        ConditionalOStream                  &pcout)
  {
    // A floating body's equilibrium is a constraint on the contact
    // pressure that only dd-newton's coarse problem imposes, and that
    // carries the normal approach only.
    const auto &entry = entry_of(parameters.solver);
    if (!entry.can.floating_bodies)
      refuse_floating_bodies(
        bodies,
        "; only Contact solver/Solver = " +
          solvers_with(&SolverCapabilities::floating_bodies) +
          " solves floating bodies, not " + parameters.solver);
    else if (parameters.friction)
      refuse_floating_bodies(bodies,
                             ", and " + parameters.solver +
                               " solves floating bodies without friction "
                               "only; hold the body by a Dirichlet "
                               "condition, or set Friction = none on its "
                               "contact pairs");
    return entry.factory(parameters, bodies, pairs, distribution, pcout);
  }

  void
  ContactSolver::refuse_floating_bodies(
    const std::vector<ElasticBody<2> *> &bodies, const std::string &reason)
  {
    for (const auto *body : bodies)
      if (body->is_floating())
        throw InputError("Body " + body->name() +
                         "/Dirichlet: the body is floating (its Dirichlet "
                         "conditions leave its " +
                         body->get_rigid_modes().description() + ")" + reason);
  }

  void
  ContactSolver::set_initial_guess()
  {
    auto u = problem.zero_iterate();
    if (parameters.initial_guess == InitialGuess::elastic_layer)
    {
      auto guess = elastic_layer_guess(problem);
      if (!guess.accepted)
        pcout << "  elastic-layer initial guess is worse than zero here ("
              << guess.step_ratio
              << " times the first step); starting from zero" << std::endl;
      u = std::move(guess.u);
    }
    const auto &bodies = problem.get_bodies();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->get_solution() = u[b];
  }

  void
  ContactSolver::continue_load_step()
  {
    if (auto *friction = friction_history())
      friction->continue_load_step();
    start_load_step();
  }

  void
  ContactSolver::start_load_step()
  {
    for (ElasticBody<2> *body : problem.get_bodies())
      body->get_material_state().commit();
    reinit_after_refinement();
  }

  LoadStepStart
  ContactSolver::load_step_start() const
  {
    LoadStepStart start;
    // friction_history() is not const: it hands out the solver's own
    // history, which this copies and does not change.
    if (const auto *friction =
          const_cast<ContactSolver *>(this)->friction_history())
      start.friction = *friction;
    for (const ElasticBody<2> *body : problem.get_bodies())
      start.bodies.push_back(body->get_material_state().snapshot());
    return start;
  }

  void
  ContactSolver::return_to_load_step_start(const LoadStepStart &start)
  {
    if (auto *friction = friction_history())
      *friction = start.friction;
    const auto &bodies = problem.get_bodies();
    AssertDimension(start.bodies.size(), bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->get_material_state().restore(start.bodies[b]);
  }

  void
  ContactSolver::initialize()
  {
    records.clear();
    problem.reset_laws();
    published.assign(problem.get_pairs().size(), PairSolution());
    uzawa.reset();
    start_phase();
    timer.restart();
  }

  void
  ContactSolver::start_phase()
  {
    phase_start = records.size();
  }

  bool
  ContactSolver::start_uzawa_phase()
  {
    if (!uzawa.update(problem))
      return false;
    start_phase();
    return true;
  }

  void
  ContactSolver::add_record(const IterationRecord &record)
  {
    records.push_back(record);
    if (iteration_callback)
    {
      complete_iterate();
      iteration_callback(record.iteration);
    }
    // SIGINT/SIGTERM: stop here, with this iteration recorded.
    interruption::check("contact iteration " +
                        std::to_string(record.iteration));
  }

  void
  ContactSolver::measure_contact(const ContactProblem::Iterate &u,
                                 IterationRecord               &record) const
  {
    for (unsigned int p = 0; p < problem.get_pairs().size(); ++p)
    {
      const auto state = problem.contact_state(p, u);
      record.force += state.normal_force;
      record.active_length += state.contact_length;
      record.max_penetration =
        std::max(record.max_penetration, state.max_penetration);
    }
  }

  std::string
  ContactSolver::penalty_entries() const
  {
    std::string entries;
    for (const auto *pair : problem.get_pairs())
      entries += (entries.empty() ? "" : ", ") +
                 ("Contact pair " + pair->name() + "/Penalty");
    return entries;
  }

  void
  ContactSolver::reinit_after_refinement()
  {
    for (unsigned int p = 0; p < problem.get_pairs().size(); ++p)
      problem.law(p).transfer_to_new_points();
    uzawa.start_mesh();
    last_sigma_n.clear();
    last_u_tilde.clear();
    // The residual jumps with the new mesh: divergence is judged anew.
    start_phase();
  }

  void
  ContactSolver::adopt_current_iterate()
  {
    last_u_tilde = problem.current_iterate();
    last_sigma_n.resize(problem.get_pairs().size());
    for (unsigned int p = 0; p < last_sigma_n.size(); ++p)
      last_sigma_n[p] = problem.pressure(p, last_u_tilde);
  }

  const BodyVector &
  ContactSolver::last_body_solution(const ElasticBody<2> &body) const
  {
    Assert(last_u_tilde.size() == problem.get_bodies().size(),
           ExcMessage("step() must be called first"));
    return last_u_tilde[problem.body_index(body)];
  }

  BoundaryTractionSamples
  ContactSolver::last_contact_traction(const ElasticBody<2> &body) const
  {
    const auto &pairs = problem.get_pairs();
    Assert(last_sigma_n.size() == pairs.size(),
           ExcMessage("step() must be called first"));
    BoundaryTractionSamples samples;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (&pairs[p]->get_body_1() == &body || &pairs[p]->get_body_2() == &body)
      {
        // With friction the tangential traction too (the FEM problem's
        // whole contact load).
        const auto &t = published[p].friction.t;
        pairs[p]->add_traction_samples(
          last_sigma_n[p],
          body,
          samples,
          t.size() == last_sigma_n[p].size() ? t : std::vector<double>());
      }
    return samples;
  }

  double
  ContactSolver::estimate_gamma_limit() const
  {
    // Power iteration on the linearised DD operator with every contact
    // point active: v -> A^{-1} (1/theta) C^T C v, whose largest eigenvalue
    // lambda_max gives the stability limit of (21), gamma* = 2/(1 +
    // lambda_max) (the spectrum of I + A^{-1} J'' lies in [1, 1 +
    // lambda_max]).
    const auto             &bodies = problem.get_bodies();
    ContactProblem::Iterate base, v(bodies.size()), w;
    // Nonlinear bodies: the operator of their tangents (of the last solve,
    // or the elastic stiffness before any), by homogeneous solves, which
    // leave the bodies' states alone.
    const bool tangent = problem.has_nonlinear_bodies();
    if (tangent)
      base = problem.zero_iterate();
    else
      problem.solve_all(ContactProblem::Iterate(bodies.size()), base);
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      v[b] = bodies[b]->get_solution();
      v[b] -= base[b];
      // Scaled by its largest entry first: a diverged iterate (1e200)
      // would overflow the sums of squares below; a non-finite one is
      // replaced by a generic start vector.
      const double largest = v[b].linfty_norm();
      if (largest > 0 && std::isfinite(largest))
        v[b] /= largest;
      else
        for (const auto i : v[b].locally_owned_elements())
          v[b](i) = 1. + 0.1 * std::sin(1. + i);
      bodies[b]->get_constraints().set_zero(v[b]);
      // The contact points read v at the traces, among a distributed
      // body's ghosts: set_zero() and the start vector wrote owned entries.
      if (bodies[b]->has_distributed_vectors())
        v[b].update_ghost_values();
    }
    double lambda = 0;
    for (unsigned int it = 0; it < 30; ++it)
    {
      auto loads = problem.zero_iterate();
      for (const auto *pair : problem.get_pairs())
      {
        const unsigned int  b1 = problem.body_index(pair->get_body_1());
        const unsigned int  b2 = problem.body_index(pair->get_body_2());
        std::vector<double> u_1n, u_2n;
        pair->normal_displacements(v[b1], v[b2], u_1n, u_2n);
        std::vector<double> sigma(u_1n.size());
        for (unsigned int q = 0; q < sigma.size(); ++q)
          sigma[q] = -(u_1n[q] + u_2n[q]) / pair->penalty();
        pair->add_contact_loads(sigma, loads[b1], loads[b2]);
      }
      problem.solve_all(loads, w, tangent);
      double norm_v = 0, norm_w = 0;
      for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        w[b] -= base[b];
        w[b] *= -1.;
        norm_v += ordered_norm_sqr(v[b]);
        norm_w += ordered_norm_sqr(w[b]);
      }
      if (norm_w == 0 || norm_v == 0)
        break;
      lambda = std::sqrt(norm_w / norm_v);
      for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        v[b] = w[b];
        v[b] /= std::sqrt(norm_w);
      }
    }
    return 2. / (1. + lambda);
  }

  bool
  ContactSolver::completing(const std::function<bool()> &work)
  {
    // The errors that every process meets at the same step (from the
    // replicated contact data, or agreed over MPI): the last iterate is
    // then written for diagnosis, so it must be whole too.
    bool result = false;
    try
    {
      result = work();
    }
    catch (const DivergenceError &)
    {
      complete_iterate();
      throw;
    }
    catch (const InterruptedError &)
    {
      complete_iterate();
      throw;
    }
    complete_iterate();
    return result;
  }

  bool
  ContactSolver::checked_step(const std::string &loop)
  {
    if (records.size() >= parameters.max_iterations)
      stop_at_iteration_limit(loop);
    return step();
  }

  bool
  ContactSolver::step_within_limit(const std::string &loop)
  {
    return completing([&]() { return checked_step(loop); });
  }

  unsigned int
  ContactSolver::run()
  {
    // The augmented Lagrangian's outer loop around the solver's own; the
    // whole iterate is exchanged once, at the end.
    completing(
      [&]()
      {
        do
          while (!checked_step("the domain decomposition"))
            ;
        while (start_uzawa_phase());
        return true;
      });
    return records.size();
  }

  void
  ContactSolver::publish_nodal_law(const ContactInterface        &interface,
                                   const PointVector             &x,
                                   const ContactProblem::Iterate &u)
  {
    if (!interface.on_nodes())
      return;
    // The monolithic solver keeps its tangential unknowns itself, after
    // the pressures, with the same test functions.
    const unsigned int n     = interface.size();
    const auto         loads = interface.normal_stresses(
      PointVector(x.begin(), x.begin() + std::min<std::size_t>(n, x.size())));
    const auto tractions = (x.size() == 2 * n)
                             ? interface.tangential_tractions(x)
                             : std::vector<std::vector<double>>();
    // The weak gaps of the bodies' own displacements, not the solver's
    // S p: an independent evaluation of the law at the nodes.
    const PointVector d = interface.penetration(u);
    for (unsigned int k = 0; k < published.size(); ++k)
    {
      auto &solution        = published[k];
      solution.load_sigma_n = loads[k];
      solution.load_t =
        tractions.empty() ? std::vector<double>() : tractions[k];
      solution.nodal_pressure.clear();
      solution.nodal_gap.clear();
      solution.nodal_penalty.clear();
    }
    for (unsigned int i = 0; i < n; ++i)
    {
      auto &solution = published[interface.shares(i)[0].pair];
      solution.nodal_pressure.push_back(x[i]);
      solution.nodal_gap.push_back(d[i]);
      solution.nodal_penalty.push_back(interface.penalty(i));
    }
  }

  ContactState
  ContactSolver::contact_state(const unsigned int p) const
  {
    return problem.contact_state(p, problem.current_iterate(), &published[p]);
  }
} // namespace ddcontact
