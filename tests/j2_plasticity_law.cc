// DESCRIPTION: The J2 elastoplastic law (J2PlasticityLaw: von Mises yield,
// linear isotropic and kinematic hardening, radial return) against closed
// forms, for isotropic-only, kinematic-only, mixed hardening and perfect
// plasticity. Uniaxial stress (sigma_22 = sigma_33 = 0 by a Newton
// iteration on the lateral strain with the law's tangent, the state
// committed per increment), loaded past yield, unloaded into reverse yield
// and reloaded: sigma_11 against the piecewise-linear curve of slopes E and
// E_t = E H / (E + H), H = H_iso + H_kin, whose reverse yield after a
// plastic leg lies 2 (sigma_y + H_iso alpha) below it (sigma_max - 2
// sigma_y with kinematic hardening, -sigma_max with isotropic). Pure shear:
// tau against tau_y = sigma_y / sqrt(3), then slope mu H / (3 mu + H). The
// consistent tangent against central differences of the stress at plastic
// points (virgin and hardened state) and at an elastic point. After
// plastic steps: f = 0, tr(eps_p) = 0, sigma = C : (eps - eps_p) and the
// evolution laws of beta and alpha, to round-off. Isotropy: a path rotated
// about the 3-axis gives the rotated stresses and plastic strains.
#include <deal.II/base/tensor.h>

