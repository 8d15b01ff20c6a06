#include <ddcontact/body/section_kinematics.h>

namespace ddcontact
{
  SectionKinematics::SectionKinematics(const Geometry geometry,
                                       const double   axis_tolerance)
    : geometry(geometry)
    , axisymmetric(geometry == Geometry::axisymmetric)
    , axis_tolerance(axis_tolerance)
  {
  }

  UpdateFlags
  SectionKinematics::update_flags(const UpdateFlags flags) const
  {
    // The hoop strain u_r / r needs the values and the points.
    return axisymmetric ? flags | update_values | update_gradients |
                            update_quadrature_points
                        : flags | update_gradients;
  }
} // namespace ddcontact
