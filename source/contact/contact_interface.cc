#include <deal.II/base/mpi.h>

#include <ddcontact/body/axis_of_symmetry.h>
#include <ddcontact/contact/contact_interface.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace ddcontact
{
  namespace
  {
    /** Per face of S_1 (@p faces): whether it wholly faces S_2, its
     * points' plain lengths summing to its length. */
    std::vector<bool>
    wholly_facing(const std::vector<std::array<Point<2>, 2>> &faces,
                  const std::vector<ContactPoint>            &points)
    {
      std::vector<double> covered(faces.size(), 0.);
      for (const auto &p : points)
        covered[p.face] += p.ds;
      std::vector<bool> whole(faces.size());
      for (unsigned int f = 0; f < faces.size(); ++f)
        whole[f] =
          covered[f] > (1. - 1e-10) * faces[f][0].distance(faces[f][1]);
      return whole;
    }

    /**
     * With the weight w = 2 pi r of an axisymmetric zone the biorthogonal
     * basis of a face is phi = D M^{-1} psi, from its weighted mass matrix
     * M_ab = int psi_a psi_b w and D = diag(int psi_a w) (the points'
     * Gauss rule integrates both exactly); for a constant weight this is
     * 2 psi_a - psi_b. The coefficients of phi_a in (psi_0, psi_1) per face
     * of @p n_faces, on the faces with @p dual_face; @p hats gives psi at
     * a point.
     */
    template <typename Hats>
    std::vector<std::array<std::array<double, 2>, 2>>
    weighted_dual_basis(const unsigned int               n_faces,
                        const std::vector<ContactPoint> &points,
                        const std::vector<bool>         &dual_face,
                        const Hats                      &hats)
    {
      std::vector<std::array<double, 5>> sums(n_faces, {{0, 0, 0, 0, 0}});
      for (const auto &p : points)
      {
        const auto psi = hats(p);
        auto      &m   = sums[p.face];
        m[0] += psi[0] * psi[0] * p.JxW;
        m[1] += psi[0] * psi[1] * p.JxW;
        m[2] += psi[1] * psi[1] * p.JxW;
        m[3] += psi[0] * p.JxW;
        m[4] += psi[1] * p.JxW;
      }
      std::vector<std::array<std::array<double, 2>, 2>> basis(n_faces);
      for (unsigned int f = 0; f < n_faces; ++f)
        if (dual_face[f])
        {
          const auto  &m   = sums[f];
          const double det = m[0] * m[2] - m[1] * m[1];
          basis[f]         = {{{{m[3] * m[2] / det, -m[3] * m[1] / det}},
                               {{-m[4] * m[1] / det, m[4] * m[0] / det}}}};
        }
      return basis;
    }

    /** A boundary vertex of a body with the displacement components that
     * its Dirichlet conditions hold. (Not the axis of an axisymmetric
     * body: a node on it has u_r = 0 on both sides, its slip is 0 by
     * symmetry, and its stick row, with a zero operator and zero data,
     * keeps t = 0; prescribing it made Spence's sphere cycle.) */
    struct HeldVertex
    {
      Point<2>            x;
      std::array<bool, 2> held;
    };

    /** The held vertices of the boundary faces of @p body's cells on this
     * process. */
    std::vector<HeldVertex>
    held_vertices(const ElasticBody<2> &body)
    {
      std::vector<HeldVertex> held;
      const auto &dirichlet = body.get_boundary_conditions().dirichlet;
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
            {
              const auto it = dirichlet.find(face->boundary_id());
              for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                HeldVertex h{face->vertex(v), {{false, false}}};
                for (unsigned int c = 0; c < 2; ++c)
                  h.held[c] = it != dirichlet.end() && it->second.mask[c];
                if (h.held[0] || h.held[1])
                  held.push_back(h);
              }
            }
      return held;
    }

    /** Whether the components that @p held holds fix the displacement
     * along @p direction. */
    bool
    holds(const std::array<bool, 2> &held, const Tensor<1, 2> &direction)
    {
      for (unsigned int c = 0; c < 2; ++c)
        if (std::abs(direction[c]) > 1e-8 && !held[c])
          return false;
      return true;
    }

    /** Whether some held vertex of @p vertices lies on the line through
     * @p x along @p normal, within @p distance of @p x along it, and holds
     * @p direction; @p tolerance is the round-off of a position. */
    bool
    held_on_normal(const std::vector<HeldVertex> &vertices,
                   const Point<2>                &x,
                   const Tensor<1, 2>            &normal,
                   const Tensor<1, 2>            &direction,
                   const double                   distance,
                   const double                   tolerance)
    {
      for (const auto &v : vertices)
      {
        const Tensor<1, 2> d     = v.x - x;
        const double       along = d * normal;
        if ((d - along * normal).norm() <= tolerance &&
            std::abs(along) <= distance + tolerance && holds(v.held, direction))
          return true;
      }
      return false;
    }
  } // namespace

  ContactInterface::ContactInterface(const ContactProblem &problem,
                                     const bool            on_nodes,
                                     const bool            exact_contact,
                                     const bool            friction,
                                     const bool            dual_basis)
    : problem(problem)
    , nodal(on_nodes)
    , exact(exact_contact)
    , tangential(friction)
    , dual(dual_basis)
  {
    Assert(on_nodes || !friction,
           ExcMessage("friction lives on the nodes of S_1"));
  }

  void
  ContactInterface::reinit()
  {
    weights.clear();
    thetas.clear();
    scales.clear();
    references.clear();
    nodal_law.clear();
    points.clear();
    point_shares.clear();
    const auto &pairs = problem.get_pairs();
    for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const unsigned int first = point_shares.size();
      if (nodal)
        add_nodes(k);
      else
        for (unsigned int q = 0; q < pairs[k]->points().size(); ++q)
        {
          point_shares.push_back({{k, q, 1., 1.}});
          points.push_back(pairs[k]->points()[q].x);
        }

      // Exact contact has no penalty: theta = 0 in (Theta + S) p = d_0.
      const double theta = exact ? 0. : pairs[k]->penalty();
      const double c     = surface_compliance(pairs[k]->get_body_1()) +
                       surface_compliance(pairs[k]->get_body_2());
      const double            reference = reference_of_pair(k);
      const std::vector<bool> prescribed =
        prescribed_slips(k, first, point_shares.size());
      for (unsigned int i = first; i < point_shares.size(); ++i)
      {
        double m = 0;
        for (const auto &share : point_shares[i])
          m += share.psi * pairs[k]->points()[share.point].JxW;
        // The friction bound averaged like the gap (the weights of the
        // points in the node's average, psi w / m).
        double bound = 0;
        for (const auto &share : point_shares[i])
        {
          const auto &point = pairs[k]->points()[share.point];
          bound += share.psi * point.JxW / m * point.friction;
        }
        weights.push_back(m);
        thetas.push_back(theta);
        scales.push_back(m * c);
        references.push_back(reference);
        nodal_law.add_node(
          pairs[k]->friction_law(), bound, prescribed[i - first]);
      }
    }
  }

  std::vector<bool>
  ContactInterface::prescribed_slips(const unsigned int k,
                                     const unsigned int first,
                                     const unsigned int last) const
  {
    const auto         &pair = *problem.get_pairs()[k];
    std::vector<double> held(last - first, 0.);
    if (!(nodal && pair.has_friction()))
      return std::vector<bool>(held.size(), false);
    const auto   held_1 = held_vertices(pair.get_body_1());
    const auto   held_2 = held_vertices(pair.get_body_2());
    const double tol_1  = AxisOfSymmetry::tolerance(
      pair.get_body_1().get_dof_handler().get_triangulation());
    const double tol_2 = AxisOfSymmetry::tolerance(
      pair.get_body_2().get_dof_handler().get_triangulation());
    for (unsigned int i = first; i < last; ++i)
    {
      // The node's normal: its faces' normals weighed by psi_i.
      Tensor<1, 2> normal;
      for (const auto &share : point_shares[i])
        normal += share.psi * pair.points()[share.point].normal;
      if (normal.norm() == 0)
        continue;
      normal /= normal.norm();
      const Tensor<1, 2> tau({-normal[1], normal[0]});
      held[i - first] =
        (held_on_normal(held_1, points[i], normal, tau, 0., tol_1) &&
         held_on_normal(held_2,
                        points[i],
                        normal,
                        tau,
                        pair.search_report().search_distance,
                        tol_2))
          ? 1.
          : 0.;
    }
    // A process holds the held vertices of its own cells only: the
    // nodes' flags are the same on every process (each runs the law).
    std::vector<double> on_any(held.size());
    Utilities::MPI::max(make_array_view(std::as_const(held)),
                        MPI_COMM_WORLD,
                        make_array_view(on_any));
    held = on_any;
    std::vector<bool> prescribed(held.size());
    for (unsigned int i = 0; i < held.size(); ++i)
      prescribed[i] = held[i] > 0;
    return prescribed;
  }

  double
  ContactInterface::reference_of_pair(const unsigned int k) const
  {
    const auto  &pair = *problem.get_pairs()[k];
    const double L    = (k < reference_lengths.size())
                          ? reference_lengths[k]
                          : std::numeric_limits<double>::infinity();
    return surface_compliance(pair.get_body_1()) *
             std::min(pair.thickness_of_body_1(), L) +
           surface_compliance(pair.get_body_2()) *
             std::min(pair.thickness_of_body_2(), L);
  }

  void
  ContactInterface::set_reference_lengths(const std::vector<double> &lengths)
  {
    reference_lengths = lengths;
    for (unsigned int q = 0; q < size(); ++q)
      references[q] = reference_of_pair(point_shares[q][0].pair);
  }

  void
  ContactInterface::add_nodes(const unsigned int k)
  {
    // The vertices of adjacent faces of S_1 are the same doubles
    // (ContactPair::zone_faces_1()), so they are matched exactly.
    const auto &pair   = *problem.get_pairs()[k];
    const auto &faces  = pair.zone_faces_1();
    const auto &points = pair.points();
    const auto  hats   = [&](const ContactPoint &p)
    {
      const auto  &f = faces[p.face];
      const double t =
        std::clamp(p.x.distance(f[0]) / f[0].distance(f[1]), 0., 1.);
      return std::array<double, 2>{{1. - t, t}};
    };

    // The dual basis phi_a = 2 psi_a - psi_b of a face, biorthogonal to
    // the hat functions: int phi_a psi_b = delta_ab int psi_a (Wohlmuth's
    // dual mortar basis). Only on a face wholly facing S_2 (its points'
    // weights sum to its length); a face partly facing it, at an end of
    // S_2 and not where a contact or stick zone ends, keeps the hat
    // functions (the dual functions of a sliver grow like the inverse of
    // its length and spoil the conditioning of S).
    const std::vector<bool> dual_face =
      dual ? wholly_facing(faces, points) : std::vector<bool>(faces.size());

    // The weight 2 pi r of an axisymmetric zone: weighted_dual_basis().
    std::vector<std::array<std::array<double, 2>, 2>> weighted_dual;
    if (dual && pair.get_body_1().get_geometry() == Geometry::axisymmetric)
      weighted_dual =
        weighted_dual_basis(faces.size(), points, dual_face, hats);

    std::map<std::pair<double, double>, unsigned int> node_of;
    for (unsigned int q = 0; q < points.size(); ++q)
    {
      const auto &f      = faces[points[q].face];
      const auto  psi    = hats(points[q]);
      const bool  d      = dual_face[points[q].face];
      double      phi[2] = {d ? 2. * psi[0] - psi[1] : psi[0],
                       d ? 2. * psi[1] - psi[0] : psi[1]};
      if (d && !weighted_dual.empty())
        for (unsigned int a = 0; a < 2; ++a)
        {
          const auto &c = weighted_dual[points[q].face][a];
          phi[a]        = c[0] * psi[0] + c[1] * psi[1];
        }
      for (unsigned int v = 0; v < 2; ++v)
      {
        const auto [it, inserted] = node_of.emplace(
          std::make_pair(f[v][0], f[v][1]), point_shares.size());
        if (inserted)
        {
          point_shares.emplace_back();
          this->points.push_back(f[v]);
        }
        point_shares[it->second].push_back({k, q, psi[v], phi[v]});
      }
    }
  }

  double
  ContactInterface::surface_compliance(const ElasticBody<2> &body)
  {
    const auto &m = body.get_elastic_constants();
    return (1. - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
  }

  double
  ContactInterface::inner(const PointVector &x, const PointVector &y) const
  {
    // The normal unknowns alone, or all (the tangential ones have the
    // weights of their nodes).
    Assert(x.size() == size() || x.size() == n_unknowns(),
           ExcDimensionMismatch(x.size(), n_unknowns()));
    AssertDimension(y.size(), x.size());
    double sum = 0;
    for (unsigned int q = 0; q < x.size(); ++q)
      sum += weight(q) * x[q] * y[q];
    return sum;
  }

  double
  ContactInterface::norm(const PointVector &x) const
  {
    return std::sqrt(inner(x, x));
  }

  std::vector<std::vector<double>>
  ContactInterface::at_points(const PointVector &x,
                              const unsigned int first,
                              const double       factor,
                              const bool         load) const
  {
    const auto                      &pairs = problem.get_pairs();
    std::vector<std::vector<double>> values(pairs.size());
    for (unsigned int k = 0; k < pairs.size(); ++k)
      values[k].assign(pairs[k]->points().size(), 0.);
    for (unsigned int i = 0; i < size(); ++i)
      for (const auto &share : point_shares[i])
        values[share.pair][share.point] +=
          factor * (load ? share.phi : share.psi) * x[first + i];
    return values;
  }

  std::vector<std::vector<double>>
  ContactInterface::normal_stresses(const PointVector &p) const
  {
    Assert(p.size() == size() || p.size() == n_unknowns(),
           ExcDimensionMismatch(p.size(), size()));
    return at_points(p, 0, -1., true);
  }

  std::vector<std::vector<double>>
  ContactInterface::reported_field(const PointVector &x,
                                   const double       factor) const
  {
    Assert(x.size() == size() || x.size() == n_unknowns(),
           ExcDimensionMismatch(x.size(), size()));
    return at_points(x, 0, factor, false);
  }

  std::vector<std::vector<double>>
  ContactInterface::tangential_tractions(const PointVector &x) const
  {
    AssertDimension(x.size(), 2 * size());
    return at_points(x, size(), 1., true);
  }

  std::vector<double>
  ContactInterface::peak_pressures(const PointVector &p) const
  {
    Assert(p.size() == size() || p.size() == n_unknowns(),
           ExcDimensionMismatch(p.size(), size()));
    std::vector<double> peak(problem.get_pairs().size(), 0.);
    for (unsigned int i = 0; i < size(); ++i)
    {
      auto &largest = peak[point_shares[i][0].pair];
      largest       = std::max(largest, p[i]);
    }
    return peak;
  }

  std::vector<std::vector<double>>
  ContactInterface::jump(const ContactProblem::Iterate &u) const
  {
    std::vector<std::vector<double>> d;
    for (const auto *pair : problem.get_pairs())
    {
      std::vector<double> u_1n, u_2n;
      pair->normal_displacements(u[problem.body_index(pair->get_body_1())],
                                 u[problem.body_index(pair->get_body_2())],
                                 u_1n,
                                 u_2n);
      for (unsigned int q = 0; q < u_1n.size(); ++q)
        u_1n[q] += u_2n[q];
      d.push_back(std::move(u_1n));
    }
    return d;
  }

  PointVector
  ContactInterface::average(
    const std::vector<std::vector<double>> &values) const
  {
    PointVector averages;
    // On the points the average is the value itself (taken as it is, so
    // that the penalty runs do not change in the last bits).
    if (!nodal)
    {
      for (const auto &v : values)
        averages.insert(averages.end(), v.begin(), v.end());
      return averages;
    }
    const auto &pairs = problem.get_pairs();
    for (unsigned int i = 0; i < size(); ++i)
    {
      double sum = 0;
      for (const auto &share : point_shares[i])
        sum += share.phi * pairs[share.pair]->points()[share.point].JxW *
               values[share.pair][share.point];
      averages.push_back(sum / weights[i]);
    }
    return averages;
  }

  PointVector
  ContactInterface::penetration(const ContactProblem::Iterate &u) const
  {
    auto d = jump(u);
    for (unsigned int k = 0; k < d.size(); ++k)
      for (unsigned int q = 0; q < d[k].size(); ++q)
        d[k][q] -= problem.law(k).shifted_gap(q);
    return with_slips(average(d), u);
  }

  PointVector
  ContactInterface::with_slips(PointVector                    normal,
                               const ContactProblem::Iterate &u) const
  {
    if (tangential)
    {
      const PointVector s = slip_average(u);
      normal.insert(normal.end(), s.begin(), s.end());
    }
    return normal;
  }

  PointVector
  ContactInterface::slip_average(const ContactProblem::Iterate &u) const
  {
    std::vector<std::vector<double>> s;
    for (const auto *pair : problem.get_pairs())
      s.push_back(pair->slips(u[problem.body_index(pair->get_body_1())],
                              u[problem.body_index(pair->get_body_2())]));
    return average(s);
  }

  void
  ContactInterface::apply(const PointVector       &x,
                          ContactProblem::Iterate &u,
                          PointVector             &Sx) const
  {
    AssertDimension(x.size(), n_unknowns());
    // Only S x is read: the other processes need the traces alone.
    if (tangential)
      problem.solve_bodies(normal_stresses(x),
                           tangential_tractions(x),
                           u,
                           true,
                           ContactProblem::Exchange::traces);
    else
      problem.solve_bodies(
        normal_stresses(x), u, true, ContactProblem::Exchange::traces);
    // A pressure pushes the bodies apart: the jump is -S x; a traction t
    // (-t tau on body 1) slips body 1 back: the slip is -S_t x.
    Sx = with_slips(average(jump(u)), u);
    for (double &v : Sx)
      v = -v;
    ++applications;
  }
} // namespace ddcontact
