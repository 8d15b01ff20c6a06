// DESCRIPTION: The material-law seam (issue 61). The linear-elastic law of
// the table gives Hooke's closed forms on homogeneous 3 x 3 strains to
// round-off: the uniaxial stress state of eps = (1, -nu, -nu) sigma / E
// has sigma_22 = sigma_33 = 0, plane strain's sigma_33 = nu (sigma_11 +
// sigma_22), pure shear tau = 2 mu gamma / 2; its tangent equals the
// finite-difference tangent of its stress (exactly, the law being linear),
// and MaterialTangent's form, shear form and split stress agree with the
// rank-4 tensor. SectionKinematics gives the strains of a Q1 field that
// holds u_r = a r, u_z = b z + d r exactly: eps = (a, b, d/2) and the hoop
// strain a, also at a vertex on the axis (its limit du_r/dr), eps_33 = 0 in
// plane strain, and the ring measure 2 pi r.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools.h>

#include <ddcontact/body/material_laws.h>
#include <ddcontact/body/section_kinematics.h>

#include "test_tools.h"

#include <cmath>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  SymmetricTensor<2, 3>
  stress_of(const MaterialLaw &law, const SymmetricTensor<2, 3> &strain)
  {
    SymmetricTensor<2, 3> sigma;
    law.evaluate(make_array_view(&strain, &strain + 1),
                 {},
                 make_array_view(&sigma, &sigma + 1),
                 nullptr,
                 {});
    return sigma;
  }

  /** u_r = a r, u_z = b z + d r. */
  class LinearField : public Function<2>
  {
  public:
    LinearField(const double a, const double b, const double d)
      : Function<2>(2)
      , a(a)
      , b(b)
      , d(d)
    {
    }
    double
    value(const Point<2> &x, const unsigned int c) const override
    {
      return c == 0 ? a * x[0] : b * x[1] + d * x[0];
    }

  private:
    const double a, b, d;
  };
} // namespace

