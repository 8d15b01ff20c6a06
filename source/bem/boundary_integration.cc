#include <deal.II/base/quadrature_lib.h>

#include <ddcontact/bem/boundary_integration.h>

#include <algorithm>

namespace ddcontact
{
  namespace BoundaryIntegration
  {
    double
    point_segment_distance(const Point<2> &p,
                           const Point<2> &a,
                           const Point<2> &b)
    {
      const Tensor<1, 2> ab = b - a;
      const double s = std::clamp(((p - a) * ab) / ab.norm_square(), 0., 1.);
      return p.distance(a + s * ab);
    }

    /** Local coordinate in [0,1] of the point of segment (a, b) closest to
     * p. */
    double
    segment_coordinate(const Point<2> &p, const Point<2> &a, const Point<2> &b)
    {
      const Tensor<1, 2> ab = b - a;
      return std::clamp(((p - a) * ab) / ab.norm_square(), 0., 1.);
    }

    namespace
    {
      /** Gauss-Legendre rules on [0,1] with 3, 4, 6 and 8 points. */
      const Quadrature<1> &
      gauss_rule(const unsigned int n_points)
      {
        static const std::array<QGauss<1>, 4> rules{
          {QGauss<1>(3), QGauss<1>(4), QGauss<1>(6), QGauss<1>(8)}};
        switch (n_points)
        {
          case 3:
            return rules[0];
          case 4:
            return rules[1];
          case 6:
            return rules[2];
          default:
            Assert(n_points == 8, ExcInternalError());
            return rules[3];
        }
      }

      template <typename Integrand>
      void
      apply_gauss(const Quadrature<1> &rule,
                  const Point<2>      &x_a,
                  const Point<2>      &x_b,
                  const double         length,
                  const double         s_begin,
                  const double         s_end,
                  Integrand           &f)
      {
        const double h = s_end - s_begin;
        for (unsigned int q = 0; q < rule.size(); ++q)
        {
          const double s = s_begin + h * rule.point(q)[0];
          f(x_a + s * (x_b - x_a), s, rule.weight(q) * h * length);
        }
      }

      /** Recursive bisection of [s_begin, s_end] until each piece is no
       * longer than kappa times its distance to xi, then 8 Gauss points per
       * piece (doc/bem-method.md §4.2). doc/bem-method.md uses kappa = 1; we
       * take kappa = 1/2: on graded meshes (neighbour faces twice as long) the
       * uniform-stress patch test at 1 % of an element length from the boundary
       * improved from 1.4e-7 to 7e-9, at the price of a few more points on the
       * one or two nearest elements. The depth limit only matters for points on
       * the element itself, which the identities exclude. */
      template <typename Integrand>
      void
      integrate_bisected(const Point<2> &xi,
                         const Point<2> &x_a,
                         const Point<2> &x_b,
                         const double    length,
                         const double    s_begin,
                         const double    s_end,
                         const unsigned  depth,
                         Integrand      &f)
      {
        const Point<2> p_begin = x_a + s_begin * (x_b - x_a);
        const Point<2> p_end   = x_a + s_end * (x_b - x_a);
        const double   d       = point_segment_distance(xi, p_begin, p_end);
        const double   kappa   = 0.5;
        if ((s_end - s_begin) * length <= kappa * d || depth >= 40)
          apply_gauss(gauss_rule(8), x_a, x_b, length, s_begin, s_end, f);
        else
        {
          const double s_mid = 0.5 * (s_begin + s_end);
          integrate_bisected(
            xi, x_a, x_b, length, s_begin, s_mid, depth + 1, f);
          integrate_bisected(xi, x_a, x_b, length, s_mid, s_end, depth + 1, f);
        }
      }

