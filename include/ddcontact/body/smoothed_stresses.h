#ifndef ddcontact_body_smoothed_stresses_h
#define ddcontact_body_smoothed_stresses_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_vector.h>

#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  template <int dim>
  class ElasticBody;

  /**
   * A continuous stress field of a body for the output: the L2 projection
   * of each component of the plane-strain stress (2) of a displacement u
   * onto the scalar finite element space of the body (the base element of
   * its vector space, on its mesh, with its hanging-node constraints and
   * no Dirichlet data). The stress of u itself jumps between cells (a
   * sawtooth on linear triangles, where it is constant per cell); the
   * projection is the continuous field closest to it in L2. A constant
   * stress is reproduced exactly (the shape functions sum to one, and
   * the load and the mass matrix use the same quadrature).
   *
   * sigma_11, sigma_22 and sigma_12 are projected (three solves of the
   * mass matrix by Jacobi-preconditioned CG); sigma_33 = nu (sigma_11 +
   * sigma_22) and the von Mises stress are taken from the projected components
   * at every node.
   *
   * Only for a mesh held whole by every process (serial or shared): a
   * distributed (p4est) mesh would need a distributed solve, which the
   * output does not do.
   */
  template <int dim>
  class SmoothedStresses
  {
  public:
    /** Project the stress of @p u, a vector of the dofs of @p body. The
     * body must outlive this object. */
    SmoothedStresses(const ElasticBody<dim> &body, const BodyVector &u);

    /** The scalar space of the projected fields. */
    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /** The projected fields, in the order of names(). */
    const std::vector<Vector<double>> &
    fields() const
    {
      return projected;
    }

    /** sigma_11_smoothed, sigma_22_smoothed, sigma_12_smoothed,
     * sigma_33_smoothed, von_mises_smoothed; sigma_rr_smoothed, ...,
     * sigma_hoop_smoothed for an axisymmetric body, whose hoop stress is
     * projected as well. */
    std::vector<std::string>
    names() const;

  private:
    DoFHandler<dim>             dof_handler;
    std::vector<Vector<double>> projected;
    bool                        axisymmetric = false;
  };
} // namespace ddcontact

#endif
