#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>

#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/reaction_forces.h>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  namespace
  {
    /** For every dof, the index into the sorted Dirichlet ids of the id
     * that prescribes it (the lowest, where ids meet), or -1. The faces of
     * ghost cells count too: a process's cells touch their nodes. */
    template <int dim>
    std::vector<int>
    support_of_dofs(const ElasticBody<dim>                &body,
                    const std::vector<types::boundary_id> &ids)
    {
      const auto      &dirichlet = body.get_boundary_conditions().dirichlet;
      const auto      &fe        = body.get_fe();
      std::vector<int> support(body.n_dofs(), -1);
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        for (const auto &face : cell->face_iterators())
        {
          if (!face->at_boundary())
            continue;
          const auto it = dirichlet.find(face->boundary_id());
          if (it == dirichlet.end())
            continue;
          const int k = std::distance(
            ids.begin(), std::find(ids.begin(), ids.end(), it->first));
          face->get_dof_indices(face_dofs);
          for (unsigned int i = 0; i < face_dofs.size(); ++i)
          {
            const unsigned int c = fe.face_system_to_component_index(i).first;
            int               &s = support[face_dofs[i]];
            if (it->second.mask[c] && (s < 0 || k < s))
              s = k;
          }
        }
      }
      return support;
    }

    /** AffineConstraints::condense() of the entries @p v stores (all of a
     * whole vector; the owned and ghost entries of a distributed one),
     * with the same operations in the same order but no exchange: the
     * entries are this process's own sums, and a hanging dof's masters
     * are on its cell. They may then be read (set_ghost_state()). */
    void
    condense_stored(const AffineConstraints<double> &constraints, BodyVector &v)
    {
      const auto &layout = *v.get_partitioner();
      const auto  stored = [&](const types::global_dof_index i)
      { return layout.in_local_range(i) || layout.is_ghost_entry(i); };
      for (const auto &line : constraints.get_lines())
        if (stored(line.index))
        {
          const double old_value = v(line.index);
          for (const auto &[column, weight] : line.entries)
            if (stored(column))
              v(column) += old_value * weight;
        }
      for (const auto &line : constraints.get_lines())
        if (stored(line.index))
          v(line.index) = 0.;
      v.set_ghost_state(true);
    }

    /** The sum of @p r over the dofs of each support, per direction; the
     * last entry is the sum over all dofs. The dofs are those of this
     * process's cells (with @p owned_only: the dofs it owns), summed over
     * the processes of the mesh. */
    template <int dim>
    std::vector<Tensor<1, dim>>
    sum_by_support(const ElasticBody<dim> &body,
                   const std::vector<int> &support,
                   const unsigned int      n_supports,
                   const BodyVector       &r,
                   const bool              owned_only)
    {
      const IndexSet &owned = body.get_dof_handler().locally_owned_dofs();
      // Component of each dof: the dofs of a cell name them.
      const auto                          &fe = body.get_fe();
      std::vector<Tensor<1, dim>>          sums(n_supports + 1);
      std::vector<bool>                    counted(body.n_dofs(), false);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          if (counted[dofs[i]] || (owned_only && !owned.is_element(dofs[i])))
            continue;
          counted[dofs[i]]     = true;
          const unsigned int c = fe.system_to_component_index(i).first;
          sums[n_supports][c] += r(dofs[i]);
          if (support[dofs[i]] >= 0)
            sums[support[dofs[i]]][c] += r(dofs[i]);
        }
      }
      for (auto &f : sums)
        f = Utilities::MPI::sum(f, body.get_triangulation().get_communicator());
      return sums;
    }

    /** int u dS / int dS over the faces of boundary id @p id (this
     * process's cells, summed over the mesh's processes). */
    template <int dim>
    Tensor<1, dim>
    mean_displacement(const ElasticBody<dim>  &body,
                      const BodyVector        &u,
                      const types::boundary_id id)
    {
      FEFaceValues<dim>                fe_face(body.get_mapping(),
                                body.get_fe(),
                                body.get_face_quadrature(),
                                update_values | update_quadrature_points |
                                  update_JxW_values);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<1, dim>>      values(fe_face.n_quadrature_points);
      Tensor<1, dim>                   integral;
      double                           area = 0;
      for (const auto &cell : body.get_dof_handler().active_cell_iterators())
        if (body.computes(cell))
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
            {
              fe_face.reinit(cell, f);
              fe_face[displacement].get_function_values(u, values);
              for (const unsigned int q : fe_face.quadrature_point_indices())
              {
                const double w =
                  fe_face.JxW(q) * section_measure(body.get_geometry(),
                                                   fe_face.quadrature_point(q));
                integral += w * values[q];
                area += w;
              }
            }
      // Each cell on one process (BodyMesh::computes()), added over them.
      for (unsigned int d = 0; d < dim; ++d)
        integral[d] = body.get_mesh().sum(integral[d]);
      area = body.get_mesh().sum(area);
      return area > 0 ? integral / area : integral;
    }
  } // namespace

  template <int dim>
  ReactionForces<dim>::ReactionForces(const ElasticBody<dim> &body,
                                      const BodyVector       &u,
                                      const BodyVector       &contact_load)
  {
    std::vector<types::boundary_id> ids;
    for (const auto &[id, d] : body.get_boundary_conditions().dirichlet)
      ids.push_back(id);
    const auto support = support_of_dofs(body, ids);

    // The residual of this process's cells, condensed onto the conforming
    // test functions, summed per support over the processes.
    BodyVector r, load;
    body.unconstrained_residual(u, r, load);
    condense_stored(body.get_hanging_node_constraints(), r);
    const auto cells = sum_by_support(body, support, ids.size(), r, false);

    // The contact load is the same on every process: each counts the dofs
    // it owns.
    std::vector<Tensor<1, dim>> by_contact(ids.size() + 1);
    if (contact_load.size() > 0)
    {
      BodyVector c;
      copy_stored(contact_load, c);
      condense_stored(body.get_hanging_node_constraints(), c);
      by_contact = sum_by_support(body, support, ids.size(), c, true);
    }

    // The loads alone: l_a(phi_i) sums to l_a(e_k) (the shape functions
    // are a partition of unity); exactly 0 without loads, where the sum of
    // r, -l_a(e_k) + a_a(u, e_k), would leave round-off.
    applied =
      sum_by_support(body, support, ids.size(), load, false)[ids.size()];
    contact = by_contact[ids.size()];
    for (unsigned int k = 0; k < ids.size(); ++k)
    {
      Support s;
      s.id           = ids[k];
      s.force        = cells[k] - by_contact[k];
      s.displacement = mean_displacement(body, u, ids[k]);
      for (unsigned int c = 0; c < dim; ++c)
        s.prescribed[c] =
          body.get_boundary_conditions().dirichlet.at(ids[k]).mask[c];
      support_forces.push_back(s);
    }
  }

  template <int dim>
  Tensor<1, dim>
  ReactionForces<dim>::imbalance() const
  {
    Tensor<1, dim> sum = applied + contact;
    for (const auto &s : support_forces)
      sum += s.force;
    return sum;
  }

  template <int dim>
  double
  ReactionForces<dim>::relative_imbalance(const bool   axial_only,
                                          const double floor) const
  {
    const auto size = [axial_only](Tensor<1, dim> f)
    {
      if (axial_only)
        f[0] = 0;
      return f.norm();
    };
    double largest = std::max({floor, size(applied), size(contact)});
    for (const auto &support : support_forces)
      largest = std::max(largest, size(support.force));
    return (largest > 0) ? size(imbalance()) / largest : 0.;
  }

  template <int dim>
  double
  ReactionForces<dim>::force_scale(const ElasticBody<dim> &body,
                                   const BodyVector       &u)
  {
    double largest = 0;
    for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
      largest = std::max(largest, std::abs(u.local_element(i)));
    largest     = Utilities::MPI::max(largest, MPI_COMM_WORLD);
    double ring = 1;
    if (body.get_geometry() == Geometry::axisymmetric)
    {
      Tensor<1, dim> radial;
      radial[0] = 1;
      ring      = 2 * M_PI * body.get_mesh().extent_along(radial).second;
    }
    return body.get_elastic_constants().youngs_modulus * largest * ring;
  }

  template class ReactionForces<2>;
} // namespace ddcontact
