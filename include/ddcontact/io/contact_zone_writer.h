#ifndef ddcontact_io_contact_zone_writer_h
#define ddcontact_io_contact_zone_writer_h

#include <deal.II/base/data_out_base.h>

#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/contact_problem.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Writes the contact zone S_1 of every contact pair for ParaView: per
   * output step one file contact_<pair>-NNNN.vtu of line cells along S_1,
   * and a record per step in contact_<pair>.pvd, next to the bodies'
   * solution.pvd.
   *
   * The vertices of the line cells are the contact points x of S_1 (the
   * Gauss points of the common refinement of the two meshes, where the
   * contact integral of (20) is evaluated): consecutive points of a face
   * of S_1 are joined, and so are the last point of a face and the first
   * of the next one; ParaView interpolates linearly between the points.
   * Every point carries
   * - pressure = -sigma_n (20), >= 0;
   * - gap f_n, penetration u_1n + u_2n - f_n (> 0 where the bodies overlap),
   *   u_1n and u_2n;
   * - active: 1 where sigma_n < 0, else 0;
   * - multiplier: -lambda of the augmented Lagrangian (only with it);
   * - displacement: u_1(x), so that the zone sits at its undeformed place
   *   and "Warp By Vector" moves it with body 1, as it moves the bodies.
   *
   * The values are those of contact_<pair>.csv (RunReport), from the same
   * ContactState. Process 0 writes (every process holds all points).
   */
  class ContactZoneWriter
  {
  public:
    explicit ContactZoneWriter(const std::string &directory);

    /**
     * Write step @p step (labelled @p time) of @p pair in the state
     * @p state; @p multipliers are the augmented Lagrangian's lambda at
     * the pair's points, empty without it.
     */
    void
    write_step(unsigned int               step,
               double                     time,
               const ContactPair         &pair,
               const ContactState        &state,
               const std::vector<double> &multipliers);

    /** The line cells of the zone of @p pair with the fields above (also
     * for tests). */
    static std::vector<DataOutBase::Patch<1, 2>>
    build_patches(const ContactPair         &pair,
                  const ContactState        &state,
                  const std::vector<double> &multipliers);

    /** The names of the fields of build_patches(), in their order. */
    static std::vector<std::string>
    field_names(bool with_multipliers, bool with_friction = false);

  private:
    const std::string directory;
    /** The .pvd records of every pair, by pair name. */
    std::map<std::string, std::vector<std::pair<double, std::string>>> records;
  };
} // namespace ddcontact

#endif