      /**
       * The distance-dependent rule of doc/bem-method.md §4.2 for a regular
       * (source not on the element) but possibly nearly singular element
       * integral: f(x, s, w) is called with the field point, the local
       * coordinate and the weight including the Jacobian. The 3-point tier for
       * d >= 12 L is ours: the Bernstein-ellipse bound (4d/L)^(-2n) and
       * the 9.5e-8 that doc/bem-method.md §4.2 measured for n = 3 at d = 8 L
       * put it below 1e-8.
       */
      template <typename Integrand>
      void
      integrate_element(const Point<2> &xi,
                        const Point<2> &x_a,
                        const Point<2> &x_b,
                        const double    length,
                        Integrand      &f)
      {
        const double d = point_segment_distance(xi, x_a, x_b);
        if (d >= 12. * length)
          apply_gauss(gauss_rule(3), x_a, x_b, length, 0., 1., f);
        else if (d >= 4. * length)
          apply_gauss(gauss_rule(4), x_a, x_b, length, 0., 1., f);
        else if (d >= 2. * length)
          apply_gauss(gauss_rule(6), x_a, x_b, length, 0., 1., f);
        else if (d >= length)
          apply_gauss(gauss_rule(8), x_a, x_b, length, 0., 1., f);
        else
          integrate_bisected(xi, x_a, x_b, length, 0., 1., 0, f);
      }

      Tensor<2, 2>
      outer(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return outer_product(a, b);
      }

      /**
       * Integrate over element @p e of @p mesh with the distance-dependent
       * rule for the point @p xi, calling f(x, n, t(x), u(x), w) at each
       * quadrature point with the boundary solution interpolated there.
       */
      template <typename Integrand>
      void
      integrate_boundary_solution(const BoundaryMesh &mesh,
                                  const Point<2>     &xi,
                                  const unsigned int  e,
                                  Integrand         &&f)
      {
        const auto        &nodes   = mesh.get_nodes();
        const auto        &element = mesh.get_elements()[e];
        const unsigned int n_shape = mesh.n_element_nodes();
        auto integrand = [&](const Point<2> &x, const double s, const double w)
        {
          const auto   shape = mesh.shape_values(s);
          Tensor<1, 2> t, u;
          for (unsigned int k = 0; k < n_shape; ++k)
          {
            t += shape[k] * element.traction[k];
            u += shape[k] * nodes[element.nodes[k]].displacement;
          }
          f(x, element.normal, t, u, w);
        };
        integrate_element(
          xi, element.x_a, element.x_b, element.length, integrand);
      }

      /** Add the contribution of element @p e to the Somigliana stress at
       * @p xi to @p sigma. */
      void
      add_element_stress(const BoundaryMesh    &mesh,
                         const KelvinSolution  &kelvin,
                         const Point<2>        &xi,
                         const unsigned int     e,
                         SymmetricTensor<2, 2> &sigma)
      {
        integrate_boundary_solution(
          mesh,
          xi,
          e,
          [&](const Point<2>     &x,
              const Tensor<1, 2> &n,
              const Tensor<1, 2> &t,
              const Tensor<1, 2> &u,
              const double        w)
          { sigma += w * kelvin.stress_integrand(xi, x, n, t, u); });
      }
    } // namespace

