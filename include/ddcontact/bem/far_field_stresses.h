#ifndef ddcontact_far_field_stresses_h
#define ddcontact_far_field_stresses_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <ddcontact/bem/boundary_mesh.h>
#include <ddcontact/bem/kelvin_solution.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The Somigliana stresses of a solved BoundaryMesh at many interior
   * points by a hierarchy of boxes: a quadtree over the points, in which
   * the elements well separated from a box act on it through a Chebyshev
   * interpolant of their (smooth) field, accurate to about 1e-8 of it,
   * and only the nearby elements are integrated at every point. The cost
   * is about linear in the points instead of points x elements.
   *
   * The boxes follow the whole set of points, spread over the processes
   * of a communicator (a distributed mesh, each process with the points
   * of its own cells): the root box and which boxes are subdivided come
   * from global reductions, so every point gets the very same value on
   * any number of processes.
   */
  class FarFieldStresses
  {
  public:
    /** Evaluate the field of the boundary solution of @p mesh with the
     * kernels of @p kelvin (mu = 1); both must outlive this object. */
    FarFieldStresses(const BoundaryMesh &mesh, const KelvinSolution &kelvin);

    /** The stresses (divided by mu) at the interior @p points (scaled
     * coordinates, BoundaryMesh::scaled()), this process's share of the
     * points of all processes of @p communicator (a collective call). */
    std::vector<SymmetricTensor<2, 2>>
    evaluate(const std::vector<Point<2>> &points,
             MPI_Comm                     communicator = MPI_COMM_SELF) const;

  private:
    /** A square box of the target tree. */
    struct TargetBox
    {
      Point<2> lower;
      double   side;

      /** The quadrant (0 to 3) of @p y; a point on a dividing line goes to
       * the upper one. */
      unsigned int
      quadrant(const Point<2> &y) const;

      /** Quadrant @p q as a box. */
      TargetBox
      child(unsigned int q) const;
    };

    /** The boxes of the tree below @p root that hold more points than
     * their leaves should (summed over @p communicator), as sorted keys:
     * the root is 1, the children of k are 4 k + q. */
    static std::vector<std::uint64_t>
    subdivided_boxes(const std::vector<Point<2>> &x,
                     const TargetBox             &root,
                     MPI_Comm                     communicator);

    /**
     * One box of the hierarchy: @p points (indices into @p x) lie in
     * @p box; @p candidates are the elements not yet accounted for by an
     * ancestor; @p parent and @p parent_values the Chebyshev interpolant of
     * what the ancestors accounted for (none at the root).
     */
    void
    stresses_in_box(const std::vector<Point<2>>              &x,
                    std::vector<std::size_t>                &&points,
                    const TargetBox                          &box,
                    std::vector<unsigned int>               &&candidates,
                    const TargetBox                          *parent,
                    const std::vector<SymmetricTensor<2, 2>> *parent_values,
                    std::vector<SymmetricTensor<2, 2>>       &stress,
                    const std::vector<std::uint64_t>         &subdivided,
                    std::uint64_t                             key,
                    unsigned int                              depth) const;

    /** What the ancestors' far elements contribute at @p y: their
     * Chebyshev interpolant on @p parent (which holds y), or zero at the
     * root (@p parent null). */
    SymmetricTensor<2, 2>
    inherited_stress(const TargetBox                          *parent,
                     const std::vector<SymmetricTensor<2, 2>> *parent_values,
                     const Point<2>                           &y) const;

    /** The field at the Chebyshev nodes of @p box: that of the @p far
     * elements plus what the ancestors contribute. */
    std::vector<SymmetricTensor<2, 2>>
    values_at_chebyshev_nodes(
      const TargetBox                          &box,
      const std::vector<unsigned int>          &far,
      const TargetBox                          *parent,
      const std::vector<SymmetricTensor<2, 2>> *parent_values) const;

    const BoundaryMesh   &mesh;
    const KelvinSolution &kelvin;
  };
} // namespace ddcontact

#endif
