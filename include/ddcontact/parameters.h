#ifndef ddcontact_parameters_h
#define ddcontact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ddcontact/adaptivity/adaptation_parameters.h>
#include <ddcontact/body/body_parameters.h>
#include <ddcontact/body/parallel_parameters.h>
#include <ddcontact/contact/contact_pair_parameters.h>
#include <ddcontact/loading/loading_parameters.h>
#include <ddcontact/parameter_tools.h>
#include <ddcontact/solvers/contact_solver_parameters.h>

#include <ostream>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** A point at which displacement and stress of one body are reported. */
  struct ReportPoint
  {
    std::string body;
    Point<2>    x;
  };

  /**
   * The top level of a parameter file: the scene's name, where results go,
   * which bodies exist (each with its own "Body <name>" subsection), named
   * constants for expressions, and output options.
   */
  struct SceneParameters
  {
    std::string              scene_name       = "scene";
    std::string              output_directory = "output";
    std::vector<std::string> body_names;
    Constants                constants;
    std::vector<ReportPoint> points;
    bool                     write_vtu         = true;
    bool                     smoothed_stresses = true;
    unsigned int             n_threads         = 0; // 0 = all cores
    Geometry                 geometry          = Geometry::plane_strain;
    /** Loading: the quasi-static load steps of the load parameter t. */
    LoadingParameters loading;

    std::vector<BodyParameters>        bodies;
    std::vector<ContactPairParameters> contact_pairs;
    ContactSolverParameters            contact_solver;
    AdaptationParameters               adaptation;
    ParallelParameters                 parallel;

    /** Declare the scene entries and, for each name, a body subsection
     * and a contact pair subsection. */
    static void
    declare(ParameterHandler               &prm,
            const std::vector<std::string> &bodies,
            const std::vector<std::string> &pairs = {});

    void
    parse(ParameterHandler &prm);

    /** Whether body @p name is in a contact pair. */
    bool
    in_contact_pair(const std::string &name) const
    {
      for (const auto &pair : contact_pairs)
        if (pair.body_1 == name || pair.body_2 == name)
          return true;
      return false;
    }
  };

  /**
   * Reads a parameter file the way the executable does: a first pass
   * learns the names of the bodies, then all subsections are declared and
   * the file is parsed strictly (an unknown entry is an error). Overrides
   * "Section/Entry=value" are applied after the file. Every failure is an
   * InputError naming the file or the entry.
   */
  class ParameterReader
  {
  public:
    ParameterReader(const std::string              &filename,
                    const std::vector<std::string> &overrides);

    /** The scene as read, checked. */
    const SceneParameters &
    scene() const
    {
      return scene_parameters;
    }

    /** Print all entries with their documentation (and current values);
     * with @p json in deal.II's JSON, with the entries' patterns. */
    void
    print(std::ostream &out, bool json = false) const;

    /** The parameters as used, to copy into the output directory. */
    void
    write_used(const std::string &filename) const;

    /** Declared but empty: for --print-parameters without a file. */
    static void
    print_defaults(std::ostream &out, bool json = false);

  private:
    mutable ParameterHandler prm;
    SceneParameters          scene_parameters;
  };

} // namespace ddcontact

#endif
