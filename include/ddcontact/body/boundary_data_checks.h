#ifndef ddcontact_boundary_data_checks_h
#define ddcontact_boundary_data_checks_h

namespace ddcontact
{
  template <int dim>
  class ElasticBody;

  /**
   * The number of load steps of the run (Loading/Steps): the load parameter
   * t of the boundary data takes the values k / Steps, k = 1, ..., Steps.
   * The checks below evaluate the data at these times and name t and the
   * step in their messages. SceneParameters::parse() sets it; it is 1 (t = 1
   * only) until then.
   */
  void
  set_checked_load_steps(unsigned int n_steps);

  /**
   * Refuse, naming Body <name>/Boundary conditions/Dirichlet, Neumann or
   * Body force, the point, t and the load step, boundary data that are not
   * finite where the body evaluates them: the prescribed displacements (5)
   * at the vertices and midpoints of their faces (where interpolation
   * evaluates them for degree 1 and 2), the tractions (6) at the quadrature
   * points of their faces and the body force at those of the cells. A NaN
   * would enter the constraints and every solution.
   *
   * ElasticBody calls it whenever it makes its constraints: for a new mesh
   * and for every load step. While the data are at t = 1 (a new body: the
   * time make_function() gives them; the last load step) all of them are
   * evaluated at every load time of the run, so that a load that is
   * infinite at one time only (1/(t - 0.5)) is refused before anything is
   * solved; this costs as many evaluations as the load vectors of all steps.
   * At another t only the Dirichlet values of that t are checked (the loads
   * are found by the assembly, throw_non_finite_load()).
   */
  template <int dim>
  void
  check_dirichlet_values(const ElasticBody<dim> &body);

  /**
   * Called when the assembled load (12) is not finite: throw an InputError
   * naming the expression (Body force or Neumann) that is not finite, where,
   * and at which t and load step.
   */
  template <int dim>
  [[noreturn]] void
  throw_non_finite_load(const ElasticBody<dim> &body);
} // namespace ddcontact

#endif
