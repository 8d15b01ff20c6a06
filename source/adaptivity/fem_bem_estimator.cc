#include <deal.II/base/timer.h>

#include <deal.II/fe/fe_values.h>

#include <ddcontact/adaptivity/fem_bem_estimator.h>

#include <cmath>

namespace ddcontact
{
  FemBemEstimator::FemBemEstimator(const ElasticBody<2> &body,
                                   const EstimatorType   variant)
    : body(body)
    , scaled(variant == EstimatorType::fem_bem_scaled)
    , bem(body.get_elastic_constants(), body.get_boundary_conditions())
  {
    Assert(is_fem_bem(variant), ExcInternalError());
    // The boundary mesh (25) follows the FEM mesh: any refinement makes
    // the BEM stale, and it is rebuilt at the next estimate.
    mesh_changed = body.get_triangulation().signals.any_change.connect(
      [this]() { bem_is_current = false; });
  }

  FemBemEstimator::~FemBemEstimator()
  {
    mesh_changed.disconnect();
  }

  double
  FemBemEstimator::compare(const CellStresses &sigma_B,
                           const CellStresses &sigma_F,
                           Vector<double>     &area)
  {
    const auto &tria = body.get_triangulation();
    area.reinit(tria.n_active_cells());
    local_error.reinit(tria.n_active_cells());
    local_energy_error.reinit(tria.n_active_cells());
    double total_area = 0, bem_norm2 = 0, error2 = 0;
    double energy_error2 = 0, energy_norm2 = 0;
    // sigma : C^{-1} sigma in plane strain, (sigma:sigma - nu tr^2) / 2 mu:
    // the energy norm of the stress error, for the global estimate.
    const double mu     = body.get_elastic_constants().mu();
    const double nu     = body.get_elastic_constants().poisson_ratio;
    const auto   energy = [&](const SymmetricTensor<2, 2> &s)
    { return (s * s - nu * trace(s) * trace(s)) / (2 * mu); };
    FEValues<2> fe_values(body.get_mapping(),
                          body.get_fe(),
                          body.get_cell_quadrature(),
                          update_JxW_values);
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
    {
      if (!body.computes(cell))
        continue;
      fe_values.reinit(cell);
      const unsigned int c  = cell->active_cell_index();
      double             e2 = 0, energy2 = 0;
      for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const auto d = sigma_B[c][q] - sigma_F[c][q];
        // sum_ij z_ij^2: the double contraction counts z_12 twice.
        e2 += (d * d) * fe_values.JxW(q);
        bem_norm2 += (sigma_B[c][q] * sigma_B[c][q]) * fe_values.JxW(q);
        energy2 += energy(d) * fe_values.JxW(q);
        energy_norm2 += energy(sigma_B[c][q]) * fe_values.JxW(q);
        area(c) += fe_values.JxW(q);
      }
      local_error(c)        = std::sqrt(e2);
      local_energy_error(c) = std::sqrt(energy2);
      energy_error2 += energy2;
      error2 += e2;
      total_area += area(c);
    }
    if (body.is_mesh_distributed())
    {
      // Each process summed its own cells.
      const MPI_Comm comm = body.get_triangulation().get_communicator();
      error2              = Utilities::MPI::sum(error2, comm);
      bem_norm2           = Utilities::MPI::sum(bem_norm2, comm);
      total_area          = Utilities::MPI::sum(total_area, comm);
      energy_error2       = Utilities::MPI::sum(energy_error2, comm);
      energy_norm2        = Utilities::MPI::sum(energy_norm2, comm);
    }
    error_norm      = std::sqrt(error2);
    energy_error    = std::sqrt(energy_error2);
    energy_norm     = std::sqrt(energy_norm2);
    bem_stress_norm = std::sqrt(bem_norm2);

    return total_area;
  }

  void
  FemBemEstimator::estimate(const BodyVector              &u_fem,
                            const BoundaryTractionSamples &contact)
  {
    Timer timer;
    if (!bem_is_current)
    {
      bem.setup(body.get_dof_handler(), body.get_mapping());
      bem_is_current = true;
      time.bem_setup += timer.wall_time();
    }

    timer.restart();
    bem.solve(contact);
    time.bem_solve += timer.wall_time();

    timer.restart();
    // The BEM stress is interpolated from the support points inside the
    // body (a fraction of the quadrature points). Under mpirun every
    // process holds the body and its boundary solution and takes a share
    // of the points, with the same result on any number of processes; a
    // distributed mesh (p4est) interpolates its own cells.
    const auto sigma_B =
      bem.interpolated_stress_at_quadrature_points(body.get_dof_handler(),
                                                   body.get_mapping(),
                                                   body.get_cell_quadrature(),
                                                   MPI_COMM_WORLD);
    time.bem_interior += timer.wall_time();

    // (24), (27), with the cell quadrature of the FEM (the sigma_B above
    // lives at its points).
    timer.restart();
    const auto     sigma_F = body.stresses(u_fem).at_quadrature_points();
    const auto    &tria    = body.get_triangulation();
    Vector<double> area;
    const double   total_area = compare(sigma_B, sigma_F, area);

    eta.reinit(tria.n_active_cells());
    const double reference =
      bem_stress_norm / (scaled ? std::sqrt(total_area) : total_area);
    for (unsigned int c = 0; c < eta.size(); ++c)
      eta(c) =
        // (Cells of other processes of a distributed mesh have no area.)
        (reference > 0 && area(c) > 0)
          ? local_error(c) / (scaled ? std::sqrt(area(c)) : area(c)) / reference
          : 0.;
    time.compare += timer.wall_time();
  }
} // namespace ddcontact