    void
    singular_element_blocks(const BoundaryMesh          &mesh,
                            const KelvinSolution        &kelvin,
                            const double                 length,
                            const Tensor<1, 2>          &tau,
                            const Tensor<1, 2>          &n,
                            const double                 s0,
                            std::array<Tensor<2, 2>, 3> &g,
                            std::array<Tensor<2, 2>, 3> &h)
    {
      // On a straight element through the source, r_vec = (s - s0) L tau,
      // so with t = s - s0 (doc/bem-method.md §2.4, §2.7):
      //   U N_k = c_U [(3-4nu)(ln L + ln|t|) delta - tau tau] N_k,
      //   T N_k = A (tau n - n tau) N_k / (L t)   (dr/dn = 0).
      // Writing N_k as a polynomial sum_m c_m t^m, every integral is a sum
      // of exact moments over t in [-s0, 1-s0]: int t^m, int ln|t| t^m, and
      // the principal value of int t^(m-1) (ln((1-s0)/s0) for m = 0). This
      // is exact for any polynomial degree (no singular quadrature rule and
      // its error to justify); for linear shapes it reproduces the closed
      // forms of doc/bem-method.md §2.4 and §2.7.
      const double       nu  = kelvin.nu;
      const double       c_u = -1. / (8. * numbers::PI * (1. - nu));
      const double       a_t = (1. - 2. * nu) / (4. * numbers::PI * (1. - nu));
      const Tensor<2, 2> identity = unit_symmetric_tensor<2>();
      const Tensor<2, 2> twist    = a_t * (outer(tau, n) - outer(n, tau));
      const double       a = s0, b = 1. - s0;

      // F(x, m) = int_0^x ln(t) t^m dt.
      const auto log_moment = [](const double x, const unsigned int m)
      {
        const double p = m + 1.;
        return x > 0 ? std::pow(x, p) * (std::log(x) / p - 1. / (p * p)) : 0.;
      };
      std::array<double, 3> power, log_power;
      for (unsigned int m = 0; m < 3; ++m)
      {
        power[m]     = (std::pow(b, m + 1.) - std::pow(-a, m + 1.)) / (m + 1.);
        log_power[m] = log_moment(b, m) + (m % 2 ? -1. : 1.) * log_moment(a, m);
      }

      // Monomial coefficients in s of the shape functions (start, end,
      // midpoint), then shifted to t = s - s0.
      const std::array<std::array<double, 3>, 3> monomials =
        mesh.degree() == 1
          ? std::array<std::array<double, 3>, 3>{{{{1., -1., 0.}},
                                                  {{0., 1., 0.}},
                                                  {{0., 0., 0.}}}}
          : std::array<std::array<double, 3>, 3>{
              {{{1., -3., 2.}}, {{0., -1., 2.}}, {{0., 4., -4.}}}};
      for (unsigned int k = 0; k < 3; ++k)
      {
        const auto                 &p = monomials[k];
        const std::array<double, 3> c{
          {p[0] + p[1] * s0 + p[2] * s0 * s0, p[1] + 2. * p[2] * s0, p[2]}};
        double integral = 0, log_integral = 0;
        for (unsigned int m = 0; m < 3; ++m)
        {
          integral += c[m] * power[m];
          log_integral += c[m] * log_power[m];
        }
        g[k] =
          c_u * ((3. - 4. * nu) * length *
                   (std::log(length) * integral + log_integral) * identity -
                 length * integral * outer(tau, tau));

        // N_k(s0) = c_0: where it is nonzero at an end of the element the
        // integral diverges; that block is left to the rigid-body trick.
        const bool singular = std::abs(c[0]) > 1e-14;
        if (singular && (a == 0. || b == 0.))
          h[k] = Tensor<2, 2>();
        else
          h[k] = ((singular ? c[0] * std::log(b / a) : 0.) + c[1] * power[0] +
                  c[2] * power[1]) *
                 twist;
      }
    }

    namespace
    {
      /** The constants of the Kelvin kernels (mu = 1) in the closed forms
       * below. */
      struct KernelConstants
      {
        explicit KernelConstants(const double nu)
          : nu(nu)
          , c_u(-1. / (8. * numbers::PI * (1. - nu)))
          , a_t((1. - 2. * nu) / (4. * numbers::PI * (1. - nu)))
        {
        }

        const double       nu;
        const double       c_u;
        const double       a_t;
        const Tensor<2, 2> identity = unit_symmetric_tensor<2>();
      };

      /** A linear element @p e adjacent to the collocation node
       * (doc/bem-method.md §2.4): closed forms of the log kernel integrated
       * exactly, and of T times the far shape function, which is constant
       * there because dr/dn = 0 and N_far = s/L cancels the 1/s. The near H
       * block is left to the rigid-body trick. */
      void
      add_adjacent_linear_element(const BoundaryMesh::Element          &element,
                                  const unsigned int                    e,
                                  const BoundaryMesh::CollocationPoint &point,
                                  const KernelConstants                &k_c,
                                  RowBlocks                            &blocks)
      {
        const double        nu = k_c.nu, c_u = k_c.c_u, a_t = k_c.a_t;
        const Tensor<2, 2> &identity = k_c.identity;
        const double        L        = element.length;
        const auto         &tau = element.tangent, &n = element.normal;
        const unsigned int  k     = element.nodes[0] == point.node ? 0 : 1;
        const Tensor<1, 2>  rhat  = k == 0 ? tau : Tensor<1, 2>(-tau);
        const double        log_l = std::log(L);
        blocks.g[e][k] +=
          c_u * ((3. - 4. * nu) * (0.5 * L * log_l - 0.75 * L) * identity -
                 0.5 * L * outer(tau, tau));
        blocks.g[e][1 - k] +=
          c_u * ((3. - 4. * nu) * (0.5 * L * log_l - 0.25 * L) * identity -
                 0.5 * L * outer(tau, tau));
        blocks.h[element.nodes[1 - k]] +=
          a_t * (outer(rhat, n) - outer(n, rhat));
      }

