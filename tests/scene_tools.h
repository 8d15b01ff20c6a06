// Helpers for the tests that run whole scenes: a run of a scene file with
// overrides, quiet on the screen, the paper's scene made quick, and the
// one-irregularity of a mesh.
#ifndef ddcontact_tests_scene_tools_h
#define ddcontact_tests_scene_tools_h

#include <ddcontact/iteration_errors.h>
#include <ddcontact/simulation.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace ddcontact
{
  namespace testing
  {
    /** Run @p scene_file with the entries @p defaults, then @p overrides
     * (later ones win), writing no VTU; the screen output is dropped. */
    inline std::unique_ptr<Simulation>
    run_scene(const std::string              &scene_file,
              std::vector<std::string>        defaults,
              const std::vector<std::string> &overrides)
    {
      defaults.push_back("Output/Write vtu=false");
      defaults.insert(defaults.end(), overrides.begin(), overrides.end());
      const ParameterReader     reader(scene_file, defaults);
      static std::ostringstream quiet;
      quiet.str("");
      auto simulation = std::make_unique<Simulation>(reader.scene(), quiet);
      simulation->run();
      return simulation;
    }
    /** The half-width c of a profile y = K sqrt(c^2 - x^2) sampled at
     * (@p x, @p y): y^2 is linear in x^2, so a least-squares line through
     * (x^2, y^2) gives c^2 = -intercept/slope. */
    inline double
    root_profile_half_width(const std::vector<double> &x,
                            const std::vector<double> &y)
    {
      double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;
      for (unsigned int q = 0; q < x.size(); ++q)
      {
        const double X = x[q] * x[q], Y = y[q] * y[q];
        s0 += 1;
        s1 += X;
        s2 += X * X;
        t0 += Y;
        t1 += X * Y;
      }
      const double slope     = (s0 * t1 - s1 * t0) / (s0 * s2 - s1 * s1);
      const double intercept = (t0 - slope * s1) / s0;
      return std::sqrt(-intercept / slope);
    }

    /**
     * The Hertz half-width of the pressure profile of pair @p pair, centred
     * on x1 = 0: p^2 = p0^2 (1 - x1^2/a^2) is linear in x1^2, so a
     * least-squares line through (x1^2, p^2) over the points in contact
     * gives a^2 = -intercept/slope. This uses the whole profile instead of
     * the last active point, whose position is known only to the spacing
     * of the contact points.
     */
    inline double
    hertz_half_width(const Simulation &s, const unsigned int pair = 0)
    {
      const auto          state = s.get_contact_solver().contact_state(pair);
      const auto         &pts   = s.get_contact_pairs()[pair]->points();
      std::vector<double> x, p;
      for (unsigned int q = 0; q < pts.size(); ++q)
        if (state.sigma_n[q] < 0)
        {
          x.push_back(pts[q].x[0]);
          p.push_back(state.sigma_n[q]);
        }
      return root_profile_half_width(x, p);
    }

    /** The magnitude of the contact force on body 1 of pair @p pair. */
    inline double
    contact_force(const Simulation &s, const unsigned int pair = 0)
    {
      return s.get_contact_solver().contact_state(pair).force_1.norm();
    }

    /** The contact pressure of prm/stability/uniaxial.prm, two equal blocks
     * (H = 1, L = 4, E = 2.1e5, nu = 0.3) pressed by Delta = 1.366e-3:
     * p = Delta / ((1 - nu^2)(H1 + H2)/E + theta) with theta = c H/E of a
     * relative penalty c (0: exact contact). Every stress state is
     * uniaxial, so that linear elements reproduce it. */
    inline double
    uniaxial_pressure(const double c)
    {
      const double Delta = 1.366e-3, E = 2.1e5, nu = 0.3, H = 1;
      return Delta / ((1 - nu * nu) * (H / E + H / E) + c * H / E);
    }

    /** The largest force_imbalance of the bodies in @p s's summary. */
    inline double
    largest_imbalance(const Simulation &s)
    {
      double largest = 0;
      for (const auto &b : s.summary().at("bodies"))
        largest = std::max(largest, b.at("force_imbalance").get<double>());
      return largest;
    }

    /** ||u_a - u_b|| / ||u_b|| over all bodies of two runs of one scene. */
    inline double
    displacement_difference(const Simulation &a, const Simulation &b)
    {
      double diff = 0, norm = 0;
      for (unsigned int i = 0; i < a.get_bodies().size(); ++i)
      {
        ddcontact::BodyVector d = a.get_bodies()[i]->get_solution();
        d -= b.get_bodies()[i]->get_solution();
        diff += d.norm_sqr();
        norm += b.get_bodies()[i]->get_solution().norm_sqr();
      }
      return std::sqrt(diff / norm);
    }

    /**
     * Run the paper's scene (prm/paper_two_bodies.prm) on coarse meshes,
     * into @p output_directory: Omega_1 refined once instead of twice,
     * Omega_2 @p omega2_refinement times, and the Anderson relaxation to a
     * residual of 1e-10, converged far below what the tests compare. Then
     * the entries @p defaults and @p overrides, as run_scene() takes them.
     */
    inline std::unique_ptr<Simulation>
    run_coarse_paper_scene(const std::string              &source_dir,
                           const std::string              &output_directory,
                           const unsigned int              omega2_refinement,
                           const std::vector<std::string> &defaults,
                           const std::vector<std::string> &overrides)
    {
      std::vector<std::string> all = {
        "Output directory=" + output_directory,
        "Body omega1/Mesh/Initial refinement=1",
        "Body omega2/Mesh/Initial refinement=" +
          std::to_string(omega2_refinement),
        "Contact solver/Domain decomposition/Relaxation=anderson",
        "Contact solver/Tolerance=1e-10"};
      all.insert(all.end(), defaults.begin(), defaults.end());
      return run_scene(
        source_dir + "/prm/paper_two_bodies.prm", all, overrides);
    }

    /** A run by @p run (a function of the overrides) with the fixed
     * relaxation (21) at @p gamma, above gamma*, must stop by a
     * DivergenceError naming Gamma instead of iterating on. */
    template <typename Run>
    void
    check_divergence_reported(const Run         &run,
                              const std::string &gamma,
                              const std::string &what)
    {
      const std::string message = error_message<DivergenceError>(
        [&]
        {
          run(std::vector<std::string>{
            "Contact solver/Domain decomposition/Relaxation=fixed",
            "Contact solver/Domain decomposition/Gamma=" + gamma});
        });
      std::cout << "gamma = " << gamma << ": " << message << std::endl;
      check(message_names(message, {"Gamma"}), what);
    }

    /** Every face of an active cell borders at most two active cells on its
     * other side: a refined neighbour face has two children, both leaves. */
    inline bool
    one_irregular(const Triangulation<2> &tria)
    {
      // (On a distributed mesh: the cells this process knows, its own and
      // its ghosts; every process checks its part.)
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
        {
          if (cell->is_artificial())
            break;
          const auto face = cell->face(f);
          if (face->has_children())
          {
            if (face->n_children() != 2)
              return false;
            for (unsigned int c = 0; c < 2; ++c)
              if (face->child(c)->has_children())
                return false;
          }
        }
      return true;
    }
  } // namespace testing
} // namespace ddcontact

#endif
