#include <deal.II/base/utilities.h>

#include <ddcontact/contact/contact_pair_parameters.h>

#include <cmath>
#include <sstream>

namespace ddcontact
{
  DDCONTACT_SELECTION(ContactFormulation,
                      {"exact", ContactFormulation::exact},
                      {"penalty", ContactFormulation::penalty})
  DDCONTACT_SELECTION(FrictionLaw,
                      {"none", FrictionLaw::none},
                      {"tresca", FrictionLaw::tresca},
                      {"coulomb", FrictionLaw::coulomb})
  DDCONTACT_SELECTION(GapType,
                      {"expression", GapType::expression},
                      {"geometric", GapType::geometric})
  DDCONTACT_SELECTION(GapEvaluation,
                      {"nodes", GapEvaluation::nodes},
                      {"points", GapEvaluation::points})
  DDCONTACT_SELECTION(PenaltyType,
                      {"relative", PenaltyType::relative},
                      {"absolute", PenaltyType::absolute})

  // Long: one entry per parameter of the section, in the order of
  // doc/parameters.md.
  void
  ContactPairParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Body 1",
                      "",
                      Patterns::Anything(),
                      "Body whose zone S_1 carries the contact integral.");
    prm.declare_entry("Boundary id 1",
                      "0",
                      Patterns::Integer(0, 254),
                      "Boundary id of S_1 on body 1.");
    prm.declare_entry("Body 2", "", Patterns::Anything(), "The opposite body.");
    prm.declare_entry("Boundary id 2",
                      "0",
                      Patterns::Integer(0, 254),
                      "Boundary id of S_2 on body 2.");
    prm.declare_entry(
      "Formulation",
      "exact",
      selection_pattern<ContactFormulation>(),
      "exact (the default): exact contact, no penetration -- with Solver = "
      "dd-newton solved directly with one pressure multiplier per node of "
      "S_1, with dd and monolithic by Uzawa updates of the penalty (an "
      "augmented Lagrangian, Contact solver/Uzawa). penalty: the penalty (15) "
      "with "
      "theta from Penalty type and Penalty, as in the paper (a soft penalty "
      "leaves a penetration and underestimates the peak pressure). All "
      "pairs of a scene take the same formulation.");
    prm.declare_entry("Gap type",
                      "expression",
                      selection_pattern<GapType>(),
                      "expression: f_n(x) given below (the paper's scene, "
                      "both zones on one line); geometric: f_n(x) = (P(x) - "
                      "x) . n_1, the distance to the orthogonal projection "
                      "P(x) of x on S_2 (curved surfaces).");
    prm.declare_entry("Gap",
                      "0",
                      Patterns::Anything(),
                      "Initial normal gap f_n(x) [length], an expression in "
                      "x, y and the constants (Gap type = expression).");
    prm.declare_entry(
      "Interference",
      "0",
      Patterns::Double(),
      "An interference fit's overlap delta [length], taken off the gap on "
      "the whole zone (f_n - delta, either Gap type): a press or shrink fit "
      "on meshes that touch; negative: a clearance.");
    prm.declare_entry(
      "Gap evaluation",
      "nodes",
      selection_pattern<GapEvaluation>(),
      "Gap type = expression. nodes: f_n interpolated on every face of S_1 "
      "from its values at the face's nodes (body 1's degree), the gap of the "
      "surfaces meshed through exact nodes, which the displacements can "
      "follow exactly; points: f_n at every contact point, as in the paper "
      "(a gap curved within a face the elements cannot follow: on the "
      "paper's scene with linear elements its peak pressure is 7 times "
      "farther off at refinement 3, doc/contact-solvers.md).");
    prm.declare_entry("Penalty type",
                      "relative",
                      selection_pattern<PenaltyType>(),
                      "relative: theta = c H / E_1 as in the paper; "
                      "absolute: theta = Penalty [length/stress].");
    prm.declare_entry("Penalty",
                      "0.05",
                      Patterns::Double(),
                      "c (relative) or theta (absolute) of the penalty (15); "
                      "> 0. With Formulation = exact, the penalty of the "
                      "Uzawa updates (Solver = dd, monolithic) and of the "
                      "initial guess; dd-newton's exact contact has none.");
    prm.declare_entry("Thickness",
                      "0",
                      Patterns::Double(0),
                      "H of theta = c H / E_1 [length]; 0: the extent of "
                      "body 1 along the contact normal.");
    prm.declare_entry(
      "Search distance",
      "auto",
      Patterns::Anything(),
      "d of the contact search [length] (doc/method.md, section 1.1): a "
      "point of S_1 is a contact candidate only where its outward normal "
      "line meets a face of S_2 that faces it (normals opposed within 60 "
      "degrees) at most d in front of it or behind it; other points carry "
      "no pressure. auto: a tenth of the smaller body's diameter (a wider gap "
      "cannot close under small strains), at least twice the longest zone "
      "face. Otherwise a length > 0.");
    prm.declare_entry(
      "Friction",
      "none",
      selection_pattern<FrictionLaw>(),
      "none (the default, the paper's frictionless contact); tresca: the "
      "tangential traction |t| <= g with slip only where |t| = g, g the "
      "Friction bound; coulomb: |t| <= mu p with mu the Friction "
      "coefficient (doc/friction.md), in load steps (Loading/Steps). Solved "
      "by Contact solver/Solver = dd-newton (the default) or monolithic; the "
      "paper's dd refuses it.");
    prm.declare_entry("Friction bound",
                      "0",
                      Patterns::Anything(),
                      "Friction = tresca: the slip bound g [stress] >= 0, an "
                      "expression in x, y and the constants.");
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Anything(),
                      "Friction = coulomb: the coefficient mu >= 0, an "
                      "expression in x, y and the constants.");
    prm.declare_entry("Gauss points",
                      "3",
                      Patterns::Integer(1, 10),
                      "Gauss points on each piece of the common refinement "
                      "of S_1 and S_2.");
  }

  void
  ContactPairParameters::parse(ParameterHandler &prm)
  {
    const std::string section = "Contact pair " + name + "/";
    body_1                    = Utilities::trim(prm.get("Body 1"));
    body_2                    = Utilities::trim(prm.get("Body 2"));
    boundary_id_1             = prm.get_integer("Boundary id 1");
    boundary_id_2             = prm.get_integer("Boundary id 2");
    formulation = parse_selection<ContactFormulation>(prm.get("Formulation"));
    gap_type    = parse_selection<GapType>(prm.get("Gap type"));
    gap_expression = prm.get("Gap");
    interference   = prm.get_double("Interference");
    gap_evaluation = parse_selection<GapEvaluation>(prm.get("Gap evaluation"));
    penalty_type   = parse_selection<PenaltyType>(prm.get("Penalty type"));
    penalty        = prm.get_double("Penalty");
    thickness      = prm.get_double("Thickness");
    n_gauss        = prm.get_integer("Gauss points");
    friction       = parse_selection<FrictionLaw>(prm.get("Friction"));
    friction_bound = prm.get("Friction bound");
    friction_coefficient       = prm.get("Friction coefficient");
    const std::string distance = Utilities::trim(prm.get("Search distance"));
    if (distance != "auto")
    {
      // A length > 0; "auto" stays 0.
      std::istringstream in(distance);
      double             d = 0;
      if (!(in >> d) || !(in >> std::ws).eof() || !(d > 0) || !std::isfinite(d))
        throw InputError(section + "Search distance: '" + distance +
                         "' is neither auto nor a length > 0");
      search_distance = d;
    }
    if (!std::isfinite(interference))
      throw InputError(section + "Interference: " + prm.get("Interference") +
                       " is not a finite length");
    if (!(penalty > 0.))
      throw InputError(section + "Penalty: " + prm.get("Penalty") +
                       " must be positive");
    if (body_1 == body_2)
      throw InputError(section + "Body 2: '" + body_2 +
                       "' is the same body as Body 1");
  }

} // namespace ddcontact
