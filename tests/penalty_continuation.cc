// DESCRIPTION: dd-newton's penalty continuation (Contact solver/DD-Newton/
// Penalty continuation) reaches the same exact-contact solution as the plain
// active-set method and the monolithic solver: on the slender plate of
// doc/stability.md in a fraction of the plain method's Newton steps and with
// counts that do not grow under refinement, on the paper scene with as many
// sets of body solves at h as at h/2; and it leaves small zones alone
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  struct Run
  {
    double       force;
    unsigned int newton_steps, sets;
  };

  Run
  measure(const Simulation &s, const std::string &name)
  {
    const auto counts = s.get_contact_solver().counts();
    const Run  run{
      contact_force(s), counts.newton_steps, counts.body_solve_sets};
    std::cout << name << ": force " << std::setprecision(12) << run.force
              << std::setprecision(6) << ", " << run.newton_steps
              << " Newton steps, " << run.sets << " sets of body solves"
              << std::endl;
    check(s.summary().at("status") == "converged", name + ": converged");
    return run;
  }

  std::string
  continuation(const bool on)
  {
    return std::string("Contact solver/DD-Newton/Penalty continuation=") +
           (on ? "true" : "false");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  const std::string paper = source_dir + "/prm/paper_two_bodies.prm";
  const std::vector<std::string> exact = {
    "Output directory=penalty_continuation_output",
    "Adaptation/Mode=none",
    "Contact solver/Solver=dd-newton",
    "Contact pair S/Formulation=exact",
    "Contact solver/Tolerance=1e-10",
    "Contact solver/DD-Newton/Max Newton iterations=300",
    "Contact solver/Monolithic/Max Newton iterations=300"};

  // 1. A plate of H/L = 0.01 clamped at its ends, pressed by a pressure onto
  //    the block across the gap r0 x^2 (scripts/stability_matrix.sh): its
  //    bending compliance is 1e3 times its surface's, and its zone shrinks
  //    from the overlap (about 200 nodes) to about 20. Both paths solve the
  //    same discrete problem to a residual of 1e-10, so their forces agree
  //    to about that times the condition of S on the zone: 1e-7. The plain
  //    active-set method releases about one node per end and step (135
  //    steps at refinement 1, 172 at 2, over 200 at 3); the continuation
  //    takes 25 and 30, and a fifth of the plain method's steps is asked.
  //    These are the counts of the hat functions as test functions
  //    (Multiplier basis = standard), which the plate keeps here. With the
  //    dual basis, the default, a node's state changes its own row alone
  //    and the plain method needs 83 steps (298 sets of body solves) at
  //    refinement 1, the continuation 34 (354 sets) and 29 at 2: the
  //    continuation still keeps the count flat in h, but no longer saves
  //    body solves at refinement 1 (doc/contact-solvers.md section 6).
  const std::vector<std::string> plate = {
    "Contact solver/Multiplier basis=standard",
    "Body omega1/Mesh/Corner 1=-2, 1",
    "Body omega1/Mesh/Corner 2=2, 1.04",
    "Body omega1/Mesh/Subdivisions=100, 1",
    "Body omega1/Element/Cell type=quadrilateral",
    "Body omega1/Element/Degree=2",
    "Body omega1/Boundary conditions/Dirichlet=0: xy: 0; 0 | 1: xy: 0; 0",
    "Body omega1/Boundary conditions/Neumann=3: 0; -q",
    "Constants=r0=1e-3, q=0.01"};
  const auto plate_run = [&](const unsigned int r, const bool on)
  {
    std::vector<std::string> overrides = plate;
    overrides.insert(
      overrides.end(),
      {continuation(on),
       "Body omega1/Mesh/Initial refinement=" + std::to_string(r),
       "Body omega2/Mesh/Initial refinement=" + std::to_string(r - 1)});
    return measure(*run_scene(paper, exact, overrides),
                   "plate, refinement " + std::to_string(r) +
                     (on ? ", continuation" : ", plain active set"));
  };
  const Run plain   = plate_run(1, false);
  const Run coarse  = plate_run(1, true);
  const Run refined = plate_run(2, true);
  check("plate: the continuation's force equals the plain method's",
        relative(coarse.force, plain.force),
        1e-7);
  // The monolithic solver (one direct solve of both bodies and the
  // multipliers per Newton step) is the independent reference: nodal
  // multipliers at c = 1e-8, whose force differs from c = 1e-10 and 1e-6 by
  // under 1e-10, so that the difference is dd-newton's residual, as above.
  {
    std::vector<std::string> overrides = plate;
    overrides.insert(overrides.end(),
                     {"Body omega1/Mesh/Initial refinement=1",
                      "Body omega2/Mesh/Initial refinement=0"});
    std::vector<std::string> monolithic = exact;
    monolithic.insert(monolithic.end(),
                      {"Contact solver/Solver=monolithic",
                       "Contact pair S/Formulation=penalty",
                       "Contact solver/Contact pressure=nodes",
                       "Contact pair S/Penalty=1e-8"});
    const auto s = run_scene(paper, monolithic, overrides);
    check(s->summary().at("status") == "converged",
          "plate, monolithic: converged");
    std::cout << "plate, refinement 1, monolithic: force "
              << std::setprecision(12) << contact_force(*s)
              << std::setprecision(6) << std::endl;
    check("plate: the continuation's force equals the monolithic solver's",
          relative(coarse.force, contact_force(*s)),
          1e-7);
  }
  check(5 * coarse.newton_steps <= plain.newton_steps,
        "plate: at most a fifth of the plain method's Newton steps");
  check(2 * refined.newton_steps <= 3 * coarse.newton_steps,
        "plate: Newton steps at h/2 within 1.5 times those at h");

  // 2. The paper scene, exact contact: refinement 3 (150 nodes overlap) and
  //    4 (h/2). The plain method needs 35 and 39 sets and grows to 50 at
  //    refinement 5; the continuation 26 and 24. The forces of both paths
  //    agree to the residual, as above.
  std::vector<Run> paper_runs;
  for (const unsigned int r : {3u, 4u})
    paper_runs.push_back(measure(
      *run_scene(
        paper,
        exact,
        {continuation(true),
         "Body omega1/Mesh/Initial refinement=" + std::to_string(1 + r),
         "Body omega2/Mesh/Initial refinement=" + std::to_string(r)}),
      "paper scene, refinement " + std::to_string(r) + ", continuation"));
  const Run paper_plain =
    measure(*run_scene(paper,
                       exact,
                       {continuation(false),
                        "Body omega1/Mesh/Initial refinement=4",
                        "Body omega2/Mesh/Initial refinement=3"}),
            "paper scene, refinement 3, plain active set");
  check("paper scene: the continuation's force equals the plain method's",
        relative(paper_runs[0].force, paper_plain.force),
        1e-7);
  check(2 * paper_runs[1].sets <= 3 * paper_runs[0].sets &&
          2 * paper_runs[0].sets <= 3 * paper_runs[1].sets,
        "paper scene: sets of body solves at h and h/2 within 1.5 times");

  // 3. Small zones (under 100 overlapping nodes, the coarse paper scene)
  //    run without stages: the same steps and force to the last bit.
  std::vector<Run> small;
  for (const bool on : {false, true})
    small.push_back(
      measure(*run_scene(paper,
                         exact,
                         {continuation(on),
                          "Body omega1/Mesh/Initial refinement=2",
                          "Body omega2/Mesh/Initial refinement=1"}),
              std::string("paper scene, refinement 1, ") +
                (on ? "continuation" : "plain active set")));
  check(small[0].force == small[1].force &&
          small[0].newton_steps == small[1].newton_steps,
        "small zone: no continuation stage");
  return report();
}
