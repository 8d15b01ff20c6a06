#ifndef ddcontact_rigid_body_modes_h
#define ddcontact_rigid_body_modes_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_vector.h>

#include <ddcontact/body/boundary_conditions.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The rigid motions a body's Dirichlet conditions (5) leave free: the
   * kernel of its stiffness a_a of (11) for a floating body (a punch pressed
   * by a force, held only by contact). In 2D they are spanned by the
   * translations in x and y and the rotation about the body's centre; the
   * free ones are those that vanish on every prescribed component.
   *
   * A floating body's problem (20) is solvable only for a load in
   * equilibrium (no work on these modes), and then only up to them.
   * FETI's answer, used here: fix as many displacement components as there
   * are free modes, chosen so that no free mode vanishes on all of them
   * (fixing_dofs()). The stiffness with these components clamped is
   * regular, and its inverse is a generalized inverse of the singular
   * one: for a load in equilibrium the clamped components carry no
   * reaction (statically determinate support), so the solution is a
   * solution of the free body. DDNewtonSolver adds the modes' amplitudes
   * and the equilibrium of each floating body as a coarse problem
   * (RigidModeCoarseSpace).
   *
   * On a p4est mesh each process knows only its cells and a ghost layer:
   * the centre, the size and the Gram matrix below are then sums (and a
   * maximum) over the dofs each process owns, added over the processes in
   * rank order, and the fixed dofs come from an argmax over the processes
   * (ties within 1e-10 to the smallest support point, which is the same
   * dof on one process and on any partition). The mode vectors take the
   * body's vector layout.
   */
  template <int dim>
  class RigidBodyModes
  {
  public:
    /**
     * The free modes of the body with dofs @p dof_handler and the
     * prescribed components of @p conditions, and the fixed components:
     * @p constraints (closed: hanging nodes and Dirichlet data) tells
     * which dofs are already constrained and may not be chosen (it must
     * hold the lines of the dofs this process owns). The modes are
     * vectors of @p layout (ElasticBody::reinit_vector()). Collective
     * over a p4est mesh's processes. An @p axisymmetric section has one
     * rigid motion only, the translation along the axis (y): a radial
     * displacement strains the hoops, a rotation leaves the section.
     */
    void
    reinit(const DoFHandler<dim>           &dof_handler,
           const Mapping<dim>              &mapping,
           const BoundaryConditions<dim>   &conditions,
           const AffineConstraints<double> &constraints,
           const std::shared_ptr<const Utilities::MPI::Partitioner> &layout,
           bool axisymmetric = false);

    /** The modes as vectors of @p layout, which owns the same dofs as the
     * layout they have (ElasticBody::distribute_vectors() adds ghosts). */
    void
    set_layout(
      const std::shared_ptr<const Utilities::MPI::Partitioner> &layout);

    /** The number of free rigid modes (0: the body is held). */
    unsigned int
    size() const
    {
      return modes.size();
    }

    /** Mode @p k as a displacement (a vector of the body's dofs). */
    const BodyVector &
    mode(const unsigned int k) const
    {
      return modes[k];
    }

    /** The dofs to clamp (one per mode). */
    const std::vector<types::global_dof_index> &
    fixing_dofs() const
    {
      return fixed;
    }

    /** "translation in y", "translation in x and y, rotation", ... */
    std::string
    description() const;

  private:
    std::vector<BodyVector>              modes;
    std::vector<types::global_dof_index> fixed;
    // Which of translation x, translation y, rotation the modes span,
    // for description(): the weights of each in the modes.
    std::vector<std::array<double, 3>> weights;
  };
} // namespace ddcontact

#endif
