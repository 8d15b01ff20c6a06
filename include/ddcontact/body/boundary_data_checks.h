#ifndef ddcontact_boundary_data_checks_h
#define ddcontact_boundary_data_checks_h

namespace ddcontact
{
  template <int dim>
  class ElasticBody;

  /**
   * Refuse, naming Body <name>/Boundary conditions/Dirichlet and the point,
   * prescribed displacements (5) that are not finite at the vertices and
   * midpoints of their faces (where interpolation evaluates them for degree
   * 1 and 2): a NaN would enter the constraints and every solution.
   */
  template <int dim>
  void
  check_dirichlet_values(const ElasticBody<dim> &body);

  /**
   * Called when the assembled load (12) is not finite: throw an InputError
   * naming the expression (Body force or Neumann) that is not finite, and
   * where.
   */
  template <int dim>
  [[noreturn]] void
  throw_non_finite_load(const ElasticBody<dim> &body);
} // namespace ddcontact

#endif
