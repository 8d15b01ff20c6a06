#ifndef ddcontact_material_h
#define ddcontact_material_h

#include <deal.II/base/symmetric_tensor.h>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Isotropic linear elastic material in plane strain: Hooke's law (2) of
   * doc/method.md with the Lamé parameters
   *   lambda = E nu / ((1+nu)(1-2nu)),  mu = E / (2(1+nu)).
   * The out-of-plane stress of plane strain is sigma_33 = nu (sigma_11 +
   * sigma_22); it enters the von Mises stress as in the paper. An
   * axisymmetric body's hoop stress is BodyStresses::out_of_plane().
   */
  struct Material
  {
    double youngs_modulus = 1.0;
    double poisson_ratio  = 0.0;

    double
    lambda() const
    {
      return youngs_modulus * poisson_ratio /
             ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    }

    double
    mu() const
    {
      return youngs_modulus / (2. * (1. + poisson_ratio));
    }

    /** In-plane stress sigma = lambda tr(eps) I + 2 mu eps. */
    template <int dim>
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain) const
    {
      return lambda() * trace(strain) * unit_symmetric_tensor<dim>() +
             2. * mu() * strain;
    }

    /** sigma_33 = nu (sigma_11 + sigma_22) (plane strain). */
    template <int dim>
    double
    out_of_plane_stress(const SymmetricTensor<2, dim> &stress) const
    {
      return poisson_ratio * trace(stress);
    }

    /** Von Mises stress of the full 3D plane-strain stress state. */
    template <int dim>
    double
    von_mises(const SymmetricTensor<2, dim> &s) const
    {
      return von_mises(s, out_of_plane_stress(s));
    }

    /** Von Mises stress of the in-plane stress @p s and the third normal
     * stress @p s33 (sigma_33 of plane strain, sigma_thetatheta of an
     * axisymmetric body); the third axis is a principal one in both. */
    template <int dim>
    double
    von_mises(const SymmetricTensor<2, dim> &s, const double s33) const
    {
      const double s11 = s[0][0], s22 = s[1][1], s12 = s[0][1];
      return std::sqrt(0.5 * ((s11 - s22) * (s11 - s22) +
                              (s22 - s33) * (s22 - s33) +
                              (s33 - s11) * (s33 - s11)) +
                       3. * s12 * s12);
    }
  };
} // namespace ddcontact

#endif
