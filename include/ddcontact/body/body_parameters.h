#ifndef ddcontact_body_parameters_h
#define ddcontact_body_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/geometry.h>
#include <ddcontact/body/material_laws.h>
#include <ddcontact/parameter_tools.h>

#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /** Body/Mesh/Type: a subdivided rectangle, or a Gmsh file. */
  enum class MeshType
  {
    rectangle,
    file
  };

  /** Body/Element/Cell type: FE_Q on quadrilaterals, or FE_SimplexP on
   * triangles. */
  enum class CellType
  {
    quadrilateral,
    triangle
  };

  /** Body/Element/Volumetric integration: the volumetric term lambda div u
   * div v of (11) with the full Gauss rule, or on one Gauss point per Q1
   * cell (selective reduced integration). */
  enum class VolumetricIntegration
  {
    full,
    reduced
  };

  /** Body/Solver/Type: a direct factorization, or CG with AMG. */
  enum class BodySolverType
  {
    direct,
    cg_amg
  };

  DDCONTACT_DECLARE_SELECTION(MeshType)
  DDCONTACT_DECLARE_SELECTION(CellType)
  DDCONTACT_DECLARE_SELECTION(VolumetricIntegration)
  DDCONTACT_DECLARE_SELECTION(BodySolverType)

  /**
   * Everything that describes one elastic body: its mesh, its element, its
   * material and its boundary conditions by boundary id. Declared in the
   * subsection "Body <name>" of the parameter file, one per name listed in
   * "Bodies".
   */
  struct BodyParameters
  {
    std::string name;

    // Mesh
    MeshType                  mesh_type = MeshType::rectangle;
    Point<2>                  corner_1{0., 0.};
    Point<2>                  corner_2{1., 1.};
    std::vector<unsigned int> subdivisions{1, 1};
    std::string               mesh_file;
    unsigned int              initial_refinement = 0;
    std::vector<double>       refinement_box; // x0, y0, x1, y1, or empty
    unsigned int              box_refinement = 0;
    // Vertices of a Gmsh file that coincide but are separate nodes (a
    // hidden crack): merged when true, refused otherwise.
    bool merge_coincident_vertices = false;

    // Element
    CellType     cell_type = CellType::quadrilateral;
    unsigned int degree    = 1;
    // The volumetric term lambda div u div v of (11) on one Gauss point
    // per Q1 cell with "reduced" (selective reduced integration).
    VolumetricIntegration volumetric_integration = VolumetricIntegration::full;

    // Material: the elastic constants every law has, the law (a row of the
    // table of material_laws.h) and the row's own entries.
    ElasticConstants     material;
    std::string          material_law = "linear-elastic";
    MaterialLawConstants material_law_constants;
    // The scene's Geometry (SceneParameters sets it on every body).
    Geometry geometry = Geometry::plane_strain;

    // Boundary conditions as written in the file, parsed by
    // make_boundary_conditions() once the constants are known.
    std::string dirichlet;
    std::string neumann;
    std::string contact_ids;
    std::string body_force;

    // Linear solver of the body problem (20).
    BodySolverType solver                = BodySolverType::direct;
    double         solver_tolerance      = 1e-12;
    unsigned int   solver_max_iterations = 10000;
    // The Newton loop of a body of a nonlinear material law.
    double       newton_tolerance      = 1e-10;
    unsigned int newton_max_iterations = 30;

    static void
    declare(ParameterHandler &prm);

    /** Read from the current subsection; checks values and throws
     * InputError naming "Body <name>/<entry>". */
    void
    parse(ParameterHandler &prm);

    /** "Body <name>/" for error messages. */
    std::string
    section() const
    {
      return "Body " + name;
    }
  };

  /**
   * Turn the boundary-condition entries of a body into functions:
   *  - Dirichlet: "id: components: expr_x; expr_y | id: ...", components
   *    one of x, y, xy (e.g. "0: xy: 0; 0 | 3: y: 0; -Delta");
   *  - Neumann:   "id: expr_x; expr_y | ..." (traction, force per length);
   *  - Contact ids: "3, 4";
   *  - Body force: "expr_x; expr_y" or empty.
   * Expressions are in x, y and the scene's constants. SceneParameters
   * calls it when the file is read, so that every error shows up then,
   * naming the body and the entry.
   */
  BoundaryConditions<2>
  make_boundary_conditions(const BodyParameters &body,
                           const Constants      &constants);
} // namespace ddcontact

#endif
