#ifndef ddcontact_contact_pair_parameters_h
#define ddcontact_contact_pair_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <ddcontact/parameter_tools.h>

#include <string>

namespace ddcontact
{
  using namespace dealii;

  /** Contact pair/Gap type: f_n from an expression, or the distance to
   * the orthogonal projection on S_2. */
  enum class GapType
  {
    expression,
    geometric
  };

  /** Contact pair/Gap evaluation (Gap type = expression): interpolated on
   * each face of S_1 from the face's nodes, or the expression at every
   * contact point. */
  enum class GapEvaluation
  {
    nodes,
    points
  };

  /** Contact pair/Penalty type: theta = c H / E_1, or theta itself. */
  enum class PenaltyType
  {
    relative,
    absolute
  };

  /** Contact pair/Formulation: exact contact (no penetration) or the
   * penalty (15) with theta. */
  enum class ContactFormulation
  {
    exact,
    penalty
  };

  /** Contact pair/Friction: frictionless (the paper), Tresca (a given slip
   * bound g) or Coulomb (the slip bound mu p). */
  enum class FrictionLaw
  {
    none,
    tresca,
    coulomb
  };

  DDCONTACT_DECLARE_SELECTION(ContactFormulation)
  DDCONTACT_DECLARE_SELECTION(FrictionLaw)
  DDCONTACT_DECLARE_SELECTION(GapType)
  DDCONTACT_DECLARE_SELECTION(GapEvaluation)
  DDCONTACT_DECLARE_SELECTION(PenaltyType)

  /**
   * A contact pair: zone S_1 (boundary id of body 1, where the contact
   * integral is computed) facing S_2 (boundary id of body 2). Declared in
   * "Contact pair <name>", one per name listed in "Contact pairs".
   */
  struct ContactPairParameters
  {
    std::string        name;
    std::string        body_1, body_2;
    unsigned int       boundary_id_1 = 0, boundary_id_2 = 0;
    ContactFormulation formulation          = ContactFormulation::exact;
    GapType            gap_type             = GapType::expression;
    std::string        gap_expression       = "0";
    double             interference         = 0; // delta, off f_n
    GapEvaluation      gap_evaluation       = GapEvaluation::nodes;
    PenaltyType        penalty_type         = PenaltyType::relative;
    double             penalty              = 0.05; // c, or theta itself
    double             thickness            = 0;    // H; 0: from body 1's mesh
    unsigned int       n_gauss              = 3;    // Gauss points per piece
    double             search_distance      = 0;    // d of the search; 0: auto
    FrictionLaw        friction             = FrictionLaw::none;
    std::string        friction_bound       = "0"; // Tresca's g(x, y) [stress]
    std::string        friction_coefficient = "0"; // Coulomb's mu(x, y)

    /** The expression of the slip bound (Tresca) or of the coefficient
     * (Coulomb), and its entry's name. */
    const std::string &
    friction_expression() const
    {
      return friction == FrictionLaw::tresca ? friction_bound
                                             : friction_coefficient;
    }

    std::string
    friction_entry() const
    {
      return "Contact pair " + name + "/" +
             (friction == FrictionLaw::tresca ? "Friction bound"
                                              : "Friction coefficient");
    }

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };
} // namespace ddcontact

#endif
