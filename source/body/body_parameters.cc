#include <deal.II/base/utilities.h>

#include <ddcontact/body/body_parameters.h>
#include <ddcontact/body/material_laws.h>

#include <algorithm>

#include <string>
#include <vector>

namespace ddcontact
{
  using parsing::parse_boundary_id;
  using parsing::parse_double;
  using parsing::split;

  DDCONTACT_SELECTION(MeshType,
                      {"rectangle", MeshType::rectangle},
                      {"file", MeshType::file})
  DDCONTACT_SELECTION(CellType,
                      {"quadrilateral", CellType::quadrilateral},
                      {"triangle", CellType::triangle})
  DDCONTACT_SELECTION(VolumetricIntegration,
                      {"full", VolumetricIntegration::full},
                      {"reduced", VolumetricIntegration::reduced})
  DDCONTACT_SELECTION(BodySolverType,
                      {"direct", BodySolverType::direct},
                      {"cg-amg", BodySolverType::cg_amg})

  namespace
  {
    /**
     * An id may hold a Dirichlet condition on some components and a
     * traction on the others (a roller with a load): every component is
     * either a displacement (5) or a traction (6), never both. The
     * traction's expression for a component that Dirichlet prescribes
     * must therefore be the number 0 (its reaction is unknown); anything
     * else gives that component twice.
     */
    void
    check_mixed_condition(const BoundaryConditions<2> &bc,
                          const types::boundary_id     id,
                          const std::string           &expression,
                          const std::string           &what)
    {
      const auto dirichlet = bc.dirichlet.find(id);
      if (dirichlet == bc.dirichlet.end())
        return;
      const auto parts = Utilities::split_string_list(expression, ';');
      for (unsigned int c = 0; c < 2; ++c)
      {
        if (!dirichlet->second.mask[c])
          continue;
        const auto   text  = Utilities::trim(parts[c]);
        std::size_t  end   = 0;
        const double value = [&]
        {
          try
          {
            return std::stod(text, &end);
          }
          catch (...)
          {
            return 1.;
          }
        }();
        if (end != text.size() || value != 0)
          throw InputError(
            what + ": boundary id " + std::to_string(id) + " has a Dirichlet " +
            "condition on " + (c == 0 ? "x" : "y") + ", so its traction's " +
            (c == 0 ? "x" : "y") + " component must be 0, not '" + text +
            "' (a component is either displaced or loaded)");
      }
    }
  } // namespace

  BoundaryConditions<2>
  make_boundary_conditions(const BodyParameters &body,
                           const Constants      &constants)
  {
    BoundaryConditions<2> bc;
    const std::string     section = body.section() + "/";

    for (const auto &item : split(body.dirichlet, '|'))
    {
      const std::string what = section + "Dirichlet";
      const auto        c1   = item.find(':');
      const auto c2 = (c1 == std::string::npos) ? c1 : item.find(':', c1 + 1);
      if (c2 == std::string::npos)
        throw InputError(what + ": '" + item +
                         "' is not 'id: components: expr_x; expr_y'");
      const auto id         = parse_boundary_id(item.substr(0, c1), what);
      const auto components = Utilities::trim(item.substr(c1 + 1, c2 - c1 - 1));
      if (components != "x" && components != "y" && components != "xy")
        throw InputError(what + ": components '" + components +
                         "' must be x, y or xy");
      if (bc.dirichlet.count(id))
        throw InputError(what + ": boundary id " + std::to_string(id) +
                         " appears twice");
      DirichletCondition<2> d;
      d.mask = ComponentMask(
        std::vector<bool>{components.find('x') != std::string::npos,
                          components.find('y') != std::string::npos});
      d.displacement =
        make_function(item.substr(c2 + 1), 2, constants, what, true);
      bc.dirichlet[id] = d;
    }

    for (const auto &item : split(body.neumann, '|'))
    {
      const std::string what = section + "Neumann";
      const auto        c1   = item.find(':');
      if (c1 == std::string::npos)
        throw InputError(what + ": '" + item + "' is not 'id: expr_x; expr_y'");
      const auto id = parse_boundary_id(item.substr(0, c1), what);
      if (bc.neumann.count(id))
        throw InputError(what + ": boundary id " + std::to_string(id) +
                         " already has a boundary condition");
      const auto expression = item.substr(c1 + 1);
      bc.neumann[id] = make_function(expression, 2, constants, what, true);
      check_mixed_condition(bc, id, expression, what);
    }

    for (const auto &item : split(body.contact_ids, ','))
    {
      const std::string what = section + "Contact ids";
      const auto        id   = parse_boundary_id(item, what);
      if (bc.neumann.count(id) || bc.dirichlet.count(id))
        throw InputError(what + ": boundary id " + std::to_string(id) +
                         " already has a Dirichlet or Neumann condition");
      bc.contact.insert(id);
    }

    if (!Utilities::trim(body.body_force).empty())
      bc.body_force = make_function(
        body.body_force, 2, constants, section + "Body force", true);

    // A body whose Dirichlet conditions leave rigid motions free (none, or
    // one component only) is floating: ElasticBody finds its rigid modes,
    // and only dd-newton, which balances them by contact, accepts it.
    return bc;
  }

