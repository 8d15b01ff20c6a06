#include <ddcontact/bem/kelvin_solution.h>

namespace ddcontact
{
  Tensor<2, 2>
  KelvinSolution::displacement_kernel(const Point<2> &xi,
                                      const Point<2> &x) const
  {
    const Tensor<1, 2> r_vec = x - xi;
    const double       r     = r_vec.norm();
    Assert(r > 0, ExcMessage("Source and field point coincide."));
    const Tensor<1, 2> dr = r_vec / r;

    Tensor<2, 2> u;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        u[i][j] =
          c_u * ((i == j ? (3. - 4. * nu) * std::log(r) : 0.) - dr[i] * dr[j]);
    return u;
  }

  Tensor<2, 2>
  KelvinSolution::traction_kernel(const Point<2>     &xi,
                                  const Point<2>     &x,
                                  const Tensor<1, 2> &normal) const
  {
    const Tensor<1, 2> r_vec = x - xi;
    const double       r     = r_vec.norm();
    Assert(r > 0, ExcMessage("Source and field point coincide."));
    const Tensor<1, 2> dr   = r_vec / r;
    const double       drdn = dr * normal;
    const double       a    = 1. - 2. * nu;

    Tensor<2, 2> t;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        t[i][j] = c_t / r *
                  (drdn * ((i == j ? a : 0.) + 2. * dr[i] * dr[j]) -
                   a * (dr[i] * normal[j] - dr[j] * normal[i]));
    return t;
  }

  std::array<SymmetricTensor<2, 2>, 2>
  KelvinSolution::stress_traction_kernel(const Point<2> &xi,
                                         const Point<2> &x) const
  {
    const Tensor<1, 2> r_vec = x - xi;
    const double       r     = r_vec.norm();
    Assert(r > 0, ExcMessage("Source and field point coincide."));
    const Tensor<1, 2> dr    = r_vec / r;
    const double       a     = 1. - 2. * nu;
    const auto         delta = [](const unsigned int p, const unsigned int q)
    { return p == q ? 1. : 0.; };

    std::array<SymmetricTensor<2, 2>, 2> d;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          d[k][i][j] = c_d / r *
                       (a * (delta(k, i) * dr[j] + delta(k, j) * dr[i] -
                             delta(i, j) * dr[k]) +
                        2. * dr[i] * dr[j] * dr[k]);
    return d;
  }

  std::array<SymmetricTensor<2, 2>, 2>
  KelvinSolution::stress_displacement_kernel(const Point<2>     &xi,
                                             const Point<2>     &x,
                                             const Tensor<1, 2> &n) const
  {
    const Tensor<1, 2> r_vec = x - xi;
    const double       r     = r_vec.norm();
    Assert(r > 0, ExcMessage("Source and field point coincide."));
    const Tensor<1, 2> dr    = r_vec / r;
    const double       drdn  = dr * n;
    const double       a     = 1. - 2. * nu;
    const auto         delta = [](const unsigned int p, const unsigned int q)
    { return p == q ? 1. : 0.; };

    std::array<SymmetricTensor<2, 2>, 2> s;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          s[k][i][j] =
            c_s / (r * r) *
            (2. * drdn *
               (a * delta(i, j) * dr[k] +
                nu * (delta(i, k) * dr[j] + delta(j, k) * dr[i]) -
                4. * dr[i] * dr[j] * dr[k]) +
             2. * nu * (n[i] * dr[j] * dr[k] + n[j] * dr[i] * dr[k]) +
             a * (2. * n[k] * dr[i] * dr[j] + n[j] * delta(i, k) +
                  n[i] * delta(j, k)) -
             (1. - 4. * nu) * n[k] * delta(i, j));
    return s;
  }

  Tensor<1, 2>
  KelvinSolution::displacement_integrand(const Point<2>     &xi,
                                         const Point<2>     &x,
                                         const Tensor<1, 2> &normal,
                                         const Tensor<1, 2> &traction,
                                         const Tensor<1, 2> &displacement) const
  {
    return displacement_kernel(xi, x) * traction -
           traction_kernel(xi, x, normal) * displacement;
  }

  Tensor<2, 2>
  KelvinSolution::corner_free_term(const Tensor<1, 2> &direction_out,
                                   const Tensor<1, 2> &direction_in) const
  {
    const double theta_1 = std::atan2(direction_out[1], direction_out[0]);
    double       theta_2 = std::atan2(direction_in[1], direction_in[0]);
    // The body lies in the counter-clockwise sector from theta_1 to theta_2.
    while (theta_2 <= theta_1)
      theta_2 += 2. * numbers::PI;
    const double psi = theta_2 - theta_1;
    const double f   = 1. / (8. * numbers::PI * (1. - nu));

    Tensor<2, 2> c;
    c[0][0] = psi / (2. * numbers::PI) +
              f * (std::sin(2. * theta_2) - std::sin(2. * theta_1));
    c[1][1] = psi / (2. * numbers::PI) -
              f * (std::sin(2. * theta_2) - std::sin(2. * theta_1));
    c[0][1] = c[1][0] = f * (std::cos(2. * theta_1) - std::cos(2. * theta_2));
    return c;
  }
} // namespace ddcontact
