#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <ddcontact/body/elastic_body.h>
#include <ddcontact/body/smoothed_stresses.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ddcontact
{
  namespace
  {
    /** The mass matrix's pattern over every cell, also on a shared mesh
     * (whose DoFTools functions take only the cells this process owns). */
    template <int dim>
    void
    make_pattern(const DoFHandler<dim>           &dof_handler,
                 const AffineConstraints<double> &constraints,
                 SparsityPattern                 &pattern)
    {
      std::vector<types::global_dof_index> dofs(
        dof_handler.get_fe().n_dofs_per_cell());
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        constraints.add_entries_local_to_global(dofs, dsp, false);
      }
      pattern.copy_from(dsp);
    }

    /**
     * The L2 projection @p x of @p load (overwritten): M x = load. The mass
     * matrix scaled by its diagonal has a condition number bounded cell by
     * cell, so independently of h and of the mesh's grading (Wathen 1987:
     * 9 for bilinear quadrilaterals, 4 for linear triangles): Jacobi-
     * preconditioned CG reaches round-off in a few dozen products, where a
     * factorization cost more than the rest of the output on fine meshes.
     * Constrained rows hold only their diagonal.
     */
    void
    solve_projection(const SparseMatrix<double>      &mass,
                     const AffineConstraints<double> &constraints,
                     Vector<double>                  &load,
                     Vector<double>                  &x)
    {
      // The last iterate of a diverged run, written for diagnosis, may
      // hold inf or NaN: its projection is NaN, not a failed CG.
      if (!std::all_of(load.begin(),
                       load.end(),
                       [](const double v) { return std::isfinite(v); }))
      {
        x = std::numeric_limits<double>::quiet_NaN();
        return;
      }
      // Solved for the load scaled to a largest entry of one, so that no
      // norm of CG overflows for huge (finite) stresses.
      const double scale = load.linfty_norm();
      if (scale == 0.)
        return;
      load /= scale;
      PreconditionJacobi<SparseMatrix<double>> jacobi;
      jacobi.initialize(mass);
      SolverControl control(std::max<unsigned int>(200, mass.m()),
                            1e-14 * load.l2_norm());
      SolverCG<Vector<double>>(control).solve(mass, x, load, jacobi);
      x *= scale;
      constraints.distribute(x);
    }
  } // namespace

  template <int dim>
  std::vector<std::string>
  SmoothedStresses<dim>::names() const
  {
    if (axisymmetric)
      return {"sigma_rr_smoothed",
              "sigma_zz_smoothed",
              "sigma_rz_smoothed",
              "sigma_hoop_smoothed",
              "von_mises_smoothed"};
    return {"sigma_11_smoothed",
            "sigma_22_smoothed",
            "sigma_12_smoothed",
            "sigma_33_smoothed",
            "von_mises_smoothed"};
  }

  template <int dim>
  SmoothedStresses<dim>::SmoothedStresses(const ElasticBody<dim> &body,
                                          const BodyVector       &u)
    : dof_handler(body.get_triangulation())
    , axisymmetric(body.get_geometry() == Geometry::axisymmetric)
  {
    Assert(!body.is_mesh_distributed(), ExcNotImplemented());
    dof_handler.distribute_dofs(body.get_fe().base_element(0));
    AffineConstraints<double> constraints;
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    constraints.close();

    const unsigned int n = dof_handler.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    SparsityPattern                      pattern;
    make_pattern(dof_handler, constraints, pattern);
    SparseMatrix<double> mass(pattern);

    // The stress of u at the quadrature points of the body's assembly
    // (BodyStresses applies a reduced dilatation if the body has one).
    // The third normal stress (sigma_33, or the hoop stress of an
    // axisymmetric body) is a fourth field: the material law gives it.
    std::vector<std::vector<double>> third;
    const auto         stress   = body.stresses(u).at_quadrature_points(&third);
    const unsigned int n_fields = 4;
    const Quadrature<dim> &quadrature = body.get_cell_quadrature();
    FEValues<dim>          fe_values(body.get_mapping(),
                            dof_handler.get_fe(),
                            quadrature,
                            update_values | update_JxW_values);
    const std::array<std::array<unsigned int, 2>, 3> components = {
      {{{0, 0}}, {{1, 1}}, {{0, 1}}}};
    std::vector<Vector<double>> load(n_fields,
                                     Vector<double>(dof_handler.n_dofs()));
    FullMatrix<double>          cell_mass(n, n);
    std::vector<Vector<double>> cell_load(n_fields, Vector<double>(n));
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      fe_values.reinit(cell);
      cell_mass = 0;
      for (auto &l : cell_load)
        l = 0;
      const auto &s = stress[cell->active_cell_index()];
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        for (unsigned int i = 0; i < n; ++i)
        {
          const double phi_i = fe_values.shape_value(i, q) * fe_values.JxW(q);
          for (unsigned int j = 0; j < n; ++j)
            cell_mass(i, j) += phi_i * fe_values.shape_value(j, q);
          for (unsigned int c = 0; c < 3; ++c)
            cell_load[c](i) += phi_i * s[q][components[c][0]][components[c][1]];
          cell_load[3](i) += phi_i * third[cell->active_cell_index()][q];
        }
      cell->get_dof_indices(dofs);
      constraints.distribute_local_to_global(cell_mass, dofs, mass);
      for (unsigned int c = 0; c < n_fields; ++c)
        constraints.distribute_local_to_global(cell_load[c], dofs, load[c]);
    }

    projected.resize(5, Vector<double>(dof_handler.n_dofs()));
    for (unsigned int c = 0; c < n_fields; ++c)
      solve_projection(mass, constraints, load[c], projected[c]);
    for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
    {
      SymmetricTensor<2, dim> s;
      s[0][0]         = projected[0](i);
      s[1][1]         = projected[1](i);
      s[0][1]         = projected[2](i);
      projected[4](i) = von_mises_stress(s, projected[3](i));
    }
  }

  template class SmoothedStresses<2>;
} // namespace ddcontact
