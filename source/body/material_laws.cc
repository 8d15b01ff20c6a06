#include <ddcontact/body/laws/linear_elastic_law.h>
#include <ddcontact/body/material_laws.h>

namespace ddcontact
{
  namespace
  {
    /** A row without entries of its own. */
    void
    no_entries(ParameterHandler &)
    {
    }

    MaterialLawConstants
    read_no_entries(ParameterHandler &, const std::string &)
    {
      return {};
    }
  } // namespace

  namespace
  {
    /** The table itself (register_material_law() adds rows). */
    std::vector<MaterialLawInfo> &
    table_of_laws()
    {
      static std::vector<MaterialLawInfo> table = []
      {
        std::vector<MaterialLawInfo> rows;
        {
          MaterialLawInfo row;
          row.name = "linear-elastic";
          row.description =
            "isotropic linear elasticity, Hooke's law sigma = lambda tr(eps) "
            "I + 2 mu eps of Young's modulus and Poisson's ratio (factorized "
            "once per mesh)";
          row.linear              = true;
          row.path_dependent      = false;
          row.reduced_integration = true;
          row.declare             = no_entries;
          row.parse               = read_no_entries;
          row.create =
            [](const ElasticConstants &constants, const MaterialLawConstants &)
          { return std::make_shared<const LinearElasticLaw>(constants); };
          rows.push_back(row);
        }
        return rows;
      }();
      return table;
    }
  } // namespace

  const std::vector<MaterialLawInfo> &
  material_laws()
  {
    return table_of_laws();
  }

  void
  register_material_law(const MaterialLawInfo &row)
  {
    for (const auto &other : table_of_laws())
      AssertThrow(other.name != row.name,
                  ExcMessage("a material law '" + row.name +
                             "' is in the table already"));
    table_of_laws().push_back(row);
  }

  const MaterialLawInfo &
  material_law_info(const std::string &name)
  {
    for (const auto &row : material_laws())
      if (row.name == name)
        return row;
    AssertThrow(false, ExcMessage("no material law '" + name + "'"));
    return material_laws().front();
  }

  Patterns::Selection
  material_law_pattern()
  {
    std::string names;
    for (const auto &row : material_laws())
      names += (names.empty() ? "" : "|") + row.name;
    return Patterns::Selection(names);
  }

  std::string
  material_law_documentation()
  {
    std::string text = "The body's constitutive law: ";
    for (const auto &row : material_laws())
      text += (&row == &material_laws().front() ? "" : "; ") + row.name +
              (&row == &material_laws().front() ? " (the default): " : ": ") +
              row.description;
    return text + ".";
  }

  std::shared_ptr<const MaterialLaw>
  create_material_law(const std::string          &name,
                      const ElasticConstants     &constants,
                      const MaterialLawConstants &own)
  {
    return material_law_info(name).create(constants, own);
  }
} // namespace ddcontact
