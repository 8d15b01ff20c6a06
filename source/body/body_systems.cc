#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Epetra_CrsMatrix.h>

#include <ddcontact/body/body_systems.h>

#include <map>

namespace ddcontact
{
  namespace
  {
    /**
     * The stiffness of a GroupSystem plus springs, MUMPS over the group:
     * the rows of each process are its own rows of K with the couplings of
     * the springs added (each process adds the entries of its own rows, so
     * nothing is sent), and the solution is gathered whole.
     */
    class GroupSpringFactorization : public SpringFactorization
    {
    public:
      GroupSpringFactorization(const GroupSystem             &system,
                               const std::vector<DofSprings> &springs)
        : system(system)
      {
        // Row by row: K's entries of each owned row with the springs'
        // entries of that row merged in, inserted in one call per row
        // (entry by entry, the copy of 8.9e4 dofs took 20 s; 0.08 s so).
        const auto             &owned = system.owned;
        const Epetra_CrsMatrix &K     = system.matrix.trilinos_matrix();
        std::map<types::global_dof_index,
                 std::map<types::global_dof_index, double>>
          extra;
        for (const auto &s : springs)
          for (unsigned int a = 0; a < s.dofs.size(); ++a)
            if (owned.is_element(s.dofs[a]))
              for (unsigned int b = 0; b < s.dofs.size(); ++b)
                extra[s.dofs[a]][s.dofs[b]] += s.stiffness * s.c[a] * s.c[b];
        std::vector<std::vector<types::global_dof_index>> columns(
          owned.n_elements());
        std::vector<std::vector<double>>  values(owned.n_elements());
        TrilinosWrappers::SparsityPattern sp(owned, system.communicator);
        unsigned int                      r = 0;
        for (const auto i : owned)
        {
          // Epetra's view of the row (deal.II's row iterator copies the
          // row again for every entry).
          std::map<types::global_dof_index, double> row;
          int                                       length      = 0;
          double                                   *row_values  = nullptr;
          int                                      *row_columns = nullptr;
          K.ExtractMyRowView(K.RowMap().LID(static_cast<int>(i)),
                             length,
                             row_values,
                             row_columns);
          for (int k = 0; k < length; ++k)
            row[K.ColMap().GID(row_columns[k])] += row_values[k];
          if (const auto e = extra.find(i); e != extra.end())
            for (const auto &[j, v] : e->second)
              row[j] += v;
          for (const auto &[j, v] : row)
          {
            columns[r].push_back(j);
            values[r].push_back(v);
          }
          sp.add_entries(i, columns[r].begin(), columns[r].end(), true);
          ++r;
        }
        sp.compress();
        matrix.reinit(sp);
        r = 0;
        for (const auto i : owned)
        {
          matrix.set(i, columns[r], values[r], false);
          ++r;
        }
        matrix.compress(VectorOperation::insert);
        direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         "Amesos_Mumps"));
        direct->initialize(matrix);
      }

      void
      solve(const BodyVector &rhs, BodyVector &v) const override
      {
        GroupSystem::VectorType b, x;
        system.right_hand_side(rhs, false, b, x);
        direct->solve(x, b);
        system.to_whole(x, v);
      }

    private:
      const GroupSystem                                      &system;
      TrilinosWrappers::SparseMatrix                          matrix;
      mutable SolverControl                                   control;
      mutable std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
    };

  } // namespace

  const double *
  values_from(const BodyVector &v, const types::global_dof_index first)
  {
    return v.begin() + v.get_partitioner()->global_to_local(first);
  }

  void
  GroupSystem::compress()
  {
    matrix.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
  }

  void
  GroupSystem::right_hand_side(const BodyVector &extra,
                               const bool        with_load,
                               VectorType       &rhs,
                               VectorType       &x) const
  {
    if (with_load)
      rhs = load;
    else
      rhs.reinit(load);
    x.reinit(load);
    if (extra.size() > 0 && owned.n_elements() > 0)
      std::transform(rhs.begin(),
                     rhs.end(),
                     values_from(extra, *owned.begin()),
                     rhs.begin(),
                     std::plus<double>());
  }

  void
  GroupSystem::to_whole(const VectorType &x, BodyVector &u) const
  {
    if (is_partitioned(u))
    {
      AssertDimension(u.size(), n_dofs);
      AssertDimension(u.locally_owned_size(), x.locally_owned_size());
      std::copy(x.begin(), x.end(), u.begin());
      return;
    }
    u.reinit(n_dofs);
    const int ierr = MPI_Allgatherv(x.begin(),
                                    x.locally_owned_size(),
                                    MPI_DOUBLE,
                                    u.begin(),
                                    range_sizes.data(),
                                    range_starts.data(),
                                    MPI_DOUBLE,
                                    communicator);
    AssertThrowMPI(ierr);
  }

  std::unique_ptr<SpringFactorization>
  factorize_group_with_springs(const GroupSystem             &system,
                               const std::vector<DofSprings> &springs)
  {
    return std::make_unique<GroupSpringFactorization>(system, springs);
  }
} // namespace ddcontact
