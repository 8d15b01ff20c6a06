#ifndef ddcontact_section_kinematics_h
#define ddcontact_section_kinematics_h

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <ddcontact/body/geometry.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The small-strain kinematics of a 2D section, in one place: the strain
   * eps(u) = (grad u + grad u^T) / 2 of (1) as a 3 x 3 tensor, with the
   * third normal strain eps_33 = 0 in plane strain and the hoop strain
   * eps_tt = u_r / r of an axisymmetric section (x = r, y = z); and the
   * section's measure, dV = dA or 2 pi r dA. Every assembly, stress
   * recovery and estimator takes its strains from here, and the material
   * laws (MaterialLaw) take 3 x 3 strains, so that neither changes for a 3D
   * body.
   */
  class SectionKinematics
  {
  public:
    /** @p axis_tolerance: how close to r = 0 a point counts as on the axis
     * (AxisOfSymmetry::tolerance()). */
    explicit SectionKinematics(Geometry geometry, double axis_tolerance = 0.);

    bool
    is_axisymmetric() const
    {
      return axisymmetric;
    }

    /** The factor of the section's measure at @p x: 1, or 2 pi r. */
    double
    measure(const Point<2> &x) const
    {
      return section_measure(geometry, x);
    }

    /** The update flags the strains need, added to @p flags. */
    UpdateFlags
    update_flags(UpdateFlags flags = update_default) const;

    /**
     * eps_33 at @p x of a displacement with radial component @p u_r and
     * d u_r / dr = @p du_r_dr: the hoop strain u_r / r of an axisymmetric
     * section, which tends to du_r / dr on the axis (where u_r = 0; output
     * evaluates at vertices, some on the axis); 0 in plane strain.
     */
    double
    out_of_plane_strain(const Point<2> &x,
                        const double    u_r,
                        const double    du_r_dr) const
    {
      if (!axisymmetric)
        return 0.;
      return x[0] > axis_tolerance ? u_r / x[0] : du_r_dr;
    }

    /** The 3 x 3 strain of the in-plane strain @p e and eps_33. */
    static SymmetricTensor<2, 3>
    embed(const SymmetricTensor<2, 2> &e, const double eps_33)
    {
      SymmetricTensor<2, 3> s;
      s[0][0] = e[0][0];
      s[1][1] = e[1][1];
      s[0][1] = e[0][1];
      s[2][2] = eps_33;
      return s;
    }

    /** The in-plane part of a 3 x 3 tensor. */
    static SymmetricTensor<2, 2>
    in_plane(const SymmetricTensor<2, 3> &s)
    {
      SymmetricTensor<2, 2> e;
      e[0][0] = s[0][0];
      e[1][1] = s[1][1];
      e[0][1] = s[0][1];
      return e;
    }

    /** The strain of the vector-valued shape function @p i at the point
     * @p q of @p fe_values (reinitialized with update_flags()). */
    SymmetricTensor<2, 3>
    shape_strain(const FEValuesBase<2> &fe_values,
                 const unsigned int     i,
                 const unsigned int     q) const
    {
      const FEValuesExtractors::Vector displacement(0);
      const auto                      &view = fe_values[displacement];
      if (!axisymmetric)
        return embed(view.symmetric_gradient(i, q), 0.);
      const Point<2> &x = fe_values.quadrature_point(q);
      return embed(view.symmetric_gradient(i, q),
                   x[0] > axis_tolerance ? view.value(i, q)[0] / x[0]
                                         : view.gradient(i, q)[0][0]);
    }

    /** The strains of the displacement @p u at the points of
     * @p fe_values (reinitialized with update_flags()). */
    template <typename VectorType>
    void
    field_strains(const FEValuesBase<2>              &fe_values,
                  const VectorType                   &u,
                  std::vector<SymmetricTensor<2, 3>> &strain) const
    {
      const unsigned int                 n = fe_values.n_quadrature_points;
      const FEValuesExtractors::Vector   displacement(0);
      std::vector<SymmetricTensor<2, 2>> in_plane_strain(n);
      std::vector<Tensor<1, 2>>          value;
      std::vector<Tensor<2, 2>>          gradient;
      fe_values[displacement].get_function_symmetric_gradients(u,
                                                               in_plane_strain);
      if (axisymmetric)
      {
        value.resize(n);
        gradient.resize(n);
        fe_values[displacement].get_function_values(u, value);
        fe_values[displacement].get_function_gradients(u, gradient);
      }
      strain.resize(n);
      for (unsigned int q = 0; q < n; ++q)
        strain[q] = embed(in_plane_strain[q],
                          axisymmetric
                            ? out_of_plane_strain(fe_values.quadrature_point(q),
                                                  value[q][0],
                                                  gradient[q][0][0])
                            : 0.);
    }

  private:
    Geometry geometry;
    bool     axisymmetric;
    double   axis_tolerance;
  };
} // namespace ddcontact

#endif
