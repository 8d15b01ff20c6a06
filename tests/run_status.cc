// DESCRIPTION: what a run reports about itself: a run stopped by
// Max iterations while its residual falls is "not_converged" (not
// "diverged") and still writes the VTU/PVD of its last iterate; a growing
// residual is "diverged"; a soft penalty gets the over-penetration warning
// in summary.json, an exact contact (augmented Lagrangian) or a stiff
// penalty none; a monolithic run stopped by Max Newton iterations reports
// its last iterate
#include <ddcontact/io/json.h>
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /**
   * prm/stability/uniaxial.prm (two blocks pressed together, closed form
   * p = Delta / ((1 - nu^2)(H1 + H2)/E + theta)) into @p directory, which
   * is emptied first; the error of the run, if any, is in @p message.
   */
  std::unique_ptr<Simulation>
  run_uniaxial(const std::string              &source_dir,
               const std::string              &directory,
               const std::vector<std::string> &overrides,
               std::string                    &message)
  {
    std::filesystem::remove_all(directory);
    std::unique_ptr<Simulation> simulation;
    message = error_message<DivergenceError>(
      [&]
      {
        simulation = run_scene(source_dir + "/prm/stability/uniaxial.prm",
                               {"Output directory=" + directory},
                               overrides);
      });
    std::cout << directory << ": "
              << (message.empty() ? std::string("no error") : message)
              << std::endl;
    return simulation;
  }

  Json
  read_summary(const std::string &directory)
  {
    std::ifstream     in(directory + "/summary.json");
    std::stringstream text;
    text << in.rdbuf();
    return in ? Json::parse(text.str()) : Json();
  }

  std::string
  status_of(const Json &summary)
  {
    return summary.contains("status") ? summary["status"].get<std::string>()
                                      : "(no summary.json)";
  }

  /** The warnings of @p summary, printed. */
  std::vector<std::string>
  warnings_of(const Json &summary)
  {
    std::vector<std::string> warnings;
    if (summary.contains("warnings"))
      for (const auto &w : summary["warnings"])
        warnings.push_back(w.get<std::string>());
    for (const auto &w : warnings)
      std::cout << "  warning: " << w << std::endl;
    return warnings;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";
  std::string                      message;

  // (a) The fixed relaxation (21) at gamma = 0.04, below gamma* = 0.0535 of
  //     this scene (tests/stability.cc), contracts by about 1 - gamma per
  //     iteration: after 30 iterations the residual still falls, far above
  //     Tolerance = 1e-10. The run is not converged, not diverged, and
  //     writes its last iterate for ParaView.
  {
    const std::string directory = "run_status_not_converged";
    run_uniaxial(source_dir,
                 directory,
                 {"Contact solver/Domain decomposition/Relaxation=fixed",
                  "Contact solver/Domain decomposition/Gamma=0.04",
                  "Contact solver/Max iterations=30",
                  "Output/Write vtu=true"},
                 message);
    const Json summary = read_summary(directory);
    check(
      message_names(
        message,
        {"has not converged in 30 iterations", "falling", "Max iterations"}),
      "Max iterations with a falling residual: 'not converged', naming "
      "Max iterations");
    check(message.find("diverged") == std::string::npos,
          "... and not 'diverged'");
    check(status_of(summary) == "not_converged",
          "summary.json status not_converged");
    check(std::filesystem::exists(directory + "/solution.pvd") &&
            std::filesystem::exists(directory + "/bodies-0000.pvtu") &&
            std::filesystem::exists(directory + "/omega1-0000.vtu") &&
            std::filesystem::exists(directory + "/omega2-0000.vtu"),
          "the failed run wrote solution.pvd and the VTU of its last "
          "iterate");
    check(std::filesystem::exists(directory + "/history.csv") &&
            std::filesystem::exists(directory + "/contact_S.csv"),
          "... and history.csv and contact_S.csv");
    check(warnings_of(summary).empty(),
          "no penetration warning for an unconverged iterate");
  }

  // (b) gamma = 0.2 above gamma* = 0.0535: the residual grows by about
  //     |1 - gamma lambda_max| = 6.3 per iteration in the most compliant
  //     mode. Stopped by the divergence test, and also when Max iterations
  //     (3) comes first, it is "diverged", with the advice naming Gamma.
  for (const std::string max_iterations : {"5000", "3"})
  {
    const std::string directory = "run_status_diverged_" + max_iterations;
    run_uniaxial(source_dir,
                 directory,
                 {"Contact solver/Domain decomposition/Relaxation=fixed",
                  "Contact solver/Domain decomposition/Gamma=0.2",
                  "Contact solver/Max iterations=" + max_iterations},
                 message);
    check(message_names(message, {"diverged", "Gamma"}) ||
            message_names(message, {"made no progress", "Gamma"}),
          "growing residual (Max iterations = " + max_iterations +
            "): diverged, naming Gamma");
    check(message.find("has not converged") == std::string::npos,
          "... not reported as 'not converged'");
    check(status_of(read_summary(directory)) == "diverged",
          "summary.json status diverged");
  }

  // (c) Penetration theta p against the approach |u_1n| + |u_2n| = Delta
  //     (two equal blocks): theta / ((1 - nu^2)(H1 + H2)/E + theta) =
  //     c / (2 (1 - nu^2) + c), with H1 = H2 and theta = c H1/E. c = 1:
  //     35 % (> 5 %, warned); c = 0.01: 0.55 % (not warned); the
  //     augmented Lagrangian at c = 1 to 1e-3 of the approach: not warned.
  //     Neither reaches 10 % of the cells (0.25): theta p <= 5e-4.
  {
    const std::vector<std::string> converge = {"Contact solver/Tolerance=1e-9"};
    auto                           with = [&](std::vector<std::string> extra)
    {
      extra.insert(extra.begin(), converge.begin(), converge.end());
      return extra;
    };
    const auto soft = run_uniaxial(source_dir,
                                   "run_status_soft_penalty",
                                   with({"Contact pair S/Penalty=1"}),
                                   message);
    check(message.empty() && status_of(soft->summary()) == "converged",
          "soft penalty c = 1: converged");
    const auto warnings = warnings_of(soft->summary());
    check(
      warnings.size() == 1 &&
        message_names(warnings[0],
                      {"contact pair S", "approach", "Formulation = exact"}),
      "soft penalty: one warning naming the pair, the approach and the "
      "augmented Lagrangian");
    check(warnings == warnings_of(read_summary("run_status_soft_penalty")),
          "... also in summary.json on disk");
    const double approach =
      soft->summary()["contact"][0]["approach"].get<double>();
    std::cout << "approach " << approach << " (Delta = 1.366e-3)" << std::endl;
    check("approach |u_1n| + |u_2n| of two equal blocks = Delta",
          relative(approach, 1.366e-3),
          1e-6);

    for (const auto &remedy :
         {std::vector<std::string>{"Contact pair S/Penalty=1",
                                   "Contact pair S/Formulation=exact"},
          std::vector<std::string>{"Contact pair S/Penalty=0.01"}})
    {
      const auto exact =
        run_uniaxial(source_dir, "run_status_exact", with(remedy), message);
      check(message.empty() && status_of(exact->summary()) == "converged",
            remedy.back() + ": converged");
      check(warnings_of(exact->summary()).empty(),
            remedy.back() + ": no penetration warning");
    }
    check(soft->summary()["units"].is_string(), "summary.json states units");
  }

  // (d) The monolithic solver stopped by Max Newton iterations = 2: its
  //     first step (from zero, no point active) activates every point, its
  //     second solves that set exactly, and the third would only confirm it.
  //     No active set repeated: not converged, not a cycle.
  //     The failed run must report that last iterate, not the bodies' zero
  //     start: force p L with the closed form p of the uniaxial scene
  //     (uniaxial_pressure(), c = 0.05, L = 4), to the round-off of one
  //     direct solve.
  {
    const std::string directory = "run_status_monolithic";
    run_uniaxial(source_dir,
                 directory,
                 {"Contact solver/Solver=monolithic",
                  "Contact solver/Monolithic/Max Newton iterations=2"},
                 message);
    check(
      message_names(
        message,
        {"did not settle", "no active set repeated", "Max Newton iterations"}),
      "monolithic stopped by Max Newton iterations before any cycle: "
      "says so, naming the entry");
    check(message.find("cycles") == std::string::npos,
          "... and does not blame a cycle");
    const Json   summary = read_summary(directory);
    const double p       = uniaxial_pressure(0.05);
    check(status_of(summary) == "not_converged",
          "summary.json status not_converged");
    const double force = summary.contains("contact")
                           ? summary["contact"][0]["force"][0][1].get<double>()
                           : 0.;
    std::cout << "monolithic, last iterate: force " << force << " against "
              << 4 * p << std::endl;
    check("the failed monolithic run reports its last iterate (force)",
          relative(force, 4 * p),
          1e-8);

    // dd-newton stopped after one step, whose CG solves the all-active set
    // to Tolerance: too few steps to call the active set cycling.
    run_uniaxial(source_dir,
                 directory,
                 {"Contact solver/Solver=dd-newton",
                  "Contact solver/DD-Newton/Max Newton iterations=1"},
                 message);
    check(message_names(message,
                        {"too few steps to tell", "Max Newton iterations"}) &&
            message.find("does not settle") == std::string::npos,
          "dd-newton stopped after one step: names Max Newton iterations, "
          "blames no cycle");
    const Json after_one = read_summary(directory);
    check(status_of(after_one) == "not_converged",
          "... summary.json status not_converged");
    check("... and reports its last iterate (force)",
          relative(after_one["contact"][0]["force"][0][1].get<double>(), 4 * p),
          1e-8);
  }

  return report();
}
