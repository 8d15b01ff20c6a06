// Cost of the BEM reference solution of the FEM-BEM estimator (22)-(27)
// against the FEM solve of the same body: the paper's Omega_2 = (-2,2) x
// (0,1), bottom clamped, unit pressure on top, uniform Q1 meshes of 1e3 to
// 5e5 cells (1e3 to 1e6 dofs). Times BEM assembly, factorization (dense
// LU, or the near-field preconditioner of GMRES), solve and the Somigliana
// stresses at all cell quadrature points, and FEM setup + factorization
// and solve. A second argument gives one size; a third, "lu" or "gmres",
// forces the BEM's solver ("auto" chooses by size); a fourth gives the
// element degree (1, default, or 2: Q2 body, quadratic boundary elements).
// Writes one CSV row per mesh to the file given as first argument (or to
// stdout). Run in Release: scripts/bem_benchmark.sh.
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>

#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/body/elastic_body.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>

using namespace ddcontact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, numbers::invalid_unsigned_int);
  std::ofstream file;
  if (argc > 1)
    file.open(argv[1]);
  std::ostream &csv = (argc > 1) ? file : std::cout;

  std::vector<unsigned int> target_cells = {
    1000, 3000, 10000, 30000, 100000, 250000, 500000};
  if (argc > 2)
    target_cells = {static_cast<unsigned int>(std::stoul(argv[2]))};

  csv << "cells,fem_dofs,bem_elements,bem_unknowns,interior_points,"
         "fem_setup_factorize_s,fem_solve_s,bem_assembly_s,bem_lu_s,"
         "bem_solve_s,bem_interior_s,bem_method,gmres_iterations,threads,"
         "rms_stress_difference"
      << std::endl;
  std::cerr << "threads: " << MultithreadInfo::n_threads() << std::endl;

  for (const unsigned int target : target_cells)
  {
    // Cells 4 m x m on the 4 x 1 rectangle.
    const unsigned int m =
      static_cast<unsigned int>(std::lround(std::sqrt(target / 4.)));
    BodyParameters p;
    p.name                    = "omega2";
    p.corner_1                = Point<2>(-2., 0.);
    p.corner_2                = Point<2>(2., 1.);
    p.subdivisions            = {4 * m, m};
    p.material.youngs_modulus = 2.1e5;
    p.material.poisson_ratio  = 0.3;
    p.dirichlet               = "2: xy: 0; 0";
    p.neumann                 = "3: 0; -1";
    if (argc > 4)
      p.degree = std::stoul(argv[4]);
    ElasticBody<2> body(p, Constants());
    body.make_mesh();

    Timer timer;
    body.setup_and_factorize();
    const double fem_setup = timer.wall_time();
    timer.restart();
    body.solve();
    const double fem_solve = timer.wall_time();

    BoundaryElementSolver bem(body.get_elastic_constants(),
                              body.get_boundary_conditions());
    if (argc > 3 && std::string(argv[3]) != "auto")
      bem.set_solver_method(std::string(argv[3]) == "lu"
                              ? CollocationSystem::Method::dense_lu
                              : CollocationSystem::Method::hierarchical);
    bem.setup(body.get_dof_handler(), body.get_mapping());
    bem.solve();
    // As the estimator evaluates it: interpolated from the support points
    // inside the body.
    const auto sigma_b = bem.interpolated_stress_at_quadrature_points(
      body.get_dof_handler(), body.get_mapping(), body.get_cell_quadrature());
    const auto &t = bem.timings();

    // The estimator's raw ingredient, as a sanity check of the numbers:
    // RMS of sigma_B - sigma_F over all quadrature points, relative.
    const auto sigma_f    = body.stresses().at_quadrature_points();
    double     difference = 0, norm = 0;
    for (unsigned int c = 0; c < sigma_b.size(); ++c)
      for (unsigned int q = 0; q < sigma_b[c].size(); ++q)
      {
        const auto d = sigma_b[c][q] - sigma_f[c][q];
        difference += d * d;
        norm += sigma_b[c][q] * sigma_b[c][q];
      }

    csv << body.get_triangulation().n_active_cells() << ',' << body.n_dofs()
        << ',' << bem.n_elements() << ',' << bem.n_unknowns() << ','
        << bem.n_interior_points() << ',' << std::setprecision(4) << fem_setup
        << ',' << fem_solve << ',' << t.assembly << ',' << t.factorization
        << ',' << t.solve << ',' << t.interior << ','
        << (bem.uses_dense_lu() ? "lu" : "gmres") << ',' << t.iterations << ','
        << MultithreadInfo::n_threads() << ',' << std::sqrt(difference / norm)
        << std::endl;
    std::cerr << body.get_triangulation().n_active_cells()
              << " cells done: BEM interior " << t.interior << " s"
              << std::endl;
  }
  return 0;
}
