#ifndef ddcontact_material_law_h
#define ddcontact_material_law_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>

#include <cmath>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The consistent tangent C = d sigma / d eps of a material law at a point,
   * on the 3 x 3 strains of SectionKinematics. An isotropic elastic tangent
   * is kept as its two Lamé parameters, C = lambda I x I + 2 mu I_s: the
   * bilinear form a_a (11) then costs two products per pair of shape
   * functions instead of a rank-4 contraction, and gives (11) exactly as
   * written. Any other tangent is a general rank-4 tensor.
   */
  class MaterialTangent
  {
  public:
    /** C = lambda I x I + 2 mu I_s. */
    static MaterialTangent
    isotropic(const double lambda, const double mu)
    {
      MaterialTangent t;
      t.is_isotropic_ = true;
      t.lambda_       = lambda;
      t.mu_           = mu;
      return t;
    }

    /** A general tangent @p C (symmetric in each index pair). */
    static MaterialTangent
    general(const SymmetricTensor<4, 3> &C)
    {
      MaterialTangent t;
      t.is_isotropic_ = false;
      t.C_            = C;
      return t;
    }

    bool
    is_isotropic() const
    {
      return is_isotropic_;
    }

    /** C : e. */
    SymmetricTensor<2, 3>
    apply(const SymmetricTensor<2, 3> &e) const
    {
      if (is_isotropic_)
        return lambda_ * trace(e) * unit_symmetric_tensor<3>() + 2. * mu_ * e;
      return C_ * e;
    }

    /** a : C : b, the integrand of a_a (11) for the strains of two shape
     * functions. */
    double
    form(const SymmetricTensor<2, 3> &a, const SymmetricTensor<2, 3> &b) const
    {
      if (is_isotropic_)
        return lambda_ * trace(a) * trace(b) + 2. * mu_ * (a * b);
      return a * (C_ * b);
    }

    /** form() with the traces of @p a and @p b given: an assembly computes
     * each shape function's once, not once per pair (the same number). */
    double
    form(const SymmetricTensor<2, 3> &a,
         const double                 trace_a,
         const SymmetricTensor<2, 3> &b,
         const double                 trace_b) const
    {
      if (is_isotropic_)
        return lambda_ * trace_a * trace_b + 2. * mu_ * (a * b);
      return a * (C_ * b);
    }

    /**
     * Selective reduced integration ("Element/Volumetric integration =
     * reduced") splits an isotropic tangent into its shear part 2 mu I_s,
     * integrated with the full rule (shear_form()), and its volumetric part
     * lambda I x I on one point per cell (volumetric_modulus()); the stress
     * then takes the cell's reduced dilatation theta in place of tr eps
     * (apply(e, theta)). Isotropic tangents only (MaterialLawInfo::
     * reduced_integration).
     */
    double
    shear_form(const SymmetricTensor<2, 3> &a,
               const SymmetricTensor<2, 3> &b) const
    {
      Assert(is_isotropic_, ExcNotImplemented());
      return 2. * mu_ * (a * b);
    }

    double
    volumetric_modulus() const
    {
      Assert(is_isotropic_, ExcNotImplemented());
      return lambda_;
    }

    /** lambda theta I + 2 mu e: C : e with the dilatation @p theta of the
     * reduced rule in place of tr e. */
    SymmetricTensor<2, 3>
    apply(const SymmetricTensor<2, 3> &e, const double theta) const
    {
      Assert(is_isotropic_, ExcNotImplemented());
      return lambda_ * theta * unit_symmetric_tensor<3>() + 2. * mu_ * e;
    }

    /** The tangent as a rank-4 tensor. */
    SymmetricTensor<4, 3>
    tensor() const
    {
      if (!is_isotropic_)
        return C_;
      return lambda_ * outer_product(unit_symmetric_tensor<3>(),
                                     unit_symmetric_tensor<3>()) +
             2. * mu_ * identity_tensor<3>();
    }

  private:
    bool                  is_isotropic_ = true;
    double                lambda_       = 0;
    double                mu_           = 0;
    SymmetricTensor<4, 3> C_;
  };

  /**
   * The elastic constants of a body's material: Young's modulus E and
   * Poisson's ratio nu, with the Lamé parameters
   *   lambda = E nu / ((1+nu)(1-2nu)),  mu = E / (2(1+nu)).
   * Every material law has them (MaterialLaw::elastic_constants()): the
   * scales of the contact solvers (penalty, Robin preconditioner,
   * compliance), the BEM's Kelvin solution and the residual estimator take
   * them from here, whatever the law.
   */
  struct ElasticConstants
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

    /** Hooke's tangent (2) of doc/method.md. */
    MaterialTangent
    tangent() const
    {
      return MaterialTangent::isotropic(lambda(), mu());
    }
  };

  /** The von Mises stress of the in-plane stress @p s and the third normal
   * stress @p s33 (sigma_33 of plane strain, sigma_tt of an axisymmetric
   * body; the third axis is a principal one in both). */
  inline double
  von_mises_stress(const SymmetricTensor<2, 2> &s, const double s33)
  {
    const double s11 = s[0][0], s22 = s[1][1], s12 = s[0][1];
    return std::sqrt(0.5 *
                       ((s11 - s22) * (s11 - s22) + (s22 - s33) * (s22 - s33) +
                        (s33 - s11) * (s33 - s11)) +
                     3. * s12 * s12);
  }

  /**
   * A material law: at the quadrature points of a cell, the stress and the
   * consistent tangent from the strain (SectionKinematics: 3 x 3, so that a
   * 3D body later needs no change here) and the state the point stored at
   * the start of the load step, and the point's new state.
   *
   * A law declares what it is: linear or not (a linear law's body is
   * factorized once per mesh and solved by one back substitution per load;
   * a nonlinear one needs a Newton loop), path-dependent or not (its state
   * is committed per load step), and its elastic constants. Laws are rows of
   * the table of material_laws.h, chosen by Body X/Material/Law.
   *
   * Laws are immutable and evaluate() is const: several threads evaluate
   * the same law on different cells.
   */
  class MaterialLaw
  {
  public:
    virtual ~MaterialLaw() = default;

    /** The table's name of the law ("linear-elastic"). */
    virtual std::string
    name() const = 0;

    /** Whether the stress is linear in the strain with a constant tangent
     * (and no state). */
    virtual bool
    is_linear() const = 0;

    /** Whether the law has a state that depends on the load path. */
    virtual bool
    is_path_dependent() const = 0;

    /** The number of state variables per quadrature point. */
    virtual unsigned int
    n_state_variables() const
    {
      return 0;
    }

    /** The initial state of a point (n_state_variables() values). */
    virtual void
    initial_state(const ArrayView<double> &state) const
    {
      AssertDimension(state.size(), n_state_variables());
      for (double &s : state)
        s = 0.;
    }

    virtual const ElasticConstants &
    elastic_constants() const = 0;

    /**
     * At the points of one cell: the @p stress of the @p strain, from the
     * points' states at the start of the step (@p old_state, n_points times
     * n_state_variables() values), the consistent @p tangent where it is
     * not null, and the points' @p new_state (same layout; may be empty
     * when the law has no state).
     */
    virtual void
    evaluate(const ArrayView<const SymmetricTensor<2, 3>> &strain,
             const ArrayView<const double>                &old_state,
             const ArrayView<SymmetricTensor<2, 3>>       &stress,
             std::vector<MaterialTangent>                 *tangent,
             const ArrayView<double>                      &new_state) const = 0;

    /** The names of the scalars that describe a point's state for the
     * output (VTU cell data, summary.json), e.g. the equivalent plastic
     * strain; none by default. */
    virtual std::vector<std::string>
    state_output_names() const
    {
      return {};
    }

    /** Those scalars of one point's @p state (n_state_variables() values)
     * into @p values (state_output_names().size() values). */
    virtual void
    state_outputs(const ArrayView<const double> &state,
                  const ArrayView<double>       &values) const
    {
      (void)state;
      (void)values;
      AssertDimension(values.size(), 0);
    }

    /** The constant tangent of a linear law. */
    virtual MaterialTangent
    linear_tangent() const
    {
      Assert(is_linear(), ExcNotImplemented());
      return elastic_constants().tangent();
    }
  };
} // namespace ddcontact

#endif
