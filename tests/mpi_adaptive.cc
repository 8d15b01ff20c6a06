// DESCRIPTION: (run under mpirun -np 2) the combined algorithm on the
// paper's scene with the bodies solved on two processes: every process
// refines to the same one-irregular mesh, the bodies are balanced again
// after refinement, the BEM interior stresses split over the processes
// equal the whole evaluation, and the result equals the one with both
// bodies on one process to 1e-10; then with every body partitioned between
// both processes (Body owners = all): the adapted mesh is repartitioned
// into two equal halves, and the result equals the serial one, both with a
// shared mesh (every process holds all cells) and with a distributed one
// (p4est: each process holds its half and a ghost layer)
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>

#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  std::unique_ptr<Simulation>
  run(const std::string &source_dir,
      const std::string &owners,
      const std::string &mesh = "shared")
  {
    return run_coarse_paper_scene(
      source_dir,
      "mpi_adaptive_output",
      0,
      {"Adaptation/Mode=combined",
       "Adaptation/Estimator=fem-bem-scaled",
       "Adaptation/Delta=0.1",
       "Adaptation/Max level=4"},
      {"Parallel/Body owners=" + owners, "Parallel/Mesh=" + mesh});
  }

  /** A number that differs between processes iff the meshes do. */
  double
  mesh_fingerprint(const Triangulation<2> &tria)
  {
    double sum = 0;
    for (const auto &cell : tria.active_cell_iterators())
      sum += cell->center()[0] * 1.3 + cell->center()[1] * 0.7 + cell->level();
    return sum;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  const MPI_Comm                   world      = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(world) == 0;
  if (Utilities::MPI::n_mpi_processes(world) != 2)
  {
    check(false, "run this test with mpirun -np 2");
    return report();
  }
  // Only the first process prints; every process checks (a failure on
  // either fails the test through the exit code mpirun reports).
  if (!root)
    std::cout.setstate(std::ios::failbit);

  // Balanced ("auto"): omega1 (2210 dofs) first on process 0; Omega_2
  // outgrows it under refinement and the two swap.
  const auto  balanced     = run(source_dir, "auto");
  const auto &omega2       = balanced->get_bodies()[1]->get_triangulation();
  const auto &distribution = balanced->get_distribution();
  std::cout << "auto: " << omega2.n_active_cells() << " cells in Omega_2, "
            << "bodies on processes " << distribution.describe() << std::endl;
  check(one_irregular(omega2), "the adapted mesh is one-irregular");
  const double fingerprint = mesh_fingerprint(omega2);
  check(Utilities::MPI::min(fingerprint, world) ==
          Utilities::MPI::max(fingerprint, world),
        "every process holds the same adapted mesh");
  check(omega2.n_active_cells() > 64, "Omega_2 was refined");
  check(distribution.owner_of(0) != distribution.owner_of(1),
        "the two bodies are solved on different processes");
  check(distribution.owner_of(1) == 0,
        "after refinement the larger Omega_2 moved to process 0");

  // The BEM's interior stresses, the estimator's main cost, are evaluated
  // by each process on its share of the cells: the same numbers as one
  // process evaluating all (these few points take the direct sums, where
  // every point is independent of the others: exactly equal).
  {
    const auto &bem  = balanced->get_adaptations()[0]->fem_bem()->get_bem();
    const auto &body = *balanced->get_bodies()[1];
    const auto  split =
      bem.stress_at_quadrature_points(body.get_dof_handler(),
                                      body.get_mapping(),
                                      body.get_cell_quadrature(),
                                      world);
    const auto whole =
      bem.stress_at_quadrature_points(body.get_dof_handler(),
                                      body.get_mapping(),
                                      body.get_cell_quadrature(),
                                      MPI_COMM_SELF);
    double difference = 0, largest = 0;
    for (unsigned int c = 0; c < whole.size(); ++c)
      for (unsigned int q = 0; q < whole[c].size(); ++q)
      {
        difference = std::max(difference, (split[c][q] - whole[c][q]).norm());
        largest    = std::max(largest, whole[c][q].norm());
      }
    std::cout << "BEM interior stresses split over the processes: max "
              << "difference " << difference << " (max |sigma_B| " << largest
              << ")" << std::endl;
    check(difference == 0 && largest > 0,
          "split BEM interior evaluation equals the whole one");
  }

  // Both bodies on process 0 (process 1 only follows): the serial
  // computation with the broadcasts of a parallel run.
  const auto one = run(source_dir, "omega1: 0, omega2: 0");
  const auto f_a = contact_force(*balanced);
  const auto f_b = contact_force(*one);
  std::cout << "force " << f_a << " (two processes) and " << f_b
            << " (one); DD iterations "
            << balanced->get_contact_solver().history().size() << " and "
            << one->get_contact_solver().history().size() << std::endl;
  check(balanced->get_contact_solver().history().size() ==
          one->get_contact_solver().history().size(),
        "the same number of DD iterations");
  check(std::abs(f_a - f_b) <= 1e-10 * f_b, "the same contact force to 1e-10");

  // Every body on both processes: the meshes are partitioned and each
  // refinement repartitions them (a shared mesh: z-order halves, siblings
  // kept together), or p4est refines each process's cells of a distributed
  // mesh, balances the forest to one irregular hanging node per face and
  // repartitions (the estimator's BEM then gathers the boundary from both
  // processes and evaluates each one's own cells).
  const unsigned int serial_cells =
    balanced->get_bodies()[1]->get_triangulation().n_active_cells();
  for (const std::string mesh : {"shared", "distributed"})
  {
    const auto  all  = run(source_dir, "all", mesh);
    const auto &tria = dynamic_cast<const parallel::TriangulationBase<2> &>(
      all->get_bodies()[1]->get_triangulation());
    const bool is_forest =
      dynamic_cast<const parallel::distributed::Triangulation<2> *>(&tria);
    check(is_forest == (mesh == "distributed"),
          mesh + ": Omega_2 has the requested kind of mesh");
    const auto owned =
      Utilities::MPI::all_gather(world, tria.n_locally_owned_active_cells());
    std::cout << mesh << ": " << tria.n_global_active_cells()
              << " cells in Omega_2, " << owned[0] << " on process 0 and "
              << owned[1] << " on process 1" << std::endl;
    // (Each process checks the cells it knows.)
    check(Utilities::MPI::min(one_irregular(tria) ? 1 : 0, world) == 1,
          mesh + ": the partitioned adapted mesh is one-irregular");
    check(tria.n_global_active_cells() == serial_cells,
          mesh + ": the partitioned run refines to the same mesh");
    check(owned[0] + owned[1] == tria.n_global_active_cells() &&
            std::max(owned[0], owned[1]) - std::min(owned[0], owned[1]) <= 4,
          mesh + ": after refinement each process owns half of the cells");
    if (is_forest)
      // Owned, ghost and (coarser) artificial cells.
      check(Utilities::MPI::max(tria.n_active_cells(), world) <
              tria.n_global_active_cells(),
            mesh + ": every process holds fewer cells than the whole mesh");
    const auto f_all = contact_force(*all);
    std::cout << "force " << f_all << " (" << mesh << "); DD iterations "
              << all->get_contact_solver().history().size() << std::endl;
    check(all->get_contact_solver().history().size() ==
            one->get_contact_solver().history().size(),
          mesh + ": the same number of DD iterations");
    check(std::abs(f_all - f_b) <= 1e-10 * f_b,
          mesh + ": the same contact force to 1e-10");
  }

  const int failed = Utilities::MPI::max(failures, world);
  failures         = failed;
  return report();
}
