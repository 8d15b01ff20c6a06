#include <deal.II/distributed/tria_base.h>

#include <ddcontact/adaptivity/error_estimator.h>
#include <ddcontact/adaptivity/fem_bem_estimator.h>
#include <ddcontact/adaptivity/kelly_estimator.h>
#include <ddcontact/adaptivity/residual_estimator.h>

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
      case EstimatorType::residual:
        return std::make_unique<ResidualEstimator>(body);
    }
    AssertThrow(false, ExcInternalError());
    return nullptr;
  }

  void
  combine_process_values(const ElasticBody<2> &body, Vector<double> &eta)
  {
    // Each cell has one owner, so on a shared mesh the sum over the
    // processes is the whole estimate (triangle meshes are never
    // distributed). A distributed one keeps the owned cells' values.
    if (const auto *tria = dynamic_cast<const parallel::TriangulationBase<2> *>(
          &body.get_triangulation());
        tria && !body.is_mesh_distributed())
      Utilities::MPI::sum(eta, tria->get_communicator(), eta);
    if (body.is_mesh_distributed())
      for (const auto &cell : body.get_triangulation().active_cell_iterators())
        if (!cell->is_locally_owned())
          eta(cell->active_cell_index()) = 0.;
  }
} // namespace ddcontact
