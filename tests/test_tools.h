// Helpers shared by the test programs: a checklist that counts failures,
// and a run of a scene file with overrides, quiet on the screen.
#ifndef ddcontact_tests_test_tools_h
#define ddcontact_tests_test_tools_h

#include <ddcontact/simulation.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace ddcontact
{
  namespace testing
  {
    /** The number of failed checks of this test program. */
    inline int failures = 0;

    /** |a - b| / |b|. */
    inline double
    relative(const double a, const double b)
    {
      return std::abs(a - b) / std::abs(b);
    }

    /** Print one check and count it if it failed. */
    inline void
    check(const bool ok, const std::string &what)
    {
      std::cout << (ok ? "  ok    " : "  FAIL  ") << what << std::endl;
      if (!ok)
        ++failures;
    }

    /** The end of main(): the verdict line and the exit code. */
    inline int
    report()
    {
      std::cout << (failures == 0 ? "PASSED" : "FAILED") << std::endl;
      return failures == 0 ? 0 : 1;
    }

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
    /** Every face of an active cell borders at most two active cells on its
     * other side: a refined neighbour face has two children, both leaves. */
    inline bool
    one_irregular(const Triangulation<2> &tria)
    {
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
        {
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
