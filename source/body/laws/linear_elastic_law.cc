#include <ddcontact/body/laws/linear_elastic_law.h>

namespace ddcontact
{
  LinearElasticLaw::LinearElasticLaw(const ElasticConstants &constants)
    : constants(constants)
    , hooke(constants.tangent())
  {
  }

  std::string
  LinearElasticLaw::name() const
  {
    return "linear-elastic";
  }

  void
  LinearElasticLaw::evaluate(
    const ArrayView<const SymmetricTensor<2, 3>> &strain,
    const ArrayView<const double> & /*old_state*/,
    const ArrayView<SymmetricTensor<2, 3>> &stress,
    std::vector<MaterialTangent>           *tangent,
    const ArrayView<double> & /*new_state*/) const
  {
    AssertDimension(strain.size(), stress.size());
    for (unsigned int q = 0; q < strain.size(); ++q)
      stress[q] = hooke.apply(strain[q]);
    if (tangent != nullptr)
      tangent->assign(strain.size(), hooke);
  }
} // namespace ddcontact
