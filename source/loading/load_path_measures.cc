#include <ddcontact/loading/load_path_measures.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  LoadPathMeasures::LoadPathMeasures(
    const std::vector<ContactState>    &states,
    const std::vector<FrictionResults> &friction,
    const std::vector<double>          &plastic_strain)
    : plastic_strain(plastic_strain)
  {
    AssertDimension(states.size(), friction.size());
    if (!plastic_strain.empty())
      for (const auto &state : states)
        normal_stress.push_back(state.sigma_n);
    for (unsigned int k = 0; k < states.size(); ++k)
    {
      const auto &state = states[k];
      dissipation += state.dissipation;
      for (unsigned int q = 0; q < state.slip.size(); ++q)
        if (state.sigma_n[q] < 0)
          displacement = std::max({displacement,
                                   std::abs(state.u_1n[q] + state.u_2n[q]),
                                   std::abs(state.slip[q])});
      traction.push_back(state.t);
      // The nodal bounds b_i (mu_i p_i or g_i).
      const auto &bounds = friction[k].nodal_bound;
      for (const double b : bounds)
        traction_bound = std::max(traction_bound, std::abs(b));
      // Above int b ds over the zone (|t| <= b: above the tangential
      // force).
      if (!bounds.empty())
        bound_force += traction_bound * state.contact_length;
    }
  }

  double
  LoadPathMeasures::difference(const LoadPathMeasures &a,
                               const LoadPathMeasures &b)
  {
    AssertDimension(a.traction.size(), b.traction.size());
    double       change = 0;
    const double bound  = std::max(a.traction_bound, b.traction_bound);
    if (bound > 0)
      for (unsigned int k = 0; k < a.traction.size(); ++k)
      {
        AssertDimension(a.traction[k].size(), b.traction[k].size());
        for (unsigned int q = 0; q < a.traction[k].size(); ++q)
          change = std::max(
            change, std::abs(a.traction[k][q] - b.traction[k][q]) / bound);
      }
    const double energy = std::max(a.bound_force, b.bound_force) *
                          std::max(a.displacement, b.displacement);
    if (energy > 0)
      change =
        std::max(change, std::abs(a.dissipation - b.dissipation) / energy);
    AssertDimension(a.normal_stress.size(), b.normal_stress.size());
    double largest = 0;
    for (const auto &pair : a.normal_stress)
      for (const double s : pair)
        largest = std::max(largest, std::abs(s));
    if (largest > 0)
      for (unsigned int k = 0; k < a.normal_stress.size(); ++k)
      {
        AssertDimension(a.normal_stress[k].size(), b.normal_stress[k].size());
        for (unsigned int q = 0; q < a.normal_stress[k].size(); ++q)
          change = std::max(
            change,
            std::abs(a.normal_stress[k][q] - b.normal_stress[k][q]) / largest);
      }
    AssertDimension(a.plastic_strain.size(), b.plastic_strain.size());
    for (unsigned int k = 0; k < a.plastic_strain.size(); ++k)
      change = std::max(
        change,
        std::abs(a.plastic_strain[k] - b.plastic_strain[k]) /
          std::max(
            {a.plastic_strain[k], b.plastic_strain[k], plastic_strain_floor}));
    return change;
  }
} // namespace ddcontact
