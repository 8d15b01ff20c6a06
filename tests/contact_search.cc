// DESCRIPTION: the contact search (doc/method.md section 1.1) on candidate
// surfaces of any extent: two elastic cylinders with the whole quarter arcs
// as zones against the plane-strain Hertz closed form (half-width, peak,
// horizontal force of the half model) and against the same meshes with cut
// arcs; zones that face away and bodies apart carry no force and warn; an
// expression gap below the meshes' distance warns with both figures; the
// contact patch test on non-matching meshes (uniform pressure and stress to
// round-off with exact contact)
#include <ddcontact/io/json.h>
#include <ddcontact/simulation.h>

#include "scene_tools.h"
#include "test_tools.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /**
   * A quarter disc of radius R touching the origin, centre (0, s R) (s = 1:
   * the lower right quarter of the upper cylinder; s = -1: the upper right
   * quarter of the lower one), meshed by gmsh with triangles of size h near
   * the origin. Its arc is split at @p cut degrees from the origin; with
   * @p whole_arc both parts are the contact id, else only the part near the
   * origin (the rest gets id + 3). Flat side: id + 1, symmetry line: id + 2.
   */
  std::string
  quarter_disc(const std::string &name,
               const double       R,
               const double       s,
               const double       h,
               const unsigned int id,
               const bool         whole_arc)
  {
    const double       cut = 10. * M_PI / 180.;
    std::ostringstream geo;
    geo.precision(17);
    geo << "R = " << R << "; s = " << s << ";\n"
        << "Point(1) = {0, s*R, 0, 1};\nPoint(2) = {0, 0, 0, 1};\n"
        << "Point(3) = {R, s*R, 0, 1};\n"
        << "Point(4) = {R*" << std::sin(cut) << ", s*R*(1 - " << std::cos(cut)
        << "), 0, 1};\n"
        << "Circle(1) = {2, 1, 4};\nCircle(4) = {4, 1, 3};\n"
        << "Line(2) = {3, 1};\nLine(3) = {1, 2};\n"
        << "Curve Loop(1) = {1, 4, 2, 3};\nPlane Surface(1) = {1};\n";
    if (whole_arc)
      geo << "Physical Curve(" << id << ") = {1, 4};\n";
    else
      geo << "Physical Curve(" << id << ") = {1};\nPhysical Curve(" << id + 3
          << ") = {4};\n";
    geo << "Physical Curve(" << id + 1 << ") = {2};\nPhysical Curve(" << id + 2
        << ") = {3};\nPhysical Surface(1) = {1};\n"
        << "Field[1] = Distance;\nField[1].PointsList = {2};\n"
        << "Field[2] = Threshold;\nField[2].InField = 1;\n"
        << "Field[2].SizeMin = " << h << ";\nField[2].SizeMax = R/5;\n"
        << "Field[2].DistMin = 0.05*R;\nField[2].DistMax = 0.8*R;\n"
        << "Background Field = 2;\nMesh.MeshSizeExtendFromBoundary = 0;\n"
        << "Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeFromCurvature = 0;\n";
    const std::string file = name + (whole_arc ? "_whole" : "_cut") + ".geo";
    std::ofstream(file) << geo.str();
    return file;
  }

  /** The scene of two cylinders R1 = 1 (E = 1000, nu = 0.3) on R2 = 2
   * (E = 2000, nu = 0.25), half model, the upper one pressed by the
   * traction q on its flat top (half force q R1). Every contact and solver
   * entry at its default: exact contact by dd-newton. */
  std::string
  cylinders_scene(const bool whole_arc)
  {
    const std::string upper =
      quarter_disc("upper", 1., 1., 0.0025, 11, whole_arc);
    const std::string lower =
      quarter_disc("lower", 2., -1., 0.004, 21, whole_arc);
    std::ostringstream prm;
    prm << "set Scene name = cylinders\nset Bodies = upper, lower\n"
        << "set Contact pairs = S\nset Constants = q=0.5\n"
        << "subsection Contact pair S\n  set Body 1 = upper\n"
        << "  set Boundary id 1 = 11\n  set Body 2 = lower\n"
        << "  set Boundary id 2 = 21\n  set Gap type = geometric\nend\n";
    const auto body = [&](const std::string &name,
                          const std::string &file,
                          const std::string &E,
                          const std::string &nu,
                          const std::string &conditions,
                          const unsigned int id)
    {
      prm << "subsection Body " << name << "\n  subsection Mesh\n"
          << "    set Type = file\n    set File = " << file << "\n  end\n"
          << "  subsection Element\n    set Cell type = triangle\n  end\n"
          << "  subsection Material\n    set Young's modulus = " << E
          << "\n    set Poisson's ratio = " << nu << "\n  end\n"
          << "  subsection Boundary conditions\n"
          << conditions << "    set Contact ids = " << id << "\n  end\nend\n";
    };
    body("upper",
         upper,
         "1000",
         "0.3",
         "    set Dirichlet = 13: x: 0; 0\n    set Neumann = 12: 0; -q\n",
         11);
    body("lower",
         lower,
         "2000",
         "0.25",
         "    set Dirichlet = 22: xy: 0; 0 | 23: x: 0; 0\n",
         21);
    const std::string file =
      std::string("cylinders_") + (whole_arc ? "whole" : "cut") + ".prm";
    std::ofstream(file) << prm.str();
    return file;
  }

  /** Two blocks: @p upper_box over the base [0, 1] x [0, 1]. */
  std::string
  blocks_scene(const std::string &name, const std::string &contents)
  {
    std::ofstream(name + ".prm") << contents;
    return name + ".prm";
  }

  const std::string blocks =
    "set Scene name = blocks\nset Bodies = block, base\n"
    "set Contact pairs = S\n"
    "subsection Contact solver\n  set Solver = dd-newton\n"
    "  set Tolerance = 1e-12\nend\n"
    "subsection Contact pair S\n  set Body 1 = block\n"
    "  set Boundary id 1 = 2\n  set Body 2 = base\n  set Boundary id 2 = 3\n"
    "  set Gap type = geometric\nend\n"
    "subsection Body block\n  subsection Mesh\n    set Corner 1 = 0, 1\n"
    "    set Corner 2 = 1, 2\n    set Subdivisions = 7, 3\n  end\n"
    "  subsection Material\n    set Young's modulus = 1000\n"
    "    set Poisson's ratio = 0.3\n  end\n"
    "  subsection Boundary conditions\n    set Dirichlet = 0: x: 0; 0\n"
    "    set Neumann = 3: 0; -2\n    set Contact ids = 2\n  end\nend\n"
    "subsection Body base\n  subsection Mesh\n    set Corner 1 = 0, 0\n"
    "    set Corner 2 = 1, 1\n    set Subdivisions = 5, 4\n  end\n"
    "  subsection Material\n    set Young's modulus = 3000\n"
    "    set Poisson's ratio = 0.2\n  end\n"
    "  subsection Boundary conditions\n"
    "    set Dirichlet = 2: y: 0; 0 | 0: x: 0; 0\n"
    "    set Contact ids = 3\n  end\nend\n";

  /** Whether one of the run's warnings contains all of @p fragments. */
  bool
  warns(const Simulation &s, const std::vector<std::string> &fragments)
  {
    for (const auto &w : s.get_contact_pairs()[0]->setup_warnings())
    {
      bool all = true;
      for (const auto &f : fragments)
        all = all && w.find(f) != std::string::npos;
      if (all)
      {
        std::cout << "  warning: " << w << std::endl;
        return true;
      }
    }
    return false;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 1. Hertz with the whole arcs as zones (doc/verification.md, 2.2).
  std::cout << "two cylinders, whole quarter arcs as zones" << std::endl;
  const auto whole = run_scene(
    cylinders_scene(true), {"Output directory=contact_search_whole"}, {});
  const auto cut = run_scene(
    cylinders_scene(false), {"Output directory=contact_search_cut"}, {});
  {
    const auto   state = whole->get_contact_solver().contact_state(0);
    const double P     = 2 * state.force_1[1]; // the whole force
    const double R     = 1. / (1. / 1. + 1. / 2.);
    const double E  = 1. / ((1 - 0.3 * 0.3) / 1000 + (1 - 0.25 * 0.25) / 2000);
    const double a  = std::sqrt(4 * P * R / (M_PI * E));
    const double p0 = 2 * P / (M_PI * a);
    // The load is q R1 = 0.5 on the half model: all of it goes through the
    // contact (equilibrium of the upper body).
    check("vertical contact force = q R1 (equilibrium)",
          relative(state.force_1[1], 0.5),
          1e-8);
    // Half-width from the whole profile (scene_tools.h).
    const double a_fit = hertz_half_width(*whole);
    double       fx    = 0;
    std::cout << "  P = " << P << ", a = " << a_fit << " (Hertz " << a
              << "), p0 = " << state.max_pressure << " (Hertz " << p0 << ")"
              << std::endl;
    // About 14 faces of h = 0.0025 cover the half zone a = 0.034: the
    // peak's error is O((h/a)^2) ~ 0.5 %, and the closed form itself
    // assumes a << R (a/R* = 5 %, its correction to a and p0 is below
    // 1 %, doc/verification.md 2.2). Each stays within 2 %.
    check("half-width a against Hertz", relative(a_fit, a), 0.02);
    check(
      "peak pressure p0 against Hertz", relative(state.max_pressure, p0), 0.02);
    // The horizontal force of the half model: the pressure along n_1 =
    // (x/R1, -...) on the upper body, int_0^a p0 sqrt(1 - x^2/a^2) x/R1 dx
    // = p0 a^2 / (3 R1), to the same accuracy as a^2 p0 (two errors of 2 %
    // and the arc's faceting).
    fx = p0 * a * a / 3.;
    check("horizontal force of the half model against p0 a^2/(3 R1)",
          relative(-state.force_1[0], fx),
          0.06);
    const auto &found = whole->get_contact_pairs()[0]->search_report();
    check(found.min_gap >= 0 && found.n_points < found.n_examined,
          "no initial overlap on the faceted arcs; far points have no partner");
    std::cout << "  " << found.n_points << " of " << found.n_examined
              << " points have a partner" << std::endl;

    // One peak (issue 30): summary.json's max_pressure is the largest
    // pressure of contact_S.csv (written with 12 digits), not the largest
    // nodal multiplier, which the CSV and the VTU do not show.
    std::ifstream csv("contact_search_whole/contact_S.csv");
    std::string   line;
    std::getline(csv, line);
    double csv_peak = 0;
    while (std::getline(csv, line))
    {
      std::istringstream row(line);
      std::string        x1, x2, pressure;
      std::getline(row, x1, ',');
      std::getline(row, x2, ',');
      std::getline(row, pressure, ',');
      csv_peak = std::max(csv_peak, std::stod(pressure));
    }
    const double summary_peak =
      whole->summary()["contact"][0]["max_pressure"].get<double>();
    check("summary.json max_pressure = the CSV's largest pressure",
          relative(summary_peak, csv_peak),
          1e-10);

    // The same meshes with the arcs cut at 10 degrees: every point that
    // can touch is a candidate either way, so the answers agree to the
    // solver's tolerance.
    const auto cut_state = cut->get_contact_solver().contact_state(0);
    check("peak with whole arcs = peak with cut arcs",
          relative(state.max_pressure, cut_state.max_pressure),
          1e-9);
    check("force with whole arcs = force with cut arcs",
          (state.force_1 - cut_state.force_1).norm() / state.force_1.norm(),
          1e-9);
  }

  // 2. A zone that faces away: the block's top against the base's bottom
  // (normals opposed, but the base lies behind the block's top).
  std::cout << "a zone that faces away" << std::endl;
  const std::string away = blocks_scene("faces_away", blocks);
  {
    const auto s = run_scene(away,
                             {"Output directory=contact_search_away"},
                             {"Contact pair S/Boundary id 1=3",
                              "Contact pair S/Boundary id 2=2",
                              "Body block/Boundary conditions/Contact ids=3",
                              "Body block/Boundary conditions/Dirichlet=0: "
                              "xy: 0; 0",
                              "Body block/Boundary conditions/Neumann=2: 0; -1",
                              "Body base/Boundary conditions/Contact ids=2",
                              "Body base/Boundary conditions/Dirichlet=3: y: "
                              "0; 0 | 0: x: 0; 0"});
    check(contact_force(*s) == 0., "zero contact force");
    check(warns(*s, {"faces the zone", "face away", "Search distance"}),
          "the warning says the zones face away");
  }

  // 3. Bodies 0.3 apart with an expression gap left at 0: the warning
  // gives both figures, and the contact is held at the expression's
  // distance (the user's model), which the warning names.
  std::cout << "bodies apart, Gap = 0" << std::endl;
  {
    const std::vector<std::string> apart = {
      "Body block/Mesh/Corner 1=0, 1.3",
      "Body block/Mesh/Corner 2=1, 2.3",
      "Contact pair S/Gap type=expression",
      "Body block/Boundary conditions/Dirichlet=0: xy: 0; 0"};
    const auto s =
      run_scene(away, {"Output directory=contact_search_apart"}, apart);
    check(warns(*s, {"Gap expression '0' gives 0", "0.3 apart"}),
          "the warning gives the expression's 0 and the meshes' 0.3");
    // Farther than the search distance (twice the longest zone face, 0.2;
    // a tenth of the blocks' diameter is less): no
    // partner, no force, and the warning.
    auto far = apart;
    far[0]   = "Body block/Mesh/Corner 1=0, 2";
    far[1]   = "Body block/Mesh/Corner 2=1, 3";
    const auto f =
      run_scene(away, {"Output directory=contact_search_far"}, far);
    check(contact_force(*f) == 0., "bodies 1.0 apart: zero contact force");
    check(warns(*f, {"within the search distance 0.4"}),
          "bodies 1.0 apart: the warning names the search distance");
  }

  // 4. The contact patch test on non-matching meshes (7 faces on 5):
  // a uniform traction q = 2 on the block's top is carried as a uniform
  // pressure, and both bodies are in the uniaxial state sigma_22 = -q.
  std::cout << "contact patch test, non-matching meshes" << std::endl;
  {
    const auto s =
      run_scene(away, {"Output directory=contact_search_patch"}, {});
    const auto state = s->get_contact_solver().contact_state(0);
    double     worst = 0;
    for (const double sigma : state.sigma_n)
      worst = std::max(worst, std::abs(sigma + 2.) / 2.);
    check("pressure = q at every contact point", worst, 1e-10);
    double worst_stress = 0;
    for (unsigned int b = 0; b < 2; ++b)
      for (const Point<2> x :
           b == 0 ? std::vector<Point<2>>{{0.5, 1.02}, {0.91, 1.66}}
                  : std::vector<Point<2>>{{0.13, 0.97}, {0.77, 0.41}})
      {
        const auto v = s->get_bodies()[b]->stresses().at_point(x);
        worst_stress = std::max({worst_stress,
                                 std::abs(v.stress[1][1] + 2.) / 2.,
                                 std::abs(v.stress[0][0]) / 2.,
                                 std::abs(v.stress[0][1]) / 2.});
      }
    check("sigma_22 = -q, sigma_11 = sigma_12 = 0 in both bodies",
          worst_stress,
          1e-9);
  }
  return report();
}