  namespace
  {
    /** The subsection Mesh: the rectangle, or the Gmsh file, and its
     * refinement. */
    void
    declare_mesh(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      {
        prm.declare_entry(
          "Type",
          "rectangle",
          selection_pattern<MeshType>(),
          "rectangle: a subdivided rectangle with boundary ids "
          "0 (left), 1 (right), 2 (bottom), 3 (top); file: a Gmsh "
          "mesh (.msh, or .geo meshed by the gmsh binary) whose "
          "physical curve tags become boundary ids.");
        prm.declare_entry(
          "Corner 1",
          "0, 0",
          Patterns::Anything(),
          "Lower left corner of the rectangle (x1, x2) [length].");
        prm.declare_entry(
          "Corner 2",
          "1, 1",
          Patterns::Anything(),
          "Upper right corner of the rectangle (x1, x2) [length].");
        prm.declare_entry("Subdivisions",
                          "1, 1",
                          Patterns::List(Patterns::Integer(1), 2, 2),
                          "Cells of the rectangle in x1 and x2.");
        prm.declare_entry("File",
                          "",
                          Patterns::Anything(),
                          "Gmsh file (.msh or .geo), relative to the parameter "
                          "file's directory or absolute.");
        prm.declare_entry("Initial refinement",
                          "0",
                          Patterns::Integer(0, 20),
                          "Number of global refinements of the initial mesh.");
        prm.declare_entry("Refinement box",
                          "",
                          Patterns::Anything(),
                          "'x0, y0, x1, y1': cells that touch this box are "
                          "refined Box refinement more times after the global "
                          "refinement (hanging nodes).");
        prm.declare_entry(
          "Box refinement",
          "0",
          Patterns::Integer(0, 20),
          "Number of refinements of the cells in Refinement box.");
        prm.declare_entry(
          "Merge coincident vertices",
          "false",
          Patterns::Bool(),
          "Type = file: vertices of different cells that lie at the same "
          "point (closer than 1e-10 times the smallest cell diameter) but "
          "are separate nodes form a hidden crack. false: such a file is "
          "refused, naming the count and one location; true: they are "
          "merged into one vertex each and the count is printed.");
      }
      prm.leave_subsection();
    }

    /** The subsection Element: cell type, degree, volumetric integration. */
    void
    declare_element(ParameterHandler &prm)
    {
      prm.enter_subsection("Element");
      {
        prm.declare_entry("Cell type",
                          "quadrilateral",
                          selection_pattern<CellType>(),
                          "quadrilateral: FE_Q with hanging-node constraints; "
                          "triangle: FE_SimplexP (a rectangle is split into "
                          "triangles; a Gmsh file must hold triangles).");
        prm.declare_entry("Degree",
                          "1",
                          Patterns::Integer(1, 2),
                          "Polynomial degree of the displacement (1 or 2).");
        prm.declare_entry(
          "Volumetric integration",
          "full",
          selection_pattern<VolumetricIntegration>(),
          "full: the bilinear form a_a (11) with (p+1)^2 Gauss points; "
          "reduced: its volumetric part lambda div u div v with one Gauss "
          "point per cell (selective reduced integration, B-bar on "
          "parallelograms), which removes the volumetric locking of Q1 as "
          "nu -> 1/2. Quadrilaterals of degree 1 only (Q2 locks far less).");
      }
      prm.leave_subsection();
    }

    /** The subsection Material: the elastic constants. */
    void
    declare_material(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      {
        prm.declare_entry(
          "Young's modulus", "2.1e5", Patterns::Double(), "E [stress], > 0.");
        prm.declare_entry("Poisson's ratio",
                          "0.3",
                          Patterns::Double(),
                          "nu, in (-1, 0.5) (plane strain).");
        prm.declare_entry("Law",
                          material_laws().front().name,
                          material_law_pattern(),
                          material_law_documentation() +
                            " Every law has the elastic constants Young's "
                            "modulus and Poisson's ratio.");
        for (const auto &row : material_laws())
          row.declare(prm);
      }
      prm.leave_subsection();
    }

