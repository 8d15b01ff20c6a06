// DESCRIPTION: the contact iterations give bit-identical histories, forces
// and iteration counts on 1 and 2 threads (the three-body scene, whose
// Anderson run turned round-off into 143 or 71 iterations before; and
// Solver = dd-newton)
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parallel.h>

#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** What a run reached: its residual history, the contact force of every
   * pair, and the message if it stopped with a DivergenceError. */
  struct Outcome
  {
    std::vector<double> residuals;
    std::vector<double> forces;
    std::string         error;
  };

  /** Run @p scene on @p n_threads threads with @p overrides. */
  Outcome
  run_on(const unsigned int              n_threads,
         const std::string              &scene,
         const std::vector<std::string> &overrides)
  {
    MultithreadInfo::set_thread_limit(n_threads);
    std::vector<std::string> all = {"Output/Write vtu=false",
                                    "Output directory=thread_determinism_" +
                                      std::to_string(n_threads)};
    all.insert(all.end(), overrides.begin(), overrides.end());
    const ParameterReader reader(scene, all);
    std::ostringstream    quiet;
    Simulation            simulation(reader.scene(), quiet);
    Outcome               outcome;
    try
    {
      simulation.run();
    }
    catch (const DivergenceError &e)
    {
      outcome.error = e.what();
    }
    const auto &solver = simulation.get_contact_solver();
    for (const auto &record : solver.history())
      outcome.residuals.push_back(record.residual);
    for (unsigned int p = 0; p < simulation.get_contact_pairs().size(); ++p)
      outcome.forces.push_back(solver.contact_state(p).force_1.norm());
    return outcome;
  }

  /** Run on 1 and 2 threads and check that everything is bit-identical. */
  void
  check_identical(const std::string              &what,
                  const std::string              &scene,
                  const std::vector<std::string> &overrides)
  {
    const Outcome one = run_on(1, scene, overrides);
    const Outcome two = run_on(2, scene, overrides);
    std::cout << what << ": " << one.residuals.size() << " and "
              << two.residuals.size() << " iterations, force "
              << std::setprecision(17)
              << (one.forces.empty() ? 0. : one.forces[0]) << " and "
              << (two.forces.empty() ? 0. : two.forces[0])
              << std::setprecision(6) << std::endl;
    check(one.residuals.size() == two.residuals.size(),
          what + ": same number of iterations on 1 and 2 threads");
    check(one.residuals == two.residuals,
          what + ": bit-identical residual history");
    check(!one.forces.empty() && one.forces == two.forces,
          what + ": bit-identical contact forces");
    check(one.error == two.error, what + ": the same outcome");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  // deal.II splits vector reductions into chunks by the number of threads
  // only from 4 x this many entries (several thousand by default); with 64
  // every vector of these small scenes takes that path, as the vectors of a
  // fine mesh do.
  internal::VectorImplementation::minimum_parallel_grain_size = 64;

  // Anderson on the three-body scene: 40 iterations are far beyond where
  // the two thread counts parted before (iteration 6). (The scene itself
  // solves with dd-newton.)
  check_identical(
    "three bodies, anderson",
    source_dir + "/prm/three_bodies.prm",
    {"Contact solver/Solver=dd", "Contact solver/Max iterations=40"});
  // The Newton solver on the same scene (its CG sums are its own, in index
  // order).
  check_identical("three bodies, dd-newton",
                  source_dir + "/prm/three_bodies.prm",
                  {"Contact solver/Solver=dd-newton"});
  return report();
}
