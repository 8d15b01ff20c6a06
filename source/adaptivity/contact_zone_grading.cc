#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <ddcontact/adaptivity/contact_zone_grading.h>
#include <ddcontact/contact/segment_search.h>

#include <limits>

namespace ddcontact
{
  namespace
  {
    /** The length of the boundary face of @p cell nearest to @p x (the
     * face of S_2 on which the projection x lies). */
    double
    nearest_boundary_face_length(
      const Triangulation<2>::active_cell_iterator &cell, const Point<2> &x)
    {
      double h = 0, nearest = std::numeric_limits<double>::max();
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
        {
          const double d =
            closest_point_on_segment(face->vertex(0), face->vertex(1), x)
              .distance(x);
          if (d < nearest)
          {
            nearest = d;
            h       = face->vertex(0).distance(face->vertex(1));
          }
        }
      return h;
    }

    /** The processes of a p4est mesh find the cells of @p points (asked by
     * the first process, one cell per point: the search of deal.II's
     * RemotePointEvaluation, by the owned cells' bounding boxes, where a
     * point-by-point search on a partitioned mesh falls back to every
     * cell for each point outside the process's own). */
    Utilities::MPI::RemotePointEvaluation<2>
    locate(const Triangulation<2>      &tria,
           const Mapping<2>            &mapping,
           const std::vector<Point<2>> &points)
    {
      const bool root =
        Utilities::MPI::this_mpi_process(tria.get_communicator()) == 0;
      Utilities::MPI::RemotePointEvaluation<2> remote(1e-6, true);
      remote.reinit(root ? points : std::vector<Point<2>>(), tria, mapping);
      return remote;
    }

    /** Whether @p cell is not flagged yet and below @p max_level. */
    bool
    may_still_refine(const Triangulation<2>::active_cell_iterator &cell,
                     const unsigned int                            max_level)
    {
      return !cell->refine_flag_set() &&
             static_cast<unsigned int>(cell->level()) < max_level;
    }

    /** Whether the cell of @p body_1 that holds each point x (inside a
     * boundary face of S_1, so in one cell) is flagged for refinement (1)
     * or not (0): on a p4est mesh only its owner knows. */
    std::vector<unsigned int>
    flags_at_points(const ElasticBody<2>            &body_1,
                    const std::vector<ContactPoint> &points)
    {
      std::vector<unsigned int> halved(points.size(), 0);
      const auto               &tria_1 = body_1.get_triangulation();
      if (body_1.is_mesh_distributed())
      {
        std::vector<Point<2>> xs;
        for (const auto &point : points)
          xs.push_back(point.x);
        const auto remote = locate(tria_1, body_1.get_mapping(), xs);
        std::vector<unsigned int> flags, buffer;
        remote.evaluate_and_process<unsigned int>(
          flags,
          buffer,
          [&](const ArrayView<unsigned int> &values, const auto &cell_data)
          {
            for (unsigned int c = 0; c < cell_data.cells.size(); ++c)
            {
              const Triangulation<2>::active_cell_iterator cell(
                &tria_1, cell_data.cells[c].first, cell_data.cells[c].second);
              for (unsigned int k = cell_data.reference_point_ptrs[c];
                   k < cell_data.reference_point_ptrs[c + 1];
                   ++k)
                values[k] = cell->refine_flag_set() ? 1 : 0;
            }
          });
        const auto &ptrs = remote.get_point_ptrs();
        for (unsigned int q = 0; q + 1 < ptrs.size(); ++q)
          if (ptrs[q + 1] > ptrs[q])
            halved[q] = flags[ptrs[q]];
        halved =
          Utilities::MPI::broadcast(tria_1.get_communicator(), halved, 0);
      }
      else
      {
        GridTools::Cache<2, 2> cache_1(tria_1, body_1.get_mapping());
        typename Triangulation<2>::active_cell_iterator hint_1;
        for (unsigned int q = 0; q < points.size(); ++q)
        {
          const auto found_1 = GridTools::find_active_cell_around_point(
            cache_1, points[q].x, hint_1, {}, 1e-10);
          if (found_1.first.state() == IteratorState::valid)
          {
            hint_1    = found_1.first;
            halved[q] = found_1.first->refine_flag_set() ? 1 : 0;
          }
        }
      }
      return halved;
    }

