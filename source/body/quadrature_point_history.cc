#include <ddcontact/body/quadrature_point_history.h>

namespace ddcontact
{
  template <int dim>
  void
  QuadraturePointHistory<dim>::setup(
    const Triangulation<dim>                        &tria,
    const MaterialLaw                               &law,
    const unsigned int                               n_points,
    const std::function<bool(const CellIterator &)> &holds)
  {
    n_values = law.n_state_variables();
    if (n_values == 0)
      return;
    Assert(this->tria == nullptr || this->tria == &tria, ExcInternalError());
    Assert(this->n_points == 0 || this->n_points == n_points,
           ExcInternalError());
    this->tria     = &tria;
    this->n_points = n_points;
    this->holds    = holds;
    initial.resize(n_values);
    law.initial_state(make_array_view(initial));
    for (const auto &cell : tria.active_cell_iterators())
    {
      if (!holds(cell))
        continue;
      // CellDataStorage::initialize() keeps a cell's existing state.
      storage.template initialize<MaterialPointState>(cell, n_points);
      for (const auto &point : storage.get_data(cell))
        if (point->committed.empty())
        {
          point->committed = initial;
          point->trial     = initial;
        }
    }
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::gather(
    const CellIterator &cell,
    std::vector<double> MaterialPointState::*which,
    std::vector<double>                     &values) const
  {
    values.resize(n_points * n_values);
    const auto data = storage.get_data(cell);
    for (unsigned int q = 0; q < n_points; ++q)
      std::copy(((*data[q]).*which).begin(),
                ((*data[q]).*which).end(),
                values.begin() + q * n_values);
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::get_committed(const CellIterator  &cell,
                                             std::vector<double> &values) const
  {
    gather(cell, &MaterialPointState::committed, values);
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::get_trial(const CellIterator  &cell,
                                         std::vector<double> &values) const
  {
    gather(cell, &MaterialPointState::trial, values);
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::set_trial(const CellIterator            &cell,
                                         const ArrayView<const double> &values)
  {
    AssertDimension(values.size(), n_points * n_values);
    const auto data = storage.get_data(cell);
    for (unsigned int q = 0; q < n_points; ++q)
      std::copy(values.begin() + q * n_values,
                values.begin() + (q + 1) * n_values,
                data[q]->trial.begin());
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::commit()
  {
    if (empty())
      return;
    for (const auto &cell : tria->active_cell_iterators())
      if (holds(cell))
        for (const auto &point : storage.get_data(cell))
          point->committed = point->trial;
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::restore()
  {
    if (empty())
      return;
    for (const auto &cell : tria->active_cell_iterators())
      if (holds(cell))
        for (const auto &point : storage.get_data(cell))
          point->trial = point->committed;
  }

  template <int dim>
  typename QuadraturePointHistory<dim>::Snapshot
  QuadraturePointHistory<dim>::snapshot() const
  {
    Snapshot result;
    if (empty())
      return result;
    for (const auto &cell : tria->active_cell_iterators())
      if (holds(cell))
      {
        get_committed(cell, result.committed[cell->id()]);
        get_trial(cell, result.trial[cell->id()]);
      }
    return result;
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::restore(const Snapshot &snapshot)
  {
    if (empty())
      return;
    for (const auto &cell : tria->active_cell_iterators())
      if (holds(cell))
      {
        const auto committed = snapshot.committed.find(cell->id());
        const auto trial     = snapshot.trial.find(cell->id());
        AssertThrow(committed != snapshot.committed.end() &&
                      trial != snapshot.trial.end(),
                    ExcMessage("a material state snapshot of another mesh"));
        const auto data = storage.get_data(cell);
        for (unsigned int q = 0; q < n_points; ++q)
        {
          const auto at = [&](const std::vector<double> &v)
          {
            return std::vector<double>(v.begin() + q * n_values,
                                       v.begin() + (q + 1) * n_values);
          };
          data[q]->committed = at(committed->second);
          data[q]->trial     = at(trial->second);
        }
      }
  }

  template <int dim>
  std::vector<double>
  QuadraturePointHistory<dim>::mean_committed(const CellIterator &cell) const
  {
    std::vector<double> mean(n_values, 0.);
    for (const auto &point : storage.get_data(cell))
      for (unsigned int k = 0; k < n_values; ++k)
        mean[k] += point->committed[k] / n_points;
    return mean;
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::set_all_points(const CellIterator        &cell,
                                              const std::vector<double> &mean)
  {
    storage.template initialize<MaterialPointState>(cell, n_points);
    for (const auto &point : storage.get_data(cell))
    {
      point->committed = mean;
      point->trial     = mean;
    }
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::prepare_for_refinement()
  {
    if (empty())
      return;
    coarsened.clear();
    for (const auto &cell : tria->cell_iterators())
    {
      if (!cell->has_children())
        continue;
      bool all_coarsened = true;
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        all_coarsened = all_coarsened && cell->child(c)->is_active() &&
                        cell->child(c)->coarsen_flag_set();
      if (!all_coarsened)
        continue;
      // The mean of the children's means (children of equal area), and
      // the children's states dropped before their iterators vanish.
      std::vector<double> mean(n_values, 0.);
      bool                known = false;
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        if (storage.try_get_data(cell->child(c)))
        {
          const auto child = mean_committed(cell->child(c));
          for (unsigned int k = 0; k < n_values; ++k)
            mean[k] += child[k] / cell->n_children();
          known = true;
          storage.erase(cell->child(c));
        }
      if (known)
        coarsened[cell->id()] = mean;
    }
  }

  template <int dim>
  void
  QuadraturePointHistory<dim>::transfer_after_refinement()
  {
    if (empty())
      return;
    for (const auto &[id, mean] : coarsened)
      set_all_points(id.to_cell(*tria), mean);
    coarsened.clear();
    // A refined parent hands its mean state to its new children.
    for (const auto &cell : tria->cell_iterators())
      if (cell->has_children() && storage.try_get_data(cell))
      {
        const std::vector<double> mean = mean_committed(cell);
        for (unsigned int c = 0; c < cell->n_children(); ++c)
          set_all_points(cell->child(c), mean);
        storage.erase(cell);
      }
  }

  template class QuadraturePointHistory<2>;
} // namespace ddcontact
