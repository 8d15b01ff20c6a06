#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/numerics/error_estimator.h>

#include <ddcontact/adaptivity/kelly_estimator.h>

namespace ddcontact
{
  KellyEstimator::KellyEstimator(const ElasticBody<2> &body)
    : body(body)
  {
  }

  void
  KellyEstimator::estimate(const Vector<double> &u_fem,
                           const BoundaryTractionSamples &)
  {
    Vector<float> kelly(body.get_triangulation().n_active_cells());
    KellyErrorEstimator<2>::estimate(body.get_mapping(),
                                     body.get_dof_handler(),
                                     QGauss<1>(body.get_fe().degree + 1),
                                     {},
                                     u_fem,
                                     kelly);
    // On a partitioned mesh every process estimates only its own cells;
    // each cell has one owner, so on a shared mesh the sum is the whole
    // estimate. A distributed one keeps the owned cells' values.
    if (const auto *tria = dynamic_cast<const parallel::TriangulationBase<2> *>(
          &body.get_triangulation());
        tria && !body.is_mesh_distributed())
      Utilities::MPI::sum(kelly, tria->get_communicator(), kelly);
    eta = kelly;
    if (body.is_mesh_distributed())
      for (const auto &cell : body.get_triangulation().active_cell_iterators())
        if (!cell->is_locally_owned())
          eta(cell->active_cell_index()) = 0.;
  }
} // namespace ddcontact
