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
  namespace
  {
    /** The stress of @p law at one point of @p strain from the point's
     * state at the start of the step @p state (empty for a law without
     * state); the new state is not kept. */
    SymmetricTensor<2, 3>
    stress_of_state(const MaterialLaw             &law,
                    const SymmetricTensor<2, 3>   &strain,
                    const ArrayView<const double> &state)
    {
      SymmetricTensor<2, 3> sigma;
      std::vector<double>   new_state(state.size());
      law.evaluate(make_array_view(&strain, &strain + 1),
                   state,
                   make_array_view(&sigma, &sigma + 1),
                   nullptr,
                   make_array_view(new_state));
      return sigma;
    }
  } // namespace

  template <int dim>
  BodyStresses<dim>::BodyStresses(const ElasticBody<dim> &body,
                                  const BodyVector       &u)
    : body(body)
    , u(u)
    , kinematics(body.get_kinematics())
    , law(body.get_material_law())
  {
    // A path-dependent law's stress from the state at the start of the
    // step: per point, and the cell's mean for points between them.
    const auto &state = body.get_material_state();
    if (!state.empty())
    {
      const unsigned int n_cells  = body.get_triangulation().n_active_cells();
      const unsigned int n_values = law.n_state_variables();
      committed.resize(n_cells);
      committed_mean.resize(n_cells);
      for (const auto &cell : body.get_triangulation().active_cell_iterators())
        if (body.computes(cell))
        {
          const unsigned int c = cell->active_cell_index();
          state.get_committed(cell, committed[c]);
          const unsigned int n_points = committed[c].size() / n_values;
          committed_mean[c].assign(n_values, 0.);
          for (unsigned int q = 0; q < n_points; ++q)
            for (unsigned int k = 0; k < n_values; ++k)
              committed_mean[c][k] += committed[c][q * n_values + k] / n_points;
        }
    }
    const Quadrature<dim> *reduced = body.get_volumetric_quadrature();
    if (reduced == nullptr)
      return;
    dilatation.assign(body.get_triangulation().n_active_cells(), 0.);
    FEValues<dim>                      fe_values(body.get_mapping(),
                            body.get_fe(),
                            *reduced,
                            kinematics.update_flags(update_gradients));
    std::vector<SymmetricTensor<2, 3>> strain(reduced->size());
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        kinematics.field_strains(fe_values, u, strain);
        dilatation[cell->active_cell_index()] = trace(strain[0]);
      }
  }

  template <int dim>
  SymmetricTensor<2, 3>
  BodyStresses<dim>::stress(const SymmetricTensor<2, 3> &strain,
                            const unsigned int           cell) const
  {
    // The volumetric part from the cell's reduced point: an isotropic
    // linear law (MaterialLawInfo::reduced_integration).
    if (!dilatation.empty())
      return law.linear_tangent().apply(strain, dilatation[cell]);
    return stress_of_state(law,
                           strain,
                           committed_mean.empty()
                             ? ArrayView<const double>()
                             : make_array_view(committed_mean[cell]));
  }

  template <int dim>
  SymmetricTensor<2, 3>
  BodyStresses<dim>::stress_at_quadrature_point(
    const SymmetricTensor<2, 3> &strain,
    const unsigned int           cell,
    const unsigned int           q) const
  {
    if (committed.empty())
      return stress(strain, cell);
    const unsigned int n_values = law.n_state_variables();
    return stress_of_state(
      law,
      strain,
      make_array_view(committed[cell].data() + q * n_values,
                      committed[cell].data() + (q + 1) * n_values));
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
    const Quadrature<dim>             &quadrature = body.get_cell_quadrature();
    FEValues<dim>                      fe_values(body.get_mapping(),
                            body.get_fe(),
                            quadrature,
                            kinematics.update_flags(update_gradients));
    std::vector<SymmetricTensor<2, 3>> strain(quadrature.size());
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        kinematics.field_strains(fe_values, u, strain);
        const unsigned int c = cell->active_cell_index();
        auto              &s = result[c];
        s.resize(strain.size());
        for (unsigned int q = 0; q < strain.size(); ++q)
        {
          const SymmetricTensor<2, 3> sigma =
            stress_at_quadrature_point(strain[q], c, q);
          s[q] = SectionKinematics::in_plane(sigma);
          if (third)
            (*third)[c].push_back(sigma[2][2]);
        }
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
    FEValues<dim>                      fe_values(body.get_mapping(),
                            body.get_fe(),
                            cell_centre(),
                            kinematics.update_flags(update_gradients));
    std::vector<SymmetricTensor<2, 3>> strain(1);
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        kinematics.field_strains(fe_values, u, strain);
        const unsigned int          c     = cell->active_cell_index();
        const SymmetricTensor<2, 3> sigma = stress(strain[0], c);
        result[c]                         = SectionKinematics::in_plane(sigma);
        if (third)
          (*third)[c] = sigma[2][2];
      }
    return result;
  }

  template <int dim>
  std::pair<double, double>
  BodyStresses<dim>::largest_strain_and_rotation() const
  {
    FEValues<dim>                      fe_values(body.get_mapping(),
                            body.get_fe(),
                            cell_centre(),
                            kinematics.update_flags(update_gradients));
    const FEValuesExtractors::Vector   displacement(0);
    std::vector<Tensor<2, dim>>        gradient(1);
    std::vector<SymmetricTensor<2, 3>> eps(1);
    double                             strain = 0, rotation = 0;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(u, gradient);
        kinematics.field_strains(fe_values, u, eps);
        // The in-plane principal strains, and eps_33 (a principal strain).
        for (const double e : eigenvalues(SectionKinematics::in_plane(eps[0])))
          strain = std::max(strain, std::abs(e));
        strain   = std::max(strain, std::abs(eps[0][2][2]));
        rotation = std::max(
          rotation, 0.5 * std::abs(gradient[0][1][0] - gradient[0][0][1]));
      }
    return {strain, rotation};
  }

  template <int dim>
  double
  BodyStresses<dim>::strain_energy() const
  {
    // 1/2 a_a(u, u) = 1/2 int eps : C : eps of the law's (constant)
    // tangent, with the quadratures of the assembly.
    Assert(law.is_linear(), ExcNotImplemented());
    const MaterialTangent              tangent    = law.linear_tangent();
    const Quadrature<dim>             &quadrature = body.get_cell_quadrature();
    FEValues<dim>                      fe_values(body.get_mapping(),
                            body.get_fe(),
                            quadrature,
                            kinematics.update_flags(update_gradients |
                                                    update_JxW_values |
                                                    update_quadrature_points));
    std::vector<SymmetricTensor<2, 3>> strain(quadrature.size());
    const bool                         reduced = !dilatation.empty();
    double                             energy  = 0;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (body.computes(cell))
      {
        fe_values.reinit(cell);
        kinematics.field_strains(fe_values, u, strain);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          energy += 0.5 *
                    (reduced ? tangent.shear_form(strain[q], strain[q])
                             : tangent.form(strain[q], strain[q])) *
                    fe_values.JxW(q) *
                    kinematics.measure(fe_values.quadrature_point(q));
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
            energy += 0.5 * tangent.volumetric_modulus() * d * d *
                      fe_reduced.JxW(q) *
                      kinematics.measure(fe_reduced.quadrature_point(q));
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
    const FEValuesExtractors::Vector   displacement(0);
    std::vector<Tensor<1, dim>>        value(1);
    std::vector<SymmetricTensor<2, 3>> strain(1);
    fe_values[displacement].get_function_values(u, value);
    kinematics.field_strains(fe_values, u, strain);
    const SymmetricTensor<2, 3> sigma =
      stress(strain[0], cell->active_cell_index());
    PointValues<dim> result;
    result.x            = x;
    result.displacement = value[0];
    result.stress       = SectionKinematics::in_plane(sigma);
    result.out_of_plane = sigma[2][2];
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
    result.von_mises = von_mises_stress(result.stress, result.out_of_plane);
    return result;
  }

  template class BodyStresses<2>;
} // namespace ddcontact
