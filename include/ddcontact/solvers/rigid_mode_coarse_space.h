#ifndef ddcontact_rigid_mode_coarse_space_h
#define ddcontact_rigid_mode_coarse_space_h

#include <deal.II/lac/full_matrix.h>

#include <ddcontact/contact/contact_interface.h>

#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The coarse problem of floating bodies in DDNewtonSolver (FETI's natural
   * coarse space): every floating body b is solved with a few components
   * clamped (RigidBodyModes), so its displacement is known only up to its
   * free rigid modes r_k, u_b = K_b^+ (f_b - contact load) + sum_k alpha_k
   * r_k, and it is in equilibrium only if the contact load does the
   * opposite work of its data on each mode. In the interface unknowns
   * (ContactInterface, inner product (.,.)_M):
   *
   *   d(p, alpha) = d_0 - S p + G alpha,   (G_k, p)_M = e_k,
   *
   * G_k = M^{-1} Psi W B r_k the averaged normal approach of mode k and
   * e_k its load (ElasticBody::get_mode_loads()). On an active set A the
   * Newton step of dd-newton is then the saddle point problem
   *
   *   (Theta + S_AA) p_A - G_A alpha = d_0,A,   G_A^T M_A p_A = e,
   *
   * solved by projected CG: p starts in equilibrium (correction()), and
   * residuals and search directions stay M-orthogonal to the columns of
   * G_A (project()), which the projector Q = I - G_A H^{-1} G_A^T M_A,
   * H = G_A^T M_A G_A, ensures. The amplitudes follow from the final
   * residual (amplitudes()). H is small (three per floating body) and
   * regular when the active set holds every mode (holds()).
   */
  class RigidModeCoarseSpace
  {
  public:
    RigidModeCoarseSpace(const ContactProblem   &problem,
                         const ContactInterface &interface);

    /**
     * G and e for the current meshes and interface. Throws InputError
     * naming the body when a combination of its modes moves no contact gap
     * at all (a punch free to slide along a flat zone): contact cannot hold
     * it.
     */
    void
    reinit();

    /** The number of floating modes of all bodies. */
    unsigned int
    size() const
    {
      return columns.size();
    }

    bool
    empty() const
    {
      return columns.empty();
    }

    /** "punch: free translation in y", for every floating body. */
    std::string
    description() const;

    /** Whether the unknowns @p active determine the amplitudes: H on
     * them is regular (relative to H on all unknowns). */
    bool
    holds(const std::vector<bool> &active) const;

    /** H on @p active and its inverse, for the functions below. */
    void
    set_active(const std::vector<bool> &active);

    /** c = G_A H^{-1} (e - G_A^T M x), zero off the active set: x + c is in
     * equilibrium. */
    PointVector
    correction(const PointVector &x) const;

    /** r <- Q r on the active set (zero off it). */
    void
    project(PointVector &r) const;

    /** H^{-1} G_A^T M_A r. */
    std::vector<double>
    amplitudes(const PointVector &r) const;

    /** G alpha at every unknown. */
    PointVector
    approach(const std::vector<double> &alpha) const;

    /** u_b += sum_k alpha_k r_k for every floating body. */
    void
    add_motion(const std::vector<double> &alpha,
               ContactProblem::Iterate   &u) const;

  private:
    /** H^{-1} @p m. */
    std::vector<double>
    solve(const std::vector<double> &m) const;

    /** G_A^T M r, one value per mode. */
    std::vector<double>
    moments(const PointVector &r) const;

    /** H on @p active (all unknowns where it is empty). */
    FullMatrix<double>
    gram(const std::vector<bool> &active) const;

    const ContactProblem                              &problem;
    const ContactInterface                            &interface;
    std::vector<PointVector>                           columns;  // G_k
    std::vector<double>                                loads;    // e_k
    std::vector<std::pair<unsigned int, unsigned int>> mode_of;  // (body, k)
    std::vector<double>                                diagonal; // H_kk, all
    std::vector<bool>                                  active;
    FullMatrix<double>                                 inverse; // H_A^{-1}
  };
} // namespace ddcontact

#endif
