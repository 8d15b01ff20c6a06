#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/bem/boundary_integration.h>
#include <ddcontact/bem/far_field_stresses.h>
#include <ddcontact/parameter_tools.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/fe/fe_values.h>
#include <limits>

// The BEM solution inside the body: Somigliana's stresses and
// displacements at points and at the quadrature points of cells (directly,
// or interpolated in the far field).
namespace ddcontact
{
  std::vector<SymmetricTensor<2, 2>>
  BoundaryElementSolver::stress_at_points(
    const std::vector<Point<2>> &points) const
  {
    return evaluate_stress(
      points, use_far_field_interpolation && points.size() > far_field_points);
  }

  bool
  BoundaryElementSolver::hierarchical(const std::size_t n_points) const
  {
    return use_far_field_interpolation && n_points > far_field_points;
  }

  std::vector<SymmetricTensor<2, 2>>
  BoundaryElementSolver::evaluate_stress(const std::vector<Point<2>> &points,
                                         const bool     hierarchical,
                                         const MPI_Comm communicator) const
  {
    Assert(is_solved, ExcMessage("Call solve() first."));
    Timer timer;

    std::vector<SymmetricTensor<2, 2>> stress(points.size());
    const double                       mu = material.mu();
    std::vector<Point<2>>              scaled(points.size());
    for (std::size_t p = 0; p < points.size(); ++p)
      scaled[p] = mesh.scaled(points[p]);

    if (hierarchical)
    {
      // Hierarchical evaluation (cost about linear in the points instead
      // of points x elements).
      stress = FarFieldStresses(mesh, kelvin).evaluate(scaled, communicator);
      for (auto &s : stress)
        s *= mu;
    }
    else
      // Embarrassingly parallel: each point reads the boundary solution
      // and writes its own result (doc/bem-method.md §4.4).
      parallel::apply_to_subranges(
        std::size_t(0),
        points.size(),
        [&](const std::size_t begin, const std::size_t end)
        {
          for (std::size_t p = begin; p < end; ++p)
            stress[p] = mu * BoundaryIntegration::somigliana_stress(
                               mesh, kelvin, scaled[p]);
        },
        16);

    std::lock_guard<std::mutex> lock(*timing_mutex);
    timing_data.interior += timer.wall_time();
    interior_points = points.size();
    return stress;
  }

  std::vector<SymmetricTensor<2, 2>>
  BoundaryElementSolver::stress_at_points(const std::vector<Point<2>> &points,
                                          const MPI_Comm communicator,
                                          const bool     hierarchical) const
  {
    // (Programs that never initialized MPI, e.g. the BEM tests, are one
    // process.)
    const unsigned int n_procs =
      Utilities::MPI::job_supports_mpi()
        ? Utilities::MPI::n_mpi_processes(communicator)
        : 1;
    if (n_procs == 1 || hierarchical)
      return evaluate_stress(points, hierarchical);

    // This process's share [first, last); the others stay zero, and the
    // sum over the processes fills them all with the very same numbers.
    const unsigned int rank  = Utilities::MPI::this_mpi_process(communicator);
    const std::size_t  first = points.size() * rank / n_procs;
    const std::size_t  last  = points.size() * (rank + 1) / n_procs;
    const auto         share = evaluate_stress(
      std::vector<Point<2>>(points.begin() + first, points.begin() + last),
      false);
    std::vector<double> values(points.size() * 3, 0.);
    for (std::size_t p = 0; p < share.size(); ++p)
      for (unsigned int k = 0; k < 3; ++k)
        values[(first + p) * 3 + k] = share[p][k == 2 ? 0 : k][k == 2 ? 1 : k];
    std::vector<double> all(values.size());
    Utilities::MPI::sum(
      ArrayView<const double>(values), communicator, ArrayView<double>(all));
    std::vector<SymmetricTensor<2, 2>> stress(points.size());
    for (std::size_t p = 0; p < points.size(); ++p)
    {
      stress[p][0][0] = all[p * 3];
      stress[p][1][1] = all[p * 3 + 1];
      stress[p][0][1] = all[p * 3 + 2];
    }
    return stress;
  }

  std::vector<Tensor<1, 2>>
  BoundaryElementSolver::displacement_at_points(
    const std::vector<Point<2>> &points) const
  {
    Assert(is_solved, ExcMessage("Call solve() first."));
    std::vector<Tensor<1, 2>> u(points.size());
    parallel::apply_to_subranges(
      std::size_t(0),
      points.size(),
      [&](const std::size_t begin, const std::size_t end)
      {
        for (std::size_t p = begin; p < end; ++p)
          u[p] =
            mesh.length_scale() * BoundaryIntegration::somigliana_displacement(
                                    mesh, kelvin, mesh.scaled(points[p]));
      },
      16);
    return u;
  }

  std::vector<std::vector<SymmetricTensor<2, 2>>>
  BoundaryElementSolver::stress_at_quadrature_points(
    const DoFHandler<2> &dof_handler,
    const Mapping<2>    &mapping,
    const Quadrature<2> &quadrature,
    const MPI_Comm       communicator) const
  {
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    // A distributed mesh (p4est): this process evaluates its own cells,
    // and the other cells' entries stay empty (no process needs them).
    if (dynamic_cast<const parallel::DistributedTriangulationBase<2> *>(
          &dof_handler.get_triangulation()))
    {
      FEValues<2> fe_values(
        mapping, dof_handler.get_fe(), quadrature, update_quadrature_points);
      std::vector<Point<2>> points;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          const auto &q_points = fe_values.get_quadrature_points();
          points.insert(points.end(), q_points.begin(), q_points.end());
        }
      // The choice of the evaluation, and its boxes, follow the whole
      // mesh, as on one process.
      const auto &tria = dof_handler.get_triangulation();
      const auto  stress =
        evaluate_stress(points,
                        hierarchical(std::size_t(tria.n_global_active_cells()) *
                                     quadrature.size()),
                        tria.get_communicator());
      std::vector<std::vector<SymmetricTensor<2, 2>>> result(n_cells);
      std::size_t                                     p = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            result[cell->active_cell_index()].push_back(stress[p++]);
      return result;
    }

    // Every cell's points, shared between the processes by
    // stress_at_points(), which gives the same numbers on any number.
    FEValues<2> fe_values(
      mapping, dof_handler.get_fe(), quadrature, update_quadrature_points);
    std::vector<Point<2>> points;
    points.reserve(std::size_t(n_cells) * quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      fe_values.reinit(cell);
      const auto &q_points = fe_values.get_quadrature_points();
      points.insert(points.end(), q_points.begin(), q_points.end());
    }
    const auto stress =
      stress_at_points(points,
                       communicator,
                       hierarchical(std::size_t(n_cells) * quadrature.size()));

    std::vector<std::vector<SymmetricTensor<2, 2>>> result(n_cells);
    std::size_t                                     p = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        result[cell->active_cell_index()].push_back(stress[p++]);
    return result;
  }

} // namespace ddcontact
