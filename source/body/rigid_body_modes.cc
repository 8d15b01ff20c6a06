#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <ddcontact/body/rigid_body_modes.h>

#include <cmath>
#include <set>

namespace ddcontact
{
  template <int dim>
  void
  RigidBodyModes<dim>::reinit(const DoFHandler<dim>           &dof_handler,
                              const Mapping<dim>              &mapping,
                              const BoundaryConditions<dim>   &conditions,
                              const AffineConstraints<double> &constraints)
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
    const unsigned int n = dof_handler.n_dofs();

    // The support point and component of every dof, from every cell: a
    // shared mesh holds all cells on every process, so this is the whole
    // body there too (DoFTools' helpers give a parallel mesh's locally
    // relevant part only).
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    std::vector<Point<dim>>   x(n);
    std::vector<bool>         is_x(n, false);
    {
      FEValues<dim>                        support(mapping,
                            fe,
                            Quadrature<dim>(fe.get_unit_support_points()),
                            update_quadrature_points);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
      {
        support.reinit(cell);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          x[dofs[i]]    = support.quadrature_point(i);
          is_x[dofs[i]] = fe.system_to_component_index(i).first == 0;
        }
      }
    }

    // The three rigid motions at every dof: translations in x and y, and
    // the rotation about the centre of the support points, scaled by the
    // body's size so that the three are of one magnitude.
    Point<dim> centre;
    for (const auto &point : x)
      centre += point / static_cast<double>(n);
    double size = 0;
    for (const auto &point : x)
      size = std::max(size, point.distance(centre));
    std::vector<std::array<double, 3>> basic(n);
    for (unsigned int i = 0; i < n; ++i)
    {
      const double rotation =
        is_x[i] ? -(x[i][1] - centre[1]) / size : (x[i][0] - centre[0]) / size;
      basic[i] = {{is_x[i] ? 1. : 0., is_x[i] ? 0. : 1., rotation}};
    }

    // The free combinations: the kernel of the Gram matrix of the three
    // at the prescribed components (entries of order one per dof, so a
    // held mode has an eigenvalue of at least about one).
    LAPACKFullMatrix<double> gram(3, 3);
    for (const auto &[id, condition] : conditions.dirichlet)
    {
      // The prescribed components on the faces of this id, each dof once
      // and in ascending order.
      std::set<types::global_dof_index>    prescribed;
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == id)
          {
            face->get_dof_indices(face_dofs);
            for (unsigned int k = 0; k < face_dofs.size(); ++k)
              if (condition.mask[fe.face_system_to_component_index(k).first])
                prescribed.insert(face_dofs[k]);
          }
      for (const auto i : prescribed)
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            gram(a, b) += basic[i][a] * basic[i][b];
    }
    gram.compute_svd();
    const auto &vt = gram.get_svd_vt();
    for (unsigned int k = 0; k < 3; ++k)
      if (gram.singular_value(k) < 1e-8)
        weights.push_back({{vt(k, 0), vt(k, 1), vt(k, 2)}});
    if (weights.empty())
      return;

    for (const auto &w : weights)
    {
      BodyVector mode(n);
      for (unsigned int i = 0; i < n; ++i)
        mode[i] = w[0] * basic[i][0] + w[1] * basic[i][1] + w[2] * basic[i][2];
      modes.push_back(std::move(mode));
    }

    // One fixed component per mode, chosen greedily: each time the free
    // dof whose mode values are farthest from the span of those already
    // chosen (pivoted Gram-Schmidt on the rows of the mode matrix). The
    // values of the modes at the fixed dofs then form a regular matrix,
    // so no free motion leaves all of them at rest. The first dof wins a
    // tie, so the choice is deterministic.
    std::vector<std::vector<double>> chosen_directions;
    // The mode values at dof i without their part along the chosen ones.
    const auto residual_row = [&](const unsigned int i)
    {
      std::vector<double> row(modes.size());
      for (unsigned int m = 0; m < modes.size(); ++m)
        row[m] = modes[m][i];
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
    for (unsigned int k = 0; k < modes.size(); ++k)
    {
      double       best     = 0;
      unsigned int best_dof = n;
      for (unsigned int i = 0; i < n; ++i)
        if (!constraints.is_constrained(i))
        {
          double norm = 0;
          for (const double v : residual_row(i))
            norm += v * v;
          if (norm > best)
          {
            best     = norm;
            best_dof = i;
          }
        }
      AssertThrow(best_dof < n && best > 1e-12,
                  ExcMessage("no free dof holds a rigid mode"));
      auto q = residual_row(best_dof);
      for (double &v : q)
        v /= std::sqrt(best);
      chosen_directions.push_back(q);
      fixed.push_back(best_dof);
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
