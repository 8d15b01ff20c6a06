// Helpers for the tests that run whole scenes: a run of a scene file with
// overrides, quiet on the screen, and the one-irregularity of a mesh.
#ifndef ddcontact_tests_scene_tools_h
#define ddcontact_tests_scene_tools_h

#include <ddcontact/simulation.h>

#include "test_tools.h"

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
