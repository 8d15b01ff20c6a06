#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <ddcontact/body/rigid_body_modes.h>
#include <ddcontact/tasks.h>

#include <cmath>
#include <numeric>
#include <set>

namespace ddcontact
{
  namespace
  {
    /**
     * The dofs of a body that this process counts and knows, their support
     * points and components, and the three rigid motions at them. Every
     * dof is counted once: on a serial or shared mesh, which holds every
     * cell, all of them here; on a p4est mesh those this process owns, the
     * sums then added over the processes in rank order (the same bits
     * everywhere; on one process own + 0 = own).
     */
    template <int dim>
    struct DofSupports
    {
      DofSupports(const DoFHandler<dim> &dof_handler,
                  const Mapping<dim>    &mapping,
                  const bool             p4est,
                  const MPI_Comm         comm)
        : counted(p4est ? dof_handler.locally_owned_dofs()
                        : complete_index_set(dof_handler.n_dofs()))
        , known(counted)
        , comm(comm)
      {
        if (p4est)
          DoFTools::extract_locally_relevant_dofs(dof_handler, known);
        // The support point and component of every dof of the cells here.
        const FiniteElement<dim> &fe = dof_handler.get_fe();
        x.resize(known.n_elements());
        is_x.resize(known.n_elements(), false);
        FEValues<dim>                        support(mapping,
                              fe,
                              Quadrature<dim>(fe.get_unit_support_points()),
                              update_quadrature_points);
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
          {
            support.reinit(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const auto k = known.index_within_set(dofs[i]);
              x[k]         = support.quadrature_point(i);
              is_x[k]      = fe.system_to_component_index(i).first == 0;
            }
          }

        // The rotation about the centre of the support points, scaled by
        // the body's size so that the three motions are of one magnitude.
        const double n = dof_handler.n_dofs();
        for (const auto i : counted)
          centre += x[known.index_within_set(i)] / n;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = total(centre[d]);
        for (const auto i : counted)
          size = std::max(size, x[known.index_within_set(i)].distance(centre));
        size = Utilities::MPI::max(size, comm);
      }

      /** The sum of @p own over the processes, in rank order. */
      double
      total(const double own) const
      {
        return ordered_sum(own, comm);
      }

      /** Translations in x and y and the rotation at the dof of index @p k
       * in known. */
      std::array<double, 3>
      basic(const unsigned int k) const
      {
        const double rotation = is_x[k] ? -(x[k][1] - centre[1]) / size
                                        : (x[k][0] - centre[0]) / size;
        return {{is_x[k] ? 1. : 0., is_x[k] ? 0. : 1., rotation}};
      }

      IndexSet                counted, known;
      std::vector<Point<dim>> x;
      std::vector<bool>       is_x;
      Point<dim>              centre;
      double                  size = 0;
      MPI_Comm                comm;
    };

