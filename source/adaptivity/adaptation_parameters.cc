#include <ddcontact/adaptivity/adaptation_parameters.h>
#include <ddcontact/parameter_messages.h>

namespace ddcontact
{
  DDCONTACT_SELECTION(AdaptationMode,
                      {"none", AdaptationMode::none},
                      {"combined", AdaptationMode::combined},
                      {"nested", AdaptationMode::nested},
                      {"uniform", AdaptationMode::uniform})
  DDCONTACT_SELECTION(EstimatorType,
                      {"fem-bem", EstimatorType::fem_bem},
                      {"fem-bem-scaled", EstimatorType::fem_bem_scaled},
                      {"kelly", EstimatorType::kelly},
                      {"residual", EstimatorType::residual})
  DDCONTACT_SELECTION(MarkingType,
                      {"threshold", MarkingType::threshold},
                      {"fraction", MarkingType::fraction},
                      {"doerfler", MarkingType::doerfler})

  namespace
  {
    /** The estimators' capabilities: axisymmetric sections, nonlinear
     * laws. */
    const std::vector<std::pair<EstimatorType, EstimatorCapabilities>>
      estimator_table = {{EstimatorType::fem_bem, {false, false}},
                         {EstimatorType::fem_bem_scaled, {false, false}},
                         {EstimatorType::kelly, {true, false}},
                         {EstimatorType::residual, {true, false}}};
  } // namespace

  const EstimatorCapabilities &
  capabilities_of(const EstimatorType type)
  {
    for (const auto &[t, can] : estimator_table)
      if (t == type)
        return can;
    Assert(false, ExcInternalError());
    return estimator_table.front().second;
  }

  std::string
  estimators_with(bool EstimatorCapabilities::*capability)
  {
    std::vector<std::string> names;
    for (const auto &[t, can] : estimator_table)
      if (can.*capability)
        names.push_back(to_string(t));
    return parameter_messages::alternatives(names);
  }

  std::string
  to_string(const AdaptationMode value)
  {
    return selection_name(value);
  }

  std::string
  to_string(const EstimatorType value)
  {
    return selection_name(value);
  }

  std::string
  to_string(const MarkingType value)
  {
    return selection_name(value);
  }

  void
  AdaptationParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Mode",
      "none",
      selection_pattern<AdaptationMode>(),
      "none: the meshes stay as built; combined: the paper's algorithm "
      "(Fig. 2), one DD step (20)-(21) then one adaptation step per cycle, "
      "until the DD test holds and no cell is marked; nested: DD to "
      "convergence on each mesh, then one adaptation step; uniform: DD to "
      "convergence, then every cell of the adapted bodies is refined "
      "(Max cycles times).");
    prm.declare_entry("Bodies",
                      "",
                      Patterns::Anything(),
                      "The adapted bodies (comma separated); the paper "
                      "adapts Omega_2 only.");
    prm.declare_entry(
      "Estimator",
      "fem-bem",
      selection_pattern<EstimatorType>(),
      "fem-bem: eta_FB of (27) as printed, ||sigma_B - sigma_F||_e/|e| over "
      "||sigma_B||/|Omega|; fem-bem-scaled: the same with square roots of "
      "the areas (local RMS stress error over global RMS stress, which "
      "decreases with h); kelly: the Kelly gradient-jump estimator (no "
      "BEM), on quadrilaterals and triangles; residual: the explicit residual "
      "estimator of elasticity, Kelly's face jumps of the traction "
      "sigma(u_h) n, the residual g - sigma(u_h) n on the faces with "
      "traction data (Neumann, traction free, and the contact zone with "
      "the whole contact traction) and the cell residual f + div "
      "sigma(u_h) (no BEM).");
    prm.declare_entry("Marking",
                      "threshold",
                      selection_pattern<MarkingType>(),
                      "threshold: refine cells with eta > delta (the "
                      "paper); fraction: the Fraction of cells with the "
                      "largest eta; doerfler: the fewest cells whose "
                      "eta^2 sum to Fraction of the total.");
    prm.declare_entry("Delta",
                      "0.1",
                      Patterns::Double(0),
                      "Threshold delta of (27) (dimensionless).");
    prm.declare_entry("Fraction",
                      "0.3",
                      Patterns::Double(0, 1),
                      "Fraction for fraction and doerfler marking.");
    prm.declare_entry("Target error",
                      "none",
                      Patterns::Anything(),
                      "none, or a number in (0, 1): the adaptive loop stops "
                      "once the FEM-BEM estimate of the relative "
                      "energy-norm error of the adapted bodies, "
                      "||sigma_B - sigma_F||_E / ||sigma_B||_E, is at most "
                      "this (FEM-BEM estimators only).");
    prm.declare_entry("Max cycles",
                      "50",
                      Patterns::Integer(0),
                      "combined: maximum number of adaptation steps; "
                      "nested and uniform: number of meshes after the "
                      "first.");
    prm.declare_entry("Max level",
                      "10",
                      Patterns::Integer(0, 30),
                      "Cells at this refinement level are not refined.");
    prm.declare_entry("Max cells",
                      "200000",
                      Patterns::Integer(1),
                      "No refinement beyond this many cells per body.");
    prm.declare_entry("Write every mesh",
                      "true",
                      Patterns::Bool(),
                      "Write VTU (with eta, D_e, d_e, K_e) and the mesh of "
                      "every adaptation step; otherwise first and last.");
  }

  void
  AdaptationParameters::parse(ParameterHandler &prm)
  {
    mode             = parse_selection<AdaptationMode>(prm.get("Mode"));
    bodies           = parsing::split(prm.get("Bodies"), ',');
    estimator        = parse_selection<EstimatorType>(prm.get("Estimator"));
    marking          = parse_selection<MarkingType>(prm.get("Marking"));
    delta            = prm.get_double("Delta");
    fraction         = prm.get_double("Fraction");
    max_cycles       = prm.get_integer("Max cycles");
    max_level        = prm.get_integer("Max level");
    max_cells        = prm.get_integer("Max cells");
    write_every_mesh = prm.get_bool("Write every mesh");
    const std::string target = prm.get("Target error");
    target_error             = 0;
    if (Utilities::trim(target) != "none")
    {
      target_error = parsing::parse_double(target, "Adaptation/Target error");
      if (!(target_error > 0 && target_error < 1))
        throw InputError("Adaptation/Target error: " + target +
                         " is not in (0, 1); give a relative error such as "
                         "0.01, or none");
      if (!is_fem_bem(estimator) || mode == AdaptationMode::uniform)
        throw InputError("Adaptation/Target error: needs Estimator = "
                         "fem-bem or fem-bem-scaled and Mode = combined or "
                         "nested (only the FEM-BEM estimate is a relative "
                         "error)");
    }
    if (enabled() && bodies.empty())
      throw InputError("Adaptation/Bodies: Mode = " + to_string(mode) +
                       " needs at least one adapted body");
  }

} // namespace ddcontact