      /** The linear element @p e that holds an off-node collocation point
       * (doc/bem-method.md §2.7): Cauchy principal values of T N_a, T N_b and
       * the log integrals in closed form, with the smooth-point free term
       * delta/2 spread on the two nodes by the shape functions. */
      void
      add_own_linear_element(const BoundaryMesh::Element          &element,
                             const unsigned int                    e,
                             const BoundaryMesh::CollocationPoint &point,
                             const KernelConstants                &k_c,
                             RowBlocks                            &blocks)
      {
        const double        nu = k_c.nu, c_u = k_c.c_u, a_t = k_c.a_t;
        const Tensor<2, 2> &identity = k_c.identity;
        const double        L        = element.length;
        const auto         &tau = element.tangent, &n = element.normal;
        const double        s0 = point.s0, s_a = s0 * L, s_b = (1. - s0) * L;
        const double        log_ratio = std::log(s_b / s_a);
        const double        pv_a      = (s_b * log_ratio - L) / L;
        const double        pv_b      = (L + s_a * log_ratio) / L;
        const Tensor<2, 2>  twist     = a_t * (outer(tau, n) - outer(n, tau));
        blocks.h[element.nodes[0]] += pv_a * twist + 0.5 * (1. - s0) * identity;
        blocks.h[element.nodes[1]] += pv_b * twist + 0.5 * s0 * identity;

        const double i0 = s_b * std::log(s_b) - s_b + s_a * std::log(s_a) - s_a;
        const double i1 = (0.5 * s_b * s_b * std::log(s_b) - 0.25 * s_b * s_b) -
                          (0.5 * s_a * s_a * std::log(s_a) - 0.25 * s_a * s_a);
        const double log_a = (s_b * i0 - i1) / L, log_b = (i1 + s_a * i0) / L;
        blocks.g[e][0] +=
          c_u * ((3. - 4. * nu) * log_a * identity - 0.5 * L * outer(tau, tau));
        blocks.g[e][1] +=
          c_u * ((3. - 4. * nu) * log_b * identity - 0.5 * L * outer(tau, tau));
      }

      /** A quadratic element @p e through the collocation point: exact
       * moments (singular_element_blocks()) at its start (s = 0), end (1),
       * midpoint (1/2) or off-node point (s0). The block of the collocation
       * node itself is replaced by the rigid-body trick; an off-node point
       * is a smooth point of its element and adds the free term delta/2,
       * spread by the shape functions. */
      void
      add_singular_quadratic_element(
        const BoundaryMesh                   &mesh,
        const KelvinSolution                 &kelvin,
        const unsigned int                    e,
        const BoundaryMesh::CollocationPoint &point,
        const Tensor<2, 2>                   &identity,
        RowBlocks                            &blocks)
      {
        const BoundaryMesh::Element &element = mesh.get_elements()[e];
        const double                 s0      = e == point.element ? point.s0
                                               : element.nodes[0] == point.node ? 0.
                                               : element.nodes[1] == point.node ? 1.
                                                                                : 0.5;
        std::array<Tensor<2, 2>, 3>  g, h;
        singular_element_blocks(mesh,
                                kelvin,
                                element.length,
                                element.tangent,
                                element.normal,
                                s0,
                                g,
                                h);
        const auto shape = mesh.shape_values(s0);
        for (unsigned int k = 0; k < 3; ++k)
        {
          blocks.g[e][k] += g[k];
          blocks.h[element.nodes[k]] += h[k];
          if (e == point.element)
            blocks.h[element.nodes[k]] += 0.5 * shape[k] * identity;
        }
      }

      /** An element @p e away from the collocation point @p xi: the kernels
       * times the shape functions by quadrature. */
      void
      add_regular_element(const BoundaryMesh   &mesh,
                          const KelvinSolution &kelvin,
                          const unsigned int    e,
                          const Point<2>       &xi,
                          RowBlocks            &blocks)
      {
        const BoundaryMesh::Element &element = mesh.get_elements()[e];
        const auto                  &n       = element.normal;
        auto                        &g       = blocks.g[e];
        const unsigned int           n_shape = mesh.n_element_nodes();
        auto integrand = [&](const Point<2> &x, const double s, const double w)
        {
          const Tensor<2, 2> u     = kelvin.displacement_kernel(xi, x);
          const Tensor<2, 2> t     = kelvin.traction_kernel(xi, x, n);
          const auto         shape = mesh.shape_values(s);
          for (unsigned int k = 0; k < n_shape; ++k)
          {
            g[k] += (w * shape[k]) * u;
            blocks.h[element.nodes[k]] += (w * shape[k]) * t;
          }
        };
        integrate_element(
          xi, element.x_a, element.x_b, element.length, integrand);
      }
    } // namespace

