#include <ddcontact/adaptivity/error_estimator.h>
#include <ddcontact/adaptivity/fem_bem_estimator.h>
#include <ddcontact/adaptivity/kelly_estimator.h>

namespace ddcontact
{
  std::unique_ptr<ErrorEstimator>
  ErrorEstimator::create(const EstimatorType type, const ElasticBody<2> &body)
  {
    switch (type)
    {
      case EstimatorType::fem_bem:
      case EstimatorType::fem_bem_scaled:
        return std::make_unique<FemBemEstimator>(body, type);
      case EstimatorType::kelly:
        return std::make_unique<KellyEstimator>(body);
    }
    AssertThrow(false, ExcInternalError());
    return nullptr;
  }
} // namespace ddcontact
