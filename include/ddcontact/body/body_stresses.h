#ifndef ddcontact_body_stresses_h
#define ddcontact_body_stresses_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_vector.h>
#include <ddcontact/body/material_law.h>
#include <ddcontact/body/section_kinematics.h>
#include <ddcontact/parameter_tools.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  template <int dim>
  class ElasticBody;

  /** Displacement and stress of a body at one point. */
  template <int dim>
  struct PointValues
  {
    Point<dim>              x;
    Tensor<1, dim>          displacement;
    SymmetricTensor<2, dim> stress;
    /** sigma_33 of plane strain, sigma_thetatheta of an axisymmetric body. */
    double out_of_plane = 0.;
    double von_mises    = 0.;
  };

  /**
   * The plane-strain stress sigma(u) of (2) of one displacement field u of
   * a body, and what is computed from it: the stress at the quadrature
   * points (for the estimator (27)), at the cell centres (for the adapted
   * meshes' files), at any point, and the elastic energy 1/2 a_a(u, u) of
   * (11).
   *
   * The strains come from the body's SectionKinematics and the stresses
   * from its MaterialLaw. With selective reduced integration (ElasticBody::
   * get_volumetric_quadrature()) the stress is sigma = lambda (div u)(x_c) I
   * + 2 mu eps(u), with the dilatation taken at the cell's reduced point
   * x_c, consistently with the assembled a_a; stress() is the one place
   * that applies this correction.
   *
   * A path-dependent law (plasticity) evaluates the stress from the state
   * committed at the start of the load step (ElasticBody::
   * get_material_state()): at the body's quadrature points each point's
   * own state, which gives exactly the stress of the body's last solve;
   * at any other point of a cell the mean of the cell's states (a
   * piecewise-constant projection of the state).
   *
   * On a distributed mesh each process computes its own cells; sums are
   * taken over the processes, and per-cell arrays hold zeros elsewhere.
   */
  template <int dim>
  class BodyStresses
  {
  public:
    /** The stresses of @p u (a vector of the body's dofs); the reduced
     * dilatation of every cell is computed here, once. Both references must
     * outlive this object. */
    BodyStresses(const ElasticBody<dim> &body, const BodyVector &u);

    /** The stress of the body's material law (3 x 3: the third normal
     * stress is sigma_33 of plane strain, sigma_tt in axisymmetry) of the
     * @p strain (SectionKinematics) at a point of the active cell with index
     * @p cell, whose reduced dilatation replaces tr(strain) in the
     * volumetric part if the cell has one. */
    SymmetricTensor<2, 3>
    stress(const SymmetricTensor<2, 3> &strain, const unsigned int cell) const;

    /** The same at the quadrature point @p q of the body's cell quadrature
     * (ElasticBody::get_cell_quadrature()): a path-dependent law from that
     * point's own state. */
    SymmetricTensor<2, 3>
    stress_at_quadrature_point(const SymmetricTensor<2, 3> &strain,
                               unsigned int                 cell,
                               unsigned int                 q) const;

    /** sigma(u) at every quadrature point of every active cell, indexed
     * [active_cell_index][q]; the third normal stress (out_of_plane())
     * into @p third if given. */
    std::vector<std::vector<SymmetricTensor<2, dim>>>
    at_quadrature_points(
      std::vector<std::vector<double>> *third = nullptr) const;

    /** sigma(u) at the centre of every active cell, by active_cell_index;
     * the third normal stress into @p third if given. */
    std::vector<SymmetricTensor<2, dim>>
    at_cell_centres(std::vector<double> *third = nullptr) const;

    /** Displacement, stress and von Mises stress at @p x; throws InputError
     * naming Output/Points if @p x lies outside the body. */
    PointValues<dim>
    at_point(const Point<dim> &x) const;

    /** The same, the stress the mean over every cell that holds @p x: at a
     * vertex or an edge, where the stress jumps between the cells, a
     * continuous value (O(h^2) at an interior vertex of a smooth field,
     * where one cell's is O(h) off); inside a cell its own. */
    PointValues<dim>
    averaged_at_point(const Point<dim> &x) const;

    /** The largest strain and the largest rotation of the body, each the
     * largest over the cell centres (of this process's cells): the
     * largest principal strain magnitude of eps(u) (1), and |omega| of the
     * skew part (d_1 u_2 - d_2 u_1) / 2 of grad u. Linear elasticity holds
     * while both are small (RunReport::small_strain_limit). The cell
     * centres soften the singular corners of a punch, which no mesh
     * resolves anyway. */
    std::pair<double, double>
    largest_strain_and_rotation() const;

    /** The elastic energy 1/2 a_a(u, u) of (11), with the quadrature of the
     * assembly. */
    double
    strain_energy() const;

  private:
    /** Displacement and stress at the unit point @p xi of @p cell (of the
     * body's DoFHandler), as at_point() reports them at @p x. */
    PointValues<dim>
    at_unit_point(const typename DoFHandler<dim>::active_cell_iterator &cell,
                  const Point<dim>                                     &xi,
                  const Point<dim> &x) const;

    /** at_point() on a distributed mesh: the process owning the cell
     * around @p x evaluates and sends; collective over the mesh's
     * processes, which all ask for @p x. Throws @p outside if no process
     * holds it. */
    PointValues<dim>
    at_point_distributed(const Point<dim> &x,
                         const InputError &outside,
                         bool              averaged = false) const;

    /** at_point() or averaged_at_point(). */
    PointValues<dim>
    at_point(const Point<dim> &x, bool averaged) const;

    /** The one-point rule at the centre of the body's cells. */
    Quadrature<dim>
    cell_centre() const;

    const ElasticBody<dim> &body;
    const BodyVector       &u;
    const SectionKinematics kinematics;
    const MaterialLaw      &law;
    /** div u (+ u_r / r in axisymmetry) at the reduced point of every
     * active cell; empty with full integration. */
    std::vector<double> dilatation;

    /** A path-dependent law's committed states, by active cell index: the
     * values of every quadrature point, then (committed_mean) their mean;
     * empty otherwise. */
    std::vector<std::vector<double>> committed;
    std::vector<std::vector<double>> committed_mean;
  };
} // namespace ddcontact

#endif
