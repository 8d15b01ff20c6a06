// Helpers shared by the BEM test programs (tests/bem_*.cc): the Q1
// displacement space of a mesh, the material of most scenes, the rigid
// motion fit of a floating body and the convergence rates of a BEM study.
#ifndef ddcontact_tests_bem_test_tools_h
#define ddcontact_tests_bem_test_tools_h

#include <deal.II/base/convergence_table.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/bem/boundary_element_solver.h>

#include "test_tools.h"

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace ddcontact
{
  namespace testing
  {
    /** The Q1 displacement space (FESystem(FE_Q(1), 2)) on a mesh, with its
     * dofs distributed, and the linear mapping. */
    struct Q1Displacement
    {
      explicit Q1Displacement(const dealii::Triangulation<2> &tria)
        : fe(dealii::FE_Q<2>(1), 2)
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
    inline Material
    steel()
    {
      Material m;
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
  } // namespace testing
} // namespace ddcontact

#endif
