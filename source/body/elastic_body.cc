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

#include <ddcontact/body/axis_of_symmetry.h>
#include <ddcontact/body/boundary_data_checks.h>
#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/refinement_transfer.h>
#include <ddcontact/iteration_errors.h>
#include <ddcontact/tasks.h>

#include <iomanip>
#include <limits>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** @p constraints without their inhomogeneities: the constraints of an
     * increment, or of a displacement that carries its Dirichlet values. */
    AffineConstraints<double>
    without_inhomogeneities(const AffineConstraints<double> &constraints)
    {
      AffineConstraints<double> result;
      for (const auto &line : constraints.get_lines())
      {
        result.add_line(line.index);
        result.add_entries(line.index, line.entries);
      }
      result.close();
      return result;
    }
  } // namespace

  template <int dim>
  SectionKinematics
  ElasticBody<dim>::get_kinematics() const
  {
    return SectionKinematics(get_geometry(),
                             get_geometry() == Geometry::axisymmetric
                               ? AxisOfSymmetry::tolerance(get_triangulation())
                               : 0.);
  }

  template <int dim>
  ElasticBody<dim>::ElasticBody(const BodyParameters &parameters,
                                const Constants      &constants,
                                const MeshKind        mesh_kind)
    : parameters(parameters)
    , law(create_material_law(parameters.material_law,
                              parameters.material,
                              parameters.material_law_constants))
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
    if (get_geometry() == Geometry::axisymmetric)
      AxisOfSymmetry::check_meridian_section(mesh.triangulation(), name());
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
    // The law's state on the cells this process computes (new cells get
    // the initial state; refine_and_transfer() moved the others').
    material_state.setup(get_triangulation(),
                         *law,
                         cell_quadrature->size(),
                         [this](const auto &cell)
                         { return cell->is_active() && mesh.computes(cell); });

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
    if (get_geometry() == Geometry::axisymmetric)
      AxisOfSymmetry::constrain_axis(dof_handler, constraints);
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
    // their inhomogeneities and the loads do): the factorization stays,
    // and only the load is assembled again.
    if (solved_here)
    {
      if (is_factorized)
        assemble_load();
      else
      {
        assemble_system();
        factorize();
      }
    }
  }

  template <int dim>
  void
  ElasticBody<dim>::setup_rigid_modes()
  {
    AffineConstraints<double> closed;
    closed.copy_from(constraints);
    closed.close();
    rigid_modes.reinit(dof_handler,
                       get_mapping(),
                       boundary_conditions,
                       closed,
                       partitioner,
                       get_geometry() == Geometry::axisymmetric);
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
      // The law's state does not move with p4est's cells yet
      // (SceneParameters refuses path-dependent laws there).
      Assert(material_state.empty(), ExcNotImplemented());
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
      material_state.prepare_for_refinement();
      get_triangulation().execute_coarsening_and_refinement();
      material_state.transfer_after_refinement();
      setup_system();
      transfer.interpolate(solution);
    }
    else
    {
      SolutionTransfer<dim, BodyVector> transfer(dof_handler);
      const BodyVector                  old_solution = solution;
      transfer.prepare_for_coarsening_and_refinement(old_solution);
      material_state.prepare_for_refinement();
      get_triangulation().execute_coarsening_and_refinement();
      material_state.transfer_after_refinement();
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
    Assert(law->is_linear(),
           ExcMessage("a nonlinear material law: use solve_nonlinear()"));
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
  BodyNewtonReport
  ElasticBody<dim>::solve_nonlinear(const BodyVector &load, BodyVector &u)
  {
    AssertThrow(solved_here && !is_solved_distributed() && !distributed_vectors,
                ExcMessage("a nonlinear material law is solved on one process "
                           "per body (for now)"));
    if (load.size() > 0)
      AssertDimension(load.size(), dof_handler.n_dofs());
    if (u.size() != dof_handler.n_dofs())
      reinit_vector(u);
    // The increments are zero on Dirichlet dofs: the constraints without
    // their inhomogeneities (u carries the Dirichlet values).
    const AffineConstraints<double> increment_constraints =
      without_inhomogeneities(constraints);
    distribute_constraints(u, false);

    // The residual is measured against the load l_a + load, condensed.
    BodyNewtonReport report;
    {
      Vector<double> l(dof_handler.n_dofs());
      assemble_cells(
        [&](const MeshWorker::CopyData<1, 1, 1> &copy)
        {
          if (!copy.local_dof_indices[0].empty())
            increment_constraints.distribute_local_to_global(
              copy.vectors[0], copy.local_dof_indices[0], l);
        });
      for (unsigned int i = 0; i < l.size() && load.size() > 0; ++i)
        l(i) += load(i);
      report.load_norm = l.l2_norm();
    }

    BodyVector du;
    // Backtracking: a step that does not reduce the residual is halved
    // (the tangent of a yield surface switches between the elastic and the
    // plastic one, and full steps can cycle between the two).
    double tau = 1, last_norm = std::numeric_limits<double>::infinity();
    for (unsigned int step = 0;; ++step)
    {
      // The tangent at u and the residual l_a + load - F(u); the state of
      // u becomes the trial state.
      linearize_at(u);
      Vector<double> residual = linear_solver->load_vector();
      for (unsigned int i = 0; i < residual.size() && load.size() > 0; ++i)
        if (!increment_constraints.is_constrained(i))
          residual(i) += load(i);
      const double norm = residual.l2_norm();
      report.residuals.push_back(norm);
      // The forces' scale where l_a + load vanishes (a body driven by its
      // Dirichlet values, or unloaded with residual stresses): the tangent
      // times the start, on the free dofs.
      if (step == 0)
      {
        Vector<double> u_values(u.size()), force(u.size());
        for (unsigned int i = 0; i < u.size(); ++i)
          u_values(i) = u(i);
        linear_solver->matrix().vmult(force, u_values);
        increment_constraints.set_zero(force);
        report.load_norm = std::max(report.load_norm, force.l2_norm());
      }
      if (!std::isfinite(norm))
        throw DivergenceError(parameters.section() +
                              ": the body's Newton loop gave a non-finite "
                              "residual; more Loading/Steps");
      if (norm >= last_norm &&
          norm > parameters.newton_tolerance * report.load_norm &&
          step < parameters.newton_max_iterations)
      {
        // No step along the Newton direction reduces the residual: the body
        // cannot carry the load (a perfectly plastic body beyond its limit
        // load), or the tangent is wrong. The caller may damp its load.
        if (tau <= 1. / 64)
        {
          std::ostringstream message;
          message << parameters.section() << ": the body's Newton loop "
                  << "stalled at the residual " << last_norm << " of the "
                  << "load's " << report.load_norm
                  << " (no step along its direction reduces it: a load "
                     "beyond what the body carries, such as a perfectly "
                     "plastic body past its limit load); lower the load, add "
                     "hardening, or take more Loading/Steps";
          throw NotConvergedError(message.str());
        }
        tau /= 2;
        u.add(-tau, du);
        continue;
      }
      last_norm = norm;
      tau       = 1;
      // Factorized before the test: the tangent at the converged u is what
      // solve_homogeneous() solves with after the loop.
      linear_solver->factorize(dof_handler);
      if (norm <= parameters.newton_tolerance * report.load_norm || norm == 0.)
        break;
      if (step == parameters.newton_max_iterations)
      {
        std::ostringstream message;
        message << parameters.section() << ": the body's Newton loop did not "
                << "converge in " << step << " steps (residual " << norm
                << " of the load's " << report.load_norm
                << "); more Loading/Steps, or a larger Solver/Newton max "
                   "iterations";
        throw NotConvergedError(message.str());
      }
      reinit_vector(du);
      linear_solver->solve(load, du);
      distribute_constraints(du, true);
      u += du;
    }
    // The factorization is the tangent at u (for solve_homogeneous()).
    is_factorized = true;
    return report;
  }

  template <int dim>
  void
  ElasticBody<dim>::set_trial_states(
    const std::vector<std::vector<double>> &new_states)
  {
    if (!material_state.empty())
      for (const auto &cell : get_triangulation().active_cell_iterators())
        if (mesh.computes(cell))
          material_state.set_trial(
            cell, make_array_view(new_states[cell->active_cell_index()]));
  }

  template <int dim>
  void
  ElasticBody<dim>::linearize_at(const BodyVector &u)
  {
    AssertThrow(solved_here && !is_solved_distributed() && !distributed_vectors,
                ExcMessage("a nonlinear material law is solved on one process "
                           "per body (for now)"));
    AssertDimension(u.size(), dof_handler.n_dofs());
    const AffineConstraints<double> increment_constraints =
      without_inhomogeneities(constraints);
    std::vector<std::vector<double>> new_states(
      get_triangulation().n_active_cells());
    linear_solver->zero();
    assemble_cells(
      [&](const MeshWorker::CopyData<1, 1, 1> &copy)
      {
        if (!copy.local_dof_indices[0].empty())
          linear_solver->add(increment_constraints,
                             copy.matrices[0],
                             copy.vectors[0],
                             copy.local_dof_indices[0]);
      },
      false,
      &u,
      &new_states);
    linear_solver->compress();
    set_trial_states(new_states);
    is_factorized = false;
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
