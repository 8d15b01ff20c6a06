#ifndef ddcontact_geometry_h
#define ddcontact_geometry_h

#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

#include <ddcontact/parameter_tools.h>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Geometry: what the 2D mesh is a section of.
   *  - plane strain: a slice of unit thickness; forces, energies and
   *    reactions are per unit thickness.
   *  - axisymmetric: a meridian section of a body of revolution, x = r >= 0
   *    and y = z the axis. Every integral over the body or a boundary is
   *    over the whole ring, dV = 2 pi r dA and dS = 2 pi r ds, so that
   *    forces, energies and reactions are totals (a Hertz sphere's P), and
   *    the strain gains the hoop component eps_tt = u_r / r.
   */
  enum class Geometry
  {
    plane_strain,
    axisymmetric
  };

  DDCONTACT_DECLARE_SELECTION(Geometry)

  /** The factor of the section's measure at @p x: 1 in plane strain, the
   * ring's 2 pi r in axisymmetry (dV = 2 pi r dA). */
  inline double
  section_measure(const Geometry geometry, const Point<2> &x)
  {
    return geometry == Geometry::axisymmetric ? 2. * numbers::PI * x[0] : 1.;
  }
} // namespace ddcontact

#endif
