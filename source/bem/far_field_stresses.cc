#include <deal.II/base/thread_management.h>

#include <ddcontact/bem/boundary_integration.h>
#include <ddcontact/bem/far_field_stresses.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace ddcontact
{
  namespace
  {
    /**
     * Tensor-product interpolation at the n x n Chebyshev points (first
     * kind) of a square box, in barycentric form (Berrut & Trefethen):
     * stable for any n, exact at the nodes.
     */
    struct ChebyshevRule
    {
      static constexpr unsigned int n = 8;
      std::array<double, n>         t, w; // nodes on [0, 1], weights

      ChebyshevRule()
      {
        for (unsigned int k = 0; k < n; ++k)
        {
          const double angle = (2. * k + 1.) * M_PI / (2. * n);
          t[k]               = 0.5 * (1. + std::cos(angle));
          w[k]               = ((k % 2) ? -1. : 1.) * std::sin(angle);
        }
      }

      /** The n Lagrange basis values at s (in box units). */
      std::array<double, n>
      basis(const double s) const
      {
        std::array<double, n> l;
        double                sum = 0;
        for (unsigned int k = 0; k < n; ++k)
        {
          if (s == t[k])
          {
            l.fill(0.);
            l[k] = 1.;
            return l;
          }
          l[k] = w[k] / (s - t[k]);
          sum += l[k];
        }
        for (auto &v : l)
          v /= sum;
        return l;
      }

      /** The interpolant of @p values (node (kx, ky) at kx n + ky) of the
       * box [lower, lower + side]^2 at y. */
      SymmetricTensor<2, 2>
      interpolate(const Point<2>                           &lower,
                  const double                              side,
                  const std::vector<SymmetricTensor<2, 2>> &values,
                  const Point<2>                           &y) const
      {
        const auto            lx = basis((y[0] - lower[0]) / side);
        const auto            ly = basis((y[1] - lower[1]) / side);
        SymmetricTensor<2, 2> result;
        for (unsigned int kx = 0; kx < n; ++kx)
        {
          SymmetricTensor<2, 2> column;
          for (unsigned int ky = 0; ky < n; ++ky)
            column += ly[ky] * values[kx * n + ky];
          result += lx[kx] * column;
        }
        return result;
      }
    };

    const ChebyshevRule &
    chebyshev_rule()
    {
      static const ChebyshevRule rule;
      return rule;
    }
    /** Sort the elements @p candidates into those well separated from the
     * box of centre @p centre and half-diagonal @p radius (@p far: at least
     * 4 radius from the centre) and the others (@p near). */
    void
    separate_far_elements(const std::vector<BoundaryMesh::Element> &elements,
                          const Point<2>                           &centre,
                          const double                              radius,
                          const std::vector<unsigned int>          &candidates,
                          std::vector<unsigned int>                &far,
                          std::vector<unsigned int>                &near)
    {
      for (const unsigned int e : candidates)
        (BoundaryIntegration::point_segment_distance(
           centre, elements[e].x_a, elements[e].x_b) >= 4. * radius
           ? far
           : near)
          .push_back(e);
    }
  } // namespace

  FarFieldStresses::FarFieldStresses(const BoundaryMesh   &mesh,
                                     const KelvinSolution &kelvin)
    : mesh(mesh)
    , kelvin(kelvin)
  {
  }

  unsigned int
  FarFieldStresses::TargetBox::quadrant(const Point<2> &y) const
  {
    const double half = 0.5 * side;
    return 2 * (y[0] >= lower[0] + half) + (y[1] >= lower[1] + half);
  }

  FarFieldStresses::TargetBox
  FarFieldStresses::TargetBox::child(const unsigned int q) const
  {
    const double half = 0.5 * side;
    return {lower + Tensor<1, 2>({half * (q / 2), half * (q % 2)}), half};
  }

  namespace
  {
    // A box with at most this many points (of all processes) is a leaf:
    // integrating its remaining elements at the points is cheaper than at
    // the interpolation nodes.
    constexpr std::size_t leaf_points = 2 * ChebyshevRule::n * ChebyshevRule::n;
    constexpr unsigned    max_depth   = 30;

    bool
    is_parallel(const MPI_Comm communicator)
    {
      return Utilities::MPI::job_supports_mpi() &&
             Utilities::MPI::n_mpi_processes(communicator) > 1;
    }
  } // namespace

  std::vector<std::uint64_t>
  FarFieldStresses::subdivided_boxes(const std::vector<Point<2>> &x,
                                     const TargetBox             &root,
                                     const MPI_Comm               communicator)
  {
    // Level by level: every process lists the same boxes (all four
    // children of a subdivided box, empty here or not) with its own
    // points, and one sum per level gives the counts of the whole set.
    struct LevelBox
    {
      TargetBox                box;
      std::uint64_t            key;
      std::vector<std::size_t> points;
    };
    std::vector<LevelBox> level(1, LevelBox{root, 1, {}});
    level[0].points.resize(x.size());
    std::iota(level[0].points.begin(), level[0].points.end(), std::size_t(0));

    std::vector<std::uint64_t> subdivided;
    for (unsigned int depth = 0; depth < max_depth && !level.empty(); ++depth)
    {
      std::vector<double> counts(level.size()); // exact below 2^53
      for (std::size_t b = 0; b < level.size(); ++b)
        counts[b] = level[b].points.size();
      if (is_parallel(communicator))
        Utilities::MPI::sum(ArrayView<const double>(counts),
                            communicator,
                            ArrayView<double>(counts));

      std::vector<LevelBox> next;
      for (std::size_t b = 0; b < level.size(); ++b)
        if (counts[b] > leaf_points)
        {
          subdivided.push_back(level[b].key);
          std::array<LevelBox, 4> children;
          for (unsigned int q = 0; q < 4; ++q)
            children[q] = {level[b].box.child(q), 4 * level[b].key + q, {}};
          for (const std::size_t i : level[b].points)
            children[level[b].box.quadrant(x[i])].points.push_back(i);
          for (auto &c : children)
            next.push_back(std::move(c));
        }
      level = std::move(next);
    }
    std::sort(subdivided.begin(), subdivided.end());
    return subdivided;
  }

  std::vector<SymmetricTensor<2, 2>>
  FarFieldStresses::evaluate(const std::vector<Point<2>> &points,
                             const MPI_Comm               communicator) const
  {
    std::vector<SymmetricTensor<2, 2>> stress(points.size());
    // The root: the bounding box of all processes' points.
    const double          big = std::numeric_limits<double>::max();
    std::array<double, 4> bounds{{big, big, big, big}}; // -x0, -x1, x0, x1
    for (const auto &y : points)
      for (unsigned int d = 0; d < 2; ++d)
      {
        bounds[d]     = std::min(bounds[d], y[d]);
        bounds[2 + d] = std::min(bounds[2 + d], -y[d]);
      }
    if (is_parallel(communicator))
      Utilities::MPI::min(ArrayView<const double>(bounds),
                          communicator,
                          ArrayView<double>(bounds));
    if (bounds[0] == big) // no point on any process
      return stress;
    const Point<2> lo(bounds[0], bounds[1]), hi(-bounds[2], -bounds[3]);
    const double side = 1.001 * std::max(hi[0] - lo[0], hi[1] - lo[1]) + 1e-12;
    const TargetBox root{lo - Tensor<1, 2>({5e-4 * side, 5e-4 * side}), side};
    const auto      subdivided = subdivided_boxes(points, root, communicator);

    std::vector<std::size_t> all_points(points.size());
    std::iota(all_points.begin(), all_points.end(), std::size_t(0));
    std::vector<unsigned int> all_elements(mesh.get_elements().size());
    std::iota(all_elements.begin(), all_elements.end(), 0u);
    if (!points.empty())
      stresses_in_box(points,
                      std::move(all_points),
                      root,
                      std::move(all_elements),
                      nullptr,
                      nullptr,
                      stress,
                      subdivided,
                      1,
                      0);
    return stress;
  }

  SymmetricTensor<2, 2>
  FarFieldStresses::inherited_stress(
    const TargetBox                          *parent,
    const std::vector<SymmetricTensor<2, 2>> *parent_values,
    const Point<2>                           &y) const
  {
    const ChebyshevRule &cheb = chebyshev_rule();
    return parent
             ? cheb.interpolate(parent->lower, parent->side, *parent_values, y)
             : SymmetricTensor<2, 2>();
  }

  std::vector<SymmetricTensor<2, 2>>
  FarFieldStresses::values_at_chebyshev_nodes(
    const TargetBox                          &box,
    const std::vector<unsigned int>          &far,
    const TargetBox                          *parent,
    const std::vector<SymmetricTensor<2, 2>> *parent_values) const
  {
    const ChebyshevRule &cheb    = chebyshev_rule();
    const unsigned int   n_nodes = ChebyshevRule::n * ChebyshevRule::n;
    std::vector<SymmetricTensor<2, 2>> values(n_nodes);
    for (unsigned int kx = 0; kx < ChebyshevRule::n; ++kx)
      for (unsigned int ky = 0; ky < ChebyshevRule::n; ++ky)
      {
        const Point<2> node = box.lower + Tensor<1, 2>({box.side * cheb.t[kx],
                                                        box.side * cheb.t[ky]});
        values[kx * ChebyshevRule::n + ky] =
          inherited_stress(parent, parent_values, node) +
          BoundaryIntegration::somigliana_stress(mesh, kelvin, node, far);
      }
    return values;
  }

  void
  FarFieldStresses::stresses_in_box(
    const std::vector<Point<2>>              &x,
    std::vector<std::size_t>                &&points,
    const TargetBox                          &box,
    std::vector<unsigned int>               &&candidates,
    const TargetBox                          *parent,
    const std::vector<SymmetricTensor<2, 2>> *parent_values,
    std::vector<SymmetricTensor<2, 2>>       &stress,
    const std::vector<std::uint64_t>         &subdivided,
    const std::uint64_t                       key,
    const unsigned int                        depth) const
  {
    // A leaf (few points in the whole set): its remaining elements are
    // integrated at the points.
    if (!std::binary_search(subdivided.begin(), subdivided.end(), key))
    {
      for (const std::size_t i : points)
        stress[i] = inherited_stress(parent, parent_values, x[i]) +
                    BoundaryIntegration::somigliana_stress(
                      mesh, kelvin, x[i], candidates);
      return;
    }

    // Elements at least 4 half-diagonals r from the centre are well
    // separated from the box: in it their field is analytic, with its
    // singularities (in each coordinate, complexified) at least 3 r = 4.2
    // half-sides from the box centre. Chebyshev interpolation of degree 7
    // then converges like rho^-8 with rho = 4.2 + sqrt(4.2^2 - 1) = 8.3
    // (the Bernstein ellipse through the nearest singularity), i.e. to
    // about 5e-8 of the far field per level.
    const double   radius = box.side / std::sqrt(2.);
    const Point<2> centre =
      box.lower + Tensor<1, 2>({0.5 * box.side, 0.5 * box.side});
    std::vector<unsigned int> far, near;
    separate_far_elements(
      mesh.get_elements(), centre, radius, candidates, far, near);
    candidates.clear();

    // With no new far element the children interpolate the ancestors'
    // field directly (their points lie in the ancestor's box too).
    std::vector<SymmetricTensor<2, 2>>        values;
    const TargetBox                          *child_parent = parent;
    const std::vector<SymmetricTensor<2, 2>> *child_values = parent_values;
    if (!far.empty())
    {
      values       = values_at_chebyshev_nodes(box, far, parent, parent_values);
      child_parent = &box;
      child_values = &values;
    }

    std::array<std::vector<std::size_t>, 4> quadrant_points;
    for (const std::size_t i : points)
      quadrant_points[box.quadrant(x[i])].push_back(i);
    points.clear();

    const auto child = [&](const unsigned int q)
    {
      if (quadrant_points[q].empty())
        return;
      stresses_in_box(x,
                      std::move(quadrant_points[q]),
                      box.child(q),
                      std::vector<unsigned int>(near),
                      child_parent,
                      child_values,
                      stress,
                      subdivided,
                      4 * key + q,
                      depth + 1);
    };
    // The top levels spread over the threads; below, one task per subtree.
    if (depth < 3)
    {
      Threads::TaskGroup<void> tasks;
      for (unsigned int q = 0; q < 4; ++q)
        tasks += Threads::new_task([&, q]() { child(q); });
      tasks.join_all();
    }
    else
      for (unsigned int q = 0; q < 4; ++q)
        child(q);
  }
} // namespace ddcontact
