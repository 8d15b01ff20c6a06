#ifndef ddcontact_j2_plasticity_law_h
#define ddcontact_j2_plasticity_law_h

#include <ddcontact/body/material_law.h>

namespace ddcontact
{
  /**
   * J2 (von Mises) elastoplasticity with linear isotropic and linear
   * kinematic (Prager) hardening, small strains, integrated by the
   * backward-Euler radial return (Simo and Hughes, Computational
   * Inelasticity, chapter 3): Body X/Material/Law = j2-plasticity
   * (doc/materials.md).
   *
   * Additive split eps = eps_e + eps_p, sigma = C : (eps - eps_p) with
   * Hooke's C of the elastic constants. The yield function is written with
   * the von Mises norm sqrt(3/2) |s| (|.| the Frobenius norm), so that
   * sigma_y is the uniaxial yield stress:
   *   f = sqrt(3/2) |dev(sigma) - beta| - (sigma_y + H_iso alpha),
   * and the flow is associated, with alpha the equivalent plastic strain:
   *   d eps_p = sqrt(3/2) d gamma n,  n = (dev(sigma) - beta)/|...|,
   *   d alpha = sqrt(2/3) |d eps_p| = d gamma,
   *   d beta  = (2/3) H_kin d eps_p.
   * In uniaxial stress this is sigma = sigma_y + (H_iso + H_kin) eps_p_11
   * on monotonic loading: the tangent modulus after yield is
   *   E_t = E (H_iso + H_kin) / (E + H_iso + H_kin),
   * and in pure shear tau_y = sigma_y / sqrt(3), then
   *   d tau / d gamma = mu H / (3 mu + H),  H = H_iso + H_kin.
   * H_iso = H_kin = 0 is perfect plasticity.
   *
   * The state of a point, n_state_variables() = 13 values: the components
   * of eps_p (0-5) and of beta (6-11) in deal.II's unrolled order of a
   * SymmetricTensor<2, 3> (SymmetricTensor::unrolled_to_component_indices),
   *   (0,0), (1,1), (2,2), (0,1), (0,2), (1,2),
   * tensor components, not engineering shears; then alpha (12). The
   * initial state is zero.
   */
  class J2PlasticityLaw : public MaterialLaw
  {
  public:
    /**
     * The law of the @p elastic constants, the uniaxial @p yield_stress
     * sigma_y > 0 and the hardening moduli H_iso = @p isotropic_hardening
     * and H_kin = @p kinematic_hardening (both >= 0).
     */
    J2PlasticityLaw(const ElasticConstants &elastic,
                    double                  yield_stress,
                    double                  isotropic_hardening,
                    double                  kinematic_hardening);

    /** Where the state's parts start in the values of one point. */
    static constexpr unsigned int plastic_strain_offset = 0;
    static constexpr unsigned int back_stress_offset    = 6;
    static constexpr unsigned int alpha_offset          = 12;
    static constexpr unsigned int n_state_values        = 13;

    std::string
    name() const override;

    bool
    is_linear() const override
    {
      return false;
    }

    bool
    is_path_dependent() const override
    {
      return true;
    }

    unsigned int
    n_state_variables() const override
    {
      return n_state_values;
    }

    const ElasticConstants &
    elastic_constants() const override
    {
      return elastic;
    }

    /**
     * The radial return at each point, from its state at the start of the
     * step (@p old_state, 13 values a point, required), driven by the total
     * @p strain. The trial stress sigma_tr = C : (eps - eps_p_old) and the
     * relative stress xi = dev(sigma_tr) - beta_old give
     *   f_tr = sqrt(3/2) |xi| - (sigma_y + H_iso alpha_old).
     * If f_tr <= 0 the step is elastic: the old state, Hooke's tangent.
     * Otherwise, with n = xi / |xi| (the direction does not change in the
     * return),
     *   d gamma = f_tr / (3 mu + H_iso + H_kin),
     *   sigma   = sigma_tr - 2 mu sqrt(3/2) d gamma n,
     * and the consistent tangent of the algorithm (not the continuum one:
     * it keeps Newton's quadratic convergence)
     *   C_alg = C - (2 mu)^2 (3/2) / (3 mu + H_iso + H_kin) n x n
     *             - (2 mu)^2 sqrt(3/2) d gamma / |xi| (I_dev - n x n),
     * a general tangent. The derivation is in the source.
     * @p tangent may be null, and @p new_state empty (then not written).
     */
    void
    evaluate(const ArrayView<const SymmetricTensor<2, 3>> &strain,
             const ArrayView<const double>                &old_state,
             const ArrayView<SymmetricTensor<2, 3>>       &stress,
             std::vector<MaterialTangent>                 *tangent,
             const ArrayView<double> &new_state) const override;

    /** "equivalent_plastic_strain": alpha, and "yielded": 1 where alpha
     * > 0, else 0. */
    std::vector<std::string>
    state_output_names() const override;

    void
    state_outputs(const ArrayView<const double> &state,
                  const ArrayView<double>       &values) const override;

  private:
    const ElasticConstants elastic;
    const double           yield_stress;
    const double           isotropic_hardening;
    const double           kinematic_hardening;
    const MaterialTangent  hooke;
  };
} // namespace ddcontact

#endif
