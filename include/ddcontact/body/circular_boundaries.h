#ifndef ddcontact_circular_boundaries_h
#define ddcontact_circular_boundaries_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The boundary ids of a Gmsh mesh that are circular arcs, kept round
   * under refinement. A Gmsh mesh carries a curved boundary only as its
   * vertices. Refined as it is, every new boundary vertex would lie on a
   * chord, and the boundary would stay the coarse mesh's polygon: a
   * cylinder's contact pressure then peaks at the polygon's corners and
   * does not converge.
   *
   * find() takes every boundary id whose vertices lie on one circle (to
   * 1e-8 of its radius; at least three vertices, not on a line). After
   * every refinement, snap() moves the new vertices of those faces radially
   * onto their circle. BodyMesh calls it from the triangulation's
   * post-refinement signal. The vertices are moved rather than described by
   * a deal.II Manifold because deal.II 9.4's MappingFE, the mapping of
   * triangles, requires one manifold id for a cell and all its faces. The
   * interior cells next to the boundary take up the moves, which are at
   * most h^2 / (8 R).
   */
  class CircularBoundaries
  {
  public:
    /** The circular boundary ids of @p tria (a coarse mesh just read). */
    void
    find(const Triangulation<2> &tria);

    /** Move every vertex of a circular boundary face onto its circle. */
    void
    snap(Triangulation<2> &tria) const;

    bool
    empty() const
    {
      return circles.empty();
    }

    /** "id 11: circle of radius 5 around (0, 5)", one per circle. */
    std::vector<std::string>
    describe() const;

  private:
    struct Circle
    {
      types::boundary_id id;
      Point<2>           centre;
      double             radius;
    };
    std::vector<Circle> circles;
  };
} // namespace ddcontact

#endif
