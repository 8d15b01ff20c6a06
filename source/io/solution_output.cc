#include <ddcontact/body/material_state_fields.h>
#include <ddcontact/io/solution_output.h>

namespace ddcontact
{
  SolutionOutput::SolutionOutput(const SceneParameters &parameters)
    : parameters(parameters)
  {
  }

  void
  SolutionOutput::write_step(const RunReport::Results &results,
                             const unsigned int        step)
  {
    // Process 0 writes the files; partitioned meshes are written in pieces
    // by all processes.
    const bool writes_files =
      Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const bool in_pieces = results.distribution.uses_process_groups();
    if (!parameters.write_vtu || (!writes_files && !in_pieces))
      return;
    if (!body_writer)
      body_writer = std::make_unique<OutputWriter>(
        parameters.output_directory,
        in_pieces ? MPI_COMM_WORLD : MPI_COMM_SELF,
        parameters.smoothed_stresses);
    const auto                         &bodies = results.bodies;
    std::vector<const ElasticBody<2> *> body_pointers;
    std::vector<const BodyVector *>     solutions;
    std::vector<OutputWriter::CellData> cell_data(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      body_pointers.push_back(bodies[b].get());
      solutions.push_back(&bodies[b]->get_solution());
      for (const auto &a : results.adaptations)
        if (&a->get_body() == bodies[b].get())
          cell_data[b] = a->cell_data();
      // A law's state (the equivalent plastic strain, yielded) per cell.
      for (auto &[name, field] : material_state_cell_fields(*bodies[b]))
        cell_data[b][name] = std::move(field);
    }
    body_writer->write_step(step, step, body_pointers, solutions, cell_data);

    // Every contact zone in the same step, with its multipliers if the
    // augmented Lagrangian is on.
    const auto &pairs = results.contact_pairs;
    if (!writes_files || pairs.empty())
      return;
    if (!zone_writer)
      zone_writer =
        std::make_unique<ContactZoneWriter>(parameters.output_directory);
    const ContactSolver &solver = *results.contact_solver;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      zone_writer->write_step(step,
                              step,
                              *pairs[p],
                              solver.contact_state(p),
                              parameters.contact_solver.exact_formulation
                                ? solver.get_problem().law(p).multipliers()
                                : std::vector<double>());
  }
} // namespace ddcontact
