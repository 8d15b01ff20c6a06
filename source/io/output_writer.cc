#include <deal.II/distributed/tria_base.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <ddcontact/body/smoothed_stresses.h>
#include <ddcontact/io/output_writer.h>
#include <ddcontact/io/vtk_flags.h>
#include <ddcontact/output_file.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <memory>
#include <set>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** Plane-strain stress (2), sigma_33 and von Mises from the
     * displacement gradient, for DataOut. */
    template <int dim>
    class StressPostprocessor : public DataPostprocessor<dim>
    {
    public:
      StressPostprocessor(const ElasticBody<dim> &body, const BodyVector &u)
        : stresses(body, u)
        , kinematics(body.get_kinematics())
        , axisymmetric(body.get_geometry() == Geometry::axisymmetric)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
        {
          SymmetricTensor<2, dim> strain;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              strain[i][j] = 0.5 * (inputs.solution_gradients[q][i][j] +
                                    inputs.solution_gradients[q][j][i]);
          // The body's own stress, with its reduced dilatation if any.
          const unsigned int cell =
            inputs.template get_cell<dim>()->active_cell_index();
          const double                eps_33 = axisymmetric
                                                 ? kinematics.out_of_plane_strain(
                                      inputs.evaluation_points[q],
                                      inputs.solution_values[q][0],
                                      inputs.solution_gradients[q][0][0])
                                                 : 0.;
          const SymmetricTensor<2, 3> sigma =
            stresses.stress(SectionKinematics::embed(strain, eps_33), cell);
          const auto   s     = SectionKinematics::in_plane(sigma);
          const double third = sigma[2][2];
          auto        &out   = computed_quantities[q];
          out(0)             = s[0][0];
          out(1)             = s[1][1];
          out(2)             = s[0][1];
          out(3)             = third;
          out(4)             = von_mises_stress(s, third);
        }
      }

      std::vector<std::string>
      get_names() const override
      {
        // Axisymmetric: r, z and the hoop direction (doc/output.md).
        if (axisymmetric)
          return {
            "sigma_rr", "sigma_zz", "sigma_rz", "sigma_hoop", "von_mises"};
        return {"sigma_11", "sigma_22", "sigma_12", "sigma_33", "von_mises"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return axisymmetric
                 ? update_values | update_gradients | update_quadrature_points
                 : update_gradients;
      }

    private:
      const BodyStresses<dim> stresses;
      const SectionKinematics kinematics;
      const bool              axisymmetric;
    };

    /** What DataOut reads when it builds its patches, kept beside it. */
    struct BodyFields
    {
      std::unique_ptr<StressPostprocessor<2>> stress;
      std::unique_ptr<SmoothedStresses<2>>    smoothed;
      Vector<double>                          body_id, level, process;
      std::vector<Vector<double>>             extra;
    };

    /**
     * Attaches the fields of body number @p b to @p data_out (its
     * @p solution, stresses, @p smooth ed stresses, the cell fields body_id,
     * level and process, and every name of @p extra_fields, from @p data
     * where it has it and zero elsewhere), held in @p fields.
     */
    void
    attach_fields(DataOut<2>                   &data_out,
                  BodyFields                   &fields,
                  const ElasticBody<2>         &body,
                  const BodyVector             &solution,
                  const unsigned int            b,
                  const std::set<std::string>  &extra_fields,
                  const OutputWriter::CellData *data,
                  const bool                    smooth)
    {
      const auto n_cells = body.get_triangulation().n_active_cells();
      data_out.attach_dof_handler(body.get_dof_handler());

      const std::vector<std::string> displacement_names(2, "displacement");
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          2, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(solution,
                               displacement_names,
                               DataOut<2>::type_dof_data,
                               interpretation);
      fields.stress = std::make_unique<StressPostprocessor<2>>(body, solution);
      data_out.add_data_vector(solution, *fields.stress);
      if (smooth)
      {
        fields.smoothed = std::make_unique<SmoothedStresses<2>>(body, solution);
        const auto names = fields.smoothed->names();
        for (unsigned int i = 0; i < names.size(); ++i)
          data_out.add_data_vector(fields.smoothed->get_dof_handler(),
                                   fields.smoothed->fields()[i],
                                   names[i]);
      }

      fields.body_id.reinit(n_cells);
      fields.level.reinit(n_cells);
      fields.process.reinit(n_cells);
      for (const auto &cell : body.get_triangulation().active_cell_iterators())
      {
        fields.body_id(cell->active_cell_index()) = b;
        fields.level(cell->active_cell_index())   = cell->level();
        // The process that assembles the cell (0 on a serial mesh).
        fields.process(cell->active_cell_index()) =
          cell->subdomain_id() == numbers::invalid_subdomain_id
            ? 0.
            : cell->subdomain_id();
      }
      data_out.add_data_vector(
        fields.body_id, "body_id", DataOut<2>::type_cell_data);
      data_out.add_data_vector(
        fields.level, "level", DataOut<2>::type_cell_data);
      data_out.add_data_vector(
        fields.process, "process", DataOut<2>::type_cell_data);

      fields.extra.reserve(extra_fields.size());
      for (const auto &field : extra_fields)
      {
        const auto it =
          data ? data->find(field) : OutputWriter::CellData::const_iterator();
        if (data && it != data->end())
          fields.extra.push_back(it->second);
        else
          fields.extra.emplace_back(n_cells);
        data_out.add_data_vector(
          fields.extra.back(), field, DataOut<2>::type_cell_data);
      }
    }

    std::string
    step_name(const std::string &base, const unsigned int step)
    {
      std::ostringstream s;
      s << base << '-' << std::setw(4) << std::setfill('0') << step;
      return s.str();
    }

    /** The VTU of one body of a step, @p name.vtu, or on a partitioned
     * mesh @p name.P.vtu of every process P that owns cells (each writes
     * its own); the names of all go into @p pieces. Collective over a
     * partitioned mesh. */
    void
    write_pieces(const DataOut<2>                     &data_out,
                 const std::string                    &name,
                 const parallel::TriangulationBase<2> *partitioned,
                 const std::string                    &directory,
                 const MPI_Comm                        communicator,
                 std::vector<std::string>             &pieces)
    {
      if (!partitioned)
      {
        pieces.push_back(name + ".vtu");
        OutputFile out(directory + "/" + pieces.back());
        out.write([&](std::ostream &s) { data_out.write_vtu(s); });
        out.commit();
        return;
      }
      const unsigned int this_process =
        Utilities::MPI::this_mpi_process(communicator);
      const auto owned = Utilities::MPI::all_gather(
        communicator, partitioned->n_locally_owned_active_cells());
      for (unsigned int p = 0; p < owned.size(); ++p)
        if (owned[p] > 0)
          pieces.push_back(name + "." + std::to_string(p) + ".vtu");
      if (owned[this_process] > 0)
      {
        OutputFile out(directory + "/" + name + "." +
                       std::to_string(this_process) + ".vtu");
        out.write([&](std::ostream &s) { data_out.write_vtu(s); });
        out.commit();
      }
    }

  } // namespace

  OutputWriter::OutputWriter(const std::string &directory,
                             const MPI_Comm     communicator,
                             const bool         smoothed_stresses)
    : directory(directory)
    , communicator(communicator)
    , smoothed_stresses(smoothed_stresses)
  {
  }

  void
  OutputWriter::write_step(const unsigned int                         step,
                           const double                               time,
                           const std::vector<const ElasticBody<2> *> &bodies,
                           const std::vector<const BodyVector *>     &solutions,
                           const std::vector<CellData>               &cell_data)
  {
    // The union of the extra cell fields, so that every piece has them all.
    std::set<std::string> extra_fields;
    for (const auto &data : cell_data)
      for (const auto &[name, values] : data)
        extra_fields.insert(name);

    std::vector<std::string> pieces;
    const std::string        group = step_name("bodies", step) + ".pvtu";
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    // The projection needs the whole mesh on this process.
    const bool smooth = smoothed_stresses &&
                        std::none_of(bodies.begin(),
                                     bodies.end(),
                                     [](const auto *body)
                                     { return body->is_mesh_distributed(); });

    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      const auto &body = *bodies[b];

      // A partitioned mesh is written by every process, each its own
      // cells (DataOut's default selection); a serial one by process 0.
      const auto *partitioned =
        dynamic_cast<const parallel::TriangulationBase<2> *>(
          &body.get_triangulation());
      if (!partitioned && !root)
        continue;

      DataOut<2> data_out;
      BodyFields fields;
      attach_fields(data_out,
                    fields,
                    body,
                    *solutions[b],
                    b,
                    extra_fields,
                    b < cell_data.size() ? &cell_data[b] : nullptr,
                    smooth);
      data_out.build_patches(body.get_mapping(), body.get_fe().degree);
      data_out.set_flags(vtk_flags());

      write_pieces(data_out,
                   step_name(body.name(), step),
                   partitioned,
                   directory,
                   communicator,
                   pieces);
      // Group the bodies of this step; every piece has the same fields.
      if (root && b + 1 == bodies.size())
      {
        OutputFile out(directory + "/" + group);
        out.write([&](std::ostream &s)
                  { data_out.write_pvtu_record(s, pieces); });
        out.commit();
      }
    }
    if (!root)
      return;

    records.emplace_back(time, group);
    OutputFile pvd(directory + "/solution.pvd");
    pvd.write([&](std::ostream &s)
              { DataOutBase::write_pvd_record(s, records); });
    pvd.commit();
  }
} // namespace ddcontact
