#include <ddcontact/contact/elastic_layer_guess.h>
#include <ddcontact/tasks.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  namespace
  {
    /** The contact loads of the elastic-layer model: on every pair the
     * pressure of springs E'/H of both bodies in series with the penalty,
     * pressed by the overlap of the contact-free solution @p u_free. */
    ContactProblem::Iterate
    elastic_layer_loads(const ContactProblem          &problem,
                        const ContactProblem::Iterate &u_free)
    {
      const auto &pairs = problem.get_pairs();
      auto        loads = problem.zero_iterate();
      for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const auto  &pair       = *pairs[p];
        const auto  &b1         = pair.get_body_1();
        const auto  &b2         = pair.get_body_2();
        const double H1         = pair.thickness_of_body_1();
        const auto   compliance = [&](const ElasticBody<2> &body, double H)
        {
          const auto &m = body.get_elastic_constants();
          return H * (1 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
        };
        // Body 2's thickness measured like body 1's.
        const double c_w =
          compliance(b1, H1) + compliance(b2, pair.thickness_of_body_2());

        std::vector<double> u_1n, u_2n;
        pair.normal_displacements(u_free[problem.body_index(b1)],
                                  u_free[problem.body_index(b2)],
                                  u_1n,
                                  u_2n);
        std::vector<double> sigma(u_1n.size());
        for (unsigned int q = 0; q < sigma.size(); ++q)
          sigma[q] = std::min(0., pair.points()[q].gap - u_1n[q] - u_2n[q]) /
                     (pair.penalty() + c_w);
        pair.add_contact_loads(
          sigma, loads[problem.body_index(b1)], loads[problem.body_index(b2)]);
      }
      return loads;
    }
  } // namespace

  ElasticLayerGuess
  elastic_layer_guess(const ContactProblem &problem)
  {
    const auto       &bodies = problem.get_bodies();
    const auto       &pairs  = problem.get_pairs();
    ElasticLayerGuess guess;
    auto             &u = guess.u;
    u                   = problem.zero_iterate();

    ContactProblem::Iterate u_free;
    problem.solve_all(ContactProblem::Iterate(bodies.size()), u_free);

    const auto loads = elastic_layer_loads(problem, u_free);
    problem.solve_all(loads, u);

    // The model knows neither bending nor chains of contacts (a plate
    // pressed onto a base bends through the gap the layer model fills),
    // and can start far worse than zero. Drop it when one step of (20)
    // moves it an order of magnitude more than it moves the zero guess
    // (three bodies: 5e4 times). A modest excess is no verdict: on the
    // paper's scene (1.08 times) and Hertz (3 times) it still saves
    // iterations.
    const auto                       zero = problem.zero_iterate();
    ContactProblem::Iterate          from_zero, from_layer;
    std::vector<std::vector<double>> sigma_zero(pairs.size()),
      sigma_layer(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      sigma_zero[p]  = problem.pressure(p, zero);
      sigma_layer[p] = problem.pressure(p, u);
    }
    // Without an initial overlap the zero guess's step is the
    // contact-free solution already at hand.
    bool zero_is_loaded = false;
    for (const auto &sigma : sigma_zero)
      for (const double v : sigma)
        zero_is_loaded = zero_is_loaded || (v != 0);
    if (zero_is_loaded)
      problem.solve_bodies(sigma_zero, from_zero);
    else
      from_zero = u_free;
    problem.solve_bodies(sigma_layer, from_layer);
    double step_zero = 0, step_layer = 0;
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      step_zero += ordered_norm_sqr(from_zero[b]);
      from_layer[b] -= u[b];
      step_layer += ordered_norm_sqr(from_layer[b]);
    }
    guess.step_ratio = std::sqrt(step_layer / step_zero);
    if (step_layer > 100 * step_zero) // squared norms: 10 times
    {
      guess.accepted = false;
      u              = zero;
    }
    return guess;
  }
} // namespace ddcontact