#include <deal.II/base/parallel.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/fe/fe_values.h>

#include <ddcontact/bem/boundary_element_solver.h>
#include <ddcontact/bem/boundary_integration.h>
#include <ddcontact/bem/far_field_stresses.h>
#include <ddcontact/parameter_tools.h>

#include <limits>

namespace ddcontact
{
  BoundaryElementSolver::BoundaryElementSolver(
    const ElasticConstants      &material,
    const BoundaryConditions<2> &boundary_conditions)
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
    Timer timer;
    timing_data = Timings();
    is_solved   = false;

    const FiniteElement<2> &fe = dof_handler.get_fe();
    if (fe.n_components() != 2)
      throw InputError("BoundaryElementSolver: the finite element has " +
                       std::to_string(fe.n_components()) +
                       " components, but a 2D displacement needs 2");
    // The BEM basis is the trace of the FEM basis (26): straight 2-node
    // elements with linear shape functions for Q1 quadrilaterals or P1
    // triangles, 3-node quadratic ones for Q2 or P2 (vertex dofs and one
    // line dof per component; no face-interior dofs in 2D).
    if ((fe.degree != 1 && fe.degree != 2) || fe.n_dofs_per_vertex() != 2 ||
        fe.n_dofs_per_line() != 2 * (fe.degree - 1))
      throw InputError(
        "BoundaryElementSolver: the finite element " + fe.get_name() +
        " has degree " + std::to_string(fe.degree) +
        ", but the boundary elements support only degree 1 (Q1 or P1) and "
        "degree 2 (Q2 or P2)");

    mesh.reinit(dof_handler, mapping);
    mesh.number_unknowns(boundary_conditions, material.mu());

    // Refinement inside the body leaves the boundary mesh (25) alone: the
    // collocation system is then the same, and so is its factorization.
    auto signature = boundary_signature();
    if (signature == current_signature && system.initialized())
      return;
    current_signature = std::move(signature);
    ++system_setups;

    FullMatrix<double> system_matrix;
    assemble_system(system_matrix);
    timing_data.assembly = timer.wall_time();