    void
    collocation_row_blocks(const BoundaryMesh                   &mesh,
                           const KelvinSolution                 &kelvin,
                           const BoundaryMesh::CollocationPoint &point,
                           RowBlocks                            &blocks)
    {
      const auto           &nodes    = mesh.get_nodes();
      const auto           &elements = mesh.get_elements();
      const KernelConstants constants(kelvin.nu);

      blocks.h.assign(nodes.size(), Tensor<2, 2>());
      blocks.g.assign(elements.size(), std::array<Tensor<2, 2>, 3>());

      for (unsigned int e = 0; e < elements.size(); ++e)
      {
        const BoundaryMesh::Element &element = elements[e];
        const bool                   on_node =
          point.node != numbers::invalid_unsigned_int &&
          (element.nodes[0] == point.node || element.nodes[1] == point.node ||
           element.nodes[2] == point.node);
        if (mesh.degree() == 1 && on_node)
          add_adjacent_linear_element(element, e, point, constants, blocks);
        else if (mesh.degree() == 1 && e == point.element)
          add_own_linear_element(element, e, point, constants, blocks);
        else if (on_node || e == point.element)
          add_singular_quadratic_element(
            mesh, kelvin, e, point, constants.identity, blocks);
        else
          add_regular_element(mesh, kelvin, e, point.x, blocks);
      }

      if (point.node != numbers::invalid_unsigned_int)
      {
        // Rigid-body (row-sum) trick (doc/bem-method.md §2.3): a translation
        // with zero traction solves the problem, so the H blocks of a row sum
        // to zero. This yields the free term c_ij plus the principal value of T
        // N_i on the adjacent elements at any corner angle.
        Tensor<2, 2> sum;
        for (unsigned int m = 0; m < nodes.size(); ++m)
          if (m != point.node)
            sum += blocks.h[m];
        blocks.h[point.node] = -sum;
      }
    }

    SymmetricTensor<2, 2>
    somigliana_stress(const BoundaryMesh   &mesh,
                      const KelvinSolution &kelvin,
                      const Point<2>       &xi)
    {
      // Somigliana stress identity (doc/bem-method.md §1.3, §4.1) with the
      // adaptive rule: the first FEM quadrature points lie at 0.21 h from the
      // boundary, where fixed Gauss rules fail completely.
      SymmetricTensor<2, 2> sigma;
      for (unsigned int e = 0; e < mesh.get_elements().size(); ++e)
        add_element_stress(mesh, kelvin, xi, e, sigma);
      return sigma;
    }

    SymmetricTensor<2, 2>
    somigliana_stress(const BoundaryMesh              &mesh,
                      const KelvinSolution            &kelvin,
                      const Point<2>                  &xi,
                      const std::vector<unsigned int> &subset)
    {
      SymmetricTensor<2, 2> sigma;
      for (const unsigned int e : subset)
        add_element_stress(mesh, kelvin, xi, e, sigma);
      return sigma;
    }

    Tensor<1, 2>
    somigliana_displacement(const BoundaryMesh   &mesh,
                            const KelvinSolution &kelvin,
                            const Point<2>       &xi)
    {
      // Somigliana displacement identity (doc/bem-method.md §1.3).
      Tensor<1, 2> result;
      for (unsigned int e = 0; e < mesh.get_elements().size(); ++e)
        integrate_boundary_solution(
          mesh,
          xi,
          e,
          [&](const Point<2>     &x,
              const Tensor<1, 2> &n,
              const Tensor<1, 2> &t,
              const Tensor<1, 2> &u,
              const double        w)
          { result += w * kelvin.displacement_integrand(xi, x, n, t, u); });
      return result;
    }
  } // namespace BoundaryIntegration
} // namespace ddcontact
