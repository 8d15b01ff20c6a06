// DESCRIPTION: quasi-static load steps (Loading/Steps) without friction:
// on the uniaxial scene the pressure of every step is the closed form at
// its load parameter t, with the paper's DD, dd-newton and the monolithic
// solver; on Hertz's scene three steps end where one step does (frictionless
// contact has no history); every step is recorded in summary.json; a new
// load time's load, assembled alone, is the whole assembly's
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  // 1. prm/stability/uniaxial.prm with the top displaced by Delta t in
  //    four steps: every stress state is uniaxial, and the pressure
  //    p = Delta t / ((1 - nu^2)(H1 + H2)/E + theta) is linear in t.
  for (const std::string solver : {"dd", "dd-newton", "monolithic"})
  {
    const double c   = 0.05;
    const auto   sim = run_scene(
      source_dir + "/prm/stability/uniaxial.prm",
      {"Output directory=load_steps_output"},
      {"Contact solver/Solver=" + solver,
         "Contact solver/Contact pressure=auto",
         "Loading/Steps=4",
         "Body omega1/Boundary conditions/Dirichlet=3: y: 0; -Delta*t | 0: "
           "x: 0; 0"});
    const auto &steps = sim->summary().at("load_steps");
    check(steps.size() == 4, solver + ": four load steps in summary.json");
    double error = 0;
    for (unsigned int k = 0; k < steps.size(); ++k)
    {
      const double t = steps[k].at("t").get<double>();
      const double p = steps[k].at("pairs")[0].at("max_pressure").get<double>();
      error          = std::max(error, relative(p, t * uniaxial_pressure(c)));
    }
    std::cout << solver << ": largest relative error of the pressure over "
              << "the steps " << error << std::endl;
    // The solvers' tolerance (Tolerance = 1e-10 of the scene; the DD's
    // relaxation stops on the relative residual).
    check(solver + ": the pressure of every step is the closed form at t",
          error,
          1e-7);
  }

  // 2. Hertz (dd-newton, exact contact) on a coarse mesh: pressed in three
  //    steps or in one, the same end (the history of frictionless contact
  //    is its current state).
  const std::vector<std::string> coarse   = {"Body upper/Mesh/Box refinement=4",
                                             "Body lower/Mesh/Box refinement=4",
                                             "Adaptation/Mode=none"};
  auto                           in_steps = coarse;
  in_steps.push_back("Loading/Steps=3");
  in_steps.push_back("Body upper/Boundary conditions/Dirichlet=3: xy: 0; "
                     "-Delta*t");
  const auto   one        = run_scene(source_dir + "/prm/hertz.prm",
                             {"Output directory=load_steps_output"},
                             coarse);
  const auto   three      = run_scene(source_dir + "/prm/hertz.prm",
                               {"Output directory=load_steps_output"},
                               in_steps);
  const double difference = displacement_difference(*three, *one);
  std::cout << "Hertz in three steps against one: displacements " << difference
            << " apart, forces " << contact_force(*three) << " and "
            << contact_force(*one) << std::endl;
  // dd-newton's Tolerance = 1e-10 of the overlap.
  check(
    "Hertz: three steps end where one does (displacements)", difference, 1e-8);
  check("Hertz: three steps end where one does (force)",
        relative(contact_force(*three), contact_force(*one)),
        1e-8);
  // 3. A new load time assembles the load alone on the same matrix
  //    (ElasticBody::set_load_time(), issue 60): the cells with a load or
  //    an inhomogeneous Dirichlet dof. Its load vector is the one a whole
  //    assembly gives at that t, to round-off: Dirichlet values, Neumann
  //    tractions and a body force all depending on t.
  {
    const auto sim = run_scene(
      source_dir + "/prm/two_bodies.prm",
      {"Output directory=load_steps_output"},
      {"Body lower/Boundary conditions/Dirichlet=2: xy: 0.001*t*x; -0.002*t",
       "Body lower/Boundary conditions/Neumann=3: 0; -p*t",
       "Body upper/Boundary conditions/Body force=0; -rho_g*t*t"});
    for (const auto &body : sim->get_bodies())
    {
      body->set_load_time(0.37);
      const Vector<double> load_only = body->get_load_vector();
      body->assemble_system();
      Vector<double> difference = body->get_load_vector();
      difference -= load_only;
      check("load at a new t: load-only against whole assembly, body " +
              body->name() + ", relative",
            difference.linfty_norm() / body->get_load_vector().linfty_norm(),
            1e-13);
    }
  }
  return report();
}