    timer.restart();
    const auto [row_keys, column_keys] = boundary_order_keys();
    system.initialize(std::move(system_matrix), row_keys, column_keys, method);
    timing_data.factorization = timer.wall_time();
  }

  std::vector<double>
  BoundaryElementSolver::boundary_signature() const
  {
    // The element end points and boundary ids determine the boundary mesh
    // and, with the body's fixed boundary data, the whole system.
    std::vector<double> signature;
    signature.reserve(5 * mesh.get_elements().size() + 3);
    signature.push_back(mesh.length_scale());
    signature.push_back(mesh.get_rigid_modes().size());
    signature.push_back(mesh.degree());
    for (const auto &element : mesh.get_elements())
      signature.insert(signature.end(),
                       {element.x_a[0],
                        element.x_a[1],
                        element.x_b[0],
                        element.x_b[1],
                        double(element.boundary_id)});
    return signature;
  }

  std::array<std::vector<double>, 2>
  BoundaryElementSolver::boundary_order_keys() const
  {
    const auto &nodes    = mesh.get_nodes();
    const auto &elements = mesh.get_elements();
    // A system bordered with rigid modes keeps the dense LU: no keys.
    if (!mesh.get_rigid_modes().empty())
      return {};

    // Number the vertices along each closed boundary curve in turn, so
    // that contiguous keys are contiguous pieces of the boundary; a
    // midpoint node sits half-way along its element.
    std::vector<double> node_key(nodes.size(), -1.);
    double              counter = 0;
    for (unsigned int start = 0; start < nodes.size(); ++start)
      if (!nodes[start].is_midpoint)
        for (unsigned int i = start; node_key[i] < 0;
             i              = elements[nodes[i].element_out].nodes[1])
          node_key[i] = counter++;
    for (const auto &element : elements)
      if (mesh.degree() == 2)
        node_key[element.nodes[2]] = node_key[element.nodes[0]] + 0.5;

    // Element-end tractions sit just inside their element.
    std::array<std::vector<double>, 2> keys;
    auto &[row_keys, column_keys] = keys;
    row_keys.assign(mesh.n_unknowns(), 0.);
    column_keys.assign(mesh.n_unknowns(), 0.);
    for (unsigned int m = 0; m < nodes.size(); ++m)
      for (unsigned int j = 0; j < 2; ++j)
        if (!nodes[m].known[j])
          column_keys[nodes[m].unknown[j]] = node_key[m];
    for (const auto &element : elements)
      for (unsigned int k = 0; k < mesh.n_element_nodes(); ++k)
        for (unsigned int j = 0; j < 2; ++j)
          if (element.dirichlet[j])
            column_keys[element.unknown[k][j]] =
              node_key[element.nodes[k]] +
              (k == 0 ? 0.25 : (k == 1 ? -0.25 : 0.));
    for (const auto &point : mesh.get_collocation_points())
      for (const unsigned int row : point.rows)
        row_keys[row] = point.node != numbers::invalid_unsigned_int
                          ? node_key[point.node]
                          : node_key[elements[point.element].nodes[0]] + 0.25;
    return keys;
  }

  namespace
  {
    /** Scatter the H and G blocks @p blocks of collocation point @p point
     * into its rows of @p system_matrix, @p contact_matrix (the contact
     * tractions, solved for elsewhere) and @p body_rhs (the known values).
     * Column swapping (doc/bem-method.md §3.1): c u + H u - G t = 0 with
     * known values moved to the right-hand side. */
    void
    add_collocation_rows(const BoundaryMesh                   &mesh,
                         const BoundaryMesh::CollocationPoint &point,
                         const BoundaryIntegration::RowBlocks &blocks,
                         FullMatrix<double>                   &system_matrix,
                         FullMatrix<double>                   &contact_matrix,
                         Vector<double>                       &body_rhs)
    {
      const auto        &nodes       = mesh.get_nodes();
      const auto        &elements    = mesh.get_elements();
      const unsigned int per_contact = mesh.contact_values_per_element();
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
          const auto &element = elements[e];
          for (unsigned int k = 0; k < mesh.n_element_nodes(); ++k)
            for (unsigned int j = 0; j < 2; ++j)
            {
              const double value = blocks.g[e][k][i][j];
              if (element.dirichlet[j])
                system_matrix(row, element.unknown[k][j]) -= value;
              else if (element.is_contact)
                contact_matrix(
                  row, per_contact * element.contact_index + 2 * k + j) +=
                  value;
              else
                rhs += value * element.traction[k][j];
            }
        }
        body_rhs(row) = rhs;
      }
    }

    /** Border the system with the free rigid modes (doc/bem-method.md §5.1):
     * [A R; R^T 0] [x; lambda] = [f; 0]. The solution has no rigid
     * component and lambda measures the equilibrium defect of the data.
     * The column enters the collocation rows of the node (2 m + c), so
     * that the defect goes to the same equations whatever the order of
     * the nodes (a p4est mesh gathers them in another order); with every
     * displacement unknown these rows are the unknowns' numbers. */
    void
    add_rigid_mode_border(const BoundaryMesh &mesh,
                          FullMatrix<double> &system_matrix)
    {
      const auto        &nodes               = mesh.get_nodes();
      const auto        &rigid_modes         = mesh.get_rigid_modes();
      const unsigned int n_boundary_unknowns = mesh.n_unknowns();
      const unsigned int n_modes             = rigid_modes.size();
      for (unsigned int q = 0; q < n_modes; ++q)
        for (unsigned int m = 0; m < nodes.size(); ++m)
          for (unsigned int c = 0; c < 2; ++c)
            if (!nodes[m].known[c])
            {
              const auto  &node = nodes[m];
              const double value =
                rigid_modes[q][c] +
                rigid_modes[q][2] * (c == 0 ? -node.x[1] : node.x[0]);
              system_matrix(2 * m + c, n_boundary_unknowns + q)       = value;
              system_matrix(n_boundary_unknowns + q, node.unknown[c]) = value;
            }
    }
  } // namespace

  void
  BoundaryElementSolver::assemble_system(FullMatrix<double> &system_matrix)
  {
    const auto        &nodes               = mesh.get_nodes();
    const auto        &collocation_points  = mesh.get_collocation_points();
    const unsigned int n_boundary_unknowns = mesh.n_unknowns();
    const unsigned int n = n_boundary_unknowns + mesh.get_rigid_modes().size();
    system_matrix.reinit(n, n);
    body_rhs.reinit(n);
    const unsigned int per_contact = mesh.contact_values_per_element();
    contact_matrix.reinit(n_boundary_unknowns,
                          per_contact * mesh.n_contact_elements());
    diagonal_blocks.assign(nodes.size(), Tensor<2, 2>());

    // Every collocation point fills its own rows only, so the points can
    // be processed in parallel without synchronisation.
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(collocation_points.size()),
      [&](const unsigned int begin, const unsigned int end)
      {
        BoundaryIntegration::RowBlocks blocks;
        for (unsigned int p = begin; p < end; ++p)
        {
          const auto &point = collocation_points[p];
          BoundaryIntegration::collocation_row_blocks(
            mesh, kelvin, point, blocks);
          if (point.node != numbers::invalid_unsigned_int)
            diagonal_blocks[point.node] = blocks.h[point.node];

          add_collocation_rows(
            mesh, point, blocks, system_matrix, contact_matrix, body_rhs);
        }
      },
      8);

    add_rigid_mode_border(mesh, system_matrix);
  }

  void
  BoundaryElementSolver::project_contact_traction(
    const BoundaryTractionSamples &contact,
    Vector<double>                &contact_values) const
  {
    const auto        &elements           = mesh.get_elements();
    const unsigned int n_contact_elements = mesh.n_contact_elements();
    const unsigned int per_element        = mesh.contact_values_per_element();
    contact_values.reinit(per_element * n_contact_elements);
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
    std::vector<std::array<Tensor<1, 2>, 3>> moments(n_contact_elements);
    for (unsigned int q = 0; q < contact.points.size(); ++q)
    {
      const Point<2> x        = mesh.scaled(contact.points[q]);
      unsigned int   nearest  = contact_elements[0];
      double         distance = std::numeric_limits<double>::max();
      for (const unsigned int e : contact_elements)
      {
        const double d = BoundaryIntegration::point_segment_distance(
          x, elements[e].x_a, elements[e].x_b);
        if (d < distance)
        {
          distance = d;
          nearest  = e;
        }
      }
      const auto  &element = elements[nearest];
      const double s =
        BoundaryIntegration::segment_coordinate(x, element.x_a, element.x_b);
      const auto shape = mesh.shape_values(s);
      for (unsigned int k = 0; k < mesh.n_element_nodes(); ++k)
        moments[element.contact_index][k] +=
          contact.weights[q] * shape[k] * contact.traction[q];
    }

    // L2 projection onto the element's traction polynomial. Linear: the
    // element mass matrix L/6 [[2,1],[1,2]] has the inverse
    // 2/L [[2,-1],[-1,2]]. Quadratic (start, end, midpoint): L/30
    // [[4,-1,2],[-1,4,2],[2,2,16]] has the inverse 1/L [[9,3,-3/2],
    // [3,9,-3/2],[-3/2,-3/2,9/4]].
    const double mu = material.mu();
    for (const unsigned int e : contact_elements)
    {
      const unsigned int          ci = elements[e].contact_index;
      const double                L  = elements[e].length * mesh.length_scale();
      const auto                 &m  = moments[ci];
      std::array<Tensor<1, 2>, 3> t;
      if (mesh.degree() == 1)
      {
        t[0] = 2. / L * (2. * m[0] - m[1]) / mu;
        t[1] = 2. / L * (2. * m[1] - m[0]) / mu;
      }
      else
      {
        t[0] = (9. * m[0] + 3. * m[1] - 1.5 * m[2]) / (L * mu);
        t[1] = (3. * m[0] + 9. * m[1] - 1.5 * m[2]) / (L * mu);
        t[2] = (-1.5 * m[0] - 1.5 * m[1] + 2.25 * m[2]) / (L * mu);
      }
      for (unsigned int k = 0; k < mesh.n_element_nodes(); ++k)
        for (unsigned int c = 0; c < 2; ++c)
          contact_values(per_element * ci + 2 * k + c) = t[k][c];
    }
  }

  void
  BoundaryElementSolver::solve(const BoundaryTractionSamples &contact)
  {
    Assert(system.initialized(), ExcMessage("Call setup() first."));
    Timer timer;

    Vector<double> contact_values;
    project_contact_traction(contact, contact_values);

    Vector<double> x(body_rhs);
    if (mesh.n_contact_elements() > 0)
    {
      Vector<double> contact_rhs(mesh.n_unknowns());
      contact_matrix.vmult(contact_rhs, contact_values);
      for (unsigned int i = 0; i < mesh.n_unknowns(); ++i)
        x(i) += contact_rhs(i);
    }
    system.solve(x);

    mesh.set_solution(x, contact_values);
    is_solved              = true;
    timing_data.solve      = timer.wall_time();
    timing_data.iterations = system.last_iterations();
  }

  unsigned int
  BoundaryElementSolver::n_nodes() const
  {
    return mesh.get_nodes().size();
  }

  unsigned int
  BoundaryElementSolver::n_elements() const
  {
    return mesh.get_elements().size();
  }

  unsigned int
  BoundaryElementSolver::n_unknowns() const
  {
    return mesh.n_unknowns();
  }

  Point<2>
  BoundaryElementSolver::node_position(const unsigned int i) const
  {
    AssertIndexRange(i, mesh.get_nodes().size());
    return mesh.get_nodes()[i].x_physical;
  }

  Tensor<1, 2>
  BoundaryElementSolver::node_displacement(const unsigned int i) const
  {
    AssertIndexRange(i, mesh.get_nodes().size());
    return mesh.length_scale() * mesh.get_nodes()[i].displacement;
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
    AssertIndexRange(e, mesh.get_elements().size());
    AssertIndexRange(end, mesh.n_element_nodes());
    return material.mu() * mesh.get_elements()[e].traction[end];
  }

  std::array<unsigned int, 2>
  BoundaryElementSolver::element_nodes(const unsigned int e) const
  {
    AssertIndexRange(e, mesh.get_elements().size());
    const auto &nodes = mesh.get_elements()[e].nodes;
    return {{nodes[0], nodes[1]}};
  }

  unsigned int
  BoundaryElementSolver::element_midpoint_node(const unsigned int e) const
  {
    AssertIndexRange(e, mesh.get_elements().size());
    return mesh.get_elements()[e].nodes[2];
  }

  unsigned int
  BoundaryElementSolver::degree() const
  {
    return mesh.degree();
  }

  types::boundary_id
  BoundaryElementSolver::element_boundary_id(const unsigned int e) const
  {
    AssertIndexRange(e, mesh.get_elements().size());
    return mesh.get_elements()[e].boundary_id;
  }

  std::array<types::global_dof_index, 2>
  BoundaryElementSolver::node_dof_indices(const unsigned int i) const
  {
    AssertIndexRange(i, mesh.get_nodes().size());
    return mesh.get_nodes()[i].dofs;
  }

  Tensor<2, 2>
  BoundaryElementSolver::diagonal_block(const unsigned int i) const
  {
    AssertIndexRange(i, mesh.get_nodes().size());
    return diagonal_blocks[i];
  }

  unsigned int
  BoundaryElementSolver::n_extra_collocation_rows() const
  {
    return mesh.n_extra_collocation_rows();
  }

  unsigned int
  BoundaryElementSolver::n_rigid_modes() const
  {
    return mesh.get_rigid_modes().size();
  }

  double
  BoundaryElementSolver::length_scale() const
  {
    return mesh.length_scale();
  }
} // namespace ddcontact