    /** The subsection Boundary conditions, as text parsed by
     * make_boundary_conditions(). */
    void
    declare_boundary_conditions(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      {
        prm.declare_entry("Dirichlet",
                          "",
                          Patterns::Anything(),
                          "Prescribed displacements (5) (Gamma_u): 'id: "
                          "components: expr_x; expr_y | id: ...' with "
                          "components x, y or xy; expressions in x, y and the "
                          "scene's constants [length]. A component not listed "
                          "may be loaded by a Neumann traction on the same "
                          "id. A body whose conditions leave a rigid motion "
                          "free (none at all, or rollers only) is floating: "
                          "held by contact alone, as a punch pressed by a "
                          "force; Solver = dd-newton solves it.");
        prm.declare_entry("Neumann",
                          "",
                          Patterns::Anything(),
                          "Prescribed tractions p (6) (Gamma_p): 'id: expr_x; "
                          "expr_y | ...' [stress]. Ids with no condition are "
                          "traction free. An id may also have a Dirichlet "
                          "condition on one component (a roller with a load, "
                          "e.g. Dirichlet '3: x: 0; 0' and Neumann '3: 0; "
                          "-p'): the traction then loads the other component "
                          "only, and its expression for the prescribed "
                          "component must be 0.");
        prm.declare_entry("Contact ids",
                          "",
                          Patterns::List(Patterns::Integer(0, 254)),
                          "Boundary ids that form the possible contact zone S "
                          "(comma separated).");
        prm.declare_entry("Body force",
                          "",
                          Patterns::Anything(),
                          "Body force 'expr_x; expr_y' [force/volume]; empty "
                          "for none.");
      }
      prm.leave_subsection();
    }

    /** The subsection Solver: the linear solver of the body problem. */
    void
    declare_solver(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      {
        prm.declare_entry("Type",
                          "direct",
                          selection_pattern<BodySolverType>(),
                          "direct: UMFPACK factorization, computed once per "
                          "mesh and reused for every right-hand side; cg-amg: "
                          "conjugate gradients with Trilinos ML AMG (large "
                          "meshes).");
        prm.declare_entry("Tolerance",
                          "1e-12",
                          Patterns::Double(0),
                          "Relative residual tolerance of cg-amg.");
        prm.declare_entry("Max iterations",
                          "10000",
                          Patterns::Integer(1),
                          "Iteration limit of cg-amg.");
        prm.declare_entry(
          "Newton tolerance",
          "1e-10",
          Patterns::Double(0),
          "A nonlinear Material/Law: the body's Newton loop stops when the "
          "residual l + contact load - internal force is this fraction of "
          "the load's norm (a linear law is solved by one factorization).");
        prm.declare_entry("Newton max iterations",
                          "30",
                          Patterns::Integer(1, 1000),
                          "A nonlinear Material/Law: the limit of the body's "
                          "Newton steps per solve.");
      }
      prm.leave_subsection();
    }

    /** Read the subsection Mesh of @p body and check it. */
    void
    parse_mesh(ParameterHandler &prm, BodyParameters &body)
    {
      const std::string section = body.section() + "/";
      prm.enter_subsection("Mesh");
      {
        body.mesh_type = parse_selection<MeshType>(prm.get("Type"));
        body.corner_1 =
          parse_point(prm.get("Corner 1"), section + "Mesh/Corner 1");
        body.corner_2 =
          parse_point(prm.get("Corner 2"), section + "Mesh/Corner 2");
        const auto n = Utilities::string_to_int(
          Utilities::split_string_list(prm.get("Subdivisions")));
        body.subdivisions       = {static_cast<unsigned int>(n[0]),
                                   static_cast<unsigned int>(n[1])};
        body.mesh_file          = prm.get("File");
        body.initial_refinement = prm.get_integer("Initial refinement");
        body.box_refinement     = prm.get_integer("Box refinement");
        body.merge_coincident_vertices =
          prm.get_bool("Merge coincident vertices");
        // The cells these entries would make are checked against the
        // machine's memory when the mesh is built (ElasticBody::make_mesh).
        const std::string box = Utilities::trim(prm.get("Refinement box"));
        body.refinement_box.clear();
        for (const auto &c : Utilities::split_string_list(box))
          body.refinement_box.push_back(
            parse_double(c, section + "Mesh/Refinement box"));
        if (!box.empty() && body.refinement_box.size() != 4)
          throw InputError(section + "Mesh/Refinement box: '" + box +
                           "' is not 'x0, y0, x1, y1'");
        if (body.mesh_type == MeshType::rectangle &&
            !(body.corner_1[0] < body.corner_2[0] &&
              body.corner_1[1] < body.corner_2[1]))
          throw InputError(section +
                           "Mesh/Corner 2: must lie above and to the right of "
                           "Corner 1");
        if (body.mesh_type == MeshType::file &&
            Utilities::trim(body.mesh_file).empty())
          throw InputError(section + "Mesh/File: empty, but Mesh/Type = file");
      }
      prm.leave_subsection();
    }

