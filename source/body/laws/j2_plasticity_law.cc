#include <ddcontact/body/laws/j2_plasticity_law.h>

#include <algorithm>

namespace ddcontact
{
  namespace
  {
    using Tensor2 = SymmetricTensor<2, 3>;

    /** The tensor of the 6 values at @p values, in unrolled order. */
    SymmetricTensor<2, 3>
    read_tensor(const double *values)
    {
      SymmetricTensor<2, 3> t;
      for (unsigned int k = 0; k < Tensor2::n_independent_components; ++k)
        t[Tensor2::unrolled_to_component_indices(k)] = values[k];
      return t;
    }

    void
    write_tensor(const SymmetricTensor<2, 3> &t, double *values)
    {
      for (unsigned int k = 0; k < Tensor2::n_independent_components; ++k)
        values[k] = t[Tensor2::unrolled_to_component_indices(k)];
    }
  } // namespace

  J2PlasticityLaw::J2PlasticityLaw(const ElasticConstants &elastic,
                                   const double            yield_stress,
                                   const double            isotropic_hardening,
                                   const double            kinematic_hardening)
    : elastic(elastic)
    , yield_stress(yield_stress)
    , isotropic_hardening(isotropic_hardening)
    , kinematic_hardening(kinematic_hardening)
    , hooke(elastic.tangent())
  {
    AssertThrow(yield_stress > 0.,
                ExcMessage("j2-plasticity: the yield stress must be > 0"));
    AssertThrow(isotropic_hardening >= 0. && kinematic_hardening >= 0.,
                ExcMessage("j2-plasticity: the hardening moduli must be >= 0"));
  }

  std::string
  J2PlasticityLaw::name() const
  {
    return "j2-plasticity";
  }

  /*
   * The return mapping. Backward Euler over the step, with n the normal at
   * the end of the step:
   *   eps_p = eps_p_old + sqrt(3/2) dgamma n,
   *   beta  = beta_old  + (2/3) H_kin sqrt(3/2) dgamma n
   *         = beta_old  + sqrt(2/3) H_kin dgamma n,
   *   alpha = alpha_old + dgamma,
   * so that dev(sigma) = dev(sigma_tr) - 2 mu sqrt(3/2) dgamma n and
   *   dev(sigma) - beta = xi - (2 mu sqrt(3/2) + sqrt(2/3) H_kin) dgamma n
   *                     = xi - sqrt(2/3) (3 mu + H_kin) dgamma n.
   * The end-of-step relative stress is thus parallel to xi: n = xi / |xi|,
   * and its norm is |xi| - sqrt(2/3) (3 mu + H_kin) dgamma. f = 0 at the
   * end of the step then reads
   *   sqrt(3/2) |xi| - (3 mu + H_kin) dgamma - sigma_y
   *     - H_iso (alpha_old + dgamma) = f_tr - (3 mu + H) dgamma = 0,
   * H = H_iso + H_kin: dgamma = f_tr / (3 mu + H), linear in f_tr.
   *
   * The consistent tangent: at the fixed old state, d xi = 2 mu I_dev :
   * d eps, so d|xi| = 2 mu n : d eps, dn = 2 mu / |xi| (I_dev - n x n) :
   * d eps and d dgamma = sqrt(3/2) 2 mu / (3 mu + H) n : d eps. From
   * sigma = C : (eps - eps_p_old) - 2 mu sqrt(3/2) dgamma n,
   *   C_alg = C - 2 mu sqrt(3/2) (n x d dgamma/d eps + dgamma dn/d eps)
   *         = C - (2 mu)^2 (3/2) / (3 mu + H) n x n
   *             - (2 mu)^2 sqrt(3/2) dgamma / |xi| (I_dev - n x n),
   * symmetric in both index pairs and major-symmetric.
   */
  void
  J2PlasticityLaw::evaluate(
    const ArrayView<const SymmetricTensor<2, 3>> &strain,
    const ArrayView<const double>                &old_state,
    const ArrayView<SymmetricTensor<2, 3>>       &stress,
    std::vector<MaterialTangent>                 *tangent,
    const ArrayView<double>                      &new_state) const
  {
    const unsigned int n_points = strain.size();
    AssertDimension(stress.size(), n_points);
    AssertDimension(old_state.size(), n_points * n_state_values);
    Assert(new_state.size() == 0 ||
             new_state.size() == n_points * n_state_values,
           ExcDimensionMismatch(new_state.size(), n_points * n_state_values));
    if (tangent != nullptr)
      tangent->resize(n_points);

    const double mu          = elastic.mu();
    const double H           = isotropic_hardening + kinematic_hardening;
    const double sqrt_3_2    = std::sqrt(1.5);
    const double sqrt_2_3    = std::sqrt(2. / 3.);
    const double denominator = 3. * mu + H;

    for (unsigned int q = 0; q < n_points; ++q)
    {
      const double               *old = old_state.data() + q * n_state_values;
      const SymmetricTensor<2, 3> eps_p_old =
        read_tensor(old + plastic_strain_offset);
      const SymmetricTensor<2, 3> beta_old =
        read_tensor(old + back_stress_offset);
      const double alpha_old = old[alpha_offset];

      const SymmetricTensor<2, 3> sigma_trial =
        hooke.apply(strain[q] - eps_p_old);
      const SymmetricTensor<2, 3> xi      = deviator(sigma_trial) - beta_old;
      const double                xi_norm = xi.norm();
      const double                f_trial =
        sqrt_3_2 * xi_norm - (yield_stress + isotropic_hardening * alpha_old);

      double *new_values =
        new_state.size() > 0 ? new_state.data() + q * n_state_values : nullptr;
      if (f_trial <= 0.)
      {
        stress[q] = sigma_trial;
        if (tangent != nullptr)
          (*tangent)[q] = hooke;
        if (new_values != nullptr)
          std::copy(old, old + n_state_values, new_values);
        continue;
      }

      const double                dgamma = f_trial / denominator;
      const SymmetricTensor<2, 3> n      = xi / xi_norm;
      stress[q] = sigma_trial - 2. * mu * sqrt_3_2 * dgamma * n;
      if (tangent != nullptr)
      {
        const SymmetricTensor<4, 3> n_x_n          = outer_product(n, n);
        const double                two_mu_squared = 4. * mu * mu;
        (*tangent)[q]                              = MaterialTangent::general(
          hooke.tensor() - two_mu_squared * 1.5 / denominator * n_x_n -
          two_mu_squared * sqrt_3_2 * dgamma / xi_norm *
            (deviator_tensor<3>() - n_x_n));
      }
      if (new_values != nullptr)
      {
        write_tensor(eps_p_old + sqrt_3_2 * dgamma * n,
                     new_values + plastic_strain_offset);
        write_tensor(beta_old + sqrt_2_3 * kinematic_hardening * dgamma * n,
                     new_values + back_stress_offset);
        new_values[alpha_offset] = alpha_old + dgamma;
      }
    }
  }
  std::vector<std::string>
  J2PlasticityLaw::state_output_names() const
  {
    return {"equivalent_plastic_strain", "yielded"};
  }

  void
  J2PlasticityLaw::state_outputs(const ArrayView<const double> &state,
                                 const ArrayView<double>       &values) const
  {
    AssertDimension(state.size(), n_state_values);
    AssertDimension(values.size(), 2);
    values[0] = state[alpha_offset];
    values[1] = (state[alpha_offset] > 0) ? 1. : 0.;
  }
} // namespace ddcontact
