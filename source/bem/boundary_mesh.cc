#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/affine_constraints.h>

#include <ddcontact/bem/boundary_mesh.h>
#include <ddcontact/parameter_tools.h>

#include <map>

namespace ddcontact
{
  namespace
  {
    /** A boundary face (25) with the global dofs of its two vertices and,
     * for degree 2, of its line (the midpoint), and whether the body lies on
     * the left of x[1] -> x[0] (deal.II does not orient faces), as sent between
     * the processes of a distributed mesh. */
    struct BoundaryFace
    {
      std::array<Point<2>, 2>                               x;
      std::array<std::array<types::global_dof_index, 2>, 2> dofs;
      std::array<types::global_dof_index, 2>                line_dofs;
      types::boundary_id                                    boundary_id;
      bool                                                  reversed;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &x &dofs &line_dofs &boundary_id &reversed;
      }
    };

    /** The vertices of a cell as placed by the mapping
     * (Mapping::get_vertices()). */
    using CellVertices =
      boost::container::small_vector<Point<2>,
                                     GeometryInfo<2>::vertices_per_cell>;

    /** The boundary face @p face_no of @p cell, with the mapped vertices
     * @p cell_vertices of the cell and their centroid. */
    BoundaryFace
    make_boundary_face(const DoFHandler<2>::active_cell_iterator &cell,
                       const unsigned int                         face_no,
                       const CellVertices                        &cell_vertices,
                       const Point<2>                            &centroid,
                       const unsigned int element_degree)
    {
      const auto   face = cell->face(face_no);
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
          Assert(
            cell->get_fe().face_system_to_component_index(2 * v + c).first == c,
            ExcInternalError());
          boundary_face.dofs[v][c] = face->vertex_dof_index(v, c);
        }
      }
      // Line dofs of FESystem(Q2 or P2, 2): one per component, after the
      // four vertex dofs of the face.
      for (unsigned int c = 0; c < 2; ++c)
      {
        boundary_face.line_dofs[c] = numbers::invalid_dof_index;
        if (element_degree == 2)
        {
          Assert(cell->get_fe().face_system_to_component_index(4 + c).first ==
                   c,
                 ExcInternalError());
          boundary_face.line_dofs[c] = face->dof_index(c);
        }
      }
      const Tensor<1, 2> tangent = boundary_face.x[1] - boundary_face.x[0];
      const Tensor<1, 2> normal{{tangent[1], -tangent[0]}};
      const Point<2> midpoint = 0.5 * (boundary_face.x[0] + boundary_face.x[1]);
      boundary_face.reversed  = normal * (midpoint - centroid) < 0;
      return boundary_face;
    }

    /** All boundary faces of the mesh of @p dof_handler. A distributed mesh
     * (p4est) knows its own cells only: each process takes the faces of its
     * cells and every process gets all of them. */
    std::vector<BoundaryFace>
    collect_boundary_faces(const DoFHandler<2> &dof_handler,
                           const Mapping<2>    &mapping,
                           const unsigned int   element_degree)
    {
      std::vector<BoundaryFace> faces;

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
          if (cell->face(f)->at_boundary())
            faces.push_back(make_boundary_face(
              cell, f, cell_vertices, centroid, element_degree));
      }
      if (distributed)
      {
        std::vector<BoundaryFace> all;
        for (const auto &from_process :
             Utilities::MPI::all_gather(distributed->get_communicator(), faces))
          all.insert(all.end(), from_process.begin(), from_process.end());
        faces = std::move(all);
      }
      return faces;
    }

    /** One element per face and one node per vertex; the vertices are told
     * apart by their dofs (the vertex numbers of a distributed mesh differ
     * between the processes). */
    void
    add_vertex_nodes_and_elements(const std::vector<BoundaryFace>    &faces,
                                  std::vector<BoundaryMesh::Node>    &nodes,
                                  std::vector<BoundaryMesh::Element> &elements)
    {
      std::map<types::global_dof_index, unsigned int> dof_to_node;
      for (const auto &face : faces)
      {
        BoundaryMesh::Element element;
        for (unsigned int v = 0; v < 2; ++v)
        {
          const auto [it, is_new] =
            dof_to_node.emplace(face.dofs[v][0], nodes.size());
          if (is_new)
          {
            BoundaryMesh::Node node;
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
    }

    /** Quadratic elements: the midpoint nodes, after all vertices (a
     * boundary face belongs to one cell, so its line dofs are its own). */
    void
    add_midpoint_nodes(const std::vector<BoundaryFace>    &faces,
                       std::vector<BoundaryMesh::Node>    &nodes,
                       std::vector<BoundaryMesh::Element> &elements)
    {
      for (unsigned int e = 0; e < elements.size(); ++e)
      {
        BoundaryMesh::Node node;
        node.x_physical      = Point<2>(0.5 * (faces[e].x[0] + faces[e].x[1]));
        node.dofs            = faces[e].line_dofs;
        node.element_in      = e;
        node.element_out     = e;
        node.is_midpoint     = true;
        elements[e].nodes[2] = nodes.size();
        nodes.push_back(node);
      }
    }

    /** Give every vertex node its incoming and outgoing element. There must
     * be exactly one of each: the boundary is a set of closed polygons. */
    void
    link_elements_at_nodes(const std::vector<BoundaryMesh::Element> &elements,
                           std::vector<BoundaryMesh::Node>          &nodes)
    {
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
    }

#ifdef DEBUG
    /** Every node has its two elements, and no node carries a hanging-node
     * constraint. */
    void
    check_nodes(const DoFHandler<2>                   &dof_handler,
                const std::vector<BoundaryMesh::Node> &nodes)
    {
      for (const auto &node : nodes)
        Assert(node.element_in != numbers::invalid_unsigned_int &&
                 node.element_out != numbers::invalid_unsigned_int,
               ExcInternalError());

      // In 2D no hanging node lies on the boundary of a single body
      // (doc/bem-method.md §2.8), so the trace of the constrained Q1 space is
      // the space of continuous piecewise linears (quadratics for degree 2)
      // on this boundary mesh.
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

    /** Do two elements meeting at a node continue each other in a straight
     * line (a smooth node), rather than form a corner? */
    bool
    meet_smoothly(const BoundaryMesh::Element &element_in,
                  const BoundaryMesh::Element &element_out)
    {
      const Tensor<1, 2> &a = element_in.tangent, &b = element_out.tangent;
      return a * b > 0 && std::abs(a[0] * b[1] - a[1] * b[0]) < 1e-8;
    }
  } // namespace

  void
  BoundaryMesh::reinit(const DoFHandler<2> &dof_handler,
                       const Mapping<2>    &mapping)
  {
    nodes.clear();
    elements.clear();

    // The BEM basis is the trace of the FEM basis (26): 2-node elements
    // for Q1/P1 (vertex dofs only), 3-node elements for Q2/P2 (one line dof
    // per component at the face midpoint).
    const FiniteElement<2> &fe = dof_handler.get_fe();
    element_degree             = fe.degree;
    Assert((element_degree == 1 || element_degree == 2) &&
             fe.n_dofs_per_vertex() == 2 &&
             fe.n_dofs_per_line() == 2 * (element_degree - 1),
           ExcInternalError());

    const std::vector<BoundaryFace> faces =
      collect_boundary_faces(dof_handler, mapping, element_degree);

    add_vertex_nodes_and_elements(faces, nodes, elements);
    if (elements.empty())
      throw InputError("BoundaryElementSolver: the mesh has no boundary faces");
    if (element_degree == 2)
      add_midpoint_nodes(faces, nodes, elements);
    link_elements_at_nodes(elements, nodes);

#ifdef DEBUG
    check_nodes(dof_handler, nodes);
#endif

    scale_nodes_and_elements();
  }

  void
  BoundaryMesh::scale_nodes_and_elements()
  {
    // Nondimensionalise (doc/bem-method.md §3.3, §5.2): lengths by the
    // bounding-box diagonal of the boundary, which keeps the body far from the
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
      node.x = scaled(node.x_physical);

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
  BoundaryMesh::number_unknowns(
    const BoundaryConditions<2> &boundary_conditions, const double mu)
  {
    apply_element_data(boundary_conditions, mu);
    // Displacement unknowns first, then the traction unknowns.
    const unsigned int n_displacement_unknowns =
      number_displacement_unknowns(boundary_conditions);
    n_boundary_unknowns = number_traction_unknowns(n_displacement_unknowns);
    set_up_collocation_points();
    find_rigid_modes();
  }

  void
  BoundaryMesh::apply_element_data(
    const BoundaryConditions<2> &boundary_conditions, const double mu)
  {
    // Boundary data of the body: which components are prescribed where,
    // and their values (displacements at nodes, tractions sampled at the
    // element ends with the element's own data, doc/bem-method.md §2.2).
    n_contact = 0;
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
      element.contact_index =
        element.is_contact ? n_contact++ : numbers::invalid_unsigned_int;

      const auto neumann =
        boundary_conditions.neumann.find(element.boundary_id);
      for (unsigned int k = 0; k < n_element_nodes(); ++k)
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
  }

  unsigned int
  BoundaryMesh::number_displacement_unknowns(
    const BoundaryConditions<2> &boundary_conditions)
  {
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
    return n;
  }

  unsigned int
  BoundaryMesh::number_traction_unknowns(unsigned int n)
  {
    // Unknown tractions: at element ends where the component is prescribed
    // as displacement. Two ends meeting at a straight (smooth) node with
    // the displacement prescribed on both sides share one unknown; at a
    // genuine corner they are independent and get an extra collocation row
    // (doc/bem-method.md §2.7).
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
        if (elements[e_in].dirichlet[c] &&
            meet_smoothly(elements[e_in], elements[e]))
          element.unknown[0][c] = elements[e_in].unknown[1][c];
        else
          element.unknown[0][c] = n++;
      }
    // Degree 2: the midpoint traction where the displacement is prescribed
    // (the midpoint node is a smooth point of its element).
    for (auto &element : elements)
      for (unsigned int c = 0; c < 2; ++c)
        element.unknown[2][c] = (element_degree == 2 && element.dirichlet[c])
                                  ? n++
                                  : numbers::invalid_unsigned_int;
    return n;
  }

  void
  BoundaryMesh::set_up_collocation_points()
  {
    // Collocation: both components at every node, rows 2i + c, then the
    // extra off-node rows at D-D corners (vertices), inside the outgoing
    // element at s0 = 1/4 (any s0 in (0,1) that is not a node works).
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
      if (nodes[i].is_midpoint)
        continue;
      const unsigned int e_in  = nodes[i].element_in,
                         e_out = nodes[i].element_out;
      CollocationPoint point;
      point.element = e_out;
      point.s0      = 0.25;
      point.x       = elements[e_out].x_a +
                point.s0 * (elements[e_out].x_b - elements[e_out].x_a);
      for (unsigned int c = 0; c < 2; ++c)
        if (elements[e_in].dirichlet[c] && elements[e_out].dirichlet[c] &&
            !meet_smoothly(elements[e_in], elements[e_out]))
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
  BoundaryMesh::find_rigid_modes()
  {
    // A rigid motion a e_x + b e_y + c (-y, x) is left free by the
    // Dirichlet data if it vanishes at every prescribed nodal component,
    // i.e. if (a, b, c) is in the null space of the Gram matrix of those
    // constraints. A floating body keeps all three (doc/bem-method.md §5.1).
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
  BoundaryMesh::set_solution(const Vector<double> &x,
                             const Vector<double> &contact_values)
  {
    for (auto &node : nodes)
      for (unsigned int c = 0; c < 2; ++c)
        if (!node.known[c])
          node.displacement[c] = x(node.unknown[c]);
    const unsigned int per_element = contact_values_per_element();
    for (auto &element : elements)
      for (unsigned int k = 0; k < n_element_nodes(); ++k)
        for (unsigned int c = 0; c < 2; ++c)
          if (element.dirichlet[c])
            element.traction[k][c] = x(element.unknown[k][c]);
          else if (element.is_contact)
            element.traction[k][c] =
              contact_values(per_element * element.contact_index + 2 * k + c);
  }
} // namespace ddcontact