#include <ddcontact/body/laws/j2_plasticity_law.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  const double u = std::numeric_limits<double>::epsilon();

  /** The stress, tangent and new state of one point. */
  struct Response
  {
    SymmetricTensor<2, 3> stress;
    SymmetricTensor<4, 3> tangent;
    std::vector<double>   state;
  };

  Response
  evaluate(const MaterialLaw           &law,
           const SymmetricTensor<2, 3> &eps,
           const std::vector<double>   &old_state)
  {
    Response                     r;
    std::vector<MaterialTangent> tangent;
    r.state.resize(law.n_state_variables());
    law.evaluate(make_array_view(&eps, &eps + 1),
                 make_array_view(old_state),
                 make_array_view(&r.stress, &r.stress + 1),
                 &tangent,
                 make_array_view(r.state));
    r.tangent = tangent.at(0).tensor();
    return r;
  }

  std::vector<double>
  initial_state(const MaterialLaw &law)
  {
    std::vector<double> state(law.n_state_variables(), 1.);
    law.initial_state(make_array_view(state));
    return state;
  }

  /** The 6 components at @p offset of a point's state. */
  SymmetricTensor<2, 3>
  state_tensor(const std::vector<double> &state, const unsigned int offset)
  {
    SymmetricTensor<2, 3> t;
    for (unsigned int k = 0; k < 6; ++k)
      t[SymmetricTensor<2, 3>::unrolled_to_component_indices(k)] =
        state[offset + k];
    return t;
  }

  SymmetricTensor<2, 3>
  plastic_strain(const std::vector<double> &state)
  {
    return state_tensor(state, J2PlasticityLaw::plastic_strain_offset);
  }

  SymmetricTensor<2, 3>
  back_stress(const std::vector<double> &state)
  {
    return state_tensor(state, J2PlasticityLaw::back_stress_offset);
  }

  struct Hardening
  {
    std::string name;
    double      isotropic, kinematic;
  };

  /**
   * The closed form of uniaxial stress under a strain path of monotonic
   * legs. The 1D reduction of the law: with p = eps_p_11 (eps_p =
   * p diag(1, -1/2, -1/2)), beta = (2/3) H_kin eps_p and dev(sigma) =
   * sigma diag(2/3, -1/3, -1/3), the yield function is |sigma - H_kin p| -
   * (sigma_y + H_iso alpha): the elastic range is the interval of width
   * 2 R, R = sigma_y + H_iso alpha, centred at H_kin p. A leg in the
   * direction s = +-1 that starts where the previous leg ended plastic
   * (at the other end of the range) is elastic, slope E, up to sigma_s +
   * 2 s R_s; the virgin material yields at s sigma_y. Plastic, sigma -
   * H_kin p = s R and eps = sigma / E + p give the slope E_t.
   */
  class UniaxialCurve
  {
  public:
    UniaxialCurve(const double E,
                  const double sigma_y,
                  const double H_iso,
                  const double H_kin)
      : E(E)
      , sigma_y(sigma_y)
      , H_iso(H_iso)
      , E_t(E * (H_iso + H_kin) / (E + H_iso + H_kin))
    {
    }

    /** Start a leg from the current point towards @p eps_end. */
    void
    start_leg(const double eps_end)
    {
      s = eps_end > eps_s ? 1. : -1.;
      if (first_leg)
        sigma_limit = s * sigma_y;
      else
        sigma_limit = sigma_s + 2. * s * (sigma_y + H_iso * alpha_s);
      eps_limit = eps_s + (sigma_limit - sigma_s) / E;
      first_leg = false;
    }

    /** sigma_11 at @p eps on the current leg. */
    double
    stress(const double eps) const
    {
      if (s * (eps - eps_limit) <= 0.)
        return sigma_s + E * (eps - eps_s);
      return sigma_limit + E_t * (eps - eps_limit);
    }

    /** End the leg at @p eps: whether it ended plastic. */
    bool
    end_leg(const double eps)
    {
      const double sigma = stress(eps);
      const double p_s = eps_s - sigma_s / E, p = eps - sigma / E;
      alpha_s += std::abs(p - p_s);
      eps_s   = eps;
      sigma_s = sigma;
      return s * (eps - eps_limit) > 0.;
    }

    /** The yield stress of the current leg (for the output). */
    double
    limit() const
    {
      return sigma_limit;
    }

  private:
    const double E, sigma_y, H_iso, E_t;
    bool         first_leg = true;
    double       eps_s = 0, sigma_s = 0, alpha_s = 0;
    double       s = 1, sigma_limit = 0, eps_limit = 0;
  };

  /** The worst errors of a uniaxial path. */
  struct UniaxialErrors
  {
    double              sigma_11 = 0, lateral = 0;
    unsigned int        max_newton_steps = 0;
    bool                legs_plastic     = true;
    std::vector<double> limits;
    std::vector<double> final_state;
  };

  /**
   * Drive eps_11 along the legs 0 -> @p turning_points[0] -> ... in
   * increments of at most @p step, with eps_22 = eps_33 found at each
   * increment by Newton's method on sigma_22 = 0 (d sigma_22 / d eps_22 =
   * C_2222 + C_2233 of the law's tangent), the state committed after each
   * increment.
   */
  UniaxialErrors
  uniaxial_path(const MaterialLaw         &law,
                UniaxialCurve             &curve,
                const std::vector<double> &turning_points,
                const double               step,
                const double               sigma_y)
  {
    UniaxialErrors      errors;
    std::vector<double> state   = initial_state(law);
    double              eps_11  = 0;
    double              lateral = 0;
    for (const double eps_end : turning_points)
    {
      curve.start_leg(eps_end);
      errors.limits.push_back(curve.limit());
      const double       eps_start = eps_11;
      const unsigned int n         = static_cast<unsigned int>(
        std::ceil(std::abs(eps_end - eps_start) / step - 1e-9));
      for (unsigned int i = 1; i <= n; ++i)
      {
        eps_11 = eps_start + (eps_end - eps_start) * i / n;
        Response     r;
        unsigned int k = 0;
        for (;; ++k)
        {
          SymmetricTensor<2, 3> eps;
          eps[0][0] = eps_11;
          eps[1][1] = eps[2][2] = lateral;
          r                     = evaluate(law, eps, state);
          if (std::abs(r.stress[1][1]) <= 1e-12 * sigma_y || k == 20)
            break;
          lateral -=
            r.stress[1][1] / (r.tangent[1][1][1][1] + r.tangent[1][1][2][2]);
        }
        errors.max_newton_steps = std::max(errors.max_newton_steps, k);
        SymmetricTensor<2, 3> lateral_stress = r.stress;
        lateral_stress[0][0]                 = 0;
        errors.lateral =
          std::max(errors.lateral, lateral_stress.norm() / sigma_y);
        errors.sigma_11 =
          std::max(errors.sigma_11,
                   std::abs(r.stress[0][0] - curve.stress(eps_11)) / sigma_y);
        state = r.state;
      }
      errors.legs_plastic = curve.end_leg(eps_11) && errors.legs_plastic;
    }
    errors.final_state = state;
    return errors;
  }

  /** R eps R^T. */
  SymmetricTensor<2, 3>
  rotate(const Tensor<2, 3> &R, const SymmetricTensor<2, 3> &eps)
  {
    return symmetrize(R * Tensor<2, 3>(eps) * transpose(R));
  }
} // namespace

