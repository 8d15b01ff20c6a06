#include <ddcontact/body/boundary_data_checks.h>
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/refinement_transfer.h>
#include <ddcontact/tasks.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/meshworker/copy_data.h>
#include <deal.II/meshworker/mesh_loop.h>
#include <deal.II/meshworker/scratch_data.h>
#include <deal.II/numerics/solution_transfer.h>
#include <deal.II/numerics/vector_tools.h>
#include <iomanip>
#include <sstream>

// ElasticBody's assembly of (11)-(12): the stiffness matrix and load, the
// residual of a displacement, and the reduced volumetric term.
namespace ddcontact
{
  namespace
  {
    /**
     * The cell values of @p scratch on @p cell, computed alike for every
     * cell. deal.II's FEValues::reinit() copies the Jacobians and shape
     * gradients of the previous cell when the new one is a translation of
     * it (CellSimilarity), but only when deal.II runs on one thread: the
     * round-off of that shortcut made the stiffness matrix, and through it
     * the DD's active sets and iteration counts, differ between Threads = 1
     * and 2 (prm/three_bodies.prm: 143 against 71 iterations). On one
     * thread every cell therefore gets a fresh FEValues (@p fresh keeps it),
     * as every cell effectively does on several threads.
     */
    template <int dim, class Iterator>
    const FEValues<dim> &
    reinit_without_similarity(MeshWorker::ScratchData<dim>   &scratch,
                              const Iterator                 &cell,
                              const Mapping<dim>             &mapping,
                              const FiniteElement<dim>       &fe,
                              const Quadrature<dim>          &quadrature,
                              const UpdateFlags               flags,
                              std::unique_ptr<FEValues<dim>> &fresh)
    {
      if (MultithreadInfo::n_threads() > 1)
        return scratch.reinit(cell);
      fresh = std::make_unique<FEValues<dim>>(mapping, fe, quadrature, flags);
      fresh->reinit(cell);
      return *fresh;
    }
  } // namespace

  template <int dim>
  void
  ElasticBody<dim>::assemble_system()
  {
    assemble(false);
  }

  template <int dim>
  void
  ElasticBody<dim>::assemble_load()
  {
    // The matrix stays (the same constraint lines): only the cells with a
    // load or an inhomogeneous dof are visited (issue 60: Steps = auto spent
    // 7 % of its time assembling the same matrix again).
    assemble(true);
  }

  template <int dim>
  void
  ElasticBody<dim>::assemble(const bool load_only)
  {
    if (load_only)
      linear_solver->zero_load();
    else
      linear_solver->zero();
    // Member-only, like the whole assembly: with a group smaller than the
    // mesh's processes the work is summed over the group (group_layout).
    BodyVector data_load;
    if (is_floating())
    {
      if (distributed_vectors && group_layout)
        data_load.reinit(group_layout);
      else
        reinit_vector(data_load);
    }
    // A load expression that is not finite somewhere (sqrt(x) at x < 0) is
    // found here, in the serial part (a worker thread must not throw), and
    // named after the loop.
    bool       non_finite_load = false;
    const auto copier          = [&](const MeshWorker::CopyData<1, 1, 1> &copy)
    {
      // (load_only: a cell without load arrives without dofs.)
      if (copy.local_dof_indices[0].empty())
        return;
      for (const double v : copy.vectors[0])
        non_finite_load = non_finite_load || !std::isfinite(v);
      if (non_finite_load)
        return;
      // The load on the dofs as assembled, before the constraints drop the
      // fixed components: its work on the rigid modes.
      if (is_floating())
        for (unsigned int i = 0; i < copy.local_dof_indices[0].size(); ++i)
          data_load(copy.local_dof_indices[0][i]) += copy.vectors[0](i);
      if (load_only)
        linear_solver->add_load(constraints,
                                copy.matrices[0],
                                copy.vectors[0],
                                copy.local_dof_indices[0]);
      else
        linear_solver->add(constraints,
                           copy.matrices[0],
                           copy.vectors[0],
                           copy.local_dof_indices[0]);
    };
    assemble_cells(copier, load_only);

    if (non_finite_load)
      throw_non_finite_load(*this);
    mode_loads.clear();
    // Distributed vectors: the loads of the ghosts go to their owners,
    // and the owned parts of the work are added in rank order.
    if (distributed_vectors && is_floating())
      data_load.compress(VectorOperation::add);
    for (unsigned int k = 0; k < rigid_modes.size(); ++k)
      mode_loads.push_back(distributed_vectors
                             ? ordered_dot(data_load, rigid_modes.mode(k))
                             : rigid_modes.mode(k) * data_load);
    // Each process of a group assembled its own cells into whole vectors.
    if (is_solved_distributed() && !distributed_vectors && !mode_loads.empty())
      Utilities::MPI::sum(ArrayView<const double>(mode_loads),
                          mesh.group_communicator(),
                          ArrayView<double>(mode_loads));
    linear_solver->compress();
  }

