#ifndef ddcontact_material_laws_h
#define ddcontact_material_laws_h

#include <deal.II/base/parameter_handler.h>

#include <ddcontact/body/material_law.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ddcontact
{
  /** A law's own entries of Body X/Material, as read (name -> value). */
  using MaterialLawConstants = std::map<std::string, double>;

  /**
   * One row of the table of material laws (Body X/Material/Law): its name
   * and description, what it is, and its entries and factory. Every law
   * reads Young's modulus and Poisson's ratio (its elastic constants); a
   * row declares and reads its further entries of Body X/Material itself.
   * A new law is its class, one row here and its test.
   */
  struct MaterialLawInfo
  {
    std::string name;
    std::string description;
    /** MaterialLaw::is_linear() and is_path_dependent() of its laws. */
    bool linear         = true;
    bool path_dependent = false;
    /** Whether Element/Volumetric integration = reduced applies (an
     * isotropic tangent, MaterialTangent::shear_form()). */
    bool reduced_integration = false;
    /** The names of the row's own entries of Body X/Material, declared
     * with an empty default: a body of another law that sets one is
     * refused (parse_material()). */
    std::vector<std::string> entries;

    /** Declare the row's own entries in the current subsection Material. */
    std::function<void(ParameterHandler &)> declare;
    /** Read and check them; @p section ("Body lower/Material/") names
     * them in errors (InputError). */
    std::function<MaterialLawConstants(ParameterHandler &,
                                       const std::string &section)>
      parse;
    /** The law of the elastic constants and the row's entries. */
    std::function<std::shared_ptr<const MaterialLaw>(
      const ElasticConstants &, const MaterialLawConstants &)>
      create;
  };

  /** The table of material laws; the first row is the default. */
  const std::vector<MaterialLawInfo> &
  material_laws();

  /** Add a row to the table (a law defined outside the library, e.g. by a
   * test or a program that links it), before any parameter file is read.
   * Its name must be new. */
  void
  register_material_law(const MaterialLawInfo &row);

  /** The row of @p name (one of the table's names). */
  const MaterialLawInfo &
  material_law_info(const std::string &name);

  /** Body X/Material/Law's values and documentation, from the table. */
  Patterns::Selection
  material_law_pattern();

  std::string
  material_law_documentation();

  /** The law @p name of @p constants and its own entries @p own. */
  std::shared_ptr<const MaterialLaw>
  create_material_law(const std::string          &name,
                      const ElasticConstants     &constants,
                      const MaterialLawConstants &own = {});
} // namespace ddcontact

#endif
