#ifndef ddcontact_load_path_measures_h
#define ddcontact_load_path_measures_h

#include <ddcontact/contact/contact_problem.h>

#include <vector>

namespace ddcontact
{
  /**
   * What the end of a load step says about the load path, to compare two
   * solutions of the same step from the same history (one step against
   * two halves, LoadStepControl): the tangential traction t at the contact
   * points of every frictional pair and the energy dissipated in the
   * step, with the scales that make their changes relative.
   */
  struct LoadPathMeasures
  {
    /** Per pair, the tangential traction at its points (empty for a
     * frictionless pair). */
    std::vector<std::vector<double>> traction;
    /** The largest slip bound (mu p or g) at a node of any pair: the
     * scale of t. */
    double traction_bound = 0;
    /** The energy dissipated in the step, summed over the pairs. */
    double dissipation = 0;
    /** The largest relative displacement of the zone at a point in
     * contact: the normal approach |u_1n + u_2n| or the slip |s|. */
    double displacement = 0;
    /** The integral of the slip bound over the zones (mu P for Coulomb
     * with a constant mu): the largest tangential force. */
    double bound_force = 0;

    /** With path-dependent bodies (plasticity): per pair the normal
     * stress at its points, and per such body its largest equivalent
     * plastic strain; empty otherwise. */
    std::vector<std::vector<double>> normal_stress;
    std::vector<double>              plastic_strain;

    /** Plastic strains below this are not told apart (the step control
     * does not split steps for them). */
    static constexpr double plastic_strain_floor = 1e-4;

    /** The measures of the pairs' states @p states and frictional
     * results @p friction (PairSolution::friction); with @p plastic_strain
     * (the largest equivalent plastic strain of each path-dependent body)
     * also the normal stresses. */
    LoadPathMeasures(const std::vector<ContactState>    &states,
                     const std::vector<FrictionResults> &friction,
                     const std::vector<double>          &plastic_strain = {});

    /**
     * The relative difference of two solutions of one step (the same
     * pairs and points): the larger of max |t_a - t_b| over the points,
     * over the largest slip bound, and |W_a - W_b| over the bound force
     * times the displacement, W the dissipated energies (W is at most
     * the bound force times the largest slip). The tangential traction
     * carries where a point sticks from (its slip at entry) and where the
     * stick zone ends; the energy what slips. 0 where nothing is in
     * contact. With path-dependent bodies also max |sigma_n,a - sigma_n,b|
     * over the largest |sigma_n|, and the change of each body's largest
     * equivalent plastic strain over the larger of the two (at least
     * plastic_strain_floor): where and how far the bodies yield.
     */
    static double
    difference(const LoadPathMeasures &a, const LoadPathMeasures &b);
  };
} // namespace ddcontact

#endif
