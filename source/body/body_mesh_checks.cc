// The checks of a body's mesh as it is read (BodyMesh): cells of positive
// area, no coincident but separate vertices (or merged on request), every
// connected piece held, the boundary ids that the conditions name.
#include <deal.II/distributed/tria.h>

#include <deal.II/grid/grid_tools.h>

#include <ddcontact/body/body_mesh.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** "(x1, x2)" in full precision, for messages. */
    template <int dim>
    std::string
    coordinates(const Point<dim> &x)
    {
      std::ostringstream s;
      s << std::setprecision(std::numeric_limits<double>::max_digits10) << '('
        << x[0] << ", " << x[1] << ')';
      return s.str();
    }

    /** The largest distance between two vertices of @p cell: its diameter
     * (the cells are convex once check_cell_areas() has passed). */
    template <class Iterator>
    double
    vertex_diameter(const Iterator &cell)
    {
      double h = 0;
      for (const unsigned int v : cell->vertex_indices())
        for (const unsigned int w : cell->vertex_indices())
          h = std::max(h, cell->vertex(v).distance(cell->vertex(w)));
      return h;
    }

    /** Groups of coincident vertices as a union-find: each group is joined
     * to its smallest vertex index. */
    class VertexGroups
    {
    public:
      explicit VertexGroups(const unsigned int n_vertices)
        : root(n_vertices)
      {
        std::iota(root.begin(), root.end(), 0u);
      }

      /** The first (smallest) vertex of the group of vertex @p i. */
      unsigned int
      first_of(unsigned int i)
      {
        while (root[i] != i)
          i = root[i] = root[root[i]];
        return i;
      }

      void
      join(const unsigned int i, const unsigned int j)
      {
        const unsigned int a = first_of(i), b = first_of(j);
        root[std::max(a, b)] = std::min(a, b);
      }

    private:
      std::vector<unsigned int> root;
    };

    /** The used vertices of @p points within @p tolerance of each other,
     * grouped. Buckets of width tolerance: two such vertices lie in the
     * same or in neighbouring buckets. */
    template <int dim>
    VertexGroups
    group_coincident_vertices(const std::vector<Point<dim>> &points,
                              const std::vector<bool>       &used,
                              const double                   tolerance)
    {
      std::map<std::array<long long, 2>, std::vector<unsigned int>> buckets;
      const auto bucket = [&](const Point<dim> &p)
      {
        return std::array<long long, 2>{
          {static_cast<long long>(std::floor(p[0] / tolerance)),
           static_cast<long long>(std::floor(p[1] / tolerance))}};
      };
      for (unsigned int i = 0; i < points.size(); ++i)
        if (used[i])
          buckets[bucket(points[i])].push_back(i);
      VertexGroups groups(points.size());
      for (const auto &[key, members] : buckets)
        for (const unsigned int i : members)
          for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
            {
              const auto near = buckets.find({{key[0] + dx, key[1] + dy}});
              if (near != buckets.end())
                for (const unsigned int j : near->second)
                  if (j > i && points[i].distance(points[j]) <= tolerance)
                    groups.join(i, j);
            }
      return groups;
    }

    /** The coarse cells of @p tria and its labelled faces, each vertex
     * replaced by its group's first. The boundary faces keep their ids; a
     * face between two merged sides of a crack is interior now and loses
     * its id (a face of a curved manifold keeps its manifold id). */
    template <int dim>
    void
    merged_coarse_mesh(const Triangulation<dim>   &tria,
                       VertexGroups               &groups,
                       std::vector<CellData<dim>> &cells,
                       SubCellData                &faces)
    {
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> n_sides;
      std::vector<CellData<1>>                                      labelled;
      std::set<unsigned int> labelled_faces;
      for (const auto &cell : tria.cell_iterators_on_level(0))
      {
        CellData<dim> c(cell->n_vertices());
        for (const unsigned int v : cell->vertex_indices())
          c.vertices[v] = groups.first_of(cell->vertex_index(v));
        c.material_id = cell->material_id();
        c.manifold_id = cell->manifold_id();
        cells.push_back(c);
        for (const unsigned int f : cell->face_indices())
        {
          const auto face = cell->face(f);
          ++n_sides[std::minmax(groups.first_of(face->vertex_index(0)),
                                groups.first_of(face->vertex_index(1)))];
          if ((face->boundary_id() != numbers::internal_face_boundary_id ||
               face->manifold_id() != numbers::flat_manifold_id) &&
              labelled_faces.insert(face->index()).second)
          {
            CellData<1> line;
            line.vertices    = {groups.first_of(face->vertex_index(0)),
                                groups.first_of(face->vertex_index(1))};
            line.boundary_id = face->boundary_id();
            line.manifold_id = face->manifold_id();
            labelled.push_back(line);
          }
        }
      }
      std::set<std::pair<unsigned int, unsigned int>> kept;
      for (auto &line : labelled)
      {
        const auto edge = std::minmax(line.vertices[0], line.vertices[1]);
        if (n_sides[edge] > 1)
        {
          if (line.manifold_id == numbers::flat_manifold_id)
            continue;
          line.boundary_id = numbers::internal_face_boundary_id;
        }
        if (kept.insert(edge).second)
          faces.boundary_lines.push_back(line);
      }
    }

    /** A connected piece of a mesh (coarse cells joined through faces). */
    template <int dim>
    struct Piece
    {
      unsigned int n_cells = 0;
      bool         held[2] = {false, false};
      bool         contact = false;
      Point<dim>   corner; // its lowest vertex of least x, for messages
    };

    /** The connected pieces of the coarse mesh of @p tria, with what
     * @p conditions hold them by. */
    template <int dim>
    std::vector<Piece<dim>>
    connected_pieces(const Triangulation<dim>      &tria,
                     const BoundaryConditions<dim> &conditions)
    {
      const auto below = [](const Point<dim> &a, const Point<dim> &b)
      { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); };

      const unsigned int        none = numbers::invalid_unsigned_int;
      std::vector<unsigned int> piece_of(tria.n_cells(0), none);
      std::vector<Piece<dim>>   pieces;
      std::vector<typename Triangulation<dim>::cell_iterator> stack;
      for (const auto &start : tria.cell_iterators_on_level(0))
      {
        if (piece_of[start->index()] != none)
          continue;
        Piece<dim> piece;
        piece.corner             = start->vertex(0);
        piece_of[start->index()] = pieces.size();
        stack                    = {start};
        while (!stack.empty())
        {
          const auto cell = stack.back();
          stack.pop_back();
          ++piece.n_cells;
          for (const unsigned int v : cell->vertex_indices())
            if (below(cell->vertex(v), piece.corner))
              piece.corner = cell->vertex(v);
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
            {
              const auto id        = cell->face(f)->boundary_id();
              const auto dirichlet = conditions.dirichlet.find(id);
              if (dirichlet != conditions.dirichlet.end())
                for (unsigned int c = 0; c < 2; ++c)
                  piece.held[c] = piece.held[c] || dirichlet->second.mask[c];
              piece.contact = piece.contact || conditions.contact.count(id) > 0;
            }
            else if (piece_of[cell->neighbor_index(f)] == none)
            {
              piece_of[cell->neighbor_index(f)] = pieces.size();
              stack.push_back(cell->neighbor(f));
            }
        }
        pieces.push_back(piece);
      }
      return pieces;
    }
  } // namespace

  template <int dim>
  void
  BodyMesh<dim>::check_cell_areas() const
  {
    static_assert(dim == 2, "the corner Jacobians are written for 2D");
    const auto cross = [](const Tensor<1, dim> &a, const Tensor<1, dim> &b)
    { return a[0] * b[1] - a[1] * b[0]; };
    // GridIn has turned cells given clockwise; what is left with a corner
    // of zero or negative Jacobian is degenerate (zero area) or folded (a
    // reflex corner, a bow tie). Such a cell makes the stiffness singular
    // or indefinite, which would later look like a material error.
    unsigned int n_bad = 0;
    Point<dim>   first_corner;
    for (const auto &cell : tria->cell_iterators_on_level(0))
    {
      const double h = vertex_diameter(cell);
      // Jacobian determinants at the corners, relative to h^2: a
      // triangle is affine (one value); a quadrilateral's corners in
      // deal.II's order 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1).
      std::vector<std::pair<double, unsigned int>> corners;
      const auto x = [&](const unsigned int v) { return cell->vertex(v); };
      if (cell->n_vertices() == 3)
        corners = {{cross(x(1) - x(0), x(2) - x(0)), 0}};
      else
        corners = {{cross(x(1) - x(0), x(2) - x(0)), 0},
                   {cross(x(1) - x(0), x(3) - x(1)), 1},
                   {cross(x(3) - x(2), x(2) - x(0)), 2},
                   {cross(x(3) - x(2), x(3) - x(1)), 3}};
      const auto worst = *std::min_element(corners.begin(), corners.end());
      if (h > 0 && worst.first > 1e-12 * h * h)
        continue;
      if (n_bad == 0)
        first_corner = x(worst.second);
      ++n_bad;
    }
    if (n_bad > 0)
      throw InputError(
        parameters.section() + "/Mesh/File: '" + file_name + "' has " +
        std::to_string(n_bad) + (n_bad == 1 ? " cell" : " cells") +
        " of zero or negative area (degenerate, or folded at a corner), the "
        "first at its corner " +
        coordinates(first_corner) + "; fix the mesh");
  }

  template <int dim>
  void
  BodyMesh<dim>::merge_coincident_vertices()
  {
    const std::vector<Point<dim>> &points = tria->get_vertices();
    std::vector<bool>              used(points.size(), false);
    double                         h = std::numeric_limits<double>::max();
    for (const auto &cell : tria->cell_iterators_on_level(0))
    {
      h = std::min(h, vertex_diameter(cell));
      for (const unsigned int v : cell->vertex_indices())
        used[cell->vertex_index(v)] = true;
    }
    const double tolerance = 1e-10 * h;

    VertexGroups groups = group_coincident_vertices(points, used, tolerance);
    unsigned int n_coincident = 0, first = 0;
    for (unsigned int i = 0; i < points.size(); ++i)
      if (used[i] && groups.first_of(i) != i && n_coincident++ == 0)
        first = i;
    if (n_coincident == 0)
      return;
    const std::string what = parameters.section() + "/Mesh/File";
    if (!parameters.merge_coincident_vertices)
      throw InputError(
        what + ": '" + file_name + "' has " + std::to_string(n_coincident) +
        (n_coincident == 1 ? " vertex" : " vertices") +
        " that coincide with another one but are separate nodes (a hidden "
        "crack), the first at " +
        coordinates(points[first]) +
        "; join them in the mesh (Gmsh: Coherence Mesh;) or set Mesh/Merge "
        "coincident vertices = true");

    // The coarse mesh again, with the groups merged.
    std::vector<Point<dim>>    vertices = points;
    std::vector<CellData<dim>> cells;
    SubCellData                faces;
    merged_coarse_mesh(*tria, groups, cells, faces);
    GridTools::delete_unused_vertices(vertices, cells, faces);
    if (!is_simplex())
      GridTools::consistently_order_cells(cells);
    tria->clear();
    try
    {
      tria->create_triangulation(vertices, cells, faces);
    }
    catch (const std::bad_alloc &)
    {
      throw;
    }
    catch (const std::exception &)
    {
      throw InputError(what + ": '" + file_name + "' with its " +
                       std::to_string(n_coincident) +
                       " coincident vertices merged is not a valid mesh "
                       "(more than two cells at an edge?); fix the mesh");
    }
    n_merged = n_coincident;
  }

  template <int dim>
  void
  BodyMesh<dim>::check_pieces(const BoundaryConditions<dim> &conditions) const
  {
    // The coarse cells exist on every process, also on a p4est mesh, and
    // refinement never joins or splits pieces.
    const std::vector<Piece<dim>> pieces = connected_pieces(*tria, conditions);
    // One piece: RigidBodyModes and the contact pairs judge it.
    if (pieces.size() < 2)
      return;

    for (const auto &piece : pieces)
    {
      if (piece.held[0] && piece.held[1])
        continue;
      std::string message = parameters.section() + "/Mesh/File: '" + file_name +
                            "' holds " + std::to_string(pieces.size()) +
                            " separate pieces (cells joined through faces), "
                            "and the piece of " +
                            std::to_string(piece.n_cells) +
                            (piece.n_cells == 1 ? " cell" : " cells") +
                            " with the vertex " + coordinates(piece.corner);
      if (!piece.held[0] && !piece.held[1] && !piece.contact)
        throw InputError(message +
                         " has no Dirichlet condition and no face among the "
                         "Contact ids: nothing holds it; hold it, join it "
                         "to the rest, or remove it");
      message += (!piece.held[0] && !piece.held[1])
                   ? " is held by contact only"
                   : std::string(" has a Dirichlet condition on ") +
                       (piece.held[0] ? "x" : "y") + " only";
      throw InputError(message +
                       ": a body of several pieces must hold each in x and "
                       "y (a floating body must be one piece); make it a "
                       "body of its own, or prescribe both components on "
                       "it");
    }
  }

  template <int dim>
  void
  BodyMesh<dim>::check_boundary_ids(
    const BoundaryConditions<dim> &boundary_conditions) const
  {
    const auto ids = tria->get_boundary_ids();
    const auto check =
      [&](const types::boundary_id id, const std::string &entry)
    {
      if (std::find(ids.begin(), ids.end(), id) == ids.end())
      {
        std::string list;
        for (const auto i : ids)
          list += (list.empty() ? "" : ", ") + std::to_string(i);
        throw InputError(parameters.section() + "/Boundary conditions/" +
                         entry + ": boundary id " + std::to_string(id) +
                         " does not exist in the mesh (its ids: " + list + ")");
      }
    };
    for (const auto &[id, d] : boundary_conditions.dirichlet)
      check(id, "Dirichlet");
    for (const auto &[id, f] : boundary_conditions.neumann)
      check(id, "Neumann");
    for (const auto id : boundary_conditions.contact)
      check(id, "Contact ids");
  }

  // The rest of BodyMesh<2> is instantiated in body_mesh.cc.
  template void
  BodyMesh<2>::check_cell_areas() const;
  template void
  BodyMesh<2>::merge_coincident_vertices();
  template void
  BodyMesh<2>::check_pieces(const BoundaryConditions<2> &) const;
  template void
  BodyMesh<2>::check_boundary_ids(const BoundaryConditions<2> &) const;
} // namespace ddcontact
