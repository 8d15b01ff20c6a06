// DESCRIPTION: dd-newton and the monolithic solver give the same answer on
// an elastoplastic frictional scene: prm/cattaneo_mindlin.prm (Hertz's
// blocks with Coulomb friction, mu = 0.3, pressed, then sheared) with the
// lower block J2 with isotropic hardening, yielding below the surface in
// the press and growing its plastic zone under the shear, in four load
// steps. The two solvers share no code past the bodies' law: dd-newton
// solves the bodies one by one and relinearizes the interface problem at
// every Newton step, the monolithic solver runs one Newton method on all
// bodies and the contact law at once. Every step's normal and tangential
// force, peak pressure, plastic zone and largest equivalent plastic strain
// agree to the solvers' tolerances.
#include <ddcontact/simulation.h>

#include "scene_tools.h"

#include <cmath>
#include <functional>
#include <iostream>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                source_dir = (argc > 1) ? argv[1] : "..";

  const std::vector<std::string> scene = {
    "Output directory=plastic_solvers_agree_output",
    "Loading/Steps=4",
    "Body upper/Mesh/Box refinement=5",
    "Body lower/Mesh/Box refinement=5",
    "Body lower/Material/Law=j2-plasticity",
    "Body lower/Material/Yield stress=0.9",
    "Body lower/Material/Isotropic hardening=100"};
  std::vector<std::unique_ptr<Simulation>> runs;
  for (const std::string solver : {"dd-newton", "monolithic"})
    runs.push_back(run_scene(source_dir + "/prm/cattaneo_mindlin.prm",
                             scene,
                             {"Contact solver/Solver=" + solver}));
  const auto &a = runs[0]->summary().at("load_steps");
  const auto &b = runs[1]->summary().at("load_steps");
  check(a.size() == 4 && b.size() == 4, "four load steps each");
  const auto &last = a.back().at("bodies")[0];
  check(last.at("plastic_zone_measure").get<double>() > 0,
        "the lower block has yielded");
  check(std::abs(a.back().at("pairs")[0].at("force")[0].get<double>()) > 0.1,
        "the last step shears the contact");
  // Relative to each quantity's largest value over the steps; Tolerance
  // 1e-10 of both solvers and the bodies' Newton tolerance 1e-10: 1e-8
  // leaves the round-off of the stopping tests a hundredfold margin.
  const auto largest = [&](const auto &value)
  {
    double m = 0;
    for (unsigned int k = 0; k < a.size(); ++k)
      m = std::max(m, std::abs(value(a[k])));
    return m;
  };
  const std::vector<std::pair<std::string, std::function<double(const Json &)>>>
    quantities = {
      {"normal force",
       [](const Json &s)
       { return s.at("pairs")[0].at("normal_force").get<double>(); }},
      {"tangential force",
       [](const Json &s)
       { return s.at("pairs")[0].at("force")[0].get<double>(); }},
      {"peak pressure",
       [](const Json &s)
       { return s.at("pairs")[0].at("max_pressure").get<double>(); }},
      {"plastic zone",
       [](const Json &s)
       { return s.at("bodies")[0].at("plastic_zone_measure").get<double>(); }},
      {"largest equivalent plastic strain",
       [](const Json &s)
       {
         return s.at("bodies")[0]
           .at("largest_equivalent_plastic_strain")
           .get<double>();
       }}};
  for (const auto &[name, value] : quantities)
  {
    double difference = 0;
    for (unsigned int k = 0; k < a.size() && k < b.size(); ++k)
      difference = std::max(difference, std::abs(value(a[k]) - value(b[k])));
    check("dd-newton = monolithic: " + name, difference / largest(value), 1e-8);
  }
  return report();
}
