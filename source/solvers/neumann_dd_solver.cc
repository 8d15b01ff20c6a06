#include <ddcontact/solvers/neumann_dd_solver.h>
#include <ddcontact/tasks.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    double
    norm(const std::vector<double> &v)
    {
      double s = 0;
      for (const double x : v)
        s += x * x;
      return std::sqrt(s);
    }

    double
    distance(const std::vector<double> &v, const std::vector<double> &w)
    {
      double s = 0;
      for (unsigned int i = 0; i < v.size(); ++i)
        s += (v[i] - w[i]) * (v[i] - w[i]);
      return std::sqrt(s);
    }

    /** Whether iteration @p k gets a line on the screen: the first five,
     * then every 10 up to 100, every 100 up to 1000, and so on -- about
     * ten lines per decade, so a run of thousands of iterations shows
     * tens of lines (history.csv keeps every iteration). */
    bool
    shown_on_screen(const unsigned int k)
    {
      unsigned int step = 1;
      while (step * 10 <= k)
        step *= 10;
      return k <= 5 || k % step == 0;
    }

    /** The entries of the bodies' vectors that this process owns (every
     * entry of a whole vector), concatenated body by body: what the
     * relaxation (21) works on. */
    Vector<double>
    flatten(const ContactProblem::Iterate &u)
    {
      std::size_t n = 0;
      for (const auto &v : u)
        n += v.locally_owned_size();
      Vector<double> flat(n);
      std::size_t    offset = 0;
      for (const auto &v : u)
      {
        std::copy(
          v.begin(), v.begin() + v.locally_owned_size(), flat.begin() + offset);
        offset += v.locally_owned_size();
      }
      return flat;
    }

    /** Back into the owned entries of @p u. */
    void
    unflatten(const Vector<double> &flat, ContactProblem::Iterate &u)
    {
      std::size_t offset = 0;
      for (auto &v : u)
      {
        std::copy(flat.begin() + offset,
                  flat.begin() + offset + v.locally_owned_size(),
                  v.begin());
        offset += v.locally_owned_size();
      }
    }

    /** x . y of flattened iterates of the layout of @p u: a whole body's
     * entries added in index order on this process, a distributed body's
     * own entries then over its processes in rank order (ordered_sum()),
     * so that every process finds the same value and takes the same
     * decisions (Anderson's filtering, Aitken's gamma). With whole vectors
     * this is ordered_dot() of the whole iterate, bit for bit. */
    Relaxation::InnerProduct
    inner_product(const ContactProblem::Iterate &u)
    {
      std::vector<std::pair<std::size_t, MPI_Comm>> segments;
      for (const auto &v : u)
        segments.emplace_back(v.locally_owned_size(), v.get_mpi_communicator());
      return [segments](const Vector<double> &x, const Vector<double> &y)
      {
        AssertDimension(x.size(), y.size());
        double      sum    = 0;
        std::size_t offset = 0;
        for (const auto &[n, comm] : segments)
        {
          const auto x0 = x.begin() + offset, y0 = y.begin() + offset;
          if (Utilities::MPI::n_mpi_processes(comm) == 1)
            sum = std::inner_product(x0, x0 + n, y0, sum);
          else
            sum += ordered_sum(std::inner_product(x0, x0 + n, y0, 0.), comm);
          offset += n;
        }
        return sum;
      };
    }
    /** The residual of (20): ||u~ - u|| / ||u~|| of the normal
     * displacements @p un_tilde and @p un on S, over all bodies. */
    double
    relative_residual(const std::vector<std::vector<double>> &un_tilde,
                      const std::vector<std::vector<double>> &un)
    {
      double diff2 = 0, norm2 = 0;
      for (unsigned int b = 0; b < un.size(); ++b)
      {
        diff2 += std::pow(distance(un_tilde[b], un[b]), 2);
        norm2 += std::pow(norm(un_tilde[b]), 2);
      }
      return (norm2 > 0) ? std::sqrt(diff2 / norm2) : std::sqrt(diff2);
    }

    /** The paper's increment: the largest relative change from @p un to
     * @p un_new of the normal displacements on S of a body. */
    double
    largest_relative_increment(const std::vector<std::vector<double>> &un_new,
                               const std::vector<std::vector<double>> &un)
    {
      double increment = 0;
      for (unsigned int b = 0; b < un_new.size(); ++b)
        if (!un_new[b].empty())
        {
          const double n = norm(un_new[b]);
          const double d = distance(un_new[b], un[b]);
          increment      = std::max(increment, (n > 0) ? d / n : d);
        }
      return increment;
    }

    /** One line of the console for a DD iteration. */
    void
    print_record(ConditionalOStream &pcout, const IterationRecord &record)
    {
      pcout << "  DD " << std::setw(5) << record.iteration << std::scientific
            << std::setprecision(3) << "  residual " << record.residual
            << "  increment " << record.increment << "  gamma " << record.gamma
            << "  normal force " << record.force << "  active "
            << record.active_length << "  penetration "
            << record.max_penetration << std::defaultfloat << std::fixed
            << std::setprecision(2) << "  t " << record.time << "s"
            << std::defaultfloat << std::endl;
    }
  } // namespace

  void
  NeumannDDSolver::initialize()
  {
    relaxation->set_gamma(parameters.dd.gamma);
    ContactSolver::initialize();
    set_initial_guess();

    if (parameters.dd.relaxation == RelaxationType::automatic)
    {
      // The optimal fixed gamma for a spectrum in [1, 1 + lambda_max] is
      // 2 / (2 + lambda_max); gamma* = 2 / (1 + lambda_max).
      const double limit      = estimate_gamma_limit();
      const double lambda_max = 2. / limit - 1.;
      relaxation->set_gamma(2. / (2. + lambda_max));
      pcout << "  automatic relaxation: gamma* = " << limit
            << ", gamma = " << relaxation->get_gamma() << std::endl;
    }
  }

  void
  NeumannDDSolver::start_phase()
  {
    relaxation->reset();
    ContactSolver::start_phase();
  }

  void
  NeumannDDSolver::relax(const ContactProblem::Iterate &u_tilde)
  {
    const auto &bodies = problem.get_bodies();
    auto        u      = problem.current_iterate();
    relaxation->set_inner_product(inner_product(u));
    unflatten(relaxation->update(flatten(u), flatten(u_tilde)), u);
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      // A distributed body's ghosts (its locally relevant dofs and the
      // traces) from their owners, collectively over its processes; then
      // the constraints on every stored entry (a ghost's masters are
      // stored too).
      if (bodies[b]->has_distributed_vectors())
        u[b].update_ghost_values();
      bodies[b]->distribute_constraints(u[b]);
      copy_stored(u[b], bodies[b]->get_solution());
    }
  }

  void
  NeumannDDSolver::check_finite_pressure(const unsigned int             p,
                                         const ContactProblem::Iterate &u,
                                         const unsigned int iteration) const
  {
    const auto &sigma = last_sigma_n[p];
    if (std::all_of(sigma.begin(),
                    sigma.end(),
                    [](const double x) { return std::isfinite(x); }))
      return;
    // Either the iterate itself is no longer finite (the iteration
    // diverged), or a finite gap over theta overflowed (theta too small).
    const bool finite_iterate = std::all_of(
      u.begin(),
      u.end(),
      [](const BodyVector &v) { return std::isfinite(v.linfty_norm()); });
    const auto &pair = *problem.get_pairs()[p];
    if (finite_iterate)
    {
      std::ostringstream s;
      s << std::setprecision(3) << "Contact pair " << pair.name()
        << "/Penalty: the contact pressure is not finite at DD iteration "
        << iteration << ": theta = " << pair.penalty()
        << " is so small that gap / theta overflows; raise the Penalty (or "
           "the pair's Thickness)";
      throw InputError(s.str());
    }
    IterationRecord record;
    record.iteration          = iteration;
    record.residual           = std::numeric_limits<double>::quiet_NaN();
    const auto [best, best_k] = best_of_phase();
    throw DivergenceError(
      divergence_message("diverged at iteration " + std::to_string(iteration),
                         record,
                         best,
                         best_k));
  }

  std::pair<double, unsigned int>
  NeumannDDSolver::best_of_phase() const
  {
    double       best   = std::numeric_limits<double>::max();
    unsigned int best_k = 0;
    for (unsigned int i = phase_start; i < records.size(); ++i)
      if (records[i].residual < best)
      {
        best   = records[i].residual;
        best_k = records[i].iteration;
      }
    return {best, best_k};
  }

  bool
  NeumannDDSolver::step()
  {
    const auto &pairs = problem.get_pairs();
    const auto  u     = problem.current_iterate();
    // Nonlinear bodies start their Newton loops from the current iterate.
    ContactProblem::Iterate u_tilde;
    if (problem.has_nonlinear_bodies())
      ContactProblem::assign(u_tilde, u);

    IterationRecord record;
    record.iteration = records.size() + 1;
    measure_contact(u, record);

    last_sigma_n.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      last_sigma_n[p] = problem.pressure(p, u);
      check_finite_pressure(p, u, record.iteration);
    }
    problem.solve_bodies(last_sigma_n, u_tilde);
    ContactProblem::assign(last_u_tilde, u_tilde);
    const auto un       = problem.normal_displacements_by_body(u);
    const auto un_tilde = problem.normal_displacements_by_body(u_tilde);

    record.residual = relative_residual(un_tilde, un);
    record.gamma    = relaxation->get_gamma();

    relax(u_tilde);

    const auto un_new =
      problem.normal_displacements_by_body(problem.current_iterate());
    record.increment = largest_relative_increment(un_new, un);
    record.time      = timer.wall_time();
    add_record(record);

    // The stopping test of Contact solver/Domain decomposition/Stopping test.
    const bool residual_test = record.residual <= parameters.tolerance;
    const bool paper_test =
      record.increment <= parameters.dd.increment_tolerance;
    const bool converged = (parameters.dd.stopping == StoppingTest::residual)
                             ? residual_test
                           : (parameters.dd.stopping == StoppingTest::paper)
                             ? paper_test
                             : residual_test || paper_test;

    // Divergence: a non-finite residual, growth far above the best residual
    // so far, or no progress at all for many iterations (a 2-cycle between
    // overlap and separation, typical for gamma above gamma*).
    const bool finite          = std::isfinite(record.residual);
    const auto [best, best_k]  = best_of_phase();
    const unsigned int k_phase = record.iteration - phase_start;
    const bool         grew    = record.residual > 1e3 * best && k_phase > 3;
    const bool         stuck =
      record.iteration - best_k > std::max<unsigned int>(50, k_phase / 2);
    const bool diverged = !finite || grew || stuck;

    if (parameters.print_every_iteration || shown_on_screen(record.iteration) ||
        converged || diverged)
      print_record(pcout, record);
    if (diverged)
      throw DivergenceError(divergence_message(
        "diverged at iteration " + std::to_string(record.iteration),
        record,
        best,
        best_k));
    return converged;
  }

  std::string
  NeumannDDSolver::divergence_message(const std::string     &event,
                                      const IterationRecord &record,
                                      const double           best,
                                      const unsigned int     best_k) const
  {
    // gamma* = 2/(1 + lambda_max) of the linearised iteration (21) tells
    // what went wrong: the relaxation (gamma above gamma*), the penalty
    // (lambda_max ~ compliance of S / theta so large that no relaxation
    // contracts in a useful number of steps), or the tolerance (the
    // residual cannot fall below round-off times lambda_max).
    const double       limit      = estimate_gamma_limit();
    const double       lambda_max = 2. / limit - 1.;
    std::ostringstream s;
    s << std::setprecision(3) << "the domain decomposition " << event
      << " (residual ";
    if (std::isfinite(record.residual))
      s << record.residual;
    else
      s << "not finite";
    s << ", best " << best << " at iteration " << best_k
      << "; estimated gamma* = " << limit << ")";

    const std::string penalty_entries = this->penalty_entries();

    const double round_off =
      1e3 * std::numeric_limits<double>::epsilon() * (1. + lambda_max);
    if (best <= round_off)
      s << ": the residual stagnates at the round-off level of this problem "
        << "(about " << round_off << " = 1000 eps (1 + lambda_max)); raise "
        << "Contact solver/Tolerance above " << 10 * best;
    else if (limit < 1e-3)
      s << ": the penalty is too stiff for the domain decomposition (the "
        << "contact-zone compliance is " << lambda_max << " times theta, so "
        << "every relaxation contracts by at most about 1 - gamma* per "
        << "iteration); raise " << penalty_entries
        << " (c of theta = c H/E_1) by a factor of about " << lambda_max / 40.
        << " (for gamma* ~ 0.05; with contrasting "
        << "materials, making the softer body Body 1 does the same) and set "
        << "Contact pair <name>/Formulation = exact for an exact "
        << "contact, or use Contact solver/Solver = monolithic";
    else if (parameters.dd.relaxation == RelaxationType::fixed &&
             parameters.dd.gamma > limit)
      s << ": Contact solver/Domain decomposition/Gamma = "
        << parameters.dd.gamma
        << " is above the estimated stable limit gamma*; use Gamma below "
        << limit << " (about " << 2 * limit / (2 + limit)
        << " is fastest) or Relaxation = anderson";
    else if (parameters.dd.relaxation == RelaxationType::fixed)
      s << ": Contact solver/Domain decomposition/Gamma = "
        << parameters.dd.gamma
        << " is below the estimated gamma* of the linearised iteration, but "
        << "the active set oscillates; use a smaller Gamma or Relaxation = "
        << "anderson";
    else
      s << " with Relaxation = " << to_string(parameters.dd.relaxation)
        << "; use Relaxation = fixed with Gamma = " << 2 * limit / (2 + limit)
        << " (below gamma*), or a larger " << penalty_entries;
    return s.str();
  }

  bool
  NeumannDDSolver::start_uzawa_phase()
  {
    if (!ContactSolver::start_uzawa_phase())
      return false;
    // A new phase of the DD with the new multipliers; Aitken's dynamic
    // gamma starts again from the given one.
    if (parameters.dd.relaxation != RelaxationType::automatic)
      relaxation->set_gamma(parameters.dd.gamma);
    return true;
  }

  SolverCounts
  NeumannDDSolver::counts() const
  {
    SolverCounts c;
    c.body_solve_sets = records.size();
    return c;
  }

  void
  NeumannDDSolver::stop_at_iteration_limit(const std::string &what) const
  {
    // Judged on the current phase (a new mesh or Uzawa update makes the
    // residual jump), or on the whole history if the phase is too short.
    const unsigned int n     = records.size();
    const unsigned int first = (n >= phase_start + 2) ? phase_start : 0;
    std::ostringstream s;
    s << std::setprecision(3) << what << " has not converged in " << n
      << " iterations (residual ";
    if (n < first + 2)
    {
      // One iteration: no trend to judge, only a limit set too low.
      s << (n > 0 ? records.back().residual : 0.) << ", Tolerance "
        << parameters.tolerance << "); raise Contact solver/Max iterations";
      throw NotConvergedError(s.str());
    }
    // Falling: the last (at most 10) iterations reached a new best of the
    // phase and ended below where they started. Anderson's residual is not
    // monotone, hence the best of the window rather than every step.
    const unsigned int window      = std::min(10u, n - 1 - first);
    const unsigned int start       = n - 1 - window;
    double             best_before = std::numeric_limits<double>::max();
    double             best_window = best_before;
    for (unsigned int i = first; i <= start; ++i)
      best_before = std::min(best_before, records[i].residual);
    for (unsigned int i = start + 1; i < n; ++i)
      best_window = std::min(best_window, records[i].residual);
    const double r_start = records[start].residual;
    const double r       = records.back().residual;
    if (!(std::isfinite(r) && best_window < best_before && r < r_start))
    {
      // Grown or stagnated: a divergence, with its advice.
      const auto [best, best_k] = best_of_phase();
      throw DivergenceError(divergence_message(
        "made no progress in its last " + std::to_string(window) +
          " iterations before Max iterations = " + std::to_string(n),
        records.back(),
        best,
        best_k));
    }
    s << r << ", falling: " << r_start / r << " times lower than " << window
      << " iterations before; Tolerance " << parameters.tolerance
      << "); raise Contact solver/Max iterations";
    // At the rate of the window, log(eps/r)/log(rate) more iterations
    // reach the residual test (not the paper's increment test).
    if (parameters.dd.stopping != StoppingTest::paper &&
        parameters.tolerance < r)
    {
      const double rate = std::pow(r / r_start, 1. / window);
      s << " (about "
        << static_cast<long long>(
             std::ceil(std::log(parameters.tolerance / r) / std::log(rate)))
        << " more at this rate)";
    }
    if (parameters.dd.relaxation == RelaxationType::anderson)
      s << " or Contact solver/Domain decomposition/Anderson depth";
    else
      s << " or use Relaxation = anderson";
    throw NotConvergedError(s.str());
  }

} // namespace ddcontact
