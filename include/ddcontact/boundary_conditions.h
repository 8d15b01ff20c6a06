#ifndef ddcontact_boundary_conditions_h
#define ddcontact_boundary_conditions_h

#include <deal.II/base/function.h>
#include <deal.II/base/types.h>

#include <deal.II/fe/component_mask.h>

#include <map>
#include <memory>
#include <set>
#include <string>

namespace ddcontact
{
  using namespace dealii;

  /**
   * A prescribed displacement (5) on one boundary id: which components are
   * prescribed, and their values as a function of x with dim components.
   */
  template <int dim>
  struct DirichletCondition
  {
    ComponentMask                  mask;
    std::shared_ptr<Function<dim>> displacement;
  };

  /**
   * The boundary description of one body, keyed by boundary id: Gamma_u
   * (Dirichlet, (5)), Gamma_p (Neumann tractions p, (6)) and the ids that
   * form the possible contact zone S. Ids not listed are traction free.
   */
  template <int dim>
  struct BoundaryConditions
  {
    std::map<types::boundary_id, DirichletCondition<dim>>        dirichlet;
    std::map<types::boundary_id, std::shared_ptr<Function<dim>>> neumann;
    std::set<types::boundary_id>                                 contact;

    /** Optional body force (dim components); nullptr means none. */
    std::shared_ptr<Function<dim>> body_force;
  };
} // namespace ddcontact

#endif
