// DESCRIPTION: The DD's relaxations on a linear fixed-point map with a known
// spectrum: the fixed relaxation (21) contracts at max|1 - gamma(1 + k)|
// and diverges above gamma* = 2/(1 + k_max), Anderson is exact after n
// steps on an n-dimensional map (GMRES), Aitken after two on a scalar one
#include <ddcontact/solvers/relaxation.h>

#include "test_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  // The linearised DD map u -> u~ = b - K u with K >= 0 diagonal, k_i from
  // 0 to k_max (the contact-zone compliance over theta, section 3): its
  // fixed point is x* = b / (1 + k).
  const unsigned int n     = 10;
  const double       k_max = 9.;

  double
  k(const unsigned int i)
  {
    return k_max * i / (n - 1.);
  }

  Vector<double>
  map(const Vector<double> &x)
  {
    Vector<double> g(n);
    for (unsigned int i = 0; i < n; ++i)
      g(i) = 1. - k(i) * x(i);
    return g;
  }

  double
  error(const Vector<double> &x)
  {
    double e = 0;
    for (unsigned int i = 0; i < n; ++i)
      e = std::max(e, std::abs(x(i) - 1. / (1. + k(i))));
    return e;
  }

  /** The errors of @p iterations steps of @p relaxation from zero. */
  std::vector<double>
  iterate(Relaxation &relaxation, const unsigned int iterations)
  {
    Vector<double>      x(n);
    std::vector<double> errors{error(x)};
    for (unsigned int it = 0; it < iterations; ++it)
    {
      x = relaxation.update(x, map(x));
      errors.push_back(error(x));
    }
    return errors;
  }

  /** The mean contraction per step over the last 20 steps. */
  double
  measured_rate(const std::vector<double> &errors)
  {
    const std::size_t m = errors.size() - 1;
    return std::pow(errors[m] / errors[m - 20], 1. / 20.);
  }
} // namespace

int
main()
{
  // The iteration matrix of (21) is I - gamma (I + K), eigenvalues
  // 1 - gamma (1 + k_i): the slowest mode decides the rate.
  std::cout << "Fixed relaxation (21):" << std::endl;
  for (const double gamma : {0.1, 2. / (2. + k_max)})
  {
    FixedRelaxation relaxation(gamma);
    const double    predicted =
      std::max(std::abs(1. - gamma), std::abs(1. - gamma * (1. + k_max)));
    // 80 steps leave the slowest mode's share of the error exact to
    // (second rate / first rate)^80; the rate is measured to 1e-6.
    check("rate at gamma = " + std::to_string(gamma),
          std::abs(measured_rate(iterate(relaxation, 80)) - predicted),
          1e-6);
  }
  {
    const double    gamma_star = 2. / (1. + k_max);
    FixedRelaxation relaxation(1.05 * gamma_star);
    const auto      errors = iterate(relaxation, 80);
    check(errors.back() > errors.front(),
          "diverges 5 % above gamma* = 2/(1 + k_max)");
  }

  // Anderson with a history as long as the dimension is GMRES: the
  // residual is minimised over a Krylov space that holds the solution
  // after n steps. Round-off in the QR of the differences bounds it.
  std::cout << "Anderson acceleration:" << std::endl;
  {
    AndersonRelaxation relaxation(1., n);
    const auto         errors = iterate(relaxation, n + 1);
    check("error after n + 1 steps", errors.back(), 1e-10);
    relaxation.reset();
    check("error after reset() and n + 1 steps",
          iterate(relaxation, n + 1).back(),
          1e-10);
  }

  // Aitken's secant gamma is exact for a scalar linear map: the second
  // step lands on the fixed point.
  std::cout << "Aitken relaxation:" << std::endl;
  {
    AitkenRelaxation relaxation(0.1);
    Vector<double>   x(1);
    const auto       scalar_map = [](const Vector<double> &y)
    {
      Vector<double> g(1);
      g(0) = 6. - 5. * y(0); // fixed point 1
      return g;
    };
    for (unsigned int it = 0; it < 2; ++it)
      x = relaxation.update(x, scalar_map(x));
    check("error after two steps on a scalar map", std::abs(x(0) - 1.), 1e-14);
    check("its gamma is the optimal 1/(1 + 5)",
          std::abs(relaxation.get_gamma() - 1. / 6.),
          1e-14);
  }

  return report();
}
