#ifndef ddcontact_circle_manifolds_h
#define ddcontact_circle_manifolds_h

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * A Gmsh mesh carries a curved boundary only as its vertices: refined as
   * it is, every new boundary vertex would lie on a chord, and the
   * boundary would stay the polygon of the coarse mesh (a cylinder's
   * contact pressure then peaks at the polygon's corners and does not
   * converge). For every boundary id of @p tria whose vertices lie on one
   * circle (to 1e-8 of its radius; at least three vertices, not on a
   * line), attach a PolarManifold around the circle's centre to the faces
   * of that id, so that refinement puts the new vertices on the circle.
   * Straight ids and ids along other curves are left flat. Returns one
   * line per circle found ("id 11: circle of radius 5 around (0, 5)"), for
   * the screen.
   */
  std::vector<std::string>
  attach_circle_manifolds(Triangulation<2> &tria);
} // namespace ddcontact

#endif
