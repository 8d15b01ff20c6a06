#include <deal.II/fe/fe_values.h>

#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/material_state_fields.h>

#include <algorithm>

namespace ddcontact
{
  namespace
  {
    /** @p f(cell, outputs) for every cell that this process computes, with
     * the law's outputs at each of its points (n_points x n_outputs). */
    template <int dim, typename Function>
    void
    for_each_cell_outputs(const ElasticBody<dim> &body, const Function &f)
    {
      const MaterialLaw &law       = body.get_material_law();
      const unsigned int n_outputs = law.state_output_names().size();
      const unsigned int n_values  = law.n_state_variables();
      const auto        &state     = body.get_material_state();
      if (n_outputs == 0 || state.empty())
        return;
      std::vector<double> values, outputs;
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
        if (body.computes(cell))
        {
          state.get_trial(cell, values);
          const unsigned int n_points = values.size() / n_values;
          outputs.assign(n_points * n_outputs, 0.);
          for (unsigned int q = 0; q < n_points; ++q)
            law.state_outputs(
              make_array_view(values.data() + q * n_values,
                              values.data() + (q + 1) * n_values),
              make_array_view(outputs.data() + q * n_outputs,
                              outputs.data() + (q + 1) * n_outputs));
          f(cell, outputs);
        }
    }
  } // namespace

  template <int dim>
  MaterialStateSummary
  summarize_material_state(const ElasticBody<dim> &body)
  {
    MaterialStateSummary summary;
    const MaterialLaw   &law = body.get_material_law();
    summary.names            = law.state_output_names();
    const unsigned int n     = summary.names.size();
    if (n == 0)
      return summary;
    summary.largest.assign(n, 0.);
    const auto yielded_at =
      std::find(summary.names.begin(), summary.names.end(), "yielded");
    const unsigned int yielded = yielded_at - summary.names.begin();

    // The plastic zone's measure with the assembly's quadrature and the
    // section's measure (2 pi r in axisymmetry).
    const SectionKinematics &kinematics = body.get_kinematics();
    FEValues<dim>            fe_values(body.get_mapping(),
                            body.get_fe(),
                            body.get_cell_quadrature(),
                            update_JxW_values | update_quadrature_points);
    for_each_cell_outputs(
      body,
      [&](const auto &cell, const std::vector<double> &outputs)
      {
        const unsigned int n_points = outputs.size() / n;
        fe_values.reinit(cell);
        AssertDimension(fe_values.n_quadrature_points, n_points);
        for (unsigned int q = 0; q < n_points; ++q)
        {
          if (outputs[q * n] > summary.largest[0])
          {
            const Point<dim> &x = fe_values.quadrature_point(q);
            summary.location_of_largest.resize(dim);
            for (unsigned int d = 0; d < dim; ++d)
              summary.location_of_largest[d] = x[d];
          }
          for (unsigned int k = 0; k < n; ++k)
            summary.largest[k] =
              std::max(summary.largest[k], outputs[q * n + k]);
        }
        if (yielded == n)
          return;
        for (unsigned int q = 0; q < n_points; ++q)
          if (outputs[q * n + yielded] > 0)
            summary.yielded_measure +=
              fe_values.JxW(q) *
              kinematics.measure(fe_values.quadrature_point(q));
      });
    // (A nonlinear law is solved on one process per body: a distributed
    // mesh would need the largest values reduced too.)
    summary.yielded_measure = body.get_mesh().sum(summary.yielded_measure);
    return summary;
  }

  template <int dim>
  std::map<std::string, Vector<double>>
  material_state_cell_fields(const ElasticBody<dim> &body)
  {
    std::map<std::string, Vector<double>> fields;
    const auto         names   = body.get_material_law().state_output_names();
    const unsigned int n_cells = body.get_triangulation().n_active_cells();
    for_each_cell_outputs(
      body,
      [&](const auto &cell, const std::vector<double> &outputs)
      {
        const unsigned int n_points = outputs.size() / names.size();
        for (unsigned int k = 0; k < names.size(); ++k)
        {
          auto &field = fields[names[k]];
          if (field.size() != n_cells)
            field.reinit(n_cells);
          double mean = 0;
          for (unsigned int q = 0; q < n_points; ++q)
            mean += outputs[q * names.size() + k] / n_points;
          field(cell->active_cell_index()) = mean;
        }
      });
    return fields;
  }

  template MaterialStateSummary
  summarize_material_state(const ElasticBody<2> &);
  template std::map<std::string, Vector<double>>
  material_state_cell_fields(const ElasticBody<2> &);
} // namespace ddcontact
