#ifndef ddcontact_boundary_mesh_h
#define ddcontact_boundary_mesh_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/boundary_conditions.h>

#include <array>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The boundary mesh of one FEM body for the direct boundary element
   * method (doc/bem-method.md §2), with its boundary data and the numbering of
   * the unknowns:
   *  - one node per boundary vertex, one straight element per active
   *    boundary face (25), oriented so that the body lies on the left
   *    (outer boundaries counter-clockwise); on a distributed mesh (p4est)
   *    the faces of all processes are gathered on every process;
   *  - for a body of degree 2 (Q2 or P2) the elements are quadratic: one
   *    more node at each face midpoint, the support point of the face's line
   *    dofs, so that the BEM basis is again the trace of the FEM basis (26);
   *    midpoint nodes are numbered after all vertices;
   *  - coordinates scaled by the bounding-box diagonal of the boundary
   *    (doc/bem-method.md §3.3), tractions by mu;
   *  - the unknowns: nodal displacement components that are not prescribed,
   *    element-end traction components where the displacement is
   *    (doc/bem-method.md §2.2, §2.7), the collocation points and rows, and the
   * rigid modes left free by the Dirichlet data (§5.1);
   *  - the boundary solution, prescribed or solved for, stored on the nodes
   *    and element ends.
   */
  class BoundaryMesh
  {
  public:
    /** A boundary node = a boundary vertex of the mesh, or the midpoint of
     * a quadratic element. Coordinates and displacements are scaled by
     * length_scale(). */
    struct Node
    {
      Point<2>                               x;
      Point<2>                               x_physical;
      std::array<types::global_dof_index, 2> dofs;
      // For a midpoint node both are its own element.
      unsigned int element_in  = numbers::invalid_unsigned_int;
      unsigned int element_out = numbers::invalid_unsigned_int;
      bool         is_midpoint = false;
      // Per component: prescribed value (scaled) or index of the unknown.
      std::array<bool, 2>         known{{false, false}};
      std::array<unsigned int, 2> unknown{
        {numbers::invalid_unsigned_int, numbers::invalid_unsigned_int}};
      Tensor<1, 2> displacement;
    };

    /** A straight boundary element = an active boundary face (25), scaled
     * coordinates. Its nodes are the start vertex (local coordinate s = 0),
     * the end vertex (s = 1) and, for degree 2, the midpoint (s = 1/2);
     * "ends" below are these element nodes. */
    struct Element
    {
      std::array<unsigned int, 3> nodes{{numbers::invalid_unsigned_int,
                                         numbers::invalid_unsigned_int,
                                         numbers::invalid_unsigned_int}};
      Point<2>                    x_a, x_b;
      Tensor<1, 2>                tangent, normal;
      double                      length;
      types::boundary_id          boundary_id;
      // Per component: is the displacement prescribed on this element?
      std::array<bool, 2> dirichlet{{false, false}};
      bool                is_contact = false;
      // Index of the element among the contact elements, if it is one.
      unsigned int contact_index = numbers::invalid_unsigned_int;
      // [end][component]: index of the unknown traction (ends may be tied).
      std::array<std::array<unsigned int, 2>, 3> unknown;
      // Tractions (scaled by mu) at the element nodes: prescribed or solved
      // for.
      std::array<Tensor<1, 2>, 3> traction;
    };

    /** A collocation point xi with the BIE components collocated there:
     * a node, or an extra point inside an element (doc/bem-method.md §2.7). */
    struct CollocationPoint
    {
      Point<2>                  x;
      unsigned int              node    = numbers::invalid_unsigned_int;
      unsigned int              element = numbers::invalid_unsigned_int;
      double                    s0      = 0;
      std::vector<unsigned int> components;
      std::vector<unsigned int> rows;
    };

    /** Build the nodes and elements from the active boundary faces of the
     * mesh of @p dof_handler (vertex dofs of Q1 or P1, vertex and line dofs
     * of Q2 or P2) and scale them. */
    void
    reinit(const DoFHandler<2> &dof_handler, const Mapping<2> &mapping);

    /** Apply the body's Dirichlet (5) and Neumann (6) data (tractions
     * divided by the shear modulus @p mu), number the unknowns, set up
     * the collocation points and find the free rigid modes. */
    void
    number_unknowns(const BoundaryConditions<2> &boundary_conditions,
                    const double                 mu);

    /** Store the solution @p x of the collocation system and the contact
     * element-end tractions @p contact_values
     * (contact_values_per_element() per contact element, scaled by mu) on
     * the nodes and element ends. */
    void
    set_solution(const Vector<double> &x, const Vector<double> &contact_values);

    /** Scaled coordinates of the physical point @p x. */
    Point<2>
    scaled(const Point<2> &x) const
    {
      return Point<2>((x - reference_center) / reference_length);
    }

    /** Polynomial degree of the elements (1 or 2), that of the FEM body. */
    unsigned int
    degree() const
    {
      return element_degree;
    }

    /** Nodes per element: degree() + 1. */
    unsigned int
    n_element_nodes() const
    {
      return element_degree + 1;
    }

    /** Contact traction values per contact element: two components at each
     * element node. */
    unsigned int
    contact_values_per_element() const
    {
      return 2 * n_element_nodes();
    }

    /** The values at local coordinate @p s of the shape functions of the
     * element nodes (start, end, midpoint): (1 - s, s) for degree 1, the
     * quadratic Lagrange polynomials for degree 2. */
    std::array<double, 3>
    shape_values(const double s) const
    {
      if (element_degree == 1)
        return {{1. - s, s, 0.}};
      return {{(1. - s) * (1. - 2. * s), s * (2. * s - 1.), 4. * s * (1. - s)}};
    }

    /** Length scale L_ref (bounding-box diagonal of the boundary). */
    double
    length_scale() const
    {
      return reference_length;
    }

    const std::vector<Node> &
    get_nodes() const
    {
      return nodes;
    }

    const std::vector<Element> &
    get_elements() const
    {
      return elements;
    }

    const std::vector<CollocationPoint> &
    get_collocation_points() const
    {
      return collocation_points;
    }

    /** Number of BEM unknowns (= collocation rows). */
    unsigned int
    n_unknowns() const
    {
      return n_boundary_unknowns;
    }

    /** Number of off-node collocation rows at D-D corners (doc/bem-method.md
     * §2.7). */
    unsigned int
    n_extra_collocation_rows() const
    {
      return n_extra_rows;
    }

    unsigned int
    n_contact_elements() const
    {
      return n_contact;
    }

    /** Free rigid modes as coefficients of (translation x, translation y,
     * rotation about the centre of the bounding box), scaled coordinates. */
    const std::vector<Tensor<1, 3>> &
    get_rigid_modes() const
    {
      return rigid_modes;
    }

  private:
    /** Scale the node coordinates by the bounding box of the boundary and
     * set the element geometry from them. */
    void
    scale_nodes_and_elements();

    /** Which components are prescribed on each element, which elements are
     * contact elements, and the prescribed tractions at the element ends. */
    void
    apply_element_data(const BoundaryConditions<2> &boundary_conditions,
                       const double                 mu);

    /** Number the nodal displacement components that are not prescribed
     * (from 0) and set the prescribed ones; return the number of them. */
    unsigned int
    number_displacement_unknowns(
      const BoundaryConditions<2> &boundary_conditions);

    /** Number the element-end traction unknowns from @p n on; return the
     * next free number. */
    unsigned int
    number_traction_unknowns(unsigned int n);

    /** The collocation points: every node, then the extra points at
     * corners (doc/bem-method.md §2.7). */
    void
    set_up_collocation_points();

    void
    find_rigid_modes();

    unsigned int element_degree   = 1;
    double       reference_length = 1;
    Point<2>     reference_center;

    std::vector<Node>             nodes;
    std::vector<Element>          elements;
    std::vector<CollocationPoint> collocation_points;
    unsigned int                  n_boundary_unknowns = 0;
    unsigned int                  n_extra_rows        = 0;
    unsigned int                  n_contact           = 0;
    std::vector<Tensor<1, 3>>     rigid_modes;
  };
} // namespace ddcontact

#endif
