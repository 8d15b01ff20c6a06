#ifndef ddcontact_reaction_forces_h
#define ddcontact_reaction_forces_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/body/body_vector.h>

#include <vector>

namespace ddcontact
{
  using namespace dealii;

  template <int dim>
  class ElasticBody;

  /**
   * The forces a body's supports exert on it, one per Dirichlet boundary id
   * of (5), and the balance of all forces on the body.
   *
   * The reaction is the residual of the discrete equilibrium (11)-(12) on
   * the prescribed components: R(w) = a_a(u, w) - l_a(w) - c(w) for the
   * conforming function w that is 1 in one direction at the nodes of an id
   * and 0 at every other Dirichlet node, with c the contact traction. This
   * is exact for the discrete solution (no stress recovery on the boundary)
   * and sums with the loads to zero: for w = e_k everywhere a_a(u, e_k)
   * vanishes, so sum_ids R + l_a(e_k) + c(e_k) = 0 up to the contact
   * solver's tolerance. A node on two Dirichlet ids counts for the lower id
   * that prescribes the component. A hanging node hands its share to its
   * parents (ElasticBody::get_hanging_node_constraints()).
   *
   * Collective over the processes of a partitioned mesh.
   */
  template <int dim>
  class ReactionForces
  {
  public:
    /** The force of one Dirichlet id, and which of its components the id
     * prescribes (the free ones carry no reaction: about 0). */
    struct Support
    {
      types::boundary_id id;
      Tensor<1, dim>     force;
      /** The mean displacement of the id's faces (weighted like every
       * integral of the body: by 2 pi r if axisymmetric): with the force,
       * a point of the force-displacement curve of a driven boundary. */
      Tensor<1, dim>        displacement;
      std::array<bool, dim> prescribed;
    };

    /** The reactions of @p body in the state @p u, loaded on its contact
     * zones by @p contact_load: the contact traction assembled without
     * constraints (ContactPair::add_unconstrained_contact_load(); size 0:
     * none). */
    ReactionForces(const ElasticBody<dim> &body,
                   const BodyVector       &u,
                   const BodyVector       &contact_load);

    /** One entry per Dirichlet id, in ascending order. */
    const std::vector<Support> &
    supports() const
    {
      return support_forces;
    }

    /** The resultant of the body force and the Neumann tractions, l_a(e_k)
     * of (12). */
    const Tensor<1, dim> &
    applied_load() const
    {
      return applied;
    }

    /** The resultant of the contact traction, c(e_k). */
    const Tensor<1, dim> &
    contact_force() const
    {
      return contact;
    }

    /** Supports + applied load + contact: zero for a body in equilibrium
     * (a floating body's clamped rigid modes carry the rest). */
    Tensor<1, dim>
    imbalance() const;

    /** |imbalance()| against the largest of the forces, or @p floor if
     * that is larger (0 without either): summary.json's force_imbalance.
     * With @p axial_only (an axisymmetric body, whose radial forces its
     * hoop stresses hold) the axial components alone. */
    double
    relative_imbalance(bool axial_only, double floor = 0) const;

    /** E max|u| (times 2 pi r_max in axisymmetry): the force that
     * displacements of the size of @p u cause in @p body, per unit
     * thickness. Against a millionth of it (the floor of
     * relative_imbalance() in the report and SelfChecks) the round-off of
     * the reactions of a body that carries no force is round-off, not a
     * relative error of 1. Collective over a partitioned mesh. */
    static double
    force_scale(const ElasticBody<dim> &body, const BodyVector &u);

  private:
    std::vector<Support> support_forces;
    Tensor<1, dim>       applied;
    Tensor<1, dim>       contact;
  };
} // namespace ddcontact

#endif