    /** The Gram matrix of the three motions at the components that
     * @p conditions prescribe (entries of order one per dof, so a held
     * mode has an eigenvalue of at least about one); its kernel holds the
     * free combinations. */
    template <int dim>
    LAPACKFullMatrix<double>
    prescribed_gram(const DoFHandler<dim>         &dof_handler,
                    const BoundaryConditions<dim> &conditions,
                    const DofSupports<dim>        &supports)
    {
      const FiniteElement<dim> &fe        = dof_handler.get_fe();
      double                    own[3][3] = {};
      for (const auto &[id, condition] : conditions.dirichlet)
      {
        // The prescribed components on the faces of this id, each dof once
        // and in ascending order.
        std::set<types::global_dof_index>    prescribed;
        std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && face->boundary_id() == id)
              {
                face->get_dof_indices(face_dofs);
                for (unsigned int k = 0; k < face_dofs.size(); ++k)
                  if (condition
                        .mask[fe.face_system_to_component_index(k).first] &&
                      supports.counted.is_element(face_dofs[k]))
                    prescribed.insert(face_dofs[k]);
              }
        for (const auto i : prescribed)
        {
          const auto e = supports.basic(supports.known.index_within_set(i));
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = 0; b < 3; ++b)
              own[a][b] += e[a] * e[b];
        }
      }
      LAPACKFullMatrix<double> gram(3, 3);
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          gram(a, b) = supports.total(own[a][b]);
      return gram;
    }

    double
    norm_sqr(const std::vector<double> &row)
    {
      return std::inner_product(row.begin(), row.end(), row.begin(), 0.);
    }

    /**
     * One fixed component per mode (with @p weights), chosen greedily: each
     * time the free dof whose mode values are farthest from the span of
     * those already chosen (pivoted Gram-Schmidt on the rows of the mode
     * matrix). The values of the modes at the fixed dofs then form a
     * regular matrix, so no free motion leaves all of them at rest.
     * Symmetric bodies have ties (the corners of a rectangle under a
     * rotation), which round-off of the centre decides: among the dofs
     * within 1e-10 of the largest value, the one with the smallest support
     * point (x, then y, then the x component) wins, which is the same dof
     * on any mesh partition and numbering.
     */
    template <int dim>
    std::vector<types::global_dof_index>
    choose_fixed_dofs(const DofSupports<dim>                   &supports,
                      const std::vector<std::array<double, 3>> &weights,
                      const AffineConstraints<double>          &constraints,
                      const bool                                p4est)
    {
      const auto                          &known = supports.known;
      std::vector<std::vector<double>>     chosen_directions;
      std::vector<types::global_dof_index> fixed;
      // The mode values at dof i without their part along the chosen ones.
      const auto residual_row = [&](const types::global_dof_index i)
      {
        const auto          e = supports.basic(known.index_within_set(i));
        std::vector<double> row(weights.size());
        for (unsigned int m = 0; m < weights.size(); ++m)
          row[m] =
            weights[m][0] * e[0] + weights[m][1] * e[1] + weights[m][2] * e[2];
        for (const auto &q : chosen_directions)
        {
          double dot = 0;
          for (unsigned int m = 0; m < row.size(); ++m)
            dot += q[m] * row[m];
          for (unsigned int m = 0; m < row.size(); ++m)
            row[m] -= dot * q[m];
        }
        return row;
      };
      // Whether candidate a = {x, y, component (0: x), dof, row} comes
      // before b (an empty one: none).
      const auto precedes =
        [](const std::vector<double> &a, const std::vector<double> &b)
      {
        return !a.empty() &&
               (b.empty() ||
                std::lexicographical_compare(
                  a.begin(), a.begin() + 3, b.begin(), b.begin() + 3));
      };
      for (unsigned int k = 0; k < weights.size(); ++k)
      {
        // The squared residual of every free counted dof (-1:
        // constrained).
        std::vector<double> norms;
        norms.reserve(supports.counted.n_elements());
        double largest = 0;
        for (const auto i : supports.counted)
        {
          norms.push_back(
            constraints.is_constrained(i) ? -1. : norm_sqr(residual_row(i)));
          largest = std::max(largest, norms.back());
        }
        largest = Utilities::MPI::max(largest, supports.comm);
        AssertThrow(largest > 1e-12,
                    ExcMessage("no free dof holds a rigid mode"));
        // This process's first candidate, then the first of all
        // processes'.
        std::vector<double> best;
        unsigned int        position = 0;
        for (const auto i : supports.counted)
          if (norms[position++] >= (1 - 1e-10) * largest)
          {
            const auto          j         = known.index_within_set(i);
            std::vector<double> candidate = {supports.x[j][0],
                                             supports.x[j][1],
                                             supports.is_x[j] ? 0. : 1.,
                                             static_cast<double>(i)};
            const auto          row       = residual_row(i);
            candidate.insert(candidate.end(), row.begin(), row.end());
            if (precedes(candidate, best))
              best = std::move(candidate);
          }
        if (p4est)
          for (const auto &offer :
               Utilities::MPI::all_gather(supports.comm, best))
            if (precedes(offer, best))
              best = offer;
        std::vector<double> direction(best.begin() + 4, best.end());
        const double        length = std::sqrt(norm_sqr(direction));
        for (double &v : direction)
          v /= length;
        chosen_directions.push_back(direction);
        fixed.push_back(static_cast<types::global_dof_index>(best[3]));
      }
      return fixed;
    }
  } // namespace

  template <int dim>
  void
  RigidBodyModes<dim>::reinit(
    const DoFHandler<dim>                                    &dof_handler,
    const Mapping<dim>                                       &mapping,
    const BoundaryConditions<dim>                            &conditions,
    const AffineConstraints<double>                          &constraints,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &layout,
    const bool                                                axisymmetric)
  {
    static_assert(dim == 2, "rigid modes are written for 2D");
    modes.clear();
    fixed.clear();
    weights.clear();
    // Both components prescribed on a boundary id clamp at least two
    // distinct points, which holds every rigid motion: nothing to compute
    // for the bodies of most scenes.
    for (const auto &[id, condition] : conditions.dirichlet)
      if (condition.mask[0] && condition.mask[1])
        return;

    const auto *p4est =
      dynamic_cast<const parallel::DistributedTriangulationBase<dim> *>(
        &dof_handler.get_triangulation());
    const DofSupports<dim> supports(dof_handler,
                                    mapping,
                                    p4est != nullptr,
                                    p4est ? p4est->get_communicator()
                                          : MPI_COMM_SELF);

    // The free combinations: the kernel of the Gram matrix of the three
    // at the prescribed components.
    LAPACKFullMatrix<double> gram =
      prescribed_gram(dof_handler, conditions, supports);
    // Axisymmetric: the translation in x and the rotation are no motions
    // of a body of revolution; held, they leave the kernel (the Gram
    // matrix is semidefinite, so the kernel of the sum is the axial part
    // of its own).
    if (axisymmetric)
    {
      gram(0, 0) += 1.;
      gram(2, 2) += 1.;
    }
    gram.compute_svd();
    const auto &vt = gram.get_svd_vt();
    for (unsigned int k = 0; k < 3; ++k)
      if (gram.singular_value(k) < 1e-8)
        weights.push_back({{vt(k, 0), vt(k, 1), vt(k, 2)}});
    if (weights.empty())
      return;

    const auto &known = supports.known;
    for (const auto &w : weights)
    {
      BodyVector mode(layout);
      for (unsigned int k = 0; k < known.n_elements(); ++k)
      {
        const auto i = known.nth_index_in_set(k);
        if (layout->in_local_range(i))
        {
          const auto e = supports.basic(k);
          mode(i)      = w[0] * e[0] + w[1] * e[1] + w[2] * e[2];
        }
      }
      mode.update_ghost_values();
      modes.push_back(std::move(mode));
    }
    fixed = choose_fixed_dofs(supports, weights, constraints, p4est);
  }

  template <int dim>
  void
  RigidBodyModes<dim>::set_layout(
    const std::shared_ptr<const Utilities::MPI::Partitioner> &layout)
  {
    for (auto &mode : modes)
    {
      BodyVector moved(layout);
      for (const auto i : layout->locally_owned_range())
        moved(i) = mode(i);
      moved.update_ghost_values();
      mode.swap(moved);
    }
  }

  template <int dim>
  std::string
  RigidBodyModes<dim>::description() const
  {
    // The translations the free modes contain (the weights are orthonormal
    // rows, so the projection of a pure translation on them has length one
    // when it is free); any further mode is a rotation.
    std::string  s;
    unsigned int n_translations = 0;
    for (unsigned int a = 0; a < 2; ++a)
    {
      double projection = 0;
      for (const auto &w : weights)
        projection += w[a] * w[a];
      if (projection > 1 - 1e-6)
      {
        s += std::string(s.empty() ? "translation in " : " and ") +
             (a == 0 ? "x" : "y");
        ++n_translations;
      }
    }
    if (weights.size() > n_translations)
      s += std::string(s.empty() ? "" : " and ") + "rotation";
    return s;
  }

  template class RigidBodyModes<2>;
} // namespace ddcontact
