#include <deal.II/base/parallel.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/thread_management.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>

#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/parameters.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <numeric>

namespace ddcontact
{
  namespace
  {
    using Clock = std::chrono::steady_clock;

    double
    seconds_since(const Clock::time_point &start)
    {
      return std::chrono::duration<double>(Clock::now() - start).count();
    }

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
     * piece (BEM.md §4.2). The note uses kappa = 1; we take kappa = 1/2:
     * on graded meshes (neighbour faces twice as long) the uniform-stress
     * patch test at 1 % of an element length from the boundary improved
     * from 1.4e-7 to 7e-9, at the price of a few more points on the one or
     * two nearest elements. The depth limit only matters for points on
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
        integrate_bisected(xi, x_a, x_b, length, s_begin, s_mid, depth + 1, f);
        integrate_bisected(xi, x_a, x_b, length, s_mid, s_end, depth + 1, f);
      }
    }

    /**
     * The distance-dependent rule of BEM.md §4.2 for a regular (source not
     * on the element) but possibly nearly singular element integral:
     * f(x, s, w) is called with the field point, the local coordinate and
     * the weight including the Jacobian. The 3-point tier for d >= 12 L is
     * ours: the Bernstein-ellipse bound (4d/L)^(-2n) and the 9.5e-8 that
     * the note measured for n = 3 at d = 8 L put it below 1e-8.
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

    Tensor<2, 2>
    outer(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return outer_product(a, b);
    }
  } // namespace

  BoundaryElementSolver::BoundaryElementSolver(
    const Material &material, const BoundaryConditions<2> &boundary_conditions)
    : material(material)
    , boundary_conditions(boundary_conditions)
    , kelvin(1., material.poisson_ratio)
  {
    // The direct BEM has no domain integral: a body force would need one
    // (or a particular solution), which this solver does not provide.
    if (boundary_conditions.body_force)
      throw InputError("BoundaryElementSolver: the body has a body force, but "
                       "the boundary element reference solution supports "
                       "boundary loads only");
    if (!(material.youngs_modulus > 0) || !(material.poisson_ratio < 0.5) ||
        !(material.poisson_ratio > -1))
      throw InputError("BoundaryElementSolver: the material needs E > 0 and "
                       "-1 < nu < 0.5 for plane strain");
  }

  void
  BoundaryElementSolver::setup(const DoFHandler<2> &dof_handler,
                               const Mapping<2>    &mapping)
  {
    const auto start = Clock::now();
    timing_data      = Timings();
    is_solved        = false;

    const FiniteElement<2> &fe = dof_handler.get_fe();
    if (fe.n_components() != 2)
      throw InputError("BoundaryElementSolver: the finite element has " +
                       std::to_string(fe.n_components()) +
                       " components, but a 2D displacement needs 2");
    // The BEM basis is the trace of the FEM basis (26): straight 2-node
    // elements with linear shape functions, i.e. Q1 quadrilaterals or P1
    // triangles only.
    if (fe.degree != 1 || fe.n_dofs_per_vertex() != 2 ||
        fe.n_dofs_per_line() != 0)
      throw InputError(
        "BoundaryElementSolver: the finite element " + fe.get_name() +
        " has degree " + std::to_string(fe.degree) +
        ", but the boundary elements support only degree 1 (Q1 or P1)");

    build_boundary_mesh(dof_handler, mapping);
    number_unknowns();
    find_rigid_modes();
    assemble_system();
    timing_data.assembly = seconds_since(start);

    const auto lu_start = Clock::now();
    system_matrix.compute_lu_factorization();
    timing_data.factorization = seconds_since(lu_start);
  }

  namespace
  {
    /** A boundary face (25) with the global dofs of its two vertices,
     * and whether the body lies on the left of x[1] -> x[0] (deal.II does
     * not orient faces), as sent between the processes of a distributed
     * mesh. */
    struct BoundaryFace
    {
      std::array<Point<2>, 2>                               x;
      std::array<std::array<types::global_dof_index, 2>, 2> dofs;
      types::boundary_id                                    boundary_id;
      bool                                                  reversed;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &x &dofs &boundary_id &reversed;
      }
    };
  } // namespace

  void
  BoundaryElementSolver::build_boundary_mesh(const DoFHandler<2> &dof_handler,
                                             const Mapping<2>    &mapping)
  {
    nodes.clear();
    elements.clear();

    std::vector<BoundaryFace> faces;

    // A distributed mesh (p4est) knows its own cells only: each process
    // takes the faces of its cells and every process gets all of them.
    const auto *distributed =
      dynamic_cast<const parallel::DistributedTriangulationBase<2> *>(
        &dof_handler.get_triangulation());
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (!cell->at_boundary() || (distributed && !cell->is_locally_owned()))
        continue;
      const auto cell_vertices = mapping.get_vertices(cell);
      Point<2>   centroid;
      for (const auto &v : cell_vertices)
        centroid += v / static_cast<double>(cell_vertices.size());

      for (const unsigned int f : cell->face_indices())
      {
        const auto face = cell->face(f);
        if (!face->at_boundary())
          continue;
        BoundaryFace boundary_face;
        boundary_face.boundary_id = face->boundary_id();
        for (unsigned int v = 0; v < 2; ++v)
        {
          unsigned int cell_vertex = numbers::invalid_unsigned_int;
          for (const unsigned int cv : cell->vertex_indices())
            if (cell->vertex_index(cv) == face->vertex_index(v))
              cell_vertex = cv;
          Assert(cell_vertex != numbers::invalid_unsigned_int,
                 ExcInternalError());
          boundary_face.x[v] = cell_vertices[cell_vertex];
          for (unsigned int c = 0; c < 2; ++c)
          {
            // Vertex dofs of FESystem(Q1 or P1, 2) are ordered by
            // component.
            Assert(dof_handler.get_fe()
                       .face_system_to_component_index(2 * v + c)
                       .first == c,
                   ExcInternalError());
            boundary_face.dofs[v][c] = face->vertex_dof_index(v, c);
          }
        }
        const Tensor<1, 2> tangent = boundary_face.x[1] - boundary_face.x[0];
        const Tensor<1, 2> normal{{tangent[1], -tangent[0]}};
        const Point<2>     midpoint =
          0.5 * (boundary_face.x[0] + boundary_face.x[1]);
        boundary_face.reversed = normal * (midpoint - centroid) < 0;
        faces.push_back(boundary_face);
      }
    }
    if (distributed)
    {
      std::vector<BoundaryFace> all;
      for (const auto &from_process :
           Utilities::MPI::all_gather(distributed->get_communicator(), faces))
        all.insert(all.end(), from_process.begin(), from_process.end());
      faces = std::move(all);
    }

    // The nodes are the vertices, told apart by their dofs (the vertex
    // numbers of a distributed mesh differ between the processes).
    std::map<types::global_dof_index, unsigned int> dof_to_node;
    for (const auto &face : faces)
    {
      Element element;
      for (unsigned int v = 0; v < 2; ++v)
      {
        const auto [it, is_new] =
          dof_to_node.emplace(face.dofs[v][0], nodes.size());
        if (is_new)
        {
          Node node;
          node.x_physical = face.x[v];
          node.dofs       = face.dofs[v];
          nodes.push_back(node);
        }
        element.nodes[v] = it->second;
      }
      if (face.reversed)
        std::swap(element.nodes[0], element.nodes[1]);
      element.boundary_id = face.boundary_id;
      elements.push_back(element);
    }
    if (elements.empty())
      throw InputError("BoundaryElementSolver: the mesh has no boundary faces");

    // Every node must have exactly one incoming and one outgoing element:
    // the boundary is a set of closed polygons.
    for (unsigned int e = 0; e < elements.size(); ++e)
    {
      auto &in  = nodes[elements[e].nodes[1]].element_in;
      auto &out = nodes[elements[e].nodes[0]].element_out;
      if (in != numbers::invalid_unsigned_int ||
          out != numbers::invalid_unsigned_int)
        throw InputError("BoundaryElementSolver: the boundary of the mesh is "
                         "not a set of simple closed polygons (a vertex is "
                         "shared by more than two boundary faces)");
      in  = e;
      out = e;
    }

