#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <ddcontact/body/axis_of_symmetry.h>
#include <ddcontact/body/body_stresses.h>
#include <ddcontact/body/elastic_body.h>

#include <array>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ddcontact
{
  template <int dim>
  BodyStresses<dim>::BodyStresses(const ElasticBody<dim> &body,
                                  const BodyVector       &u)
    : body(body)
    , u(u)
    , axisymmetric(body.get_geometry() == Geometry::axisymmetric)
    , axis_tolerance(
        axisymmetric ? AxisOfSymmetry::tolerance(body.get_triangulation()) : 0.)
  {
    const Quadrature<dim> *reduced = body.get_volumetric_quadrature();
    if (reduced == nullptr)
      return;
    dilatation.assign(body.get_triangulation().n_active_cells(), 0.);
    FEValues<dim>                        fe_values(body.get_mapping(),
                            body.get_fe(),
                            *reduced,
                            strain_flags(update_gradients));
    std::vector<SymmetricTensor<2, dim>> strain(reduced->size());
    std::vector<double>                  hoop(reduced->size());
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        strains(fe_values, strain, hoop);
        dilatation[cell->active_cell_index()] =
          axisymmetric ? trace(strain[0]) + hoop[0] : trace(strain[0]);
      }
  }

  template <int dim>
  UpdateFlags
  BodyStresses<dim>::strain_flags(const UpdateFlags flags) const
  {
    return axisymmetric ? flags | update_values | update_gradients |
                            update_quadrature_points
                        : flags | update_gradients;
  }

  template <int dim>
  void
  BodyStresses<dim>::strains(const FEValues<dim>                  &fe_values,
                             std::vector<SymmetricTensor<2, dim>> &strain,
                             std::vector<double>                  &hoop) const
  {
    const FEValuesExtractors::Vector displacement(0);
    fe_values[displacement].get_function_symmetric_gradients(u, strain);
    hoop.assign(strain.size(), 0.);
    if (!axisymmetric)
      return;
    std::vector<Tensor<1, dim>> value(strain.size());
    std::vector<Tensor<2, dim>> gradient(strain.size());
    fe_values[displacement].get_function_values(u, value);
    fe_values[displacement].get_function_gradients(u, gradient);
    for (unsigned int q = 0; q < strain.size(); ++q)
      hoop[q] =
        hoop_strain(fe_values.quadrature_point(q), value[q], gradient[q]);
  }

  template <int dim>
  double
  BodyStresses<dim>::hoop_strain(const Point<dim>     &x,
                                 const Tensor<1, dim> &value,
                                 const Tensor<2, dim> &gradient) const
  {
    if (!axisymmetric)
      return 0.;
    // Output evaluates at vertices, some on the axis: there u_r = 0 and
    // u_r / r tends to du_r/dr.
    return x[0] > axis_tolerance ? value[0] / x[0] : gradient[0][0];
  }

  template <int dim>
  SymmetricTensor<2, dim>
  BodyStresses<dim>::stress(const SymmetricTensor<2, dim> &strain,
                            const unsigned int             cell,
                            const double                   hoop_strain) const
  {
    const Material &material = body.get_material();
    auto            s        = material.stress(strain);
    if (axisymmetric)
    {
      // lambda (tr eps + eps_tt) I + 2 mu eps, the volumetric part
      // possibly from the reduced point.
      const double volumetric =
        dilatation.empty() ? trace(strain) + hoop_strain : dilatation[cell];
      s += material.lambda() * (volumetric - trace(strain)) *
           unit_symmetric_tensor<dim>();
      return s;
    }
    if (!dilatation.empty())
      s += material.lambda() * (dilatation[cell] - trace(strain)) *
           unit_symmetric_tensor<dim>();
    return s;
  }

  template <int dim>
  double
  BodyStresses<dim>::out_of_plane(const SymmetricTensor<2, dim> &strain,
                                  const unsigned int             cell,
                                  const double hoop_strain) const
  {
    const Material &material = body.get_material();
    if (!axisymmetric)
      return material.out_of_plane_stress(stress(strain, cell));
    const double volumetric =
      dilatation.empty() ? trace(strain) + hoop_strain : dilatation[cell];
    return material.lambda() * volumetric + 2. * material.mu() * hoop_strain;
  }

  template <int dim>
  std::vector<std::vector<SymmetricTensor<2, dim>>>
  BodyStresses<dim>::at_quadrature_points(
    std::vector<std::vector<double>> *third) const
  {
    const unsigned int n_cells = body.get_triangulation().n_active_cells();
    std::vector<std::vector<SymmetricTensor<2, dim>>> result(n_cells);
    if (third)
      third->assign(n_cells, {});
    const Quadrature<dim> &quadrature = body.get_cell_quadrature();
    FEValues<dim>          fe_values(body.get_mapping(),
                            body.get_fe(),
                            quadrature,
                            strain_flags(update_gradients));
    std::vector<SymmetricTensor<2, dim>> strain(quadrature.size());
    std::vector<double>                  hoop(quadrature.size());
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        strains(fe_values, strain, hoop);
        const unsigned int c = cell->active_cell_index();
        auto              &s = result[c];
        s.resize(strain.size());
        for (unsigned int q = 0; q < strain.size(); ++q)
          s[q] = stress(strain[q], c, hoop[q]);
        if (third)
          for (unsigned int q = 0; q < strain.size(); ++q)
            (*third)[c].push_back(out_of_plane(strain[q], c, hoop[q]));
      }
    return result;
  }

  template <int dim>
  Quadrature<dim>
  BodyStresses<dim>::cell_centre() const
  {
    return body.is_simplex() ? Quadrature<dim>(QGaussSimplex<dim>(1))
                             : Quadrature<dim>(QGauss<dim>(1));
  }

  template <int dim>
  std::vector<SymmetricTensor<2, dim>>
  BodyStresses<dim>::at_cell_centres(std::vector<double> *third) const
  {
    const unsigned int n_cells = body.get_triangulation().n_active_cells();
    std::vector<SymmetricTensor<2, dim>> result(n_cells);
    if (third)
      third->assign(n_cells, 0.);
    FEValues<dim>                        fe_values(body.get_mapping(),
                            body.get_fe(),
                            cell_centre(),
                            strain_flags(update_gradients));
    std::vector<SymmetricTensor<2, dim>> strain(1);
    std::vector<double>                  hoop(1);
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        strains(fe_values, strain, hoop);
        const unsigned int c = cell->active_cell_index();
        result[c]            = stress(strain[0], c, hoop[0]);
        if (third)
          (*third)[c] = out_of_plane(strain[0], c, hoop[0]);
      }
    return result;
  }

  template <int dim>
  std::pair<double, double>
  BodyStresses<dim>::largest_strain_and_rotation() const
  {
    FEValues<dim>                        fe_values(body.get_mapping(),
                            body.get_fe(),
                            cell_centre(),
                            strain_flags(update_gradients));
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<2, dim>>          gradient(1);
    std::vector<SymmetricTensor<2, dim>> unused(1);
    std::vector<double>                  hoop(1);
    double                               strain = 0, rotation = 0;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(u, gradient);
        const SymmetricTensor<2, dim> eps = symmetrize(gradient[0]);
        for (const double e : eigenvalues(eps))
          strain = std::max(strain, std::abs(e));
        if (axisymmetric)
        {
          strains(fe_values, unused, hoop);
          strain = std::max(strain, std::abs(hoop[0]));
        }
        rotation = std::max(
          rotation, 0.5 * std::abs(gradient[0][1][0] - gradient[0][0][1]));
      }
    return {strain, rotation};
  }

  template <int dim>
  double
  BodyStresses<dim>::strain_energy() const
  {
    const Material                  &material   = body.get_material();
    const Quadrature<dim>           &quadrature = body.get_cell_quadrature();
    FEValues<dim>                    fe_values(body.get_mapping(),
                            body.get_fe(),
                            quadrature,
                            strain_flags(update_gradients | update_JxW_values |
                                         update_quadrature_points));
    const FEValuesExtractors::Vector displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(quadrature.size());
    std::vector<double>                  hoop(quadrature.size());
    const bool                           reduced  = !dilatation.empty();
    const Geometry                       geometry = body.get_geometry();
    double                               energy   = 0;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        strains(fe_values, strain, hoop);
        for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double JxW =
            fe_values.JxW(q) *
            section_measure(geometry, fe_values.quadrature_point(q));
          if (axisymmetric)
          {
            // 1/2 (sigma : eps + sigma_tt eps_tt), as assembled.
            const double shear      = strain[q] * strain[q] + hoop[q] * hoop[q];
            const double volumetric = trace(strain[q]) + hoop[q];
            energy +=
              0.5 *
              (2. * material.mu() * shear +
               (reduced ? 0. : material.lambda() * volumetric * volumetric)) *
              JxW;
            continue;
          }
          energy += 0.5 *
                    (reduced ? 2. * material.mu() * (strain[q] * strain[q])
                             : material.stress(strain[q]) * strain[q]) *
                    JxW;
        }
      }
    if (reduced)
    {
      // The volumetric part on its own (one-point) rule, as assembled.
      FEValues<dim> fe_reduced(body.get_mapping(),
                               body.get_fe(),
                               *body.get_volumetric_quadrature(),
                               update_JxW_values | update_quadrature_points);
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
        if (body.computes(cell))
        {
          fe_reduced.reinit(cell);
          const double d = dilatation[cell->active_cell_index()];
          for (const unsigned int q : fe_reduced.quadrature_point_indices())
            energy += 0.5 * material.lambda() * d * d * fe_reduced.JxW(q) *
                      section_measure(geometry, fe_reduced.quadrature_point(q));
        }
    }
    return body.get_mesh().sum(energy);
  }

  template <int dim>
  PointValues<dim>
  BodyStresses<dim>::at_unit_point(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const Point<dim>                                     &xi,
    const Point<dim>                                     &x) const
  {
    const Quadrature<dim> at_xi(std::vector<Point<dim>>{xi});
    FEValues<dim>         fe_values(body.get_mapping(),
                            body.get_fe(),
                            at_xi,
                            update_values | update_gradients |
                              update_quadrature_points);
    fe_values.reinit(cell);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<1, dim>>          value(1);
    std::vector<Tensor<2, dim>>          gradient(1);
    std::vector<SymmetricTensor<2, dim>> strain(1);
    fe_values[displacement].get_function_values(u, value);
    fe_values[displacement].get_function_gradients(u, gradient);
    fe_values[displacement].get_function_symmetric_gradients(u, strain);
    const double hoop =
      hoop_strain(fe_values.quadrature_point(0), value[0], gradient[0]);
    const unsigned int c = cell->active_cell_index();
    PointValues<dim>   result;
    result.x            = x;
    result.displacement = value[0];
    result.stress       = stress(strain[0], c, hoop);
    result.out_of_plane = out_of_plane(strain[0], c, hoop);
    return result;
  }

  template <int dim>
  PointValues<dim>
  BodyStresses<dim>::at_point_distributed(const Point<dim> &x,
                                          const InputError &outside,
                                          const bool        averaged) const
  {
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    const Triangulation<dim> &tria = body.get_triangulation();
    static_assert(dim == 2, "six values: u and the stress");
    using Values = std::array<double, 6>;
    // Averaged: every cell around x answers (get_point_ptrs()).
    Utilities::MPI::RemotePointEvaluation<dim> remote(1e-6, !averaged);
    remote.reinit({x}, tria, body.get_mapping());
    if (!remote.all_points_found())
      throw outside;
    std::vector<Values> found, buffer;
    remote.template evaluate_and_process<Values>(
      found,
      buffer,
      [&](const ArrayView<Values> &values, const auto &cell_data)
      {
        for (unsigned int c = 0; c < cell_data.cells.size(); ++c)
        {
          const CellIterator cell(&tria,
                                  cell_data.cells[c].first,
                                  cell_data.cells[c].second,
                                  &body.get_dof_handler());
          for (unsigned int k = cell_data.reference_point_ptrs[c];
               k < cell_data.reference_point_ptrs[c + 1];
               ++k)
          {
            const auto v =
              at_unit_point(cell, cell_data.reference_point_values[k], x);
            values[k] = {{v.displacement[0],
                          v.displacement[1],
                          v.stress[0][0],
                          v.stress[1][1],
                          v.stress[0][1],
                          v.out_of_plane}};
          }
        }
      });
    Values             v = found.at(0);
    const unsigned int n = remote.get_point_ptrs().at(1);
    if (averaged && n > 1)
    {
      v.fill(0.);
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int c = 0; c < v.size(); ++c)
          v[c] += found[k][c] / n;
    }
    PointValues<dim> result;
    result.x            = x;
    result.displacement = Tensor<1, dim>({v[0], v[1]});
    result.stress[0][0] = v[2];
    result.stress[1][1] = v[3];
    result.stress[0][1] = v[4];
    result.out_of_plane = v[5];
    return result;
  }

  template <int dim>
  PointValues<dim>
  BodyStresses<dim>::at_point(const Point<dim> &x) const
  {
    return at_point(x, false);
  }

  template <int dim>
  PointValues<dim>
  BodyStresses<dim>::averaged_at_point(const Point<dim> &x) const
  {
    return at_point(x, true);
  }

  template <int dim>
  PointValues<dim>
  BodyStresses<dim>::at_point(const Point<dim> &x, const bool averaged) const
  {
    std::ostringstream message;
    message << std::setprecision(std::numeric_limits<double>::max_digits10)
            << "Output/Points: the point (" << x << ") does not lie in body '"
            << body.name() << "'";
    const InputError outside(message.str());

    PointValues<dim> result;
    if (body.is_mesh_distributed())
      result = at_point_distributed(x, outside, averaged);
    else
    {
      // The cache version reports a point outside the mesh by an invalid
      // iterator instead of an assertion.
      const Triangulation<dim>   &tria = body.get_triangulation();
      const GridTools::Cache<dim> cache(tria, body.get_mapping());
      const auto found = GridTools::find_active_cell_around_point(cache, x);
      if (found.first.state() != IteratorState::valid)
        throw outside;
      const auto with_dofs = [&](const auto &cell)
      {
        return typename DoFHandler<dim>::active_cell_iterator(
          &tria, cell->level(), cell->index(), &body.get_dof_handler());
      };
      result = at_unit_point(with_dofs(found.first), found.second, x);
      if (averaged)
      {
        const auto around = GridTools::find_all_active_cells_around_point(
          body.get_mapping(), tria, x, 1e-10, found);
        if (around.size() > 1)
        {
          result.stress       = 0;
          result.out_of_plane = 0;
          for (const auto &[cell, xi] : around)
          {
            const auto v = at_unit_point(with_dofs(cell), xi, x);
            result.stress += v.stress / double(around.size());
            result.out_of_plane += v.out_of_plane / around.size();
          }
        }
      }
    }
    result.von_mises =
      body.get_material().von_mises(result.stress, result.out_of_plane);
    return result;
  }

  template class BodyStresses<2>;
} // namespace ddcontact
