#ifndef ddcontact_linear_elastic_law_h
#define ddcontact_linear_elastic_law_h

#include <ddcontact/body/material_law.h>

namespace ddcontact
{
  /**
   * Material/Law = linear-elastic: isotropic linear elasticity, Hooke's law
   * (2) of doc/method.md, sigma = lambda tr(eps) I + 2 mu eps on the 3 x 3
   * strain (sigma_33 = lambda tr(eps) in plane strain, the hoop stress of
   * an axisymmetric section). No state; the tangent is constant, so the
   * body is factorized once per mesh.
   */
  class LinearElasticLaw : public MaterialLaw
  {
  public:
    explicit LinearElasticLaw(const ElasticConstants &constants);

    std::string
    name() const override;

    bool
    is_linear() const override
    {
      return true;
    }

    bool
    is_path_dependent() const override
    {
      return false;
    }

    const ElasticConstants &
    elastic_constants() const override
    {
      return constants;
    }

    void
    evaluate(const ArrayView<const SymmetricTensor<2, 3>> &strain,
             const ArrayView<const double>                &old_state,
             const ArrayView<SymmetricTensor<2, 3>>       &stress,
             std::vector<MaterialTangent>                 *tangent,
             const ArrayView<double> &new_state) const override;

  private:
    const ElasticConstants constants;
    const MaterialTangent  hooke;
  };
} // namespace ddcontact

#endif