#ifdef DEBUG
    for (const auto &node : nodes)
      Assert(node.element_in != numbers::invalid_unsigned_int &&
               node.element_out != numbers::invalid_unsigned_int,
             ExcInternalError());

    // In 2D no hanging node lies on the boundary of a single body (BEM.md
    // §2.8), so the trace of the constrained Q1 space is the space of
    // continuous piecewise linears on this boundary mesh.
    {
      AffineConstraints<double> hanging_nodes;
      DoFTools::make_hanging_node_constraints(dof_handler, hanging_nodes);
      hanging_nodes.close();
      for (const auto &node : nodes)
        for (const auto dof : node.dofs)
          Assert(!hanging_nodes.is_constrained(dof),
                 ExcMessage("A boundary vertex carries a hanging-node "
                            "constraint; the BEM trace would be wrong."));
    }
#endif

    // Nondimensionalise (BEM.md §3.3, §5.2): lengths by the bounding-box
    // diagonal of the boundary, which keeps the body far from the
    // degenerate scale of the log kernel; tractions by mu.
    Point<2> lower = nodes[0].x_physical, upper = nodes[0].x_physical;
    for (const auto &node : nodes)
      for (unsigned int d = 0; d < 2; ++d)
      {
        lower[d] = std::min(lower[d], node.x_physical[d]);
        upper[d] = std::max(upper[d], node.x_physical[d]);
      }
    reference_length = lower.distance(upper);
    reference_center = 0.5 * (lower + upper);
    for (auto &node : nodes)
      node.x =
        Point<2>((node.x_physical - reference_center) / reference_length);

    for (auto &element : elements)
    {
      element.x_a          = nodes[element.nodes[0]].x;
      element.x_b          = nodes[element.nodes[1]].x;
      const Tensor<1, 2> t = element.x_b - element.x_a;
      element.length       = t.norm();
      Assert(element.length > 0, ExcInternalError());
      element.tangent = t / element.length;
      element.normal  = Tensor<1, 2>{{element.tangent[1], -element.tangent[0]}};
    }
  }

  void
  BoundaryElementSolver::number_unknowns()
  {
    const double mu = material.mu();

    // Boundary data of the body: which components are prescribed where,
    // and their values (displacements at nodes, tractions sampled at the
    // element ends with the element's own data, BEM.md §2.2).
    n_contact_elements = 0;
    for (auto &element : elements)
    {
      const auto dirichlet =
        boundary_conditions.dirichlet.find(element.boundary_id);
      for (unsigned int c = 0; c < 2; ++c)
        element.dirichlet[c] =
          dirichlet != boundary_conditions.dirichlet.end() &&
          dirichlet->second.mask[c];
      element.is_contact =
        boundary_conditions.contact.count(element.boundary_id) > 0;
      element.contact_index = element.is_contact
                                ? n_contact_elements++
                                : numbers::invalid_unsigned_int;

      const auto neumann =
        boundary_conditions.neumann.find(element.boundary_id);
      for (unsigned int k = 0; k < 2; ++k)
      {
        element.traction[k] = Tensor<1, 2>();
        if (neumann != boundary_conditions.neumann.end())
          for (unsigned int c = 0; c < 2; ++c)
            if (!element.dirichlet[c])
              element.traction[k][c] =
                neumann->second->value(nodes[element.nodes[k]].x_physical, c) /
                mu;
      }
    }

    unsigned int n = 0;
    for (auto &node : nodes)
      for (unsigned int c = 0; c < 2; ++c)
      {
        // Where two Dirichlet ids meet, the smaller id wins, as in the FEM
        // constraints built by interpolate_boundary_values() id by id.
        node.known[c]         = false;
        node.unknown[c]       = numbers::invalid_unsigned_int;
        types::boundary_id id = numbers::invalid_boundary_id;
        for (const unsigned int e : {node.element_in, node.element_out})
          if (elements[e].dirichlet[c])
            id = std::min(id, elements[e].boundary_id);
        if (id != numbers::invalid_boundary_id)
        {
          node.known[c] = true;
          node.displacement[c] =
            boundary_conditions.dirichlet.at(id).displacement->value(
              node.x_physical, c) /
            reference_length;
        }
        else
        {
          node.unknown[c]      = n++;
          node.displacement[c] = 0;
        }
      }

    // Unknown tractions: at element ends where the component is prescribed
    // as displacement. Two ends meeting at a straight (smooth) node with
    // the displacement prescribed on both sides share one unknown; at a
    // genuine corner they are independent and get an extra collocation row
    // (BEM.md §2.7).
    const auto is_smooth =
      [&](const unsigned int e_in, const unsigned int e_out)
    {
      const Tensor<1, 2> &a = elements[e_in].tangent,
                         &b = elements[e_out].tangent;
      return a * b > 0 && std::abs(a[0] * b[1] - a[1] * b[0]) < 1e-8;
    };
    for (auto &element : elements)
      for (unsigned int c = 0; c < 2; ++c)
        element.unknown[1][c] =
          element.dirichlet[c] ? n++ : numbers::invalid_unsigned_int;
    for (unsigned int e = 0; e < elements.size(); ++e)
      for (unsigned int c = 0; c < 2; ++c)
      {
        auto &element = elements[e];
        if (!element.dirichlet[c])
        {
          element.unknown[0][c] = numbers::invalid_unsigned_int;
          continue;
        }
        const unsigned int e_in = nodes[element.nodes[0]].element_in;
        if (elements[e_in].dirichlet[c] && is_smooth(e_in, e))
          element.unknown[0][c] = elements[e_in].unknown[1][c];
        else
          element.unknown[0][c] = n++;
      }
    n_boundary_unknowns = n;

    // Collocation: both components at every node, rows 2i + c, then the
    // extra off-node rows at D-D corners, inside the outgoing element at
    // s0 = 1/4 (any s0 in (0,1) works).
    collocation_points.clear();
    for (unsigned int i = 0; i < nodes.size(); ++i)
    {
      CollocationPoint point;
      point.x          = nodes[i].x;
      point.node       = i;
      point.components = {0, 1};
      point.rows       = {2 * i, 2 * i + 1};
      collocation_points.push_back(point);
    }
    unsigned int row = 2 * nodes.size();
    for (unsigned int i = 0; i < nodes.size(); ++i)
    {
      const unsigned int e_in  = nodes[i].element_in,
                         e_out = nodes[i].element_out;
      CollocationPoint point;
      point.element = e_out;
      point.s0      = 0.25;
      point.x       = elements[e_out].x_a +
                point.s0 * (elements[e_out].x_b - elements[e_out].x_a);
      for (unsigned int c = 0; c < 2; ++c)
        if (elements[e_in].dirichlet[c] && elements[e_out].dirichlet[c] &&
            !is_smooth(e_in, e_out))
        {
          point.components.push_back(c);
          point.rows.push_back(row++);
        }
      if (!point.components.empty())
        collocation_points.push_back(point);
    }
    n_extra_rows = row - 2 * nodes.size();
    AssertThrow(row == n_boundary_unknowns,
                ExcMessage("BEM: the number of collocation rows (" +
                           std::to_string(row) +
                           ") differs from the number of unknowns (" +
                           std::to_string(n_boundary_unknowns) + ")"));
  }

  void
  BoundaryElementSolver::find_rigid_modes()
  {
    // A rigid motion a e_x + b e_y + c (-y, x) is left free by the
    // Dirichlet data if it vanishes at every prescribed nodal component,
    // i.e. if (a, b, c) is in the null space of the Gram matrix of those
    // constraints. A floating body keeps all three (BEM.md §5.1).
    SymmetricTensor<2, 3> gram;
    for (const auto &node : nodes)
      for (unsigned int c = 0; c < 2; ++c)
        if (node.known[c])
        {
          const Tensor<1, 3> r{{c == 0 ? 1. : 0.,
                                c == 1 ? 1. : 0.,
                                c == 0 ? -node.x[1] : node.x[0]}};
          for (unsigned int p = 0; p < 3; ++p)
            for (unsigned int q = p; q < 3; ++q)
              gram[p][q] += r[p] * r[q];
        }

    rigid_modes.clear();
    const double size = trace(gram);
    if (size == 0)
      for (unsigned int p = 0; p < 3; ++p)
      {
        Tensor<1, 3> mode;
        mode[p] = 1;
        rigid_modes.push_back(mode);
      }
    else
      for (const auto &[value, vector] : eigenvectors(gram))
        if (value <= 1e-10 * size)
          rigid_modes.push_back(vector);
  }

  void
  BoundaryElementSolver::compute_row_blocks(const CollocationPoint &point,
                                            RowBlocks &blocks) const
  {
    const double       nu  = kelvin.nu;
    const double       c_u = -1. / (8. * numbers::PI * (1. - nu)); // mu = 1
    const double       a_t = (1. - 2. * nu) / (4. * numbers::PI * (1. - nu));
    const Tensor<2, 2> identity = unit_symmetric_tensor<2>();

    blocks.h.assign(nodes.size(), Tensor<2, 2>());
    blocks.g.assign(elements.size(), std::array<Tensor<2, 2>, 2>());
    const Point<2> &xi = point.x;

    for (unsigned int e = 0; e < elements.size(); ++e)
    {
      const Element &element = elements[e];
      const double   L       = element.length;
      const auto    &tau = element.tangent, &n = element.normal;

      if (point.node != numbers::invalid_unsigned_int &&
          (element.nodes[0] == point.node || element.nodes[1] == point.node))
      {
        // Closed forms on the two elements adjacent to the collocation
        // node (BEM.md §2.4): the log kernel integrated exactly, and T
        // times the far shape function, which is constant there because
        // dr/dn = 0 and N_far = s/L cancels the 1/s. The near H block is
        // left to the rigid-body trick below.
        const unsigned int k     = element.nodes[0] == point.node ? 0 : 1;
        const Tensor<1, 2> rhat  = k == 0 ? tau : Tensor<1, 2>(-tau);
        const double       log_l = std::log(L);
        blocks.g[e][k] +=
          c_u * ((3. - 4. * nu) * (0.5 * L * log_l - 0.75 * L) * identity -
                 0.5 * L * outer(tau, tau));
        blocks.g[e][1 - k] +=
          c_u * ((3. - 4. * nu) * (0.5 * L * log_l - 0.25 * L) * identity -
                 0.5 * L * outer(tau, tau));
        blocks.h[element.nodes[1 - k]] +=
          a_t * (outer(rhat, n) - outer(n, rhat));
      }
      else if (e == point.element)
      {
        // Off-node collocation point inside its own element (BEM.md §2.7):
        // Cauchy principal values of T N_a, T N_b and the log integrals in
        // closed form, with the smooth-point free term delta/2 spread on
        // the two nodes by the shape functions.
        const double       s0 = point.s0, s_a = s0 * L, s_b = (1. - s0) * L;
        const double       log_ratio = std::log(s_b / s_a);
        const double       pv_a      = (s_b * log_ratio - L) / L;
        const double       pv_b      = (L + s_a * log_ratio) / L;
        const Tensor<2, 2> twist     = a_t * (outer(tau, n) - outer(n, tau));
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
      else
      {
        Tensor<2, 2> &h_a = blocks.h[element.nodes[0]];
        Tensor<2, 2> &h_b = blocks.h[element.nodes[1]];
        auto         &g   = blocks.g[e];
        auto integrand = [&](const Point<2> &x, const double s, const double w)
        {
          const Tensor<2, 2> u = kelvin.displacement_kernel(xi, x);
          const Tensor<2, 2> t = kelvin.traction_kernel(xi, x, n);
          g[0] += (w * (1. - s)) * u;
          g[1] += (w * s) * u;
          h_a += (w * (1. - s)) * t;
          h_b += (w * s) * t;
        };
        integrate_element(xi, element.x_a, element.x_b, L, integrand);
      }
    }

    if (point.node != numbers::invalid_unsigned_int)
    {
      // Rigid-body (row-sum) trick (BEM.md §2.3): a translation with zero
      // traction solves the problem, so the H blocks of a row sum to zero.
      // This yields the free term c_ij plus the principal value of T N_i
      // on the adjacent elements at any corner angle.
      Tensor<2, 2> sum;
      for (unsigned int m = 0; m < nodes.size(); ++m)
        if (m != point.node)
          sum += blocks.h[m];
      blocks.h[point.node] = -sum;
    }
  }

  void
  BoundaryElementSolver::assemble_system()
  {
    const unsigned int n_modes = rigid_modes.size();
    const unsigned int n       = n_boundary_unknowns + n_modes;
    system_matrix.reinit(n, n);
    body_rhs.reinit(n);
    contact_matrix.reinit(n_boundary_unknowns, 4 * n_contact_elements);

    // Every collocation point fills its own rows only, so the points can
    // be processed in parallel without synchronisation.
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(collocation_points.size()),
      [&](const unsigned int begin, const unsigned int end)
      {
        RowBlocks blocks;
        for (unsigned int p = begin; p < end; ++p)
        {
          const CollocationPoint &point = collocation_points[p];
          compute_row_blocks(point, blocks);
          if (point.node != numbers::invalid_unsigned_int)
            nodes[point.node].diagonal_block = blocks.h[point.node];

          // Column swapping (BEM.md §3.1): c u + H u - G t = 0 with known
          // values moved to the right-hand side.
          for (unsigned int r = 0; r < point.rows.size(); ++r)
          {
            const unsigned int row = point.rows[r], i = point.components[r];
            double             rhs = 0;
            for (unsigned int m = 0; m < nodes.size(); ++m)
              for (unsigned int j = 0; j < 2; ++j)
              {
                const double value = blocks.h[m][i][j];
                if (nodes[m].known[j])
                  rhs -= value * nodes[m].displacement[j];
                else
                  system_matrix(row, nodes[m].unknown[j]) += value;
              }
            for (unsigned int e = 0; e < elements.size(); ++e)
            {
              const Element &element = elements[e];
              for (unsigned int k = 0; k < 2; ++k)
                for (unsigned int j = 0; j < 2; ++j)
                {
                  const double value = blocks.g[e][k][i][j];
                  if (element.dirichlet[j])
                    system_matrix(row, element.unknown[k][j]) -= value;
                  else if (element.is_contact)
                    contact_matrix(
                      row, 4 * element.contact_index + 2 * k + j) += value;
                  else
                    rhs += value * element.traction[k][j];
                }
            }
            body_rhs(row) = rhs;
          }
        }
      },
      8);

    // Border the system with the free rigid modes (BEM.md §5.1):
    // [A R; R^T 0] [x; lambda] = [f; 0]. The solution has no rigid
    // component and lambda measures the equilibrium defect of the data.
    for (unsigned int q = 0; q < n_modes; ++q)
      for (const auto &node : nodes)
        for (unsigned int c = 0; c < 2; ++c)
          if (!node.known[c])
          {
            const double value =
              rigid_modes[q][c] +
              rigid_modes[q][2] * (c == 0 ? -node.x[1] : node.x[0]);
            system_matrix(node.unknown[c], n_boundary_unknowns + q) = value;
            system_matrix(n_boundary_unknowns + q, node.unknown[c]) = value;
          }
  }

  void
  BoundaryElementSolver::project_contact_traction(
    const BoundaryTractionSamples &contact,
    Vector<double>                &contact_values) const
  {
    contact_values.reinit(4 * n_contact_elements);
    if (contact.points.empty())
      return;
    if (contact.weights.size() != contact.points.size() ||
        contact.traction.size() != contact.points.size())
      throw InputError("BoundaryElementSolver: the contact traction samples "
                       "need as many weights and tractions as points");
    if (n_contact_elements == 0)
      throw InputError("BoundaryElementSolver: contact tractions were given, "
                       "but the body has no contact boundary id");

    std::vector<unsigned int> contact_elements;
    for (unsigned int e = 0; e < elements.size(); ++e)
      if (elements[e].is_contact)
        contact_elements.push_back(e);

    // Moments sum_q w_q t_q N_a(x_q) per element end, physical units.
    std::vector<std::array<Tensor<1, 2>, 2>> moments(n_contact_elements);
    for (unsigned int q = 0; q < contact.points.size(); ++q)
    {
      const Point<2> x((contact.points[q] - reference_center) /
                       reference_length);
      unsigned int   nearest  = contact_elements[0];
      double         distance = std::numeric_limits<double>::max();
      for (const unsigned int e : contact_elements)
      {
        const double d =
          point_segment_distance(x, elements[e].x_a, elements[e].x_b);
        if (d < distance)
        {
          distance = d;
          nearest  = e;
        }
      }
      const Element &element = elements[nearest];
      const double   s       = segment_coordinate(x, element.x_a, element.x_b);
      moments[element.contact_index][0] +=
        contact.weights[q] * (1. - s) * contact.traction[q];
      moments[element.contact_index][1] +=
        contact.weights[q] * s * contact.traction[q];
    }

    // L2 projection onto the linear element-end traction: the element mass
    // matrix L/6 [[2,1],[1,2]] has the inverse 2/L [[2,-1],[-1,2]].
    const double mu = material.mu();
    for (const unsigned int e : contact_elements)
    {
      const unsigned int  ci  = elements[e].contact_index;
      const double        L   = elements[e].length * reference_length;
      const Tensor<1, 2> &m_a = moments[ci][0], &m_b = moments[ci][1];
      const Tensor<1, 2>  t_a = 2. / L * (2. * m_a - m_b) / mu;
      const Tensor<1, 2>  t_b = 2. / L * (2. * m_b - m_a) / mu;
      for (unsigned int c = 0; c < 2; ++c)
      {
        contact_values(4 * ci + c)     = t_a[c];
        contact_values(4 * ci + 2 + c) = t_b[c];
      }
    }
  }

  void
  BoundaryElementSolver::solve(const BoundaryTractionSamples &contact)
  {
    Assert(system_matrix.m() > 0, ExcMessage("Call setup() first."));
    const auto start = Clock::now();

    Vector<double> contact_values;
    project_contact_traction(contact, contact_values);

    Vector<double> x(body_rhs);
    if (n_contact_elements > 0)
    {
      Vector<double> contact_rhs(n_boundary_unknowns);
      contact_matrix.vmult(contact_rhs, contact_values);
      for (unsigned int i = 0; i < n_boundary_unknowns; ++i)
        x(i) += contact_rhs(i);
    }
    system_matrix.solve(x);

    for (auto &node : nodes)
      for (unsigned int c = 0; c < 2; ++c)
        if (!node.known[c])
          node.displacement[c] = x(node.unknown[c]);
    for (auto &element : elements)
      for (unsigned int k = 0; k < 2; ++k)
        for (unsigned int c = 0; c < 2; ++c)
          if (element.dirichlet[c])
            element.traction[k][c] = x(element.unknown[k][c]);
          else if (element.is_contact)
            element.traction[k][c] =
              contact_values(4 * element.contact_index + 2 * k + c);
    is_solved         = true;
    timing_data.solve = seconds_since(start);
  }

  template <typename Integrand>
  void
  BoundaryElementSolver::integrate_boundary_solution(const Point<2>    &xi,
                                                     const unsigned int e,
                                                     Integrand        &&f) const
  {
    const Element      &element = elements[e];
    const Tensor<1, 2> &u_a     = nodes[element.nodes[0]].displacement;
    const Tensor<1, 2> &u_b     = nodes[element.nodes[1]].displacement;
    const Tensor<1, 2> &t_a = element.traction[0], &t_b = element.traction[1];
    auto integrand = [&](const Point<2> &x, const double s, const double w)
    {
      f(x,
        element.normal,
        (1. - s) * t_a + s * t_b,
        (1. - s) * u_a + s * u_b,
        w);
    };
    integrate_element(xi, element.x_a, element.x_b, element.length, integrand);
  }

  void
  BoundaryElementSolver::add_element_stress(const Point<2>        &xi,
                                            const unsigned int     e,
                                            SymmetricTensor<2, 2> &sigma) const
  {
    integrate_boundary_solution(xi,
                                e,
                                [&](const Point<2>     &x,
                                    const Tensor<1, 2> &n,
                                    const Tensor<1, 2> &t,
                                    const Tensor<1, 2> &u,
                                    const double        w) {
                                  sigma +=
                                    w * kelvin.stress_integrand(xi, x, n, t, u);
                                });
  }

  SymmetricTensor<2, 2>
  BoundaryElementSolver::scaled_stress(const Point<2> &xi) const
  {
    // Somigliana stress identity (BEM.md §1.3, §4.1) with the adaptive
    // rule: the first FEM quadrature points lie at 0.21 h from the
    // boundary, where fixed Gauss rules fail completely.
    SymmetricTensor<2, 2> sigma;
    for (unsigned int e = 0; e < elements.size(); ++e)
      add_element_stress(xi, e, sigma);
    return sigma;
  }

  SymmetricTensor<2, 2>
  BoundaryElementSolver::scaled_stress(
    const Point<2> &xi, const std::vector<unsigned int> &subset) const
  {
    SymmetricTensor<2, 2> sigma;
    for (const unsigned int e : subset)
      add_element_stress(xi, e, sigma);
    return sigma;
  }

  void
  BoundaryElementSolver::stresses_in_box(
    const std::vector<Point<2>>              &x,
    std::vector<std::size_t>                &&points,
    const TargetBox                          &box,
    std::vector<unsigned int>               &&candidates,
    const TargetBox                          *parent,
    const std::vector<SymmetricTensor<2, 2>> *parent_values,
    std::vector<SymmetricTensor<2, 2>>       &stress,
    const unsigned int                        depth) const
  {
    const ChebyshevRule &cheb = chebyshev_rule();
    // What the ancestors' far elements contribute at y: their Chebyshev
    // interpolant (y lies in the parent box).
    const auto inherited = [&](const Point<2> &y)
    {
      return parent ? cheb.interpolate(
                        parent->lower, parent->side, *parent_values, y)
                    : SymmetricTensor<2, 2>();
    };

    // A box with few points: integrating its remaining elements at the
    // points is cheaper than at the interpolation nodes.
    const unsigned int n_nodes = ChebyshevRule::n * ChebyshevRule::n;
    if (points.size() <= 2 * n_nodes || depth >= 30)
    {
      for (const std::size_t i : points)
        stress[i] = inherited(x[i]) + scaled_stress(x[i], candidates);
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
    for (const unsigned int e : candidates)
      (point_segment_distance(centre, elements[e].x_a, elements[e].x_b) >=
           4. * radius
         ? far
         : near)
        .push_back(e);
    candidates.clear();

    // With no new far element the children interpolate the ancestors'
    // field directly (their points lie in the ancestor's box too).
    std::vector<SymmetricTensor<2, 2>>        values;
    const TargetBox                          *child_parent = parent;
    const std::vector<SymmetricTensor<2, 2>> *child_values = parent_values;
    if (!far.empty())
    {
      values.resize(n_nodes);
      for (unsigned int kx = 0; kx < ChebyshevRule::n; ++kx)
        for (unsigned int ky = 0; ky < ChebyshevRule::n; ++ky)
        {
          const Point<2> node =
            box.lower +
            Tensor<1, 2>({box.side * cheb.t[kx], box.side * cheb.t[ky]});
          values[kx * ChebyshevRule::n + ky] =
            inherited(node) + scaled_stress(node, far);
        }
      child_parent = &box;
      child_values = &values;
    }

    // Quadrants; a point on a dividing line goes to the upper one.
    const double                            half = 0.5 * box.side;
    std::array<std::vector<std::size_t>, 4> quadrant_points;
    for (const std::size_t i : points)
      quadrant_points[2 * (x[i][0] >= box.lower[0] + half) +
                      (x[i][1] >= box.lower[1] + half)]
        .push_back(i);
    points.clear();

    const auto child = [&](const unsigned int q)
    {
      if (quadrant_points[q].empty())
        return;
      const TargetBox sub{
        box.lower + Tensor<1, 2>({half * (q / 2), half * (q % 2)}), half};
      stresses_in_box(x,
                      std::move(quadrant_points[q]),
                      sub,
                      std::vector<unsigned int>(near),
                      child_parent,
                      child_values,
                      stress,
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

  Tensor<1, 2>
  BoundaryElementSolver::scaled_displacement(const Point<2> &xi) const
  {
    // Somigliana displacement identity (BEM.md §1.3).
    Tensor<1, 2> result;
    for (unsigned int e = 0; e < elements.size(); ++e)
      integrate_boundary_solution(
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

  std::vector<SymmetricTensor<2, 2>>
  BoundaryElementSolver::stress_at_points(
    const std::vector<Point<2>> &points) const
  {
    Assert(is_solved, ExcMessage("Call solve() first."));
    const auto start = Clock::now();

    std::vector<SymmetricTensor<2, 2>> stress(points.size());
    const double                       mu = material.mu();
    std::vector<Point<2>>              scaled(points.size());
    for (std::size_t p = 0; p < points.size(); ++p)
      scaled[p] = Point<2>((points[p] - reference_center) / reference_length);

    if (use_far_field_interpolation && points.size() > 1000)
    {
      // Hierarchical evaluation: a quadtree over the points, each box
      // taking the field of the elements well separated from it through
      // a Chebyshev interpolant (cost about linear in the points instead
      // of points x elements).
      Point<2> lo = scaled[0], hi = scaled[0];
      for (const auto &y : scaled)
        for (unsigned int d = 0; d < 2; ++d)
        {
          lo[d] = std::min(lo[d], y[d]);
          hi[d] = std::max(hi[d], y[d]);
        }
      const double side =
        1.001 * std::max(hi[0] - lo[0], hi[1] - lo[1]) + 1e-12;
      const TargetBox root{lo - Tensor<1, 2>({5e-4 * side, 5e-4 * side}), side};
      std::vector<std::size_t> all_points(points.size());
      std::iota(all_points.begin(), all_points.end(), std::size_t(0));
      std::vector<unsigned int> all_elements(elements.size());
      std::iota(all_elements.begin(), all_elements.end(), 0u);
      stresses_in_box(scaled,
                      std::move(all_points),
                      root,
                      std::move(all_elements),
                      nullptr,
                      nullptr,
                      stress,
                      0);
      for (auto &s : stress)
        s *= mu;
    }
    else
      // Embarrassingly parallel: each point reads the boundary solution
      // and writes its own result (BEM.md §4.4).
      parallel::apply_to_subranges(
        std::size_t(0),
        points.size(),
        [&](const std::size_t begin, const std::size_t end)
        {
          for (std::size_t p = begin; p < end; ++p)
            stress[p] = mu * scaled_stress(scaled[p]);
        },
        16);

    std::lock_guard<std::mutex> lock(*timing_mutex);
    timing_data.interior += seconds_since(start);
    return stress;
  }

  std::vector<Tensor<1, 2>>
  BoundaryElementSolver::displacement_at_points(
    const std::vector<Point<2>> &points) const
  {
    Assert(is_solved, ExcMessage("Call solve() first."));
    std::vector<Tensor<1, 2>> u(points.size());
    parallel::apply_to_subranges(
      std::size_t(0),
      points.size(),
      [&](const std::size_t begin, const std::size_t end)
      {
        for (std::size_t p = begin; p < end; ++p)
          u[p] = reference_length *
                 scaled_displacement(
                   Point<2>((points[p] - reference_center) / reference_length));
      },
      16);
    return u;
  }

  std::vector<std::vector<SymmetricTensor<2, 2>>>
  BoundaryElementSolver::stress_at_quadrature_points(
    const DoFHandler<2> &dof_handler,
    const Mapping<2>    &mapping,
    const Quadrature<2> &quadrature,
    const MPI_Comm       communicator) const
  {
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    // A distributed mesh (p4est): this process evaluates its own cells,
    // and the other cells' entries stay empty (no process needs them).
    if (dynamic_cast<const parallel::DistributedTriangulationBase<2> *>(
          &dof_handler.get_triangulation()))
    {
      FEValues<2> fe_values(
        mapping, dof_handler.get_fe(), quadrature, update_quadrature_points);
      std::vector<Point<2>> points;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          const auto &q_points = fe_values.get_quadrature_points();
          points.insert(points.end(), q_points.begin(), q_points.end());
        }
      const auto stress = stress_at_points(points);
      std::vector<std::vector<SymmetricTensor<2, 2>>> result(n_cells);
      std::size_t                                     p = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            result[cell->active_cell_index()].push_back(stress[p++]);
      return result;
    }

    // This process's share: cells [first, last) in active cell order.
    // (Programs that never initialized MPI, e.g. the BEM tests, are one
    // process.)
    const bool         mpi = Utilities::MPI::job_supports_mpi();
    const unsigned int n_procs =
      mpi ? Utilities::MPI::n_mpi_processes(communicator) : 1;
    const unsigned int rank =
      mpi ? Utilities::MPI::this_mpi_process(communicator) : 0;
    const unsigned int first = std::uint64_t(n_cells) * rank / n_procs;
    const unsigned int last  = std::uint64_t(n_cells) * (rank + 1) / n_procs;

    FEValues<2> fe_values(
      mapping, dof_handler.get_fe(), quadrature, update_quadrature_points);
    std::vector<Point<2>> points;
    points.reserve((last - first) * quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->active_cell_index() >= first &&
          cell->active_cell_index() < last)
      {
        fe_values.reinit(cell);
        const auto &q_points = fe_values.get_quadrature_points();
        points.insert(points.end(), q_points.begin(), q_points.end());
      }

    const auto stress = stress_at_points(points);

    // The three components of every point of every cell, zero outside
    // this process's share; the sum over the processes fills them all.
    const unsigned int  n_q = quadrature.size();
    std::vector<double> values(std::size_t(n_cells) * n_q * 3, 0.);
    for (std::size_t p = 0; p < stress.size(); ++p)
      for (unsigned int k = 0; k < 3; ++k)
        values[(std::size_t(first) * n_q + p) * 3 + k] =
          stress[p][k == 2 ? 0 : k][k == 2 ? 1 : k];
    if (n_procs > 1)
    {
      std::vector<double> own = values;
      Utilities::MPI::sum(
        ArrayView<const double>(own), communicator, ArrayView<double>(values));
    }

    std::vector<std::vector<SymmetricTensor<2, 2>>> result(
      n_cells, std::vector<SymmetricTensor<2, 2>>(n_q));
    for (unsigned int c = 0; c < n_cells; ++c)
      for (unsigned int q = 0; q < n_q; ++q)
      {
        const double *v    = &values[(std::size_t(c) * n_q + q) * 3];
        result[c][q][0][0] = v[0];
        result[c][q][1][1] = v[1];
        result[c][q][0][1] = v[2];
      }
    return result;
  }

  unsigned int
  BoundaryElementSolver::n_nodes() const
  {
    return nodes.size();
  }

  unsigned int
  BoundaryElementSolver::n_elements() const
  {
    return elements.size();
  }

  unsigned int
  BoundaryElementSolver::n_unknowns() const
  {
    return n_boundary_unknowns;
  }

  Point<2>
  BoundaryElementSolver::node_position(const unsigned int i) const
  {
    AssertIndexRange(i, nodes.size());
    return nodes[i].x_physical;
  }

  Tensor<1, 2>
  BoundaryElementSolver::node_displacement(const unsigned int i) const
  {
    AssertIndexRange(i, nodes.size());
    return reference_length * nodes[i].displacement;
  }

  const BoundaryElementSolver::Timings &
  BoundaryElementSolver::timings() const
  {
    return timing_data;
  }

  Tensor<1, 2>
  BoundaryElementSolver::element_traction(const unsigned int e,
                                          const unsigned int end) const
  {
    AssertIndexRange(e, elements.size());
    AssertIndexRange(end, 2);
    return material.mu() * elements[e].traction[end];
  }

  std::array<unsigned int, 2>
  BoundaryElementSolver::element_nodes(const unsigned int e) const
  {
    AssertIndexRange(e, elements.size());
    return elements[e].nodes;
  }

  types::boundary_id
  BoundaryElementSolver::element_boundary_id(const unsigned int e) const
  {
    AssertIndexRange(e, elements.size());
    return elements[e].boundary_id;
  }

  std::array<types::global_dof_index, 2>
  BoundaryElementSolver::node_dof_indices(const unsigned int i) const
  {
    AssertIndexRange(i, nodes.size());
    return nodes[i].dofs;
  }

  Tensor<2, 2>
  BoundaryElementSolver::diagonal_block(const unsigned int i) const
  {
    AssertIndexRange(i, nodes.size());
    return nodes[i].diagonal_block;
  }

  unsigned int
  BoundaryElementSolver::n_extra_collocation_rows() const
  {
    return n_extra_rows;
  }

  unsigned int
  BoundaryElementSolver::n_rigid_modes() const
  {
    return rigid_modes.size();
  }

  double
  BoundaryElementSolver::length_scale() const
  {
    return reference_length;
  }
} // namespace ddcontact
