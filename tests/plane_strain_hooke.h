#ifndef ddcontact_tests_plane_strain_hooke_h
#define ddcontact_tests_plane_strain_hooke_h

#include <deal.II/base/symmetric_tensor.h>

#include <ddcontact/body/material_law.h>

// The tests' own plane-strain Hooke's law, written from the formulas and
// not through the code's material law, so that the closed forms they build
// from it are independent of the code under test.
namespace ddcontact
{
  namespace test
  {
    /** sigma = lambda tr(eps) I + 2 mu eps (in-plane). */
    inline SymmetricTensor<2, 2>
    hooke(const ElasticConstants &m, const SymmetricTensor<2, 2> &eps)
    {
      const double          E = m.youngs_modulus, nu = m.poisson_ratio;
      const double          lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
      const double          mu     = E / (2. * (1. + nu));
      SymmetricTensor<2, 2> s;
      s[0][0] = lambda * (eps[0][0] + eps[1][1]) + 2. * mu * eps[0][0];
      s[1][1] = lambda * (eps[0][0] + eps[1][1]) + 2. * mu * eps[1][1];
      s[0][1] = 2. * mu * eps[0][1];
      return s;
    }

    /** sigma_33 = nu (sigma_11 + sigma_22) of plane strain. */
    inline double
    plane_strain_sigma_33(const ElasticConstants      &m,
                          const SymmetricTensor<2, 2> &sigma)
    {
      return m.poisson_ratio * (sigma[0][0] + sigma[1][1]);
    }
  } // namespace test
} // namespace ddcontact

#endif
