#include <ddcontact/body/geometry.h>

namespace ddcontact
{
  DDCONTACT_SELECTION(Geometry,
                      {"plane strain", Geometry::plane_strain},
                      {"axisymmetric", Geometry::axisymmetric})
} // namespace ddcontact