int
main()
{
  ElasticConstants steel;
  steel.youngs_modulus = 2e5; // MPa
  steel.poisson_ratio  = 0.3;
  const double E = steel.youngs_modulus, mu = steel.mu();
  const double sigma_y = 250., eps_y = sigma_y / E;

  const std::vector<Hardening> hardenings = {{"isotropic", 1e4, 0.},
                                             {"kinematic", 0., 1e4},
                                             {"mixed", 4e3, 1.2e4},
                                             {"perfect", 0., 0.}};

  {
    const J2PlasticityLaw law(steel, sigma_y, 1e3, 2e3);
    check(law.name() == "j2-plasticity" && !law.is_linear() &&
            law.is_path_dependent() && law.n_state_variables() == 13 &&
            law.elastic_constants().youngs_modulus == E,
          "j2-plasticity: nonlinear, path-dependent, 13 state variables");
    const std::vector<double> state = initial_state(law);
    check(std::all_of(
            state.begin(), state.end(), [](const double s) { return s == 0.; }),
          "the initial state is zero");
  }

  // 1. Uniaxial stress: load to 3.2 eps_y, unload to -3.2 eps_y, reload to
  // 3.2 eps_y, in increments of eps_y / 12. Each leg ends plastic. Along
  // the legs the stress direction n = +-diag(2, -1, -1) / sqrt(6) does not
  // change, so the radial return is exact for any increment (also across
  // the yield point) and sigma_11 is the closed form to round-off: each of
  // the 193 increments adds a few ulps (4) of E |eps| ~ 640 (1e-13) to the
  // committed plastic strain's stress, at worst 193 * 4 * 1.1e-13 = 9e-11,
  // 3.5e-13 sigma_y: 1e-12 sigma_y. The lateral stress is Newton's
  // tolerance, 1e-12 sigma_y.
  std::cout << "Uniaxial stress, load, unload, reload:" << std::endl;
  for (const Hardening &h : hardenings)
  {
    const J2PlasticityLaw law(steel, sigma_y, h.isotropic, h.kinematic);
    UniaxialCurve         curve(E, sigma_y, h.isotropic, h.kinematic);
    const double          eps_max = 3.2 * eps_y;
    const UniaxialErrors  errors  = uniaxial_path(
      law, curve, {eps_max, -eps_max, eps_max}, eps_y / 12., sigma_y);
    std::cout << std::setprecision(6) << "  " << h.name << ": yield at "
              << errors.limits[0] << ", reverse yield at " << errors.limits[1]
              << ", reyield at " << errors.limits[2] << "; "
              << errors.max_newton_steps << " Newton steps at most"
              << std::endl;
    check(errors.legs_plastic && errors.max_newton_steps < 20,
          h.name + ": every leg ends plastic, Newton converged");
    check(h.name + ": sigma_11 = the closed form", errors.sigma_11, 1e-12);
    check(
      h.name + ": sigma_22 = sigma_33 = 0, no shear", errors.lateral, 1e-12);
  }
  // The reverse yield of the closed form's two limits, sigma_max - 2
  // sigma_y (kinematic) and -sigma_max (isotropic), met by the law along
  // the path above: the same path stopped at the reverse yield point
  // +- one hundredth of an increment is elastic before it and plastic after.
  for (const Hardening &h : {hardenings[0], hardenings[1]})
  {
    const J2PlasticityLaw law(steel, sigma_y, h.isotropic, h.kinematic);
    const double          H       = h.isotropic + h.kinematic;
    const double          eps_max = 3.2 * eps_y;
    const double sigma_max = sigma_y + E * H / (E + H) * (eps_max - eps_y);
    const double sigma_reverse =
      h.kinematic > 0 ? sigma_max - 2. * sigma_y : -sigma_max;
    const double eps_reverse = eps_max - (sigma_max - sigma_reverse) / E;
    bool         ok          = true;
    for (const double delta : {1., -1.})
    {
      UniaxialCurve        curve(E, sigma_y, h.isotropic, h.kinematic);
      const UniaxialErrors errors =
        uniaxial_path(law,
                      curve,
                      {eps_max, eps_reverse + delta * eps_y / 1200.},
                      eps_y / 12.,
                      sigma_y);
      // alpha after the reverse leg: unchanged before the reverse yield
      // (delta = +1), grown after it.
      const double alpha_max = eps_max - sigma_max / E;
      const double alpha = errors.final_state[J2PlasticityLaw::alpha_offset];
      ok = ok && (delta > 0 ? std::abs(alpha - alpha_max) < 1e-12 * alpha_max
                            : alpha > alpha_max * (1. + 1e-6));
    }
    check(ok,
          h.name + ": reverse yield at " +
            (h.kinematic > 0 ? "sigma_max - 2 sigma_y" : "-sigma_max"));
  }

  // 2. Pure shear eps_12 = gamma / 2 to 5 gamma_y, gamma_y = tau_y / mu,
  // tau_y = sigma_y / sqrt(3) (sqrt(3/2) |s| = sqrt(3) tau). Plastic: eps_p
  // = p (e1 x e2 + e2 x e1) with alpha = 2 p / sqrt(3), beta_12 = (2/3)
  // H_kin p, and f = 0 reads sqrt(3) (tau - beta_12) = sigma_y + H_iso
  // alpha: tau = tau_y + H gamma_p / 3, gamma_p = 2 p = gamma - tau / mu,
  // so d tau / d gamma = mu H / (3 mu + H). The direction is fixed: exact
  // to round-off of mu gamma ~ 700 over 60 increments (1e-12 sigma_y).
  std::cout << "Pure shear:" << std::endl;
  for (const Hardening &h : hardenings)
  {
    const J2PlasticityLaw law(steel, sigma_y, h.isotropic, h.kinematic);
    const double          H       = h.isotropic + h.kinematic;
    const double          tau_y   = sigma_y / std::sqrt(3.);
    const double          gamma_y = tau_y / mu;
    std::vector<double>   state   = initial_state(law);
    double                error   = 0;
    const unsigned int    n       = 60;
    for (unsigned int i = 1; i <= n; ++i)
    {
      const double          gamma = 5. * gamma_y * i / n;
      SymmetricTensor<2, 3> eps;
      eps[0][1]                 = gamma / 2.;
      const Response        r   = evaluate(law, eps, state);
      const double          tau = gamma <= gamma_y
                                    ? mu * gamma
                                    : tau_y + mu * H / (3. * mu + H) * (gamma - gamma_y);
      SymmetricTensor<2, 3> exact;
      exact[0][1] = tau;
      error       = std::max(error, (r.stress - exact).norm() / sigma_y);
      state       = r.state;
    }
    check(h.name + ": tau = the closed form, no other stress", error, 1e-12);
  }

  // 3. The consistent tangent against central differences of the stress,
  // the state fixed at the old one, step h in each of the 6 components.
  // Plastic: sigma = C : (eps - eps_p_old) - K n(xi) + (linear in eps),
  // K = 2 mu sqrt(3/2) R / (3 mu + H), R = sigma_y + H_iso alpha_old. A
  // step h moves xi by 2 mu dev(d eps), at most a |xi| with a = 2 sqrt(2)
  // mu h / |xi|; along it the third derivative of n = xi / |xi| is at most
  // 3 a^3 (reached for a step normal to xi), so the central difference
  // quotient is off by K 3 a^3 / 6 / h (truncation). Round-off: a few ulps
  // (8) of E |eps| over 2 h. Both relative to E; with h = 1e-7 they are
  // about 2e-10 and 4e-11 here (printed); the tolerance is twice their sum.
  // An elastic point has no truncation error (sigma linear in eps).
  std::cout << "Consistent tangent against finite differences:" << std::endl;
  {
    const Hardening      &h = hardenings[2];
    const J2PlasticityLaw law(steel, sigma_y, h.isotropic, h.kinematic);
    // A hardened state: uniaxial loading to 3.2 eps_y and back to
    // -1.5 eps_y.
    UniaxialCurve             curve(E, sigma_y, h.isotropic, h.kinematic);
    const std::vector<double> hardened =
      uniaxial_path(
        law, curve, {3.2 * eps_y, -1.5 * eps_y}, eps_y / 12., sigma_y)
        .final_state;
    // A general strain, all 6 components, away from the uniaxial direction.
    SymmetricTensor<2, 3> general;
    general[0][0]               = 1.1e-3;
    general[1][1]               = -2.3e-3;
    general[2][2]               = 0.4e-3;
    general[0][1]               = 1.7e-3;
    general[0][2]               = -0.9e-3;
    general[1][2]               = 1.3e-3;
    SymmetricTensor<2, 3> small = general / 20.;

    struct Case
    {
      std::string           name;
      SymmetricTensor<2, 3> eps;
      std::vector<double>   state;
      bool                  plastic;
    };
    const std::vector<Case> cases = {
      {"plastic, virgin state", general, initial_state(law), true},
      {"plastic, hardened state",
       plastic_strain(hardened) + general,
       hardened,
       true},
      {"elastic, hardened state",
       plastic_strain(hardened) + small,
       hardened,
       false}};
    const double h_fd = 1e-7;
    for (const Case &c : cases)
    {
      const Response r       = evaluate(law, c.eps, c.state);
      const bool     yielded = r.state != c.state;
      const double   R =
        sigma_y + h.isotropic * c.state[J2PlasticityLaw::alpha_offset];
      double error = 0, major = 0;
      bool   all_same_branch = true;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = k; l < 3; ++l)
        {
          SymmetricTensor<2, 3> d;
          d[k][l]              = h_fd;
          const Response plus  = evaluate(law, c.eps + d, c.state);
          const Response minus = evaluate(law, c.eps - d, c.state);
          all_same_branch      = all_same_branch &&
                            (plus.state != c.state) == yielded &&
                            (minus.state != c.state) == yielded;
          const SymmetricTensor<2, 3> fd =
            (plus.stress - minus.stress) / (2. * h_fd);
          error = std::max(error, (fd - r.tangent * d / h_fd).norm() / E);
        }
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              major = std::max(
                major,
                std::abs(r.tangent[i][j][k][l] - r.tangent[k][l][i][j]) / E);
      // |xi| of the trial state: |dev(sigma) - beta| at the end of the step
      // plus the return sqrt(2/3) (3 mu + H_kin) dgamma.
      const double dgamma = r.state[J2PlasticityLaw::alpha_offset] -
                            c.state[J2PlasticityLaw::alpha_offset];
      const double xi = (deviator(r.stress) - back_stress(r.state)).norm() +
                        std::sqrt(2. / 3.) * (3. * mu + h.kinematic) * dgamma;
      const double K =
        2. * mu * std::sqrt(1.5) * R / (3. * mu + h.isotropic + h.kinematic);
      const double a = 2. * std::sqrt(2.) * mu * h_fd / xi;
      const double truncation =
        c.plastic ? K * a * a * a / (2. * h_fd) / E : 0.;
      const double round_off = 8. * u * E * c.eps.norm() / (2. * h_fd) / E;
      const double tolerance = 2. * (truncation + round_off);
      std::cout << std::setprecision(3) << "  " << c.name << ": |xi| = " << xi
                << ", truncation bound " << truncation << ", round-off bound "
                << round_off << std::endl;
      check(yielded == c.plastic && all_same_branch,
            c.name + ": " + (c.plastic ? "plastic" : "elastic") +
              " at the point and its 12 neighbours");
      check(c.name + ": tangent = finite differences", error, tolerance);
      check(c.name + ": tangent major-symmetric", major, 1e-14);
    }
  }

  // 4. After plastic steps of a non-proportional path (each law, the state
  // committed): f = 0 at the new state, tr(eps_p) = 0, sigma = C : (eps -
  // eps_p), beta - beta_old = (2/3) H_kin (eps_p - eps_p_old) and alpha -
  // alpha_old = sqrt(2/3) |eps_p - eps_p_old|. Exact algebra on numbers of
  // size sigma_y and |eps_p|: a few ulps, 1e-13 relative.
  std::cout << "Yield surface and plastic flow after plastic steps:"
            << std::endl;
  for (const Hardening &h : hardenings)
  {
    const J2PlasticityLaw law(steel, sigma_y, h.isotropic, h.kinematic);
    std::vector<double>   state = initial_state(law);
    double f_error = 0, trace_error = 0, stress_error = 0, evolution_error = 0;
    unsigned int plastic_steps = 0;
    for (unsigned int i = 1; i <= 12; ++i)
    {
      // A strain that turns in the space of strains as it grows.
      const double          t = 0.5 * i;
      SymmetricTensor<2, 3> eps;
      eps[0][0]                = 1e-3 * t * std::cos(t);
      eps[1][1]                = 1e-3 * t * std::sin(t);
      eps[2][2]                = -0.5e-3 * t;
      eps[0][1]                = 0.8e-3 * std::sin(2. * t);
      eps[0][2]                = 0.3e-3 * t;
      eps[1][2]                = -0.6e-3 * std::cos(3. * t);
      const Response r         = evaluate(law, eps, state);
      const double   alpha_old = state[J2PlasticityLaw::alpha_offset],
                   alpha       = r.state[J2PlasticityLaw::alpha_offset];
      if (alpha > alpha_old)
      {
        ++plastic_steps;
        const SymmetricTensor<2, 3> eps_p   = plastic_strain(r.state);
        const SymmetricTensor<2, 3> d_eps_p = eps_p - plastic_strain(state);
        const SymmetricTensor<2, 3> beta    = back_stress(r.state);
        const double f = std::sqrt(1.5) * (deviator(r.stress) - beta).norm() -
                         (sigma_y + h.isotropic * alpha);
        f_error = std::max(f_error, std::abs(f) / sigma_y);
        trace_error =
          std::max(trace_error, std::abs(trace(eps_p)) / eps_p.norm());
        stress_error =
          std::max(stress_error,
                   (r.stress - steel.tangent().apply(eps - eps_p)).norm() /
                     r.stress.norm());
        evolution_error = std::max(
          {evolution_error,
           (beta - back_stress(state) - 2. / 3. * h.kinematic * d_eps_p)
               .norm() /
             sigma_y,
           std::abs(alpha - alpha_old - std::sqrt(2. / 3.) * d_eps_p.norm()) /
             (alpha - alpha_old)});
      }
      state = r.state;
    }
    check(plastic_steps >= 8, h.name + ": most steps plastic");
    check(h.name + ": f = 0 after the return", f_error, 1e-13);
    check(h.name + ": tr(eps_p) = 0", trace_error, 1e-13);
    check(h.name + ": sigma = C : (eps - eps_p)", stress_error, 1e-13);
    check(h.name + ": beta and alpha follow eps_p", evolution_error, 1e-13);
  }

  // 5. Isotropy: the path of 4. and the same path rotated by 0.7 about the
  // 3-axis, R eps R^T, give R sigma R^T and R eps_p R^T: a few ulps of
  // sigma from the rotations and the norms, 1e-13 sigma_y.
  std::cout << "Isotropy:" << std::endl;
  {
    const Hardening      &h = hardenings[2];
    const J2PlasticityLaw law(steel, sigma_y, h.isotropic, h.kinematic);
    const double          theta = 0.7;
    Tensor<2, 3>          R;
    R[0][0] = R[1][1]         = std::cos(theta);
    R[0][1]                   = -std::sin(theta);
    R[1][0]                   = std::sin(theta);
    R[2][2]                   = 1.;
    std::vector<double> state = initial_state(law), rotated_state = state;
    double              stress_error = 0, state_error = 0;
    for (unsigned int i = 1; i <= 12; ++i)
    {
      const double          t = 0.5 * i;
      SymmetricTensor<2, 3> eps;
      eps[0][0]          = 1e-3 * t * std::cos(t);
      eps[1][1]          = 1e-3 * t * std::sin(t);
      eps[2][2]          = -0.5e-3 * t;
      eps[0][1]          = 0.8e-3 * std::sin(2. * t);
      eps[0][2]          = 0.3e-3 * t;
      eps[1][2]          = -0.6e-3 * std::cos(3. * t);
      const Response r   = evaluate(law, eps, state);
      const Response r_R = evaluate(law, rotate(R, eps), rotated_state);
      stress_error       = std::max(
        stress_error, (r_R.stress - rotate(R, r.stress)).norm() / sigma_y);
      state_error = std::max(
        {state_error,
         (plastic_strain(r_R.state) - rotate(R, plastic_strain(r.state)))
             .norm() /
           eps_y,
         (back_stress(r_R.state) - rotate(R, back_stress(r.state))).norm() /
           sigma_y,
         std::abs(r_R.state[J2PlasticityLaw::alpha_offset] -
                  r.state[J2PlasticityLaw::alpha_offset]) /
           eps_y});
      state         = r.state;
      rotated_state = r_R.state;
    }
    check("rotated strain path: rotated stresses", stress_error, 1e-13);
    check("rotated strain path: rotated eps_p, beta; same alpha",
          state_error,
          1e-13);
  }
  return report();
}
