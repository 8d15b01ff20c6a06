#ifndef ddcontact_quadrature_point_history_h
#define ddcontact_quadrature_point_history_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/quadrature_point_data.h>

#include <deal.II/grid/tria.h>

#include <ddcontact/body/material_law.h>

#include <functional>
#include <map>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The state of a path-dependent material law at one quadrature point:
   * the state at the start of the load step (committed) and that of the
   * current iterate (trial), the law's n_state_variables() values each.
   * Transferable, so that p4est meshes can carry the committed state
   * through deal.II's ContinuousQuadratureDataTransfer.
   */
  struct MaterialPointState : public TransferableQuadraturePointData
  {
    std::vector<double> committed;
    std::vector<double> trial;

    unsigned int
    number_of_values() const override
    {
      return committed.size();
    }

    void
    pack_values(std::vector<double> &values) const override
    {
      values = committed;
    }

    void
    unpack_values(const std::vector<double> &values) override
    {
      committed = values;
      trial     = values;
    }
  };

  /**
   * The quadrature-point state of a body's material law (deal.II's
   * CellDataStorage of MaterialPointState): read by the law at
   * the start of the step, written by each iterate, committed at the end of
   * a load step and restored when Loading/Steps = auto or Check path solves
   * a step again from its start (Snapshot). Under refinement a new child
   * takes its parent's state, averaged over the parent's points (the L2
   * projection on constants), and a coarsened parent the mean of its
   * children's. Empty for a law without state.
   */
  template <int dim>
  class QuadraturePointHistory
  {
  public:
    using CellIterator = typename Triangulation<dim>::cell_iterator;

    /** The committed and trial states of every cell, for a return to the
     * start of a load step (ContactSolver::load_step_start(): taken after
     * a step's solve, its trial state is the next step's start once
     * committed). */
    struct Snapshot
    {
      std::map<CellId, std::vector<double>> committed;
      std::map<CellId, std::vector<double>> trial;
    };

    /** No state (a law without one) until setup(). */
    QuadraturePointHistory() = default;

    /**
     * The states of @p law at @p n_points points per cell, on the active
     * cells of @p tria for which @p holds is true; a cell that has a state
     * keeps it, a new one gets the law's initial state. Call after every
     * change of the mesh (after transfer_after_refinement()).
     */
    void
    setup(const Triangulation<dim>                        &tria,
          const MaterialLaw                               &law,
          unsigned int                                     n_points,
          const std::function<bool(const CellIterator &)> &holds);

    /** Whether the law has a state. */
    bool
    empty() const
    {
      return n_values == 0;
    }

    /** The state at the start of the load step of @p cell's points, into
     * @p values (n_points times n_state_variables()). */
    void
    get_committed(const CellIterator &cell, std::vector<double> &values) const;

    /** The state of the current iterate at @p cell's points. */
    void
    get_trial(const CellIterator &cell, std::vector<double> &values) const;

    /** Set the current iterate's state of @p cell's points. */
    void
    set_trial(const CellIterator &cell, const ArrayView<const double> &values);

    /** The current iterate's state becomes the start of the next step. */
    void
    commit();

    /** The trial state back to the committed one. */
    void
    restore();

    /** The states, to return to later (restore(Snapshot)). */
    Snapshot
    snapshot() const;

    /** Committed and trial states from @p snapshot (of the same mesh). */
    void
    restore(const Snapshot &snapshot);

    /** Before the triangulation executes its refinement flags: a parent
     * whose children are all flagged for coarsening gets the mean of their
     * committed states. */
    void
    prepare_for_refinement();

    /** After it: new children take their parent's committed state
     * averaged over its points; cells that vanished are dropped. Then
     * setup() for the new cells. */
    void
    transfer_after_refinement();

  private:
    /** The committed or trial states (@p which) of @p cell's points. */
    void
    gather(const CellIterator &cell,
           std::vector<double> MaterialPointState::*which,
           std::vector<double>                     &values) const;

    /** The mean over the points of @p cell of their committed states. */
    std::vector<double>
    mean_committed(const CellIterator &cell) const;

    /** Every point of @p cell gets the committed state @p mean (and the
     * same trial state). */
    void
    set_all_points(const CellIterator &cell, const std::vector<double> &mean);

    const Triangulation<dim>                         *tria     = nullptr;
    unsigned int                                      n_points = 0;
    unsigned int                                      n_values = 0; // per point
    std::vector<double>                               initial; // of one point
    std::function<bool(const CellIterator &)>         holds;
    CellDataStorage<CellIterator, MaterialPointState> storage;
    // prepare_for_refinement()'s states of the parents to be.
    std::map<CellId, std::vector<double>> coarsened;
  };
} // namespace ddcontact

#endif
