#ifndef ddcontact_refinement_transfer_h
#define ddcontact_refinement_transfer_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_vector.h>

#include <utility>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Carry a finite element field over a refinement (no coarsening) of its
   * serial or shared mesh: each cell that was active before gives its
   * values to itself or, if refined, to its children by the prolongation
   * matrices, as SolutionTransfer does.
   *
   * Used for triangles instead of SolutionTransfer, whose Debug-mode check
   * that the children sharing a node agree to 1e-11 relative fails there
   * for no error: FE_SimplexP's embedding matrices are computed
   * numerically, so a new node where the field vanishes (a clamped
   * component, a zero initial iterate) gets round-off of ~1e-20 that
   * differs between the children. The values set are the same.
   */
  class RefinementTransfer
  {
  public:
    explicit RefinementTransfer(const DoFHandler<2> &dof_handler);

    /** Keep the cell values of @p u; call before the refinement. */
    void
    prepare(const BodyVector &u);

    /** The kept field on the refined mesh, whose dofs are distributed;
     * distribute the constraints after. */
    void
    interpolate(BodyVector &u) const;

  private:
    const DoFHandler<2> &dof_handler;
    /** (level, index) of each formerly active cell with its values. */
    std::vector<std::pair<std::pair<int, int>, Vector<double>>> cell_values;
  };
} // namespace ddcontact

#endif
