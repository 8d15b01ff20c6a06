#include <deal.II/grid/tria_accessor.h>

#include <deal.II/dofs/dof_accessor.h>

#include <ddcontact/body/refinement_transfer.h>

namespace ddcontact
{
  RefinementTransfer::RefinementTransfer(const DoFHandler<2> &dof_handler)
    : dof_handler(dof_handler)
  {
  }

  void
  RefinementTransfer::prepare(const BodyVector &u)
  {
    cell_values.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      AssertThrow(!cell->coarsen_flag_set(),
                  ExcMessage("RefinementTransfer refines only"));
      Vector<double> values(cell->get_fe().n_dofs_per_cell());
      cell->get_dof_values(u, values);
      cell_values.emplace_back(std::make_pair(cell->level(), cell->index()),
                               std::move(values));
    }
  }

  void
  RefinementTransfer::interpolate(BodyVector &u) const
  {
    u.reinit(dof_handler.n_dofs());
    for (const auto &[where, values] : cell_values)
    {
      const typename DoFHandler<2>::cell_iterator cell(
        &dof_handler.get_triangulation(),
        where.first,
        where.second,
        &dof_handler);
      // Recurses into the children of a refined cell (prolongation).
      cell->set_dof_values_by_interpolation(values, u);
    }
  }
} // namespace ddcontact