    /** The cells of body 2 that hold the projections P(x), on a p4est
     * mesh: the owner of the cell that holds P(x) decides, with h_1 sent to
     * it. Returns the number flagged on all processes. */
    unsigned int
    flag_cells_at_projections_distributed(
      const ElasticBody<2>            &body_2,
      Triangulation<2>                &triangulation_2,
      const std::vector<ContactPoint> &points,
      const std::vector<double>       &h_1,
      const unsigned int               max_level,
      const double                     ratio)
    {
      unsigned int          flagged = 0;
      std::vector<Point<2>> projections;
      for (const auto &point : points)
        projections.push_back(point.projection);
      const auto remote =
        locate(triangulation_2, body_2.get_mapping(), projections);
      const bool root = Utilities::MPI::this_mpi_process(
                          triangulation_2.get_communicator()) == 0;
      std::vector<double> buffer;
      remote.process_and_evaluate<double>(
        root ? h_1 : std::vector<double>(),
        buffer,
        [&](const ArrayView<const double> &h_1_at, const auto &cell_data)
        {
          for (unsigned int c = 0; c < cell_data.cells.size(); ++c)
          {
            const Triangulation<2>::active_cell_iterator cell(
              &triangulation_2,
              cell_data.cells[c].first,
              cell_data.cells[c].second);
            for (unsigned int k = cell_data.reference_point_ptrs[c];
                 k < cell_data.reference_point_ptrs[c + 1] &&
                 may_still_refine(cell, max_level);
                 ++k)
            {
              const Point<2> x =
                body_2.get_mapping().transform_unit_to_real_cell(
                  cell, cell_data.reference_point_values[k]);
              if (nearest_boundary_face_length(cell, x) > ratio * h_1_at[k])
              {
                cell->set_refine_flag();
                ++flagged;
              }
            }
          }
        });
      return Utilities::MPI::sum(flagged, triangulation_2.get_communicator());
    }
  } // namespace

  unsigned int
  grade_contact_zone(const ContactPair &pair,
                     Triangulation<2>  &triangulation_2,
                     const unsigned int max_level,
                     const double       ratio)
  {
    const auto &body_2 = pair.get_body_2();
    const auto &zone_1 = pair.zone_faces_1();
    const auto &points = pair.points();

    const std::vector<unsigned int> halved =
      flags_at_points(pair.get_body_1(), points);
    // The face of S_1 that holds x as it will be: halved where its cell is
    // flagged.
    std::vector<double> h_1(points.size());
    for (unsigned int q = 0; q < points.size(); ++q)
      h_1[q] = zone_1[points[q].face][0].distance(zone_1[points[q].face][1]) /
               (halved[q] ? 2. : 1.);

    if (body_2.is_mesh_distributed())
      return flag_cells_at_projections_distributed(
        body_2, triangulation_2, points, h_1, max_level, ratio);

    unsigned int           flagged = 0;
    GridTools::Cache<2, 2> cache(triangulation_2, body_2.get_mapping());
    typename Triangulation<2>::active_cell_iterator hint;
    for (unsigned int q = 0; q < points.size(); ++q)
    {
      const auto found = GridTools::find_active_cell_around_point(
        cache, points[q].projection, hint, {}, 1e-10);
      if (found.first.state() != IteratorState::valid)
        continue;
      const auto cell = found.first;
      hint            = cell;
      if (may_still_refine(cell, max_level) &&
          nearest_boundary_face_length(cell, points[q].projection) >
            ratio * h_1[q])
      {
        cell->set_refine_flag();
        ++flagged;
      }
    }
    return flagged;
  }
} // namespace ddcontact
