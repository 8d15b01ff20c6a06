#include <deal.II/base/mpi.h>

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
    const auto            &points = pair.points();
    GridTools::Cache<2, 2> cache_1(body_1.get_triangulation(),
                                   body_1.get_mapping());
    GridTools::Cache<2, 2> cache(triangulation_2, body_2.get_mapping());
    unsigned int           flagged = 0;
    typename Triangulation<2>::active_cell_iterator hint, hint_1;

    // Whether the cell of body 1 that holds each point x (inside a
    // boundary face of S_1, so in one cell) is flagged: on a p4est mesh
    // only its owner knows.
    std::vector<unsigned int> halved(points.size(), 0);
    for (unsigned int q = 0; q < points.size(); ++q)
    {
      const auto found_1 = GridTools::find_active_cell_around_point(
        cache_1, points[q].x, hint_1, {}, 1e-10);
      if (found_1.first.state() == IteratorState::valid &&
          body_1.computes(found_1.first))
      {
        hint_1    = found_1.first;
        halved[q] = found_1.first->refine_flag_set() ? 1 : 0;
      }
    }
    if (body_1.is_mesh_distributed())
    {
      const int ierr =
        MPI_Allreduce(MPI_IN_PLACE,
                      halved.data(),
                      halved.size(),
                      MPI_UNSIGNED,
                      MPI_MAX,
                      body_1.get_triangulation().get_communicator());
      AssertThrowMPI(ierr);
    }

    for (unsigned int q = 0; q < points.size(); ++q)
    {
      const auto &point = points[q];
      // The face of S_1 as it will be: halved where its cell is flagged.
      double h_1 = zone_1[point.face][0].distance(zone_1[point.face][1]);
      if (halved[q])
        h_1 /= 2;
      const auto found = GridTools::find_active_cell_around_point(
        cache, point.projection, hint, {}, 1e-10);
      if (found.first.state() != IteratorState::valid ||
          !body_2.computes(found.first))
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
    return body_2.is_mesh_distributed()
             ? Utilities::MPI::sum(flagged, triangulation_2.get_communicator())
             : flagged;
  }
} // namespace ddcontact
