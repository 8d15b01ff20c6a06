#ifndef ddcontact_axis_of_symmetry_h
#define ddcontact_axis_of_symmetry_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>

#include <cmath>
#include <string>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The axis r = 0 of an axisymmetric section (Geometry = axisymmetric).
   *
   * A meridian section lies in r >= 0: check_meridian_section() refuses a
   * mesh with a vertex at r < 0, naming the body and the vertex.
   *
   * On the axis the radial displacement of a body of revolution vanishes
   * (a point of the axis stays on it), and the hoop strain u_r / r stays
   * finite only so; the energy space of the weak form holds no other field.
   * constrain_axis() therefore sets u_r = 0 at every dof of a boundary face
   * on the axis, and at a vertex where a body only touches the axis. The
   * user writes no condition there; a Dirichlet condition on u_z of the
   * axis is an ordinary condition, and one that prescribes u_r != 0 there
   * is refused (check_dirichlet_values()).
   */
  class AxisOfSymmetry
  {
  public:
    /** Throws InputError "Body <name>/Mesh: ..." for a vertex at r < 0
     * (beyond round-off of the mesh's size). */
    static void
    check_meridian_section(const Triangulation<2> &triangulation,
                           const std::string      &body_name);

    /** u_r = 0 at the dofs of the boundary faces on r = 0, and at the
     * boundary vertices on r = 0 of other faces, that
     * @p constraints does not constrain already and can store. Call before
     * constraints.close(). */
    static void
    constrain_axis(const DoFHandler<2>       &dof_handler,
                   AffineConstraints<double> &constraints);

    /** Whether boundary @p face lies on the axis. */
    template <class FaceIterator>
    static bool
    on_axis(const FaceIterator &face, const double tolerance)
    {
      for (const unsigned int v : face->vertex_indices())
        if (std::abs(face->vertex(v)[0]) > tolerance)
          return false;
      return true;
    }

    /** Round-off of a vertex's r: 1e-10 times the mesh's size. */
    static double
    tolerance(const Triangulation<2> &triangulation);
  };
} // namespace ddcontact

#endif