int
main()
{
  // The table: the default row is linear-elastic, linear and without state.
  check(material_laws().front().name == "linear-elastic",
        "the table's first (default) row is linear-elastic");
  ElasticConstants steel;
  steel.youngs_modulus = 2.1e5;
  steel.poisson_ratio  = 0.3;
  const auto law       = create_material_law("linear-elastic", steel);
  check(law->is_linear() && !law->is_path_dependent() &&
          law->n_state_variables() == 0 && law->name() == "linear-elastic",
        "linear-elastic: linear, not path-dependent, no state");
  const double E = steel.youngs_modulus, nu = steel.poisson_ratio;
  const double scale = 100.; // a stress of 100

  // Uniaxial stress sigma_11 = s: eps = s/E (1, -nu, -nu).
  {
    SymmetricTensor<2, 3> eps;
    eps[0][0] = scale / E;
    eps[1][1] = eps[2][2]       = -nu * scale / E;
    const auto            sigma = stress_of(*law, eps);
    SymmetricTensor<2, 3> exact;
    exact[0][0] = scale;
    check("uniaxial stress: sigma = (s, 0, 0)",
          (sigma - exact).norm() / scale,
          1e-14);
  }
  // Plane strain eps = (e1, e2, 0): sigma_33 = nu (sigma_11 + sigma_22).
  {
    SymmetricTensor<2, 3> eps;
    eps[0][0]        = 3e-4;
    eps[1][1]        = -1e-4;
    const auto sigma = stress_of(*law, eps);
    check("plane strain: sigma_33 = nu (sigma_11 + sigma_22)",
          std::abs(sigma[2][2] - nu * (sigma[0][0] + sigma[1][1])) / scale,
          1e-14);
  }
  // Pure shear: eps_12 = gamma / 2, sigma_12 = mu gamma.
  {
    const double          gamma = 1e-3;
    SymmetricTensor<2, 3> eps;
    eps[0][1]          = gamma / 2;
    const auto   sigma = stress_of(*law, eps);
    const double mu    = E / (2 * (1 + nu));
    check("pure shear: sigma_12 = mu gamma, nothing else",
          (std::abs(sigma[0][1] - mu * gamma) + std::abs(trace(sigma))) /
            (mu * gamma),
          1e-14);
  }

  // The tangent against the finite-difference tangent of the stress, on a
  // general strain (a linear law: central differences are exact to
  // round-off of sigma / h).
  {
    SymmetricTensor<2, 3> eps;
    eps[0][0] = 2e-4;
    eps[1][1] = -1e-4;
    eps[2][2] = 5e-5;
    eps[0][1] = 3e-5;
    eps[0][2] = -2e-5;
    eps[1][2] = 1e-5;
    std::vector<MaterialTangent> tangent;
    SymmetricTensor<2, 3>        sigma;
    law->evaluate(make_array_view(&eps, &eps + 1),
                  {},
                  make_array_view(&sigma, &sigma + 1),
                  &tangent,
                  {});
    const SymmetricTensor<4, 3> C     = tangent.at(0).tensor();
    const double                h     = 1e-6;
    double                      error = 0;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = k; l < 3; ++l)
      {
        // d eps = h (e_k x e_l + e_l x e_k) / 2: one symmetric component.
        SymmetricTensor<2, 3> d;
        d[k][l] = h;
        const SymmetricTensor<2, 3> fd =
          (stress_of(*law, eps + d) - stress_of(*law, eps - d)) / (2. * h);
        error = std::max(error, (fd - C * d / h).norm() / E);
      }
    // Round-off: |sigma| eps / h ~ 4e-9 against E, 2e-14.
    check("consistent tangent = finite-difference tangent", error, 1e-12);

    // MaterialTangent's isotropic shortcuts against the rank-4 tensor.
    const MaterialTangent &t = tangent[0];
    SymmetricTensor<2, 3>  b;
    b[0][0]             = -1e-4;
    b[1][2]             = 4e-5;
    b[2][2]             = 2e-4;
    const double form_4 = eps * (C * b);
    check("form(a, b) = a : C : b",
          std::abs(t.form(eps, b) - form_4) / std::abs(form_4),
          1e-14);
    const double lambda = steel.lambda();
    check(
      "shear_form + lambda tr a tr b = form",
      std::abs(t.shear_form(eps, b) + lambda * trace(eps) * trace(b) - form_4) /
        std::abs(form_4),
      1e-14);
    check("apply(e, tr e) = C : e",
          (t.apply(eps, trace(eps)) - C * eps).norm() / sigma.norm(),
          1e-14);
    check("a general tangent of the same C gives the same form",
          std::abs(MaterialTangent::general(C).form(eps, b) - form_4) /
            std::abs(form_4),
          1e-14);
  }

  // SectionKinematics on a Q1 field that holds the linear field exactly:
  // a square [0, 1]^2 with its left side on the axis.
  {
    Triangulation<2> tria;
    GridGenerator::hyper_cube(tria, 0., 1.);
    tria.refine_global(2);
    const FESystem<2> fe(FE_Q<2>(1), 2);
    DoFHandler<2>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const double   a = 2e-3, b = -1e-3, d = 5e-4;
    Vector<double> u(dof_handler.n_dofs());
    VectorTools::interpolate(dof_handler, LinearField(a, b, d), u);

    SymmetricTensor<2, 3> exact;
    exact[0][0] = a;
    exact[1][1] = b;
    exact[0][1] = d / 2;
    exact[2][2] = a;
    // Gauss points and the vertices (some on the axis).
    const QGauss<2>                    gauss(2);
    const QTrapezoid<2>                vertices;
    double                             axisymmetric_error = 0, plane_error = 0;
    double                             measure_error = 0, shape_error = 0;
    const SectionKinematics            ring(Geometry::axisymmetric, 1e-10);
    const SectionKinematics            plane(Geometry::plane_strain);
    std::vector<SymmetricTensor<2, 3>> strain;
    for (const Quadrature<2> *rule :
         {static_cast<const Quadrature<2> *>(&gauss),
          static_cast<const Quadrature<2> *>(&vertices)})
    {
      FEValues<2> fe_values(fe, *rule, ring.update_flags(update_JxW_values));
      for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        ring.field_strains(fe_values, u, strain);
        for (const auto &e : strain)
          axisymmetric_error =
            std::max(axisymmetric_error, (e - exact).norm() / a);
        plane.field_strains(fe_values, u, strain);
        SymmetricTensor<2, 3> in_plane = exact;
        in_plane[2][2]                 = 0;
        for (const auto &e : strain)
          plane_error = std::max(plane_error, (e - in_plane).norm() / a);
        for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const Point<2> &x = fe_values.quadrature_point(q);
          measure_error =
            std::max(measure_error,
                     std::abs(ring.measure(x) - 2 * numbers::PI * x[0]) +
                       std::abs(plane.measure(x) - 1.));
          // The shape functions' strains summed with u's coefficients
          // are the field's.
          std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          SymmetricTensor<2, 3> sum;
          for (unsigned int i = 0; i < dofs.size(); ++i)
            sum += u(dofs[i]) * ring.shape_strain(fe_values, i, q);
          shape_error = std::max(shape_error, (sum - exact).norm() / a);
        }
      }
    }
    check("axisymmetric strain (a, b, d/2; hoop a), also on the axis",
          axisymmetric_error,
          1e-12);
    check("plane strain: eps_33 = 0", plane_error, 1e-12);
    check(
      "the shape functions' strains sum to the field's", shape_error, 1e-12);
    check("measure: 2 pi r, and 1 in plane strain", measure_error, 1e-14);
  }
  return report();
}
