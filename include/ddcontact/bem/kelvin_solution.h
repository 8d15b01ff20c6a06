#ifndef ddcontact_kelvin_solution_h
#define ddcontact_kelvin_solution_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Kelvin's fundamental solution of plane-strain elastostatics and the
   * kernels of the Somigliana identities, the building blocks of the
   * boundary element reference solution sigma_B of the estimator (23)-(27).
   *
   * Conventions (doc/bem-method.md §1.1; the signs of T, D
   * and S depend on them): xi is the source point (collocation node or
   * interior point), x the field point on the boundary, r_vec = x - xi
   * (field minus source), r_i = (x_i - xi_i)/r, n the unit outward normal at
   * x, dr/dn = r_k n_k. For U and T the first index i is the direction of
   * the unit point force at xi and the second index j the component of the
   * displacement or traction at x. For D and S the first index k is the
   * component of the boundary traction or displacement at x and (i, j) the
   * stress component at xi.
   *
   * With these kernels the displacement and stress at an interior point are
   *   u_i(xi)      = int U_ij t_j - int T_ij u_j,
   *   sigma_ij(xi) = int D_kij t_k - int S_kij u_k.
   */
  class KelvinSolution
  {
  public:
    KelvinSolution(const double mu, const double nu)
      : mu(mu)
      , nu(nu)
      , c_u(-1. / (8. * numbers::PI * mu * (1. - nu)))
      , c_t(-1. / (4. * numbers::PI * (1. - nu)))
      , c_d(1. / (4. * numbers::PI * (1. - nu)))
      , c_s(mu / (2. * numbers::PI * (1. - nu)))
    {
    }

    /** U_ij(xi, x) = -1/(8 pi mu (1-nu)) [(3-4nu) ln r delta_ij - r_i r_j]. */
    Tensor<2, 2>
    displacement_kernel(const Point<2> &xi, const Point<2> &x) const;

    /** T_ij(xi, x; n), the traction on a facet with normal n at x. */
    Tensor<2, 2>
    traction_kernel(const Point<2>     &xi,
                    const Point<2>     &x,
                    const Tensor<1, 2> &normal) const;

    /** D_kij(xi, x), returned as [k][i][j]. */
    std::array<SymmetricTensor<2, 2>, 2>
    stress_traction_kernel(const Point<2> &xi, const Point<2> &x) const;

    /** S_kij(xi, x; n), returned as [k][i][j]. */
    std::array<SymmetricTensor<2, 2>, 2>
    stress_displacement_kernel(const Point<2>     &xi,
                               const Point<2>     &x,
                               const Tensor<1, 2> &normal) const;

    /**
     * The integrand of the Somigliana stress identity at one boundary
     * point, D_kij t_k - S_kij u_k, contracted in closed form (the hot loop
     * of the interior evaluation; equal to the explicit kernels above).
     */
    inline SymmetricTensor<2, 2>
    stress_integrand(const Point<2>     &xi,
                     const Point<2>     &x,
                     const Tensor<1, 2> &normal,
                     const Tensor<1, 2> &traction,
                     const Tensor<1, 2> &displacement) const;

    /** The integrand of the Somigliana displacement identity,
     * U_ij t_j - T_ij u_j. */
    Tensor<1, 2>
    displacement_integrand(const Point<2>     &xi,
                           const Point<2>     &x,
                           const Tensor<1, 2> &normal,
                           const Tensor<1, 2> &traction,
                           const Tensor<1, 2> &displacement) const;

    /**
     * Free term c_ij of the boundary integral equation at a corner whose
     * two boundary rays leave xi in the directions @p direction_out (along
     * the element that starts at xi) and @p direction_in (back along the
     * element that ends at xi); the body occupies the counter-clockwise
     * sector from the first to the second (doc/bem-method.md §2.1):
     *   c_11 = psi/(2 pi) + (sin 2 theta2 - sin 2 theta1)/(8 pi (1-nu)), ...
     * A smooth point gives delta_ij/2.
     */
    Tensor<2, 2>
    corner_free_term(const Tensor<1, 2> &direction_out,
                     const Tensor<1, 2> &direction_in) const;

    /** Shear modulus and Poisson ratio the kernels were built with. */
    const double mu;
    const double nu;

  private:
    const double c_u, c_t, c_d, c_s;
  };

  inline SymmetricTensor<2, 2>
  KelvinSolution::stress_integrand(const Point<2>     &xi,
                                   const Point<2>     &x,
                                   const Tensor<1, 2> &normal,
                                   const Tensor<1, 2> &traction,
                                   const Tensor<1, 2> &displacement) const
  {
    // Plain doubles instead of tensor loops: this runs N_points x N_b x n_q
    // times. The contraction over k of D_kij t_k and S_kij u_k is written
    // out term by term from the kernels of doc/bem-method.md §1.3.
    const double dx = x[0] - xi[0], dy = x[1] - xi[1];
    const double r2 = dx * dx + dy * dy, r = std::sqrt(r2);
    const double r0 = dx / r, r1 = dy / r;
    const double n0 = normal[0], n1 = normal[1];
    const double t0 = traction[0], t1 = traction[1];
    const double u0 = displacement[0], u1 = displacement[1];

    const double a       = 1. - 2. * nu;
    const double rt      = r0 * t0 + r1 * t1;
    const double ru      = r0 * u0 + r1 * u1;
    const double n_dot_u = n0 * u0 + n1 * u1;
    const double drdn    = r0 * n0 + r1 * n1;

    // D_kij t_k = c_d/r [a (t_i r_j + t_j r_i - delta_ij r.t)
    //                    + 2 r_i r_j r.t]
    const double fd  = c_d / r;
    const double d00 = fd * (a * (2. * t0 * r0 - rt) + 2. * r0 * r0 * rt);
    const double d11 = fd * (a * (2. * t1 * r1 - rt) + 2. * r1 * r1 * rt);
    const double d01 = fd * (a * (t0 * r1 + t1 * r0) + 2. * r0 * r1 * rt);

    // S_kij u_k = c_s/r^2 {2 dr/dn [a delta_ij r.u + nu (u_i r_j + u_j r_i)
    //                               - 4 r_i r_j r.u]
    //                      + 2 nu (n_i r_j + n_j r_i) r.u
    //                      + a (2 n.u r_i r_j + n_j u_i + n_i u_j)
    //                      - (1 - 4 nu) n.u delta_ij}
    const double fs = c_s / r2;
    const double b  = 1. - 4. * nu;
    const double s00 =
      fs * (2. * drdn * (a * ru + 2. * nu * u0 * r0 - 4. * r0 * r0 * ru) +
            4. * nu * n0 * r0 * ru +
            a * (2. * n_dot_u * r0 * r0 + 2. * n0 * u0) - b * n_dot_u);
    const double s11 =
      fs * (2. * drdn * (a * ru + 2. * nu * u1 * r1 - 4. * r1 * r1 * ru) +
            4. * nu * n1 * r1 * ru +
            a * (2. * n_dot_u * r1 * r1 + 2. * n1 * u1) - b * n_dot_u);
    const double s01 =
      fs * (2. * drdn * (nu * (u0 * r1 + u1 * r0) - 4. * r0 * r1 * ru) +
            2. * nu * (n0 * r1 + n1 * r0) * ru +
            a * (2. * n_dot_u * r0 * r1 + n1 * u0 + n0 * u1));

    SymmetricTensor<2, 2> sigma;
    sigma[0][0] = d00 - s00;
    sigma[1][1] = d11 - s11;
    sigma[0][1] = d01 - s01;
    return sigma;
  }
} // namespace ddcontact

#endif
