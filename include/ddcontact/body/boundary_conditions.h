#ifndef ddcontact_boundary_conditions_h
#define ddcontact_boundary_conditions_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/fe/component_mask.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

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
   *
   * An id may be in both dirichlet and neumann (a roller with a load): the
   * components of its Dirichlet mask are prescribed displacements, the
   * others are loaded by the traction, whose prescribed components are
   * ignored (make_boundary_conditions() requires them to be written 0).
   * A contact id has no other condition.
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

  /**
   * A traction known at sample points of the contact zone of a body, e.g.
   * the penalty pressure sigma_n^k n of the current DD iterate (20) at the
   * contact points (for body 2 of a pair: at the projections P(x), with the
   * weights of S_1). The BEM turns it into element-end tractions by an L2
   * projection on each boundary element of the contact ids: the moments
   * sum_q w_q t_q N_a(x_q) are the same that load the FEM problem, so the
   * BEM and the FEM see the same resultant force and moment.
   */
  struct BoundaryTractionSamples
  {
    std::vector<Point<2>>     points;
    std::vector<double>       weights;
    std::vector<Tensor<1, 2>> traction; // physical traction t = sigma n
  };
} // namespace ddcontact

#endif
