#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <ddcontact/adaptivity/contact_zone_grading.h>
#include <ddcontact/contact/segment_search.h>

#include <limits>

namespace ddcontact
{
  unsigned int
  grade_contact_zone(const ContactPair &pair,
                     Triangulation<2>  &triangulation_2,
                     const unsigned int max_level,
                     const double       ratio)
  {
    const auto            &body_1 = pair.get_body_1();
    const auto            &body_2 = pair.get_body_2();
    const auto            &zone_1 = pair.zone_faces_1();
    GridTools::Cache<2, 2> cache_1(body_1.get_triangulation(),
                                   body_1.get_mapping());
    GridTools::Cache<2, 2> cache(triangulation_2, body_2.get_mapping());
    unsigned int           flagged = 0;
    typename Triangulation<2>::active_cell_iterator hint, hint_1;
    for (const auto &point : pair.points())
    {
      // The face of S_1 as it will be: halved where its cell is flagged.
      double     h_1 = zone_1[point.face][0].distance(zone_1[point.face][1]);
      const auto found_1 = GridTools::find_active_cell_around_point(
        cache_1, point.x, hint_1, {}, 1e-10);
      if (found_1.first.state() == IteratorState::valid)
      {
        hint_1 = found_1.first;
        if (found_1.first->refine_flag_set())
          h_1 /= 2;
      }
      const auto found = GridTools::find_active_cell_around_point(
        cache, point.projection, hint, {}, 1e-10);
      if (found.first.state() != IteratorState::valid)
        continue;
      const auto cell = found.first;
      hint            = cell;
      if (cell->refine_flag_set() ||
          static_cast<unsigned int>(cell->level()) >= max_level)
        continue;
      // The face of the cell on which P(x) lies: the nearest boundary face.
      double h_2 = 0, nearest = std::numeric_limits<double>::max();
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
        {
          const double d = closest_point_on_segment(
                             face->vertex(0), face->vertex(1), point.projection)
                             .distance(point.projection);
          if (d < nearest)
          {
            nearest = d;
            h_2     = face->vertex(0).distance(face->vertex(1));
          }
        }
      if (h_2 > ratio * h_1)
      {
        cell->set_refine_flag();
        ++flagged;
      }
    }
    return flagged;
  }
} // namespace ddcontact
