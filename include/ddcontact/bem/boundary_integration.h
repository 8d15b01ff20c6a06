#ifndef ddcontact_boundary_integration_h
#define ddcontact_boundary_integration_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ddcontact/bem/boundary_mesh.h>
#include <ddcontact/bem/kelvin_solution.h>

#include <array>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Integration over the straight elements of a BoundaryMesh (scaled
   * coordinates, kernels with mu = 1, doc/bem-method.md §2.4, §4.2):
   *  - regular and nearly singular element integrals by Gauss rules whose
   *    number of points grows as the source point approaches the element,
   *    with adaptive bisection close to it;
   *  - the singular integrals on the elements adjacent to a collocation
   *    point in closed form (for quadratic elements by exact moments of
   *    the shape polynomials), and the free term by the rigid-body trick;
   *  - the Somigliana identities for interior points (doc/bem-method.md §1.3,
   * §4.1).
   */
  namespace BoundaryIntegration
  {
    /** Distance from @p p to the segment (a, b). */
    double
    point_segment_distance(const Point<2> &p,
                           const Point<2> &a,
                           const Point<2> &b);

    /** Local coordinate in [0,1] of the point of segment (a, b) closest to
     * @p p. */
    double
    segment_coordinate(const Point<2> &p, const Point<2> &a, const Point<2> &b);

    /** One 2x2 block per node (H) and per element node (G, indexed like
     * BoundaryMesh::Element::nodes) of the BIE row at one collocation
     * point. */
    struct RowBlocks
    {
      std::vector<Tensor<2, 2>>                h;
      std::vector<std::array<Tensor<2, 2>, 3>> g;
    };

    /**
     * The exact integrals over a straight element of length @p length
     * (scaled), tangent @p tau and normal @p n, of the kernels times the
     * shape functions of @p mesh, for a source point on the element at local
     * coordinate @p s0: G_k = int U N_k and, where finite, the principal
     * value H_k = PV int T N_k. H_k is set to zero where N_k(s0) != 0 and s0
     * is an end (the diagonal block of the rigid-body trick). Used for
     * quadratic elements; exposed for the tests.
     */
    void
    singular_element_blocks(const BoundaryMesh          &mesh,
                            const KelvinSolution        &kelvin,
                            const double                 length,
                            const Tensor<1, 2>          &tau,
                            const Tensor<1, 2>          &n,
                            const double                 s0,
                            std::array<Tensor<2, 2>, 3> &g,
                            std::array<Tensor<2, 2>, 3> &h);

    /**
     * The H and G blocks of the boundary integral equation collocated at
     * @p point: closed forms on the elements through the point, the
     * distance-dependent rule on the others, and at a node the diagonal
     * block from the rigid-body trick (doc/bem-method.md §2.3, §2.4, §2.7).
     */
    void
    collocation_row_blocks(const BoundaryMesh                   &mesh,
                           const KelvinSolution                 &kelvin,
                           const BoundaryMesh::CollocationPoint &point,
                           RowBlocks                            &blocks);

    /** Somigliana stress identity at the interior point @p xi, summed over
     * all elements of @p mesh with their boundary solution (scaled). */
    SymmetricTensor<2, 2>
    somigliana_stress(const BoundaryMesh   &mesh,
                      const KelvinSolution &kelvin,
                      const Point<2>       &xi);

    /** The contribution of the elements @p subset to the Somigliana
     * stress at @p xi (scaled). */
    SymmetricTensor<2, 2>
    somigliana_stress(const BoundaryMesh              &mesh,
                      const KelvinSolution            &kelvin,
                      const Point<2>                  &xi,
                      const std::vector<unsigned int> &subset);

    /** Somigliana displacement identity at the interior point @p xi
     * (scaled). */
    Tensor<1, 2>
    somigliana_displacement(const BoundaryMesh   &mesh,
                            const KelvinSolution &kelvin,
                            const Point<2>       &xi);
  } // namespace BoundaryIntegration
} // namespace ddcontact

#endif
