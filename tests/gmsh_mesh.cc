// DESCRIPTION: Gmsh meshes through "Mesh/Type = file": a .msh written here
// (quadrilaterals) and a .geo meshed by the gmsh binary (triangles) carry
// their physical curve tags 11-14 as boundary ids on the right faces; a
// uniaxial stress state with Dirichlet data on one tag and a traction on
// another is reproduced exactly; a tag missing from the file is an
// InputError naming the boundary id; a circular boundary stays on its
// circle under refinement; a hidden crack (coincident nodes) is refused, and
// merged on request it gives the conforming mesh's answer
#include <deal.II/base/function_parser.h>

#include <deal.II/numerics/vector_tools.h>

#include <ddcontact/body/elastic_body.h>

#include "test_tools.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  // The rectangle [0, L] x [0, H] and its physical curves: bottom 11,
  // right 12, top 13, left 14; the surface is physical 1.
  const double L = 2., H = 1.;

  /**
   * A legacy ASCII (2.2) Gmsh file of nx x ny quadrilaterals whose interior
   * nodes are moved off the grid (by up to 0.2 h, deterministically) so the
   * cells are general quadrilaterals; the sides stay straight. With
   * @p crack_column in (0, nx), the cells right of the node column
   * crack_column use copies of its nodes: a hidden crack, the same points
   * twice.
   */
  void
  write_msh(const std::string &filename,
            const unsigned int nx,
            const unsigned int ny,
            const unsigned int crack_column = 0)
  {
    std::ofstream out(filename);
    out << std::setprecision(17);
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
    out << "$PhysicalNames\n5\n"
        << "1 11 \"bottom\"\n1 12 \"right\"\n1 13 \"top\"\n1 14 \"left\"\n"
        << "2 1 \"body\"\n$EndPhysicalNames\n";

    const bool         crack   = crack_column > 0 && crack_column < nx;
    const unsigned int n_nodes = (nx + 1) * (ny + 1);
    // Node (i, j) as used by the cells of column @p cell_i.
    const auto node = [&](const unsigned int i,
                          const unsigned int j,
                          const unsigned int cell_i = 0)
    {
      if (crack && i == crack_column && cell_i >= crack_column)
        return n_nodes + 1 + j;
      return 1 + i + j * (nx + 1);
    };
    const auto position = [&](const unsigned int i, const unsigned int j)
    {
      double x = L * i / nx, y = H * j / ny;
      if (i > 0 && i < nx && j > 0 && j < ny)
      {
        x += 0.2 * (L / nx) * std::sin(1.7 * i + 2.3 * j);
        y += 0.2 * (H / ny) * std::cos(0.9 * i + 3.1 * j);
      }
      return Point<2>(x, y);
    };
    out << "$Nodes\n" << n_nodes + (crack ? ny + 1 : 0) << "\n";
    for (unsigned int j = 0; j <= ny; ++j)
      for (unsigned int i = 0; i <= nx; ++i)
        out << node(i, j) << " " << position(i, j)[0] << " "
            << position(i, j)[1] << " 0\n";
    if (crack)
      for (unsigned int j = 0; j <= ny; ++j)
        out << node(crack_column, j, crack_column) << " "
            << position(crack_column, j)[0] << " "
            << position(crack_column, j)[1] << " 0\n";
    out << "$EndNodes\n";

    // Elements: "id type n_tags physical elementary nodes..."; type 1 is a
    // 2-node line, type 3 a 4-node quadrilateral.
    std::ostringstream elements;
    unsigned int       n_elements = 0;
    const auto         line =
      [&](const unsigned int tag, const unsigned int a, const unsigned int b)
    {
      elements << ++n_elements << " 1 2 " << tag << " " << tag << " " << a
               << " " << b << "\n";
    };
    for (unsigned int i = 0; i < nx; ++i)
      line(11, node(i, 0, i), node(i + 1, 0, i));
    for (unsigned int j = 0; j < ny; ++j)
      line(12, node(nx, j), node(nx, j + 1));
    for (unsigned int i = nx; i > 0; --i)
      line(13, node(i, ny, i - 1), node(i - 1, ny, i - 1));
    for (unsigned int j = ny; j > 0; --j)
      line(14, node(0, j), node(0, j - 1));
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        elements << ++n_elements << " 3 2 1 1 " << node(i, j, i) << " "
                 << node(i + 1, j, i) << " " << node(i + 1, j + 1, i) << " "
                 << node(i, j + 1, i) << "\n";
    out << "$Elements\n"
        << n_elements << "\n"
        << elements.str() << "$EndElements\n";
  }

  /** The same rectangle as a Gmsh geometry; gmsh meshes it in triangles. */
  void
  write_geo(const std::string &filename)
  {
    std::ofstream out(filename);
    out << "// written by the ddcontact test gmsh_mesh\n"
        << "h = 0.3;\n"
        << "Point(1) = {0, 0, 0, h};\n"
        << "Point(2) = {" << L << ", 0, 0, h};\n"
        << "Point(3) = {" << L << ", " << H << ", 0, h};\n"
        << "Point(4) = {0, " << H << ", 0, h};\n"
        << "Line(1) = {1, 2};\nLine(2) = {2, 3};\n"
        << "Line(3) = {3, 4};\nLine(4) = {4, 1};\n"
        << "Curve Loop(1) = {1, 2, 3, 4};\n"
        << "Plane Surface(1) = {1};\n"
        << "Physical Curve(11) = {1};\nPhysical Curve(12) = {2};\n"
        << "Physical Curve(13) = {3};\nPhysical Curve(14) = {4};\n"
        << "Physical Surface(1) = {1};\n";
  }

  /** The tag a boundary face must carry, from the position of its centre. */
  types::boundary_id
  expected_id(const Point<2> &c)
  {
    const double tol = 1e-10;
    if (std::abs(c[1]) < tol)
      return 11;
    if (std::abs(c[0] - L) < tol)
      return 12;
    if (std::abs(c[1] - H) < tol)
      return 13;
    if (std::abs(c[0]) < tol)
      return 14;
    return numbers::invalid_boundary_id;
  }

  /**
   * Every boundary face against expected_id(), on the mesh as read and once
   * more after a global refinement (the children must inherit the ids).
   */
  void
  check_boundary_ids(Triangulation<2> &tria, const std::string &what)
  {
    for (unsigned int round = 0; round < 2; ++round)
    {
      std::map<types::boundary_id, unsigned int> n_faces;
      unsigned int                               n_wrong = 0;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
        {
          ++n_faces[face->boundary_id()];
          if (face->boundary_id() != expected_id(face->center()))
          {
            if (n_wrong < 3)
              std::cout << "  face at (" << face->center() << ") has id "
                        << face->boundary_id() << ", expected "
                        << expected_id(face->center()) << std::endl;
            ++n_wrong;
          }
        }
      const std::string label =
        what + (round == 0 ? ", as read" : ", refined once");
      std::cout << label << ": " << tria.n_active_cells()
                << " cells, boundary faces";
      for (const auto &[id, n] : n_faces)
        std::cout << " [id " << id << ": " << n << "]";
      std::cout << std::endl;
      check(n_wrong == 0 && n_faces.size() == 4,
            label + ": four boundary ids, " + std::to_string(n_wrong) +
              " faces with a wrong one");
      if (round == 0)
        tria.refine_global(1);
    }
  }

  BodyParameters
  body_parameters(const std::string &name,
                  const std::string &file,
                  const std::string &cell_type)
  {
    BodyParameters p;
    p.name                    = name;
    p.mesh_type               = MeshType::file;
    p.mesh_file               = file;
    p.cell_type               = parse_selection<CellType>(cell_type);
    p.material.youngs_modulus = 2.1e5;
    p.material.poisson_ratio  = 0.3;
    return p;
  }

  /**
   * Uniaxial tension sigma = s e_x (x) e_x through the file mesh: the left
   * side (tag 14) held at the exact displacement, the traction (s, 0) on
   * the right (tag 12), top and bottom traction free. In plane strain
   *   u_x = (1 - nu^2) s x / E,   u_y = -nu (1 + nu) s y / E,
   * linear, so every element reproduces it up to round-off (1e-10
   * relative: these systems have condition numbers ~1e3-1e4).
   */
  void
  check_uniaxial_tension(const std::string &name,
                         const std::string &file,
                         const std::string &cell_type)
  {
    const double   s = 100.;
    BodyParameters p = body_parameters(name, file, cell_type);
    const double   E = p.material.youngs_modulus, nu = p.material.poisson_ratio;
    const Constants constants = {
      {"a", (1. - nu * nu) * s / E}, {"b", -nu * (1. + nu) * s / E}, {"s", s}};
    p.dirichlet = "14: xy: a*x; b*y";
    p.neumann   = "12: s; 0";

    ElasticBody<2> body(p, constants);
    body.make_mesh(".");
    body.get_triangulation().refine_global(1);
    body.setup_and_factorize();
    body.solve();

    FunctionParser<2> exact(2);
    exact.initialize("x,y", "a*x; b*y", constants);
    BodyVector difference(body.n_dofs());
    VectorTools::interpolate(
      body.get_mapping(), body.get_dof_handler(), exact, difference);
    difference -= body.get_solution();
    const double u_error =
      difference.linfty_norm() / body.get_solution().linfty_norm();

    SymmetricTensor<2, 2> sigma;
    sigma[0][0]    = s;
    double s_error = 0;
    for (const auto &cell_stress : body.stresses().at_quadrature_points())
      for (const auto &stress : cell_stress)
        s_error = std::max(s_error, (stress - sigma).norm() / s);

    const std::string label = file + ", " + cell_type;
    std::cout << label
              << ": uniaxial tension (Dirichlet on 14, traction on 12), "
              << body.get_triangulation().n_active_cells() << " cells"
              << std::endl;
    check(label + ": max nodal error", u_error, 1e-10);
    check(label + ": max stress error", s_error, 1e-10);
  }

  /** A boundary condition on a tag the file does not have must be an
   * InputError from make_mesh() that names the entry and the id. */
  void
  check_missing_tag(const std::string &file,
                    const std::string &cell_type,
                    const std::string &dirichlet,
                    const std::string &neumann,
                    const std::string &expected_message)
  {
    BodyParameters p          = body_parameters("missing_tag", file, cell_type);
    p.dirichlet               = dirichlet;
    p.neumann                 = neumann;
    const std::string message = error_message<InputError>(
      [&]
      {
        ElasticBody<2> body(p, Constants());
        body.make_mesh(".");
      });
    std::cout << "Dirichlet '" << dirichlet << "', Neumann '" << neumann
              << "' on " << file << ": " << message << std::endl;
    check(message_names(message, {expected_message}),
          "an InputError '" + expected_message + "'");
  }

  /**
   * The curved boundary of meshes/half_cylinder.geo (arc 11 of radius 5
   * around (0, 5), flat top 12) under refinement: twice refined, every
   * vertex of the arc lies on the circle to round-off (without a manifold
   * the new ones would sit on the chords, up to h^2 / (8 R) = 0.016 inside)
   * and the top stays flat.
   */
  void
  check_circular_boundary(const std::string &source_dir)
  {
    BodyParameters p = body_parameters("gmsh_mesh_cylinder",
                                       source_dir + "/meshes/half_cylinder.geo",
                                       "triangle");
    p.dirichlet      = "12: xy: 0; 0";
    ElasticBody<2> body(p, Constants());
    body.make_mesh(".");
    check(body.get_mesh().circular_boundaries().size() == 1,
          "half cylinder: one circular boundary found (" +
            (body.get_mesh().circular_boundaries().empty()
               ? std::string("none")
               : body.get_mesh().circular_boundaries()[0]) +
            ")");
    body.get_triangulation().refine_global(2);
    const Point<2> centre(0, 5);
    double         off_circle = 0, off_top = 0;
    for (const auto &face : body.get_triangulation().active_face_iterators())
      if (face->at_boundary())
        for (const unsigned int v : face->vertex_indices())
        {
          const Point<2> x = face->vertex(v);
          if (face->boundary_id() == 11)
            off_circle = std::max(off_circle, std::abs(x.distance(centre) - 5));
          else
            off_top = std::max(off_top, std::abs(x[1] - 5));
        }
    check("half cylinder refined twice: arc vertices off the circle",
          off_circle / 5,
          1e-12);
    check(
      "half cylinder refined twice: top vertices off the line", off_top, 1e-12);
  }

  /**
   * A hidden crack: gmsh_mesh_crack.msh is the 6 x 3 mesh of @p conforming
   * with the node column x = L/2 given twice, once for the cells on each
   * side. Read as it is, it is refused, naming the 4 coincident vertices;
   * with Mesh/Merge coincident vertices they are merged, and the body is
   * the conforming one: as many vertices, and the same displacement of a
   * cantilever under a top load (not linear, so every cell counts) to
   * round-off.
   */
  void
  check_merged_crack(const std::string &conforming)
  {
    const std::string cracked = "gmsh_mesh_crack.msh";
    write_msh(cracked, 6, 3, 3);

    BodyParameters p =
      body_parameters("gmsh_mesh_crack", cracked, "quadrilateral");
    p.dirichlet               = "14: xy: 0; 0";
    p.neumann                 = "13: 0; -1";
    const std::string message = error_message<InputError>(
      [&]
      {
        ElasticBody<2> body(p, Constants());
        body.make_mesh(".");
      });
    std::cout << "hidden crack: " << message << std::endl;
    check(
      message_names(message, {"has 4 vertices that coincide with another one"}),
      "hidden crack refused, naming the 4 coincident vertices");

    const Point<2> x(0.7 * L, 0.4 * H);
    const auto     solve = [&](const BodyParameters &q, unsigned int &n_merged)
    {
      ElasticBody<2> body(q, Constants());
      body.make_mesh(".");
      n_merged = body.get_mesh().n_merged_vertices();
      body.setup_and_factorize();
      body.solve();
      Vector<double> u(2);
      VectorTools::point_value(
        body.get_mapping(), body.get_dof_handler(), body.get_solution(), x, u);
      return std::make_pair(body.get_triangulation().n_vertices(), u);
    };
    p.merge_coincident_vertices = true;
    unsigned int n_merged = 0, n_none = 0;
    const auto [n_vertices, u]            = solve(p, n_merged);
    BodyParameters reference              = p;
    reference.mesh_file                   = conforming;
    const auto [n_reference, u_reference] = solve(reference, n_none);
    std::cout << "hidden crack merged: " << n_merged << " vertices merged, "
              << n_vertices << " vertices (conforming: " << n_reference
              << "), u(" << x << ") = " << u << " (conforming: " << u_reference
              << ")" << std::endl;
    check(n_merged == 4 && n_none == 0 && n_vertices == n_reference,
          "merged crack: 4 vertices merged, as many vertices as the "
          "conforming mesh");
    Vector<double> difference = u;
    difference -= u_reference;
    check("merged crack: displacement against the conforming mesh",
          difference.linfty_norm() / u_reference.linfty_norm(),
          1e-10);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // Both files go into the working directory (the test's build
  // directory); make_mesh() meshes the .geo into <body name>.msh there, so
  // the body names differ from the file names.
  const std::string msh = "gmsh_mesh_quads.msh";
  const std::string geo = "gmsh_mesh_rectangle.geo";
  write_msh(msh, 6, 3);
  write_geo(geo);

  try
  {
    for (const auto &[file, cell_type] :
         {std::pair<std::string, std::string>{msh, "quadrilateral"},
          std::pair<std::string, std::string>{geo, "triangle"}})
    {
      BodyParameters p = body_parameters("gmsh_mesh_ids", file, cell_type);
      p.dirichlet      = "14: xy: 0; 0";
      p.neumann        = "11: 0; 0 | 12: 0; 0 | 13: 0; 0";
      ElasticBody<2> body(p, Constants());
      body.make_mesh(".");
      check_boundary_ids(body.get_triangulation(), file + ", " + cell_type);
    }

    check_circular_boundary(argc > 1 ? argv[1] : "..");

    check_uniaxial_tension("gmsh_mesh_tension_quads", msh, "quadrilateral");
    check_uniaxial_tension("gmsh_mesh_tension_triangles", geo, "triangle");

    check_merged_crack(msh);

    check_missing_tag(msh,
                      "quadrilateral",
                      "14: xy: 0; 0",
                      "15: 1; 0",
                      "Neumann: boundary id 15 does not exist");
    check_missing_tag(geo,
                      "triangle",
                      "14: xy: 0; 0 | 16: y: 0; 0",
                      "12: 1; 0",
                      "Dirichlet: boundary id 16 does not exist");
  }
  catch (const std::exception &e)
  {
    check(false, std::string("unexpected exception: ") + e.what());
  }
  return report();
}
