#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/nodal_contact_law.h>

#include <cmath>

namespace ddcontact
{
  void
  NodalContactLaw::clear()
  {
    laws.clear();
    coefficients.clear();
    prescribed.clear();
  }

  void
  NodalContactLaw::add_node(const FrictionLaw law,
                            const double      coefficient,
                            const bool        prescribed_slip)
  {
    laws.push_back(law);
    coefficients.push_back(coefficient);
    prescribed.push_back(prescribed_slip);
  }

  NodeStatus
  NodalContactLaw::prescribed_slip_status(const unsigned int i,
                                          const Trial       &x) const
  {
    if (std::abs(x.r) <= 1e-10 * x.c_t * bound(i, x))
      return {NodeState::slip, 0};
    return {NodeState::slip, x.r > 0 ? 1 : -1};
  }

  double
  NodalContactLaw::bound(const unsigned int i, const Trial &x) const
  {
    switch (laws[i])
    {
      case FrictionLaw::tresca:
        return coefficients[i];
      case FrictionLaw::coulomb:
        // mu at the pressure of the normal law's trial, p + (d - theta p)/c
        // (p where the gap is closed; positive only where it closes).
        return coefficients[i] *
               std::max(0., x.p + (x.d - x.theta * x.p) / x.c);
      case FrictionLaw::none:
        break;
    }
    return 0.;
  }

  double
  NodalContactLaw::converged_bound(const unsigned int i, const double p) const
  {
    return coefficients[i] * (laws[i] == FrictionLaw::tresca ? 1. : p);
  }

  NodeStatus
  NodalContactLaw::status(const unsigned int i, const Trial &x) const
  {
    if (!closed(x))
      return {NodeState::open, 0};
    if (!frictional(i))
      return {NodeState::slip, 0};
    if (prescribed[i])
      return prescribed_slip_status(i, x);
    const double trial = trial_traction(x);
    if (std::abs(trial) <= bound(i, x))
      return {NodeState::stick, 0};
    return {NodeState::slip, trial > 0 ? 1 : -1};
  }

  NodeStatus
  NodalContactLaw::prescribed_status(const unsigned int i,
                                     const Trial       &x,
                                     const int          direction) const
  {
    if (!closed(x))
      return {NodeState::open, 0};
    if (!frictional(i))
      return {NodeState::slip, 0};
    if (prescribed[i])
      return prescribed_slip_status(i, x);
    if (direction == 0)
      return {NodeState::stick, 0};
    return {NodeState::slip, direction > 0 ? 1 : -1};
  }

  double
  NodalContactLaw::tangential_residual(const unsigned int i,
                                       const Trial       &x) const
  {
    if (!frictional(i) || !closed(x))
      return x.t;
    const double b = bound(i, x);
    return x.t - std::clamp(trial_traction(x), -b, b);
  }

  NodalContactLaw::SlipEquation
  NodalContactLaw::slip_equation(const unsigned int i,
                                 const NodeStatus  &s,
                                 const double       b,
                                 const bool         linearise_coulomb) const
  {
    if (s.state != NodeState::slip || s.direction == 0)
      return {};
    if (laws[i] == FrictionLaw::coulomb && linearise_coulomb)
      return {0., s.direction * coefficients[i]};
    return {s.direction * b, 0.};
  }

  std::string
  tresca_lift_off_note(const std::vector<ContactPair *> &pairs)
  {
    std::string names;
    for (const auto *pair : pairs)
      if (pair->friction_law() == FrictionLaw::tresca)
        names += (names.empty() ? "Contact pair " : ", ") + pair->name();
    if (names.empty())
      return "";
    return ". With Tresca friction (" + names +
           ") the slip bound g holds where the bodies touch and drops to 0 "
           "where a node opens: where the tangential traction g itself lifts "
           "nodes off (a large g against the pressure, bodies of different "
           "materials), no state of such a node is consistent (slipping it "
           "opens, open it penetrates) and the active set cycles between "
           "open and slip, which more Newton steps do not cure; Coulomb's "
           "bound mu p vanishes with the pressure (Friction = coulomb), or "
           "a smaller Friction bound keeps the zone closed";
  }
} // namespace ddcontact
