#include <deal.II/base/mpi.h>

#include <ddcontact/io/self_checks.h>
#include <ddcontact/solvers/contact_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** The largest of @p values' magnitudes. */
    double
    largest_magnitude(const std::vector<double> &values)
    {
      double m = 0;
      for (const double v : values)
        m = std::max(m, std::abs(v));
      return m;
    }

    /** A check whose value is the largest of @p violation(i) over the
     * nodes i < @p n, with the node that gives it. */
    template <typename Violation>
    SelfCheck
    worst_node(const std::string &name,
               const std::string &pair,
               const unsigned int n,
               const double       limit,
               const Violation   &violation)
    {
      SelfCheck    check{name, 0., limit, "", ""};
      unsigned int worst = 0;
      for (unsigned int i = 0; i < n; ++i)
      {
        const double v = violation(i);
        // A NaN is the worst of all.
        if (!(v <= check.value))
        {
          check.value = v;
          worst       = i;
          if (std::isnan(v))
            break;
        }
      }
      check.where =
        "contact pair " + pair + ", node " + std::to_string(worst) + " of S_1";
      return check;
    }

    /** The largest |u_1n| + |u_2n| and |slip| of @p state: the scale of
     * a gap or a slip (not |u_1n + u_2n|, which vanishes where bodies
     * touch with no gap). */
    double
    zone_displacement(const ContactState &state)
    {
      double a = largest_magnitude(state.slip);
      for (unsigned int q = 0; q < state.u_1n.size(); ++q)
        a = std::max(a, std::abs(state.u_1n[q]) + std::abs(state.u_2n[q]));
      return a;
    }

    /** Non-finite entries of @p body's solution stored on this process. */
    unsigned int
    non_finite_entries(const ElasticBody<2> &body)
    {
      const BodyVector &u = body.get_solution();
      unsigned int      n = 0;
      for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
        if (!std::isfinite(u.local_element(i)))
          ++n;
      return n;
    }

    /** What to change when a converged answer breaks a law: the solver
     * that did not check it, and another one to compare with. */
    std::string
    law_advice(const RunReport::Results &results)
    {
      const std::string solver =
        results.contact_solver ? results.contact_solver->name() : "";
      return "lower Contact solver/Tolerance, or compare with Contact "
             "solver/Solver = " +
             std::string(solver == "monolithic" ? "dd-newton" : "monolithic");
    }
  } // namespace

  SelfChecks::SelfChecks(std::vector<SelfCheck> checks)
    : checks(std::move(checks))
  {
  }

  SelfChecks::SelfChecks(const RunReport::Results &results,
                         const double              tolerance)
    : SelfChecks(results, RunReport::answer_of(results), tolerance)
  {
  }

  SelfChecks::SelfChecks(const RunReport::Results &results,
                         const RunReport::Answer  &answer,
                         const double              tolerance)
  {
    // The solvers' relative residuals reach round-off, not below it.
    const double limit = std::max(limit_factor * tolerance, 1e-12);
    const std::vector<ContactState> &states = answer.states;

    // Finite numbers: the displacements of every body, the forces of
    // every pair.
    unsigned int non_finite = 0;
    std::string  where;
    for (const auto &body : results.bodies)
    {
      const unsigned int n =
        Utilities::MPI::sum(non_finite_entries(*body), MPI_COMM_WORLD);
      if (n > 0 && where.empty())
        where = "the displacements of body '" + body->name() + "'";
      non_finite += n;
    }
    for (unsigned int p = 0; p < states.size(); ++p)
      if (!std::isfinite(states[p].normal_force) ||
          !std::isfinite(states[p].tangential_force) ||
          !std::isfinite(states[p].force_1.norm()))
      {
        if (where.empty())
          where =
            "the forces of contact pair " + results.contact_pairs[p]->name();
        ++non_finite;
      }
    checks.push_back({"finite",
                      double(non_finite),
                      0.,
                      where,
                      "the solve broke down; check the units, and that "
                      "every body is held against its rigid motions"});

    // Equilibrium of every body. A pressure at the points is the penalty
    // law's of the displacements, p = max(0, d) / theta: the solvers'
    // residual on the displacements, Tolerance relative in the Euclidean
    // norm over the N points, bounds a point's error by sqrt(N) Tolerance
    // A (A the zone's displacement), and the force by as much / theta
    // over the zone: relative to the force, sqrt(N) A / (theta p_mean)
    // times Tolerance (the relaxed DD on the flat punch at theta = 1e-7:
    // 4.5e-7 at Tolerance 1e-10). On the nodes the penalty amplifies the
    // round-off of the solve the same way (the monolithic solver at
    // theta = 1e-8 on the paper's scene: 1.1e-8); exact contact loads the
    // bodies with the pressure it reports: no amplification.
    double amplification = 1;
    for (unsigned int p = 0; p < states.size(); ++p)
    {
      const auto &pair     = *results.contact_pairs[p];
      const auto &solution = results.contact_solver->solution_of(p);
      // The theta in use: the nodes' (0 for exact contact), or the pair's
      // at the points.
      double theta = solution.nodal_pressure.empty() ? pair.penalty() : 0.;
      for (const double t : solution.nodal_penalty)
        theta = std::max(theta, t);
      // The mean pressure over the closed part of the zone: the force is
      // its integral (a peak at a singular edge would understate the
      // amplification).
      double area = 0;
      for (unsigned int q = 0; q < states[p].sigma_n.size(); ++q)
        if (states[p].sigma_n[q] < 0)
          area += pair.points()[q].JxW;
      const double P = (area > 0) ? states[p].normal_force / area : 0.;
      if (theta > 0 && P > 0)
        amplification = std::max(amplification,
                                 std::sqrt(double(states[p].sigma_n.size())) *
                                   zone_displacement(states[p]) / (theta * P));
    }
    // The relaxed DD's iterate u + gamma (u~ - u) is no solution of the
    // bodies under any contact load: it trails its last solves by its
    // change, and its stopping test bounds that change times 1 / gamma
    // (the uniaxial blocks without contact: 4.9e-8 at Tolerance 1e-8 and
    // gamma 0.02).
    if (results.contact_solver != nullptr &&
        !results.contact_solver->history().empty())
    {
      const double gamma = results.contact_solver->history().back().gamma;
      if (gamma > 0 && gamma < 1)
        amplification /= gamma;
    }
    // Not below 1e-6: the sums of many damped Newton and Krylov updates
    // leave round-off in the balance that the Tolerance does not bound
    // (a slender plate after 150 damped Newton steps: 1.1e-8 at
    // Tolerance 1e-10). A broken answer is far above it (2e-2, 1e19).
    SelfCheck equilibrium{"equilibrium",
                          0.,
                          std::max(limit * amplification, 1e-6),
                          "",
                          "the bodies do not balance the forces they "
                          "exchange; " +
                            law_advice(results)};
    // A body that the others have released (lift-off) holds round-off
    // forces, which the contact solver's tolerance bounds relative to the
    // scene's forces, not to its own: measured against at least 1e-3 of
    // the largest force scale of the bodies (E max |u|).
    std::vector<double> force_scales;
    double              scene_scale = 0;
    for (const auto &body : results.bodies)
    {
      force_scales.push_back(
        ReactionForces<2>::force_scale(*body, body->get_solution()));
      scene_scale = std::max(scene_scale, force_scales.back());
    }
    for (unsigned int b = 0; b < results.bodies.size(); ++b)
    {
      const auto  &body      = results.bodies[b];
      const double imbalance = answer.reactions[b].relative_imbalance(
        body->get_geometry() == Geometry::axisymmetric,
        std::max(1e-6 * force_scales[b], 1e-3 * scene_scale));
      if (!(imbalance <= equilibrium.value))
      {
        equilibrium.value = imbalance;
        equilibrium.where = "body '" + body->name() + "'";
      }
    }
    checks.push_back(equilibrium);

    // The contact law at the nodes, and the inner solves.
    for (unsigned int p = 0; p < states.size(); ++p)
    {
      const auto law = nodal_law(results.contact_solver->solution_of(p),
                                 results.contact_pairs[p]->name(),
                                 zone_displacement(states[p]),
                                 limit);
      for (auto check : law)
      {
        check.advice = law_advice(results);
        // The worst pair's value under each name.
        const auto it = std::find_if(checks.begin(),
                                     checks.end(),
                                     [&](const SelfCheck &c)
                                     { return c.name == check.name; });
        if (it == checks.end())
          checks.push_back(check);
        else if (!(check.value <= it->value))
          *it = check;
      }
    }
    if (results.contact_solver != nullptr)
      checks.push_back(
        {"inner_solves",
         results.contact_solver->inner_solve_converged() ? 0. : 1.,
         0.,
         "the last Newton step's Krylov solve on the contact interface",
         "its system is singular or badly conditioned; try Contact "
         "solver/Solver = monolithic"});
  }

  std::vector<SelfCheck>
  SelfChecks::nodal_law(const PairSolution &solution,
                        const std::string  &pair,
                        const double        displacement,
                        const double        limit)
  {
    std::vector<SelfCheck> law;
    const auto            &p     = solution.nodal_pressure;
    const auto            &d     = solution.nodal_gap;
    const auto            &theta = solution.nodal_penalty;
    const unsigned int     n     = p.size();
    if (n == 0 || d.size() != n || theta.size() != n)
      return law;
    const double P = largest_magnitude(p);

    // A zone without pressure and without displacement has nothing to
    // violate: the scales only divide what is nonzero.
    const double P_scale = (P > 0) ? P : 1.;
    const double A       = (displacement > 0) ? displacement : 1.;
    law.push_back(worst_node("contact_sign",
                             pair,
                             n,
                             limit,
                             [&](const unsigned int i)
                             { return std::max(0., -p[i]) / P_scale; }));
    law.push_back(worst_node("contact_gap",
                             pair,
                             n,
                             limit,
                             [&](const unsigned int i) {
                               return std::max(0., d[i] - theta[i] * p[i]) / A;
                             }));
    law.push_back(worst_node("complementarity",
                             pair,
                             n,
                             limit,
                             [&](const unsigned int i)
                             {
                               return std::max(0., p[i]) *
                                      std::max(0., theta[i] * p[i] - d[i]) /
                                      (P_scale * A);
                             }));

    const auto        &f = solution.friction;
    const auto        &t = f.nodal_t, &b = f.nodal_bound;
    const auto        &ds = f.nodal_inelastic_slip;
    const unsigned int m  = t.size();
    if (m > 0 && ds.size() == m && b.size() == m)
    {
      const double B  = largest_magnitude(b);
      const double B_ = (B > 0) ? B : 1.;
      // The slips against the displacements (not against the largest
      // slip: on a zone that sticks, that is round-off).
      const double S_ = A;

      // An open node (p_i = 0) carries no traction, whatever its bound.
      const auto closed = [&](const unsigned int i)
      { return i >= n || p[i] > 0; };
      law.push_back(worst_node(
        "friction_bound",
        pair,
        m,
        limit,
        [&](const unsigned int i)
        { return closed(i) ? std::max(0., std::abs(t[i]) - b[i]) / B_ : 0.; }));
      // The traction -t tau on body 1 opposes the slip (u_1 - u_2) . tau:
      // a slipping node has t = b sign(ds).
      law.push_back(worst_node("slip_at_bound",
                               pair,
                               m,
                               limit,
                               [&](const unsigned int i)
                               {
                                 if (!closed(i))
                                   return 0.;
                                 const double direction =
                                   (ds[i] > 0) ? 1. : -1.;
                                 return std::abs(ds[i]) / S_ *
                                        std::max(0., b[i] - direction * t[i]) /
                                        B_;
                               }));
    }
    return law;
  }

  bool
  SelfChecks::passed() const
  {
    return std::all_of(checks.begin(),
                       checks.end(),
                       [](const SelfCheck &c) { return c.passed(); });
  }

  std::string
  SelfChecks::failure() const
  {
    for (const auto &c : checks)
      if (!c.passed())
      {
        std::ostringstream s;
        s << std::setprecision(3) << "self-check '" << c.name << "' failed";
        if (!c.where.empty())
          s << " at " << c.where;
        s << ": " << c.value << " where at most " << c.limit
          << " holds for a converged answer; " << c.advice;
        return s.str();
      }
    return "";
  }

  Json
  SelfChecks::json() const
  {
    Json list = Json::array();
    for (const auto &c : checks)
    {
      Json j;
      j["name"]   = c.name;
      j["value"]  = std::isfinite(c.value) ? Json(c.value) : Json(); // null
      j["limit"]  = c.limit;
      j["passed"] = c.passed();
      // Where a passing check is worst is round-off's choice (it differs
      // with the number of processes): named only where it fails.
      if (!c.passed() && !c.where.empty())
        j["where"] = c.where;
      list.push_back(j);
    }
    return Json{{"passed", passed()}, {"checks", list}};
  }
} // namespace ddcontact
