#ifndef ddcontact_contact_zone_grading_h
#define ddcontact_contact_zone_grading_h

#include <deal.II/grid/tria.h>

#include <ddcontact/contact/contact_pair.h>

namespace ddcontact
{
  using namespace dealii;

  /**
   * Keep S_2 at least as fine as S_1 where they touch. Exact contact puts
   * its multipliers on the nodes of S_1 (doc/method.md 1.3); where the
   * adapted S_1 is finer than the facing S_2, the multiplier space is too
   * rich for the displacements of S_2 (the discrete inf-sup condition of
   * mortar methods fails) and the pressure oscillates from node to node.
   * Measured on the paper's scene with Kelly adaptation from coarse
   * meshes: a peak 3.1 % high at 6.8e3 unknowns, 1.5 % at 2.4e4, where the
   * same meshes with the pair's sides swapped give 0.16 % and 0.02 %.
   *
   * After marking, flags the cells of body 2 (@p triangulation_2, its
   * mesh) that hold the projection P(x) of a point of S_1 and whose face
   * there is longer than @p ratio times the face of S_1 that holds x as it
   * will be (halved where its cell is flagged), below @p max_level.
   * Returns the number of cells flagged (on all processes). On a p4est
   * mesh the owner of a cell decides; whether the cell of body 1 that
   * holds x is flagged is gathered from its owner. With it the peak above falls
   * to 0.96 %, 0.15 % and 0.04 % after 3, 5 and 7 cycles.
   */
  unsigned int
  grade_contact_zone(const ContactPair &pair,
                     Triangulation<2>  &triangulation_2,
                     const unsigned int max_level,
                     const double       ratio = 1.5);
} // namespace ddcontact

#endif
