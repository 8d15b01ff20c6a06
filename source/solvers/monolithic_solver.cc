#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>

#include <ddcontact/solvers/errors.h>
#include <ddcontact/solvers/monolithic_solver.h>

namespace ddcontact
{
  MonolithicContactSolver::MonolithicContactSolver(
    const ContactProblem &problem,
    const unsigned int    max_iterations,
    ConditionalOStream   &pcout)
    : problem(problem)
    , max_iterations(max_iterations)
    , pcout(pcout)
  {
  }

  unsigned int
  MonolithicContactSolver::run()
  {
    const auto &bodies = problem.get_bodies();
    const auto &pairs  = problem.get_pairs();
    // lambda + g/theta = (f_n + theta lambda - u_1n - u_2n)/theta: the
    // multipliers shift the gap of every contact point.
    const auto gap = [&](const unsigned int p, const unsigned int q)
    { return problem.law(p).shifted_gap(q); };

    // One global numbering: the bodies' dofs one after another.
    std::vector<types::global_dof_index> offset(bodies.size() + 1, 0);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      offset[b + 1] = offset[b] + bodies[b]->n_dofs();
    const auto n = offset.back();

    // The bodies' constraints (hanging nodes, Dirichlet data), shifted.
    AffineConstraints<double> constraints;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (const auto &line : bodies[b]->get_constraints().get_lines())
      {
        constraints.add_line(line.index + offset[b]);
        for (const auto &[column, weight] : line.entries)
          constraints.add_entry(
            line.index + offset[b], column + offset[b], weight);
        constraints.set_inhomogeneity(line.index + offset[b],
                                      line.inhomogeneity);
      }
    constraints.close();

    // Each contact point couples the dofs of both of its cells.
    const auto point_dofs = [&](const ContactPair &pair, const ContactPoint &p)
    {
      std::vector<types::global_dof_index> dofs;
      for (const auto i : p.dofs_1)
        dofs.push_back(i + offset[problem.body_index(pair.get_body_1())]);
      for (const auto i : p.dofs_2)
        dofs.push_back(i + offset[problem.body_index(pair.get_body_2())]);
      return dofs;
    };

    DynamicSparsityPattern dsp(n);
    for (unsigned int b = 0; b < bodies.size(); ++b)
    {
      const auto &K = bodies[b]->get_stiffness_matrix();
      for (types::global_dof_index i = 0; i < K.m(); ++i)
        for (auto it = K.begin(i); it != K.end(i); ++it)
          dsp.add(i + offset[b], it->column() + offset[b]);
    }
    for (const auto *pair : pairs)
      for (const auto &p : pair->points())
        constraints.add_entries_local_to_global(
          point_dofs(*pair, p), dsp, false);
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);

    // Current state, flattened.
    Vector<double> u(n);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (types::global_dof_index i = 0; i < bodies[b]->n_dofs(); ++i)
        u(i + offset[b]) = bodies[b]->get_solution()(i);

    // Base right-hand side: the bodies' condensed loads (12).
    Vector<double> base_rhs(n);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (types::global_dof_index i = 0; i < bodies[b]->n_dofs(); ++i)
        base_rhs(i + offset[b]) = bodies[b]->get_load_vector()(i);

    std::vector<std::vector<bool>> active(pairs.size());
    unsigned int                   iteration = 0;
    for (; iteration < max_iterations; ++iteration)
    {
      // The active set of the current iterate.
      bool         changed  = (iteration == 0);
      unsigned int n_active = 0;
      for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const auto &pts = pairs[p]->points();
        active[p].resize(pts.size(), false);
        for (unsigned int q = 0; q < pts.size(); ++q)
        {
          const auto dofs = point_dofs(*pairs[p], pts[q]);
          double     cu   = 0;
          for (unsigned int i = 0; i < pts[q].a.size(); ++i)
            cu += pts[q].a[i] * u(dofs[i]);
          for (unsigned int i = 0; i < pts[q].b.size(); ++i)
            cu += pts[q].b[i] * u(dofs[pts[q].a.size() + i]);
          const bool now = gap(p, q) - cu < 0;
          changed        = changed || (now != active[p][q]);
          active[p][q]   = now;
          n_active += now;
        }
      }
      pcout << "  Newton " << iteration << ": " << n_active
            << " active contact points" << std::endl;
      if (!changed)
        break;

      // Matrix blockdiag(K_a) + (1/theta) sum_active w c c^T and right-hand
      // side L + (1/theta) sum_active w f_n c (f_n shifted by theta lambda).
      SparseMatrix<double> matrix(sparsity);
      for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const auto &K = bodies[b]->get_stiffness_matrix();
        for (types::global_dof_index i = 0; i < K.m(); ++i)
          for (auto it = K.begin(i); it != K.end(i); ++it)
            matrix.add(i + offset[b], it->column() + offset[b], it->value());
      }
      Vector<double> rhs(base_rhs);
      for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const double theta = problem.law(p).theta();
        const auto  &pts   = pairs[p]->points();
        for (unsigned int q = 0; q < pts.size(); ++q)
          if (active[p][q])
          {
            const auto          dofs = point_dofs(*pairs[p], pts[q]);
            std::vector<double> c(pts[q].a);
            c.insert(c.end(), pts[q].b.begin(), pts[q].b.end());
            FullMatrix<double> local_matrix(c.size(), c.size());
            Vector<double>     local_rhs(c.size());
            const double       w = pts[q].JxW / theta;
            for (unsigned int i = 0; i < c.size(); ++i)
            {
              local_rhs(i) = w * gap(p, q) * c[i];
              for (unsigned int j = 0; j < c.size(); ++j)
                local_matrix(i, j) = w * c[i] * c[j];
            }
            constraints.distribute_local_to_global(
              local_matrix, local_rhs, dofs, matrix, rhs);
          }
      }
      SparseDirectUMFPACK solver;
      solver.initialize(matrix);
      solver.vmult(u, rhs);
      constraints.distribute(u);
      for (const double v : u)
        if (!std::isfinite(v))
          throw DivergenceError("the monolithic Newton solver produced a "
                                "non-finite displacement");
    }
    if (iteration == max_iterations)
      throw DivergenceError(
        "the monolithic Newton solver did not settle its active set in " +
        std::to_string(max_iterations) +
        " iterations (the active set cycles when theta is small against "
        "the compliance of the contact zone, e.g. a slender body); raise the "
        "contact pairs' Penalty (c) or Domain decomposition/Max Newton "
        "iterations");

    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (types::global_dof_index i = 0; i < bodies[b]->n_dofs(); ++i)
        bodies[b]->get_solution()(i) = u(i + offset[b]);
    return iteration;
  }
} // namespace ddcontact
