#include <ddcontact/body/laws/j2_plasticity_law.h>
#include <ddcontact/body/laws/linear_elastic_law.h>
#include <ddcontact/body/material_laws.h>
#include <ddcontact/parameter_tools.h>

#include <cmath>

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
    /** j2-plasticity's entries: empty defaults, so that a body of another
     * law that sets one is told (MaterialLawInfo::entries). */
    void
    declare_j2_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Yield stress",
                        "",
                        Patterns::Anything(),
                        "j2-plasticity: the uniaxial yield stress sigma_y "
                        "[stress], > 0 (required by that law; von Mises: "
                        "the shear yield stress is sigma_y / sqrt(3)).");
      prm.declare_entry("Isotropic hardening",
                        "",
                        Patterns::Anything(),
                        "j2-plasticity: the linear isotropic hardening "
                        "modulus H_iso [stress], >= 0 (empty: 0); the yield "
                        "stress grows by H_iso times the equivalent plastic "
                        "strain.");
      prm.declare_entry("Kinematic hardening",
                        "",
                        Patterns::Anything(),
                        "j2-plasticity: the linear kinematic (Prager) "
                        "hardening modulus H_kin [stress], >= 0 (empty: 0). "
                        "H_iso = H_kin = 0 is perfect plasticity; in "
                        "uniaxial stress the slope after yield is E H / (E + "
                        "H), H = H_iso + H_kin.");
    }

    MaterialLawConstants
    read_j2_entries(ParameterHandler &prm, const std::string &section)
    {
      MaterialLawConstants own;
      const auto           read = [&](const std::string &entry)
      {
        const std::string text = Utilities::trim(prm.get(entry));
        return text.empty() ? 0. : parsing::parse_double(text, section + entry);
      };
      if (Utilities::trim(prm.get("Yield stress")).empty())
        throw InputError(section +
                         "Yield stress: required by Law = j2-plasticity "
                         "(the uniaxial yield stress, > 0)");
      own["Yield stress"] = read("Yield stress");
      if (!(own["Yield stress"] > 0.))
        throw InputError(section + "Yield stress = " + prm.get("Yield stress") +
                         " must be > 0");
      const double E = prm.get_double("Young's modulus");
      for (const std::string entry :
           {"Isotropic hardening", "Kinematic hardening"})
      {
        own[entry] = read(entry);
        // Softening (H < 0) makes the tangent singular at 3 mu + H = 0 and
        // the answer mesh-dependent; a modulus far above E is no plasticity.
        if (!(own[entry] >= 0. && own[entry] <= 1e6 * std::abs(E)))
          throw InputError(section + entry + " = " + prm.get(entry) +
                           " must be >= 0 (softening is not supported: it "
                           "makes the tangent singular) and at most 1e6 E");
      }
      return own;
    }

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
        {
          MaterialLawInfo row;
          row.name = "j2-plasticity";
          row.description =
            "von Mises elastoplasticity with linear isotropic and kinematic "
            "hardening (entries Yield stress, Isotropic hardening, Kinematic "
            "hardening), backward-Euler radial return with its consistent "
            "tangent; the plastic strain is committed per load step "
            "(doc/materials.md)";
          row.linear              = false;
          row.path_dependent      = true;
          row.reduced_integration = false;
          row.entries             = {
                        "Yield stress", "Isotropic hardening", "Kinematic hardening"};
          row.declare = declare_j2_entries;
          row.parse   = read_j2_entries;
          row.create  = [](const ElasticConstants     &constants,
                          const MaterialLawConstants &own)
          {
            return std::make_shared<const J2PlasticityLaw>(
              constants,
              own.at("Yield stress"),
              own.at("Isotropic hardening"),
              own.at("Kinematic hardening"));
          };
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