    /** Read the subsection Material of @p body and check it (with the
     * element read before: locking depends on it). */
    void
    parse_material(ParameterHandler &prm, BodyParameters &body)
    {
      const std::string section = body.section() + "/";
      prm.enter_subsection("Material");
      {
        body.material_law          = prm.get("Law");
        const MaterialLawInfo &law = material_law_info(body.material_law);
        // An entry of another law would be ignored silently.
        for (const auto &other : material_laws())
          if (other.name != law.name)
            for (const auto &entry : other.entries)
              if (std::find(law.entries.begin(), law.entries.end(), entry) ==
                    law.entries.end() &&
                  !Utilities::trim(prm.get(entry)).empty())
                throw InputError(section + "Material/" + entry + " = " +
                                 prm.get(entry) +
                                 " belongs to Law = " + other.name +
                                 ", but the body's Law is " + law.name +
                                 "; set Material/Law = " + other.name +
                                 ", or remove the entry");
        body.material_law_constants = law.parse(prm, section + "Material/");
        if (body.volumetric_integration == VolumetricIntegration::reduced &&
            !law.reduced_integration)
          throw InputError(section +
                           "Element/Volumetric integration = "
                           "reduced: Material/Law = " +
                           law.name +
                           " has no reduced volumetric part; set it to full");
        body.material.youngs_modulus = prm.get_double("Young's modulus");
        body.material.poisson_ratio  = prm.get_double("Poisson's ratio");
        // Stiffness entries are E times O(1) factors summed over cells: at
        // 1e300 they overflow. Any unit system fits within 1e-30..1e30.
        if (!(body.material.youngs_modulus >= 1e-30 &&
              body.material.youngs_modulus <= 1e30))
          throw InputError(section + "Material/Young's modulus: E = " +
                           prm.get("Young's modulus") +
                           " must be positive and within 1e-30 .. 1e30");
        if (!(body.material.poisson_ratio > -1. &&
              body.material.poisson_ratio < 0.5))
          throw InputError(section + "Material/Poisson's ratio: nu = " +
                           prm.get("Poisson's ratio") +
                           " must lie in (-1, 0.5)");
        // Volumetric locking: with lambda/mu = 2 nu/(1 - 2 nu) >= 100 the
        // fully integrated linear elements (Q1, P1) can only represent nearly
        // divergence-free fields by moving almost nothing, and the answer is
        // silently far too stiff (the contact force of the paper's scene is
        // 30 % off at nu = 0.499, 200 % at 0.4999, on 4 cells across).
        const double nu = body.material.poisson_ratio;
        if (body.degree == 1 &&
            body.volumetric_integration == VolumetricIntegration::full &&
            2. * nu / (1. - 2. * nu) >= 100.)
          throw InputError(
            section +
            "Material/Poisson's ratio: nu = " + prm.get("Poisson's ratio") +
            " makes linear elements lock (lambda/mu >= 100); set Element/"
            "Degree = 2" +
            (body.cell_type == CellType::quadrilateral
               ? " or Element/Volumetric integration = reduced"
               : ""));
      }
      prm.leave_subsection();
    }
  } // namespace

  void
  BodyParameters::declare(ParameterHandler &prm)
  {
    declare_mesh(prm);
    declare_element(prm);
    declare_material(prm);
    declare_boundary_conditions(prm);
    declare_solver(prm);
  }

  void
  BodyParameters::parse(ParameterHandler &prm)
  {
    const std::string section = this->section() + "/";
    parse_mesh(prm, *this);

    prm.enter_subsection("Element");
    {
      cell_type              = parse_selection<CellType>(prm.get("Cell type"));
      degree                 = prm.get_integer("Degree");
      volumetric_integration = parse_selection<VolumetricIntegration>(
        prm.get("Volumetric integration"));
      if (volumetric_integration == VolumetricIntegration::reduced &&
          !(cell_type == CellType::quadrilateral && degree == 1))
        throw InputError(section +
                         "Element/Volumetric integration: reduced needs Cell "
                         "type = quadrilateral and Degree = 1 (for triangles "
                         "or degree 2 use full; near nu = 1/2 use Degree = "
                         "2)");
    }
    prm.leave_subsection();

    parse_material(prm, *this);

    prm.enter_subsection("Boundary conditions");
    {
      dirichlet   = prm.get("Dirichlet");
      neumann     = prm.get("Neumann");
      contact_ids = prm.get("Contact ids");
      body_force  = prm.get("Body force");
    }
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    {
      solver                = parse_selection<BodySolverType>(prm.get("Type"));
      solver_tolerance      = prm.get_double("Tolerance");
      solver_max_iterations = prm.get_integer("Max iterations");
      newton_tolerance      = prm.get_double("Newton tolerance");
      newton_max_iterations = prm.get_integer("Newton max iterations");
    }
    prm.leave_subsection();
  }

} // namespace ddcontact
