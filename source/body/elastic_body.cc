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

#include <ddcontact/body/boundary_data_checks.h>
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/refinement_transfer.h>
#include <ddcontact/tasks.h>

#include <iomanip>
#include <sstream>

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
  ElasticBody<dim>::ElasticBody(const BodyParameters &parameters,
                                const Constants      &constants,
                                const MeshKind        mesh_kind)
    : parameters(parameters)
    , material(parameters.material)
    , boundary_conditions(make_boundary_conditions(parameters, constants))
    , mesh(this->parameters, mesh_kind)
  {
    static_assert(dim == 2, "ddcontact bodies are two-dimensional");
    const unsigned int p = parameters.degree;
    if (is_simplex())
    {
      fe = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(p), dim);
      cell_quadrature = std::make_unique<QGaussSimplex<dim>>(p + 1);
    }
    else
    {
      fe              = std::make_unique<FESystem<dim>>(FE_Q<dim>(p), dim);
      cell_quadrature = std::make_unique<QGauss<dim>>(p + 1);
      if (parameters.volumetric_integration == VolumetricIntegration::reduced)
        volumetric_quadrature = std::make_unique<QGauss<dim>>(p);
    }
    face_quadrature = std::make_unique<QGauss<dim - 1>>(p + 1);
  }

  template <int dim>
  void
  ElasticBody<dim>::make_mesh(const std::string &work_directory)
  {
    mesh.make(boundary_conditions, work_directory);
  }

  template <int dim>
  void
  ElasticBody<dim>::set_process_group(const std::vector<unsigned int> &ranks,
                                      const MPI_Comm                   group)
  {
    const bool changed = mesh.set_process_group(ranks, group);
    if (changed && (mesh.is_distributed() || mesh.is_shared()))
      setup_system();
    mesh.release_previous_mesh();
  }

  namespace
  {
    /** One constraint u_i = sum_k w_k u_{m_k} + b_i, as sent between
     * processes. */
    struct ConstraintLine
    {
      types::global_dof_index              index;
      std::vector<types::global_dof_index> masters;
      std::vector<double>                  weights;
      double                               inhomogeneity;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &index &masters &weights &inhomogeneity;
      }
    };
  } // namespace

  template <int dim>
  void
  ElasticBody<dim>::share_constraints(
    AffineConstraints<double>         &to_complete,
    const Utilities::MPI::Partitioner *layout) const
  {
    // The distributed DD computes the constrained entries it stores from
    // their masters (the relaxation (21), the transfer after refinement,
    // every solve), which must give the same numbers on every process:
    // a line computed from another cell can differ in the last bit, and
    // the replicated iteration then drifts apart between the processes.
    // These are the Dirichlet dofs of (5) and the hanging nodes.
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    IndexSet        sent(dof_handler.n_dofs());
    if (layout != nullptr)
      for (const auto &[begin, end] : layout->import_indices())
        for (unsigned int i = begin; i < end; ++i)
          sent.add_index(owned.nth_index_in_set(i));
    std::vector<ConstraintLine> own_lines, sent_lines;
    for (const auto &line : to_complete.get_lines())
      if (owned.is_element(line.index))
      {
        ConstraintLine l{line.index, {}, {}, line.inhomogeneity};
        for (const auto &[master, weight] : line.entries)
        {
          l.masters.push_back(master);
          l.weights.push_back(weight);
        }
        if (layout == nullptr || sent.is_element(line.index))
          sent_lines.push_back(l);
        own_lines.push_back(std::move(l));
      }
    const auto add = [&](const ConstraintLine &l)
    {
      to_complete.add_line(l.index);
      for (unsigned int k = 0; k < l.masters.size(); ++k)
        to_complete.add_entry(l.index, l.masters[k], l.weights[k]);
      to_complete.set_inhomogeneity(l.index, l.inhomogeneity);
    };
    if (layout == nullptr)
      // (reinit() drops the restriction to the locally relevant dofs.)
      to_complete.reinit();
    else
    {
      IndexSet stored = owned;
      stored.add_indices(layout->ghost_indices());
      to_complete.reinit(stored);
      for (const auto &l : own_lines)
        add(l);
    }
    for (const auto &from_process : Utilities::MPI::all_gather(
           get_triangulation().get_communicator(), sent_lines))
      for (const auto &l : from_process)
        if (layout == nullptr || layout->is_ghost_entry(l.index))
          add(l);
    to_complete.close();
  }

  template <int dim>
  void
  ElasticBody<dim>::setup_system()
  {
    dof_handler.reinit(get_triangulation());
    dof_handler.distribute_dofs(*fe);

    IndexSet relevant;
    if (mesh.is_distributed())
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    // Distributed vectors stay distributed, with the locally relevant dofs
    // as ghosts until distribute_vectors() adds the new traces.
    if (distributed_vectors)
      partitioner = std::make_shared<Utilities::MPI::Partitioner>(
        dof_handler.locally_owned_dofs(),
        relevant,
        get_triangulation().get_communicator());
    else
      partitioner =
        std::make_shared<Utilities::MPI::Partitioner>(dof_handler.n_dofs());
    // A p4est body on a group smaller than its mesh's processes: the
    // group's own ghost exchange, for its solves (import_group_ghosts()).
    group_layout.reset();
    if (is_solved_by_part_of_mesh() &&
        mesh.group_communicator() != MPI_COMM_NULL)
      group_layout = std::make_shared<Utilities::MPI::Partitioner>(
        dof_handler.locally_owned_dofs(), relevant, mesh.group_communicator());
    make_constraints();
    reinit_vector(solution);
    if (solved_here)
      setup_matrix();
    is_factorized = false;
  }

  template <int dim>
  void
  ElasticBody<dim>::make_constraints()
  {
    // Hanging nodes first, then the Dirichlet data (5); merged in one
    // object so that a Dirichlet node that is also hanging is handled. A
    // distributed mesh computes the constraints of its locally relevant
    // dofs (below, they are completed).
    constraints.clear();
    hanging_node_constraints.clear();
    if (mesh.is_distributed())
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      constraints.reinit(relevant);
      hanging_node_constraints.reinit(relevant);
    }
    const Utilities::MPI::Partitioner *stored =
      distributed_vectors ? partitioner.get() : nullptr;
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();
    if (mesh.is_distributed())
      share_constraints(hanging_node_constraints, stored);
    check_dirichlet_values(*this);
    for (const auto &[id, d] : boundary_conditions.dirichlet)
      VectorTools::interpolate_boundary_values(
        get_mapping(), dof_handler, id, *d.displacement, constraints, d.mask);
    setup_rigid_modes();
    constraints.close();
    if (mesh.is_distributed())
      share_constraints(constraints, stored);
  }

  template <int dim>
  void
  ElasticBody<dim>::set_load_time(const double t)
  {
    const auto &bc = boundary_conditions;
    for (const auto &[id, d] : bc.dirichlet)
      d.displacement->set_time(t);
    for (const auto &[id, traction] : bc.neumann)
      traction->set_time(t);
    if (bc.body_force)
      bc.body_force->set_time(t);
    // The Dirichlet values (5) of the new t; the same lines, so the
    // contact points' coefficients stay valid.
    make_constraints();
    // The matrix does not change with t (the same constraint lines; only
    // their inhomogeneities and the loads do): the factorization stays.
    if (solved_here)
    {
      assemble_system();
      if (!is_factorized)
        factorize();
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::setup_rigid_modes()
  {
    AffineConstraints<double> closed;
    closed.copy_from(constraints);
    closed.close();
    rigid_modes.reinit(
      dof_handler, get_mapping(), boundary_conditions, closed, partitioner);
    // Every process that stores a fixed dof holds its line.
    for (const auto i : rigid_modes.fixing_dofs())
      if (constraints.can_store_line(i))
        constraints.add_line(i);
  }

  template <int dim>
  void
  ElasticBody<dim>::setup_matrix()
  {
    // The old factorization refers to the old matrix (and MUMPS frees its
    // factors collectively over the group): release it first.
    linear_solver.reset();
    linear_solver = BodyLinearSolver<dim>::create(
      parameters, mesh.group_communicator(), mesh.process_group().size());
    linear_solver->reinit(dof_handler, constraints);
  }

  template <int dim>
  void
  ElasticBody<dim>::assemble_system()
  {
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
      for (const double v : copy.vectors[0])
        non_finite_load = non_finite_load || !std::isfinite(v);
      if (non_finite_load)
        return;
      // The load on the dofs as assembled, before the constraints drop the
      // fixed components: its work on the rigid modes.
      if (is_floating())
        for (unsigned int i = 0; i < copy.local_dof_indices[0].size(); ++i)
          data_load(copy.local_dof_indices[0][i]) += copy.vectors[0](i);
      linear_solver->add(constraints,
                         copy.matrices[0],
                         copy.vectors[0],
                         copy.local_dof_indices[0]);
    };
    assemble_cells(copier);

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
  void
  ElasticBody<dim>::unconstrained_residual(const BodyVector &u,
                                           BodyVector       &r,
                                           BodyVector       &load) const
  {
    AssertDimension(u.size(), dof_handler.n_dofs());
    reinit_vector(r);
    reinit_vector(load);
    // r_K = A_K u_K - f_K of every cell, added without constraints: the
    // same cell matrices and loads the solver was given.
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
    const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &copier)
    const
  {
    using Iterator = typename DoFHandler<dim>::active_cell_iterator;
    const FEValuesExtractors::Vector displacement(0);
    const double                     lambda = material.lambda();
    const double                     mu     = material.mu();
    // With reduced volumetric integration the lambda term is added below,
    // on its own quadrature.
    const double lambda_full = (volumetric_quadrature != nullptr) ? 0. : lambda;

    const UpdateFlags cell_flags = update_values | update_gradients |
                                   update_quadrature_points | update_JxW_values;
    // a_a(u, v) of (11) and the body-force part of l_a(v).
    const auto cell_worker = [&](const Iterator                &cell,
                                 MeshWorker::ScratchData<dim>  &scratch,
                                 MeshWorker::CopyData<1, 1, 1> &copy)
    {
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

      std::vector<SymmetricTensor<2, dim>> eps(dofs_per_cell);
      std::vector<double>                  div(dofs_per_cell);
      for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          eps[i] = fe_values[displacement].symmetric_gradient(i, q);
          div[i] = trace(eps[i]);
        }
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            cell_matrix(i, j) +=
              (lambda_full * div[i] * div[j] + 2. * mu * (eps[i] * eps[j])) *
              JxW;
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
      if (it == boundary_conditions.neumann.end())
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
          cell_rhs(i) +=
            fe_face.shape_value(i, q) * traction[q](c) * fe_face.JxW(q);
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
      assemble_reduced_volumetric_term(copier);
  }

  template <int dim>
  void
  ElasticBody<dim>::assemble_reduced_volumetric_term(
    const std::function<void(const MeshWorker::CopyData<1, 1, 1> &)> &copier)
    const
  {
    using Iterator = typename DoFHandler<dim>::active_cell_iterator;
    const FEValuesExtractors::Vector displacement(0);
    const double                     lambda = material.lambda();
    const UpdateFlags flags = update_gradients | update_JxW_values;

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
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          div[i] = fe_values[displacement].divergence(i, q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            copy.matrices[0](i, j) +=
              lambda * div[i] * div[j] * fe_values.JxW(q);
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

  template <int dim>
  void
  ElasticBody<dim>::factorize()
  {
    linear_solver->factorize(dof_handler);
    is_factorized = true;
  }

  template <int dim>
  void
  ElasticBody<dim>::setup_and_factorize()
  {
    setup_system();
    if (solved_here)
    {
      assemble_system();
      factorize();
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::refine_and_transfer()
  {
    get_triangulation().prepare_coarsening_and_refinement();
    mesh.check_refinement_size("the refinement");
    if (mesh.is_distributed())
    {
      // p4est refines the owned cells, repartitions, and moves the
      // transferred values with the cells. The solution holds its owned
      // dofs and the ghosts the interpolation needs (a p4est body's
      // vectors are always distributed, Simulation::distribute_body_vectors());
      // the new one is distributed likewise.
      AssertThrow(distributed_vectors, ExcInternalError());
      parallel::distributed::SolutionTransfer<dim, BodyVector> transfer(
        dof_handler);
      transfer.prepare_for_coarsening_and_refinement(solution);
      get_triangulation().execute_coarsening_and_refinement();
      setup_system();
      transfer.interpolate(solution);
      solution.update_ghost_values();
      distribute_constraints(solution, false);
      if (solved_here)
      {
        assemble_system();
        factorize();
      }
      return;
    }
    else if (mesh.is_simplex())
    {
      // SolutionTransfer's Debug check rejects the round-off of the
      // numerical FE_SimplexP prolongation (see RefinementTransfer).
      RefinementTransfer transfer(dof_handler);
      transfer.prepare(solution);
      get_triangulation().execute_coarsening_and_refinement();
      setup_system();
      transfer.interpolate(solution);
    }
    else
    {
      SolutionTransfer<dim, BodyVector> transfer(dof_handler);
      const BodyVector                  old_solution = solution;
      transfer.prepare_for_coarsening_and_refinement(old_solution);
      get_triangulation().execute_coarsening_and_refinement();

      setup_system();
      transfer.interpolate(old_solution, solution);
    }
    // New hanging nodes and the Dirichlet data (5) on new boundary vertices.
    distribute_constraints(solution);
    if (solved_here)
    {
      assemble_system();
      factorize();
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::set_solved_here(const bool here)
  {
    solved_here = here;
    if (solved_here && !is_factorized)
    {
      setup_matrix();
      assemble_system();
      factorize();
    }
    else if (!solved_here && is_factorized)
    {
      linear_solver.reset();
      is_factorized = false;
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::distribute_vectors(
    const std::vector<types::global_dof_index> &traces)
  {
    AssertThrow(mesh.is_distributed(), ExcInternalError());
    IndexSet ghosts;
    DoFTools::extract_locally_relevant_dofs(dof_handler, ghosts);
    ghosts.add_indices(traces.begin(), traces.end());
    const auto layout = std::make_shared<Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(),
      ghosts,
      get_triangulation().get_communicator());
    BodyVector distributed(layout);
    // The solution is still whole (or of the old layout) here.
    for (const auto i : dof_handler.locally_owned_dofs())
      distributed(i) = solution(i);
    distributed.update_ghost_values();
    solution.swap(distributed);
    partitioner         = layout;
    distributed_vectors = true;
    rigid_modes.set_layout(layout);
    // The lines of the entries now stored, the traces among them.
    share_constraints(constraints, layout.get());
    share_constraints(hanging_node_constraints, layout.get());
  }

  template <int dim>
  void
  ElasticBody<dim>::import_group_ghosts(BodyVector &u) const
  {
    if (!group_layout)
    {
      u.update_ghost_values();
      return;
    }
    // Over the group alone: the other processes do not take part in its
    // solves. The owned rows are the same in both layouts.
    BodyVector         g(group_layout);
    const unsigned int n_owned = group_layout->locally_owned_size();
    AssertDimension(u.locally_owned_size(), n_owned);
    for (unsigned int l = 0; l < n_owned; ++l)
      g.local_element(l) = u.local_element(l);
    g.update_ghost_values();
    for (unsigned int j = 0; j < group_layout->n_ghost_indices(); ++j)
      u(group_layout->local_to_global(n_owned + j)) =
        g.local_element(n_owned + j);
  }

  template <int dim>
  bool
  ElasticBody<dim>::is_solved_by_part_of_mesh() const
  {
    return mesh.is_distributed() && mesh.process_group().size() <
                                      Utilities::MPI::n_mpi_processes(
                                        get_triangulation().get_communicator());
  }

  template <int dim>
  void
  ElasticBody<dim>::distribute_constraints(BodyVector &u,
                                           const bool  homogeneous) const
  {
    // As AffineConstraints::distribute(), in the same order of operations
    // (which on a whole vector gives the same numbers), but on the ghosts
    // too and without its exchanges. The constraints are closed, so every
    // entry refers to an unconstrained dof.
    const auto &layout = *u.get_partitioner();
    for (const auto &line : constraints.get_lines())
      if (layout.in_local_range(line.index) ||
          layout.is_ghost_entry(line.index))
      {
        double value = homogeneous ? 0. : line.inhomogeneity;
        for (const auto &[column, weight] : line.entries)
          value += u(column) * weight;
        u(line.index) = value;
      }
  }

  template <int dim>
  void
  ElasticBody<dim>::solve(const BodyVector &load, BodyVector &u) const
  {
    Assert(is_factorized, ExcMessage("factorize() must be called first"));
    if (load.size() > 0)
      AssertDimension(load.size(), dof_handler.n_dofs());
    if (distributed_vectors && u.get_partitioner() != partitioner)
      reinit_vector(u);
    linear_solver->solve(load, u);
    if (distributed_vectors)
      import_group_ghosts(u);
    distribute_constraints(u, false);
    for (const double v : u)
      if (!std::isfinite(v))
        throw InputError(parameters.section() +
                         ": the body problem gave a non-finite displacement; "
                         "check the Dirichlet conditions and the material");
  }

  template <int dim>
  void
  ElasticBody<dim>::solve_homogeneous(const BodyVector &load,
                                      BodyVector       &u) const
  {
    Assert(is_factorized, ExcMessage("factorize() must be called first"));
    if (distributed_vectors && u.get_partitioner() != partitioner)
      reinit_vector(u);
    linear_solver->solve(load, u, false);
    if (distributed_vectors)
      import_group_ghosts(u);
    distribute_constraints(u, true);
  }

  template <int dim>
  void
  ElasticBody<dim>::solve()
  {
    solve(BodyVector(), solution);
  }

  template class ElasticBody<2>;
} // namespace ddcontact