  template <int dim>
  bool
  ElasticBody<dim>::loaded_cell(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    if (boundary_conditions.body_force)
      return true;
    if (cell->at_boundary())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() &&
            boundary_conditions.neumann.count(face->boundary_id()) > 0)
          return true;
    std::vector<types::global_dof_index> dofs(fe->n_dofs_per_cell());
    cell->get_dof_indices(dofs);
    return std::any_of(dofs.begin(),
                       dofs.end(),
                       [&](const types::global_dof_index i) {
                         return constraints.is_inhomogeneously_constrained(i);
                       });
  }

  template <int dim>
  void
  ElasticBody<dim>::unconstrained_residual(const BodyVector &u,
                                           BodyVector       &r,
                                           BodyVector       &load) const
  {
    AssertDimension(u.size(), dof_handler.n_dofs());
    reinit_vector(r);
    reinit_vector(load);
    // r_K = A_K u_K - f_K of every cell, added without constraints: the
    // same cell matrices and loads the solver was given. A nonlinear law:
    // r = F(u) - l_a, the negated loads minus internal forces of the
    // linearization at u, and the loads of the plain assembly.
    if (!law->is_linear())
    {
      const auto add = [](const MeshWorker::CopyData<1, 1, 1> &copy,
                          const double                         sign,
                          BodyVector                          &to)
      {
        const auto &dofs = copy.local_dof_indices[0];
        for (unsigned int i = 0; i < dofs.size(); ++i)
          to(dofs[i]) += sign * copy.vectors[0](i);
      };
      assemble_cells([&](const auto &copy) { add(copy, -1., r); }, false, &u);
      assemble_cells([&](const auto &copy) { add(copy, 1., load); });
      r.set_ghost_state(true);
      load.set_ghost_state(true);
      return;
    }
    Vector<double> u_cell, r_cell;
    assemble_cells(
      [&](const MeshWorker::CopyData<1, 1, 1> &copy)
      {
        const auto &dofs = copy.local_dof_indices[0];
        // (mesh_loop hands over an empty copy for another process's cell.)
        if (dofs.empty())
          return;
        u_cell.reinit(dofs.size());
        r_cell.reinit(dofs.size());
        for (unsigned int i = 0; i < dofs.size(); ++i)
          u_cell(i) = u(dofs[i]);
        copy.matrices[0].vmult(r_cell, u_cell);
        r_cell -= copy.vectors[0];
        for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          r(dofs[i]) += r_cell(i);
          load(dofs[i]) += copy.vectors[0](i);
        }
      });
    // The entries are this process's sums, to be read as they are (no
    // ghost exchange; see BodyVector).
    r.set_ghost_state(true);
    load.set_ghost_state(true);
  }

  template <int dim>
  void
  ElasticBody<dim>::assemble_cells(
    const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &copier,
    const bool                                                        load_only,
    const BodyVector                 *linearization,
    std::vector<std::vector<double>> *new_states) const
  {
    using Iterator = typename DoFHandler<dim>::active_cell_iterator;
    const SectionKinematics kinematics = get_kinematics();
    // a_a (11) with the law's tangent C: int eps(v) : C : eps(u). A linear
    // law's is constant; a nonlinear law's is its linearization at a
    // displacement (solve_nonlinear()).
    // (Without a linearization a nonlinear law's matrices are those of its
    // elastic constants: only the loads count then.)
    Assert(linearization == nullptr || volumetric_quadrature == nullptr,
           ExcNotImplemented());
    const MaterialTangent tangent = law->is_linear()
                                      ? law->linear_tangent()
                                      : law->elastic_constants().tangent();
    // With reduced volumetric integration the volumetric part of C is
    // added below, on its own quadrature.
    const bool reduced = volumetric_quadrature != nullptr;

    const UpdateFlags cell_flags = update_values | update_gradients |
                                   update_quadrature_points | update_JxW_values;
    // a_a(u, v) of (11) and the body-force part of l_a(v).
    const auto cell_worker = [&](const Iterator                &cell,
                                 MeshWorker::ScratchData<dim>  &scratch,
                                 MeshWorker::CopyData<1, 1, 1> &copy)
    {
      if (load_only && !loaded_cell(cell))
      {
        copy.local_dof_indices[0].clear();
        return;
      }
      std::unique_ptr<FEValues<dim>> fresh;
      const auto                    &fe_values = reinit_without_similarity(
        scratch, cell, get_mapping(), *fe, *cell_quadrature, cell_flags, fresh);
      const unsigned int dofs_per_cell = fe_values.dofs_per_cell;
      copy.reinit(dofs_per_cell);
      cell->get_dof_indices(copy.local_dof_indices[0]);
      auto &cell_matrix = copy.matrices[0];
      auto &cell_rhs    = copy.vectors[0];

      std::vector<Vector<double>> force(fe_values.n_quadrature_points,
                                        Vector<double>(dim));
      if (boundary_conditions.body_force)
        boundary_conditions.body_force->vector_value_list(
          fe_values.get_quadrature_points(), force);

      // A nonlinear law at the points, linearized at the displacement:
      // the stress and tangent of its strain, from the points' states at
      // the start of the step.
      std::vector<SymmetricTensor<2, 3>> stress;
      std::vector<MaterialTangent>       tangents;
      if (linearization != nullptr)
      {
        std::vector<SymmetricTensor<2, 3>> strain;
        kinematics.field_strains(fe_values, *linearization, strain);
        std::vector<double> old_state;
        if (!material_state.empty())
          material_state.get_committed(
            typename Triangulation<dim>::cell_iterator(cell), old_state);
        std::vector<double> new_state(old_state.size());
        stress.resize(strain.size());
        law->evaluate(make_array_view(strain),
                      make_array_view(old_state),
                      make_array_view(stress),
                      &tangents,
                      make_array_view(new_state));
        if (new_states != nullptr)
          (*new_states)[cell->active_cell_index()] = std::move(new_state);
      }

      // The strains of the shape functions (the hoop strain u_r / r in
      // eps_33 of an axisymmetric body, 0 in plane strain).
      std::vector<SymmetricTensor<2, 3>> eps(dofs_per_cell);
      std::vector<double>                tr(dofs_per_cell);
      // C : eps(phi_j) of a general tangent, once per j.
      std::vector<SymmetricTensor<2, 3>> C_eps;
      for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const Point<dim> &x = fe_values.quadrature_point(q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          eps[i] = kinematics.shape_strain(fe_values, i, q);
          tr[i]  = trace(eps[i]);
        }
        const double           JxW = fe_values.JxW(q) * kinematics.measure(x);
        const MaterialTangent &C   = linearization ? tangents[q] : tangent;
        if (!C.is_isotropic())
        {
          C_eps.resize(dofs_per_cell);
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            C_eps[j] = C.apply(eps[j]);
        }
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            cell_matrix(i, j) +=
              (reduced            ? C.shear_form(eps[i], eps[j])
               : C.is_isotropic() ? C.form(eps[i], tr[i], eps[j], tr[j])
                                  : eps[i] * C_eps[j]) *
              JxW;
          // l_a(phi_i) - F(u)(phi_i): the internal force sigma : eps(phi_i).
          if (linearization)
            cell_rhs(i) -= (stress[q] * eps[i]) * JxW;
          if (boundary_conditions.body_force)
          {
            const unsigned int c = fe->system_to_component_index(i).first;
            cell_rhs(i) += fe_values.shape_value(i, q) * force[q](c) * JxW;
          }
        }
      }
    };

    // The traction part of l_a(v), (12), on Gamma_p.
    const auto boundary_worker = [&](const Iterator                &cell,
                                     const unsigned int             face_no,
                                     MeshWorker::ScratchData<dim>  &scratch,
                                     MeshWorker::CopyData<1, 1, 1> &copy)
    {
      const auto it =
        boundary_conditions.neumann.find(cell->face(face_no)->boundary_id());
      if (it == boundary_conditions.neumann.end() ||
          copy.local_dof_indices[0].empty())
        return;
      const auto                 &fe_face = scratch.reinit(cell, face_no);
      std::vector<Vector<double>> traction(fe_face.n_quadrature_points,
                                           Vector<double>(dim));
      it->second->vector_value_list(fe_face.get_quadrature_points(), traction);
      // On an id that is also Dirichlet (a roller with a load) the traction
      // loads only the free components; the prescribed ones carry the
      // unknown reaction.
      const auto dirichlet =
        boundary_conditions.dirichlet.find(cell->face(face_no)->boundary_id());
      auto &cell_rhs = copy.vectors[0];
      for (const unsigned int q : fe_face.quadrature_point_indices())
        for (unsigned int i = 0; i < fe_face.dofs_per_cell; ++i)
        {
          const unsigned int c = fe->system_to_component_index(i).first;
          if (dirichlet != boundary_conditions.dirichlet.end() &&
              dirichlet->second.mask[c])
            continue;
          cell_rhs(i) += fe_face.shape_value(i, q) * traction[q](c) *
                         fe_face.JxW(q) *
                         kinematics.measure(fe_face.quadrature_point(q));
        }
    };

    // On a partitioned mesh mesh_loop visits only this process's cells.
    MeshWorker::ScratchData<dim> scratch(
      get_mapping(),
      *fe,
      *cell_quadrature,
      cell_flags,
      *face_quadrature,
      update_values | update_quadrature_points | update_JxW_values);
    MeshWorker::CopyData<1, 1, 1> copy;
    MeshWorker::mesh_loop(dof_handler.active_cell_iterators(),
                          cell_worker,
                          copier,
                          scratch,
                          copy,
                          MeshWorker::assemble_own_cells |
                            MeshWorker::assemble_boundary_faces,
                          boundary_worker);
    if ((volumetric_quadrature != nullptr))
      assemble_reduced_volumetric_term(copier, load_only);
  }

  template <int dim>
  void
  ElasticBody<dim>::assemble_reduced_volumetric_term(
    const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &copier,
    const bool load_only) const
  {
    using Iterator = typename DoFHandler<dim>::active_cell_iterator;
    const SectionKinematics kinematics = get_kinematics();
    // The volumetric modulus lambda of the law's isotropic tangent
    // (MaterialLawInfo::reduced_integration).
    const double      lambda = law->linear_tangent().volumetric_modulus();
    const UpdateFlags flags  = update_values | update_gradients |
                              update_quadrature_points | update_JxW_values;

    // Selective reduced integration: lambda div u div v on one Gauss point
    // per cell. For nu -> 1/2 (lambda/mu -> infinity) the full rule forces
    // div u = 0 at all four points of a Q1 cell, which only a few fields
    // satisfy (locking); one point leaves one constraint per cell, as many
    // as a pressure constant per cell. The deviatoric-shear part keeps the
    // full rule, so no hourglass mode appears. The copier adds the
    // Dirichlet inhomogeneities of this part to the load vector.
    const auto volumetric_worker = [&](const Iterator                &cell,
                                       MeshWorker::ScratchData<dim>  &scratch,
                                       MeshWorker::CopyData<1, 1, 1> &copy)
    {
      if (load_only && !loaded_cell(cell))
      {
        copy.local_dof_indices[0].clear();
        return;
      }
      std::unique_ptr<FEValues<dim>> fresh;
      const auto        &fe_values     = reinit_without_similarity(scratch,
                                                        cell,
                                                        get_mapping(),
                                                        *fe,
                                                        *volumetric_quadrature,
                                                        flags,
                                                        fresh);
      const unsigned int dofs_per_cell = fe_values.dofs_per_cell;
      copy.reinit(dofs_per_cell);
      cell->get_dof_indices(copy.local_dof_indices[0]);
      std::vector<double> div(dofs_per_cell);
      for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        // tr eps: div u + u_r / r in axisymmetry, the whole volumetric
        // strain.
        const Point<dim> &x = fe_values.quadrature_point(q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          div[i] = trace(kinematics.shape_strain(fe_values, i, q));
        const double JxW = fe_values.JxW(q) * kinematics.measure(x);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            copy.matrices[0](i, j) += lambda * div[i] * div[j] * JxW;
      }
    };
    MeshWorker::ScratchData<dim> volumetric_scratch(
      get_mapping(), *fe, *volumetric_quadrature, flags);
    MeshWorker::CopyData<1, 1, 1> copy;
    MeshWorker::mesh_loop(dof_handler.active_cell_iterators(),
                          volumetric_worker,
                          copier,
                          volumetric_scratch,
                          copy,
                          MeshWorker::assemble_own_cells);
  }

  // The members defined here (ElasticBody<2> itself is instantiated in
  // elastic_body.cc).
  template void
  ElasticBody<2>::assemble_system();
  template void
  ElasticBody<2>::unconstrained_residual(const BodyVector &,
                                         BodyVector &,
                                         BodyVector &) const;
  template void
  ElasticBody<2>::assemble_load();
  template void
  ElasticBody<2>::assemble(bool);
  template bool
  ElasticBody<2>::loaded_cell(
    const typename DoFHandler<2>::active_cell_iterator &) const;
  template void
  ElasticBody<2>::assemble_cells(
    const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &,
    bool,
    const BodyVector *,
    std::vector<std::vector<double>> *) const;
  template void
  ElasticBody<2>::assemble_reduced_volumetric_term(
    const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &,
    bool) const;
} // namespace ddcontact
