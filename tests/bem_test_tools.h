// Helpers shared by the BEM test programs (tests/bem_*.cc): the Q1 (or Q2)
// displacement space of a mesh, the material of most scenes, the rigid
// motion fit of a floating body, the convergence rates of a BEM study and
// the Timoshenko-Goodier cantilever.
#ifndef ddcontact_tests_bem_test_tools_h
#define ddcontact_tests_bem_test_tools_h

#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/bem/boundary_element_solver.h>

#include "test_tools.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ddcontact
{
  namespace testing
  {
    /** The Q1 (or Q<degree>) displacement space (FESystem(FE_Q(degree), 2))
     * on a mesh, with its dofs distributed, and the linear mapping. */
    struct Q1Displacement
    {
      explicit Q1Displacement(const dealii::Triangulation<2> &tria,
                              const unsigned int              degree = 1)
        : fe(dealii::FE_Q<2>(degree), 2)
        , dof_handler(tria)
        , mapping(1)
      {
        dof_handler.distribute_dofs(fe);
      }

      dealii::FESystem<2>   fe;
      dealii::DoFHandler<2> dof_handler;
      dealii::MappingQ<2>   mapping;
    };

    /** Steel: E = 2.1e5, nu = 0.3. */
    inline ElasticConstants
    steel()
    {
      ElasticConstants m;
      m.youngs_modulus = 2.1e5;
      m.poisson_ratio  = 0.3;
      return m;
    }

    /** Subtract from @p difference (one vector per node of @p bem) its
     * least-squares rigid motion a + omega (-y, x), by the 3x3 normal
     * equations: the bordered system of a floating body fixes its own
     * rigid part, so only the rest can be compared. */
    inline void
    remove_rigid_motion(const BoundaryElementSolver       &bem,
                        std::vector<dealii::Tensor<1, 2>> &difference)
    {
      dealii::FullMatrix<double> m(3, 3);
      dealii::Vector<double>     rhs(3), coefficients(3);
      for (unsigned int i = 0; i < bem.n_nodes(); ++i)
      {
        const dealii::Point<2> x = bem.node_position(i);
        for (unsigned int c = 0; c < 2; ++c)
        {
          const double r[3] = {
            c == 0 ? 1. : 0., c == 1 ? 1. : 0., c == 0 ? -x[1] : x[0]};
          for (unsigned int p = 0; p < 3; ++p)
          {
            rhs(p) += r[p] * difference[i][c];
            for (unsigned int q = 0; q < 3; ++q)
              m(p, q) += r[p] * r[q];
          }
        }
      }
      m.gauss_jordan();
      m.vmult(coefficients, rhs);
      for (unsigned int i = 0; i < bem.n_nodes(); ++i)
      {
        const dealii::Point<2> x = bem.node_position(i);
        difference[i][0] -= coefficients(0) - coefficients(2) * x[1];
        difference[i][1] -= coefficients(1) + coefficients(2) * x[0];
      }
    }

    /** Boundary ids of the rectangle (0,2)x(0,1) of the patch tests: 0
     * left, 1 right, 2 bottom, 3 top. */
    inline void
    set_rectangle_ids(dealii::Triangulation<2> &tria)
    {
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
        {
          const auto c = face->center();
          face->set_boundary_id(c[0] < 1e-10       ? 0
                                : c[0] > 2 - 1e-10 ? 1
                                : c[1] < 1e-10     ? 2
                                                   : 3);
        }
    }

    /** The largest nodal displacement error of @p bem against @p exact
     * (without the rigid part for a floating body) relative to the largest
     * exact nodal displacement, and that largest displacement. */
    inline std::pair<double, double>
    nodal_displacement_error(const BoundaryElementSolver &bem,
                             const dealii::Function<2>   &exact)
    {
      double                            u_max = 0, error = 0;
      std::vector<dealii::Tensor<1, 2>> difference(bem.n_nodes());
      for (unsigned int i = 0; i < bem.n_nodes(); ++i)
      {
        dealii::Tensor<1, 2> u;
        for (unsigned int c = 0; c < 2; ++c)
          u[c] = exact.value(bem.node_position(i), c);
        difference[i] = bem.node_displacement(i) - u;
        u_max         = std::max(u_max, u.norm());
      }
      if (bem.n_rigid_modes() > 0)
        remove_rigid_motion(bem, difference);
      for (const auto &d : difference)
        error = std::max(error, d.norm() / u_max);
      return {error, u_max};
    }

    /**
     * A BEM convergence study on meshes whose h halves each time: the
     * relative errors of the interior stresses, the nodal displacements
     * and, if studied, the element-end tractions everywhere and away from
     * the corners, in a table with their rates.
     */
    struct ConvergenceStudy
    {
      /** The table columns of the errors; tractions are studied if
       * @p t_column is not empty. */
      ConvergenceStudy(const std::string &u_column,
                       const std::string &sigma_column,
                       const std::string &t_column      = "",
                       const std::string &t_away_column = "")
        : columns{u_column}
      {
        if (!t_column.empty())
        {
          columns.push_back(t_column);
          columns.push_back(t_away_column);
        }
        columns.push_back(sigma_column);
      }

      /** Add the errors of one mesh to the lists and to the table (after
       * the columns describing the mesh). */
      void
      add(const double u_error,
          const double sigma_error,
          const double t_error      = 0,
          const double t_away_error = 0)
      {
        u.push_back(u_error);
        sigma.push_back(sigma_error);
        std::vector<double> values{u_error};
        if (columns.size() == 4)
        {
          t.push_back(t_error);
          t_away.push_back(t_away_error);
          values.push_back(t_error);
          values.push_back(t_away_error);
        }
        values.push_back(sigma_error);
        for (unsigned int c = 0; c < columns.size(); ++c)
          table.add_value(columns[c], values[c]);
      }

      /** Print the table with the rates of the error columns. */
      void
      print_table()
      {
        print_with_rates(table, columns);
      }

      /**
       * Print the rates over the last two refinements on one line and check
       * them: O(h^2) for the stresses and, away from the corners, the
       * tractions; @p u_rate for the displacements; O(h) for the tractions
       * in the max norm, which the corners limit. The tractions, if any,
       * are called @p traction in the printed checks.
       */
      void
      check_rates(const double u_rate, const std::string &traction = "") const
      {
        std::ostringstream line;
        line << std::fixed << std::setprecision(2)
             << "rates (last two levels): sigma " << rate_of_last_two(sigma)
             << ", u " << rate_of_last_two(u);
        if (!t.empty())
          line << ", t " << rate_of_last_two(t) << ", t away from corners "
               << rate_of_last_two(t_away);
        std::cout << line.str() << std::endl;

        std::ostringstream u_check;
        u_check << "nodal displacement rate > " << u_rate;
        check(rate_of_last_two(sigma) > 1.7, "interior stress rate > 1.7");
        check(rate_of_last_two(u) > u_rate, u_check.str());
        if (t.empty())
          return;
        check(rate_of_last_two(t) > 0.8, traction + " rate (max norm) > 0.8");
        check(rate_of_last_two(t_away) > 1.7,
              traction + " rate away from corners > 1.7");
      }

      /** The mesh columns come first, then the errors. */
      dealii::ConvergenceTable table;
      std::vector<double>      sigma, u, t, t_away;

    private:
      std::vector<std::string> columns;
    };

    /**
     * The Timoshenko-Goodier cantilever (doc/bem-method.md §6(d)): L = 8,
     * D = 2, parabolic end shear P = 1 on x = L, plane strain.
     */
    namespace cantilever
    {
      using namespace dealii;

      const double L = 8., D = 2., P = 1., I = D * D * D / 12.;

      inline SymmetricTensor<2, 2>
      exact_stress(const Point<2> &x)
      {
        SymmetricTensor<2, 2> s;
        s[0][0] = -P * (L - x[0]) * x[1] / I;
        s[1][1] = 0.;
        s[0][1] = P / (2. * I) * (D * D / 4. - x[1] * x[1]);
        return s;
      }

      /** Exact displacement; plane strain via E' = E/(1-nu^2),
       * nu' = nu/(1-nu). */
      class ExactDisplacement : public Function<2>
      {
      public:
        ExactDisplacement(const ElasticConstants &m)
          : Function<2>(2)
          , E(m.youngs_modulus / (1. - m.poisson_ratio * m.poisson_ratio))
          , nu(m.poisson_ratio / (1. - m.poisson_ratio))
        {
        }

        double
        value(const Point<2> &p, const unsigned int c) const override
        {
          const double x = p[0], y = p[1];
          if (c == 0)
            return -P * y / (6. * E * I) *
                   ((6. * L - 3. * x) * x + (2. + nu) * (y * y - D * D / 4.));
          return P / (6. * E * I) *
                 (3. * nu * y * y * (L - x) + (4. + 5. * nu) * D * D * x / 4. +
                  (3. * L - x) * x * x);
        }

        const double E, nu;
      };

      /** The parabolic shear on x = L (sigma_xx vanishes there). */
      class EndShear : public Function<2>
      {
      public:
        EndShear()
          : Function<2>(2)
        {
        }

        double
        value(const Point<2> &x, const unsigned int c) const override
        {
          return (exact_stress(x) * Tensor<1, 2>{{1., 0.}})[c];
        }
      };

      /** Relative errors of one BEM solve: nodal displacements (max), the
       * unknown tractions on x = 0 at every element node (max, and away
       * from the corners) and the stresses at four interior points. */
      struct Errors
      {
        double       h;
        unsigned int elements, unknowns;
        double       u = 0, t = 0, t_away = 0, sigma = 0;
      };

      /** The traction -sigma e_x on x = 0. */
      class RootTraction : public Function<2>
      {
      public:
        RootTraction()
          : Function<2>(2)
        {
        }

        double
        value(const Point<2> &x, const unsigned int c) const override
        {
          return (exact_stress(x) * Tensor<1, 2>{{-1., 0.}})[c];
        }
      };

      /** Solve on the 8 x 2 mesh refined @p level times with elements of
       * degree @p degree: exact u on x = 0 (id 0; its exact traction if
       * @p floating, and the rigid part of the error removed), the end
       * shear on x = L (id 1), top and bottom traction free. */
      inline Errors
      solve(const unsigned int level,
            const unsigned int degree,
            const bool         floating = false)
      {
        ElasticConstants material;
        material.youngs_modulus = 1e3;
        material.poisson_ratio  = 0.3;
        const auto exact        = std::make_shared<ExactDisplacement>(material);
        BoundaryConditions<2> bc;
        if (floating)
          bc.neumann[0] = std::make_shared<RootTraction>();
        else
          bc.dirichlet[0] = {ComponentMask(2, true), exact};
        bc.neumann[1] = std::make_shared<EndShear>();

        const std::vector<Point<2>> interior_points = {Point<2>(2., 0.5),
                                                       Point<2>(4., -0.5),
                                                       Point<2>(6., 0.25),
                                                       Point<2>(1., 0.)};
        double                      s_max           = 0;
        for (const auto &x : interior_points)
          s_max = std::max(s_max, exact_stress(x).norm());

        Triangulation<2> tria;
        GridGenerator::subdivided_hyper_rectangle(
          tria, {8, 2}, Point<2>(0., -D / 2), Point<2>(L, D / 2), true);
        tria.refine_global(level);
        const Q1Displacement space(tria, degree);

        BoundaryElementSolver bem(material, bc);
        bem.setup(space.dof_handler, space.mapping);
        bem.solve();

        Errors errors{L / (8 << level), bem.n_elements(), bem.n_unknowns()};
        // The unknown tractions on x = 0 (outward normal -e_x).
        double t_error = 0, t_max = 0, t_error_away = 0;
        for (unsigned int e = 0; e < bem.n_elements(); ++e)
          if (bem.element_boundary_id(e) == 0 && !floating)
            for (unsigned int end = 0; end <= degree; ++end)
            {
              const Point<2> x =
                bem.node_position(end < 2 ? bem.element_nodes(e)[end]
                                          : bem.element_midpoint_node(e));
              const auto   t     = exact_stress(x) * Tensor<1, 2>{{-1., 0.}};
              const double error = (bem.element_traction(e, end) - t).norm();
              t_error            = std::max(t_error, error);
              t_max              = std::max(t_max, t.norm());
              // Away (> 0.2) from the Dirichlet-Neumann corners (0, +-D/2).
              if (std::abs(x[1]) < D / 2 - 0.2)
                t_error_away = std::max(t_error_away, error);
            }
        double     s_error = 0;
        const auto stress  = bem.stress_at_points(interior_points);
        for (unsigned int q = 0; q < interior_points.size(); ++q)
          s_error = std::max(
            s_error, (stress[q] - exact_stress(interior_points[q])).norm());

        errors.u      = nodal_displacement_error(bem, *exact).first;
        errors.t      = t_max > 0 ? t_error / t_max : 0.;
        errors.t_away = t_max > 0 ? t_error_away / t_max : 0.;
        errors.sigma  = s_error / s_max;
        return errors;
      }
    } // namespace cantilever
  }   // namespace testing
} // namespace ddcontact

#endif
