

#include <ddcontact/adaptivity/adaptive_refinement.h>
#include <ddcontact/adaptivity/marking.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ddcontact
{
  namespace
  {
    /** Circumscribed and inscribed circle diameters of a triangle. */
    std::pair<double, double>
    triangle_diameters(const Point<2> &a, const Point<2> &b, const Point<2> &c)
    {
      const double ab = a.distance(b), bc = b.distance(c), ca = c.distance(a);
      const double area = 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) -
                                         (c[0] - a[0]) * (b[1] - a[1]));
      if (area == 0.)
        return {std::numeric_limits<double>::infinity(), 0.};
      // R = ab bc ca / (4 area), r = area / s with s the half perimeter.
      return {ab * bc * ca / (2. * area), 4. * area / (ab + bc + ca)};
    }
  } // namespace

  ElementDiameters
  element_diameters(const Triangulation<2> &triangulation)
  {
    ElementDiameters result;
    const auto       n = triangulation.n_active_cells();
    result.D.reinit(n);
    result.d.reinit(n);
    result.K.reinit(n);
    for (const auto &cell : triangulation.active_cell_iterators())
    {
      double             D = 0, d = std::numeric_limits<double>::max();
      const unsigned int nv = cell->n_vertices();
      // A triangle is its own (only) triangle; a quadrilateral gives the
      // four triangles of three of its vertices (Definition 1).
      for (unsigned int skip = 0; skip < (nv == 3 ? 1u : nv); ++skip)
      {
        std::array<Point<2>, 3> t;
        unsigned int            k = 0;
        for (unsigned int v = 0; v < nv; ++v)
          if (nv == 3 || v != skip)
            t[k++] = cell->vertex(v);
        const auto [Dt, dt] = triangle_diameters(t[0], t[1], t[2]);
        D                   = std::max(D, Dt);
        d                   = std::min(d, dt);
      }
      const unsigned int c = cell->active_cell_index();
      result.D(c)          = D;
      result.d(c)          = d;
      result.K(c)          = D / d; // Definition 2
    }
    return result;
  }

  AdaptiveRefinement::AdaptiveRefinement(ElasticBody<2>             &body,
                                         const AdaptationParameters &parameters)
    : body(body)
    , parameters(parameters)
  {
    if (parameters.mode == AdaptationMode::uniform)
      return;
    // Triangles refine locally like quadrilaterals; Kelly's indicator on
    // them is KellyEstimator's own face-jump integral (deal.II 9.4's
    // KellyErrorEstimator aborts on a triangle with a refined neighbour).
    estimator = ErrorEstimator::create(parameters.estimator, body);
    if (parameters.marking == MarkingType::threshold &&
        !estimator->comparable_with_delta())
      throw InputError("Adaptation/Marking: threshold compares eta with the "
                       "dimensionless delta of (27) and needs a fem-bem "
                       "estimator; use fraction or doerfler with kelly or "
                       "residual");
  }

  void
  AdaptiveRefinement::estimate(const BodyVector              &u_fem,
                               const BoundaryTractionSamples &contact)
  {
    AssertThrow(estimator, ExcMessage("uniform refinement estimates nothing"));
    estimator->estimate(u_fem, contact);
    eta                     = estimator->indicators();
    refinable_contributions = estimator->error_contributions();
    for (const auto &cell : body.get_triangulation().active_cell_iterators())
      if (static_cast<unsigned int>(cell->level()) >= parameters.max_level)
        refinable_contributions(cell->active_cell_index()) = 0.;
    // A distributed mesh holds eta on its own cells (zero elsewhere).
    eta_maximum = eta.linfty_norm();
    eta_total   = eta.l1_norm();
    if (body.is_mesh_distributed())
    {
      const MPI_Comm comm = body.get_triangulation().get_communicator();
      eta_maximum         = Utilities::MPI::max(eta_maximum, comm);
      eta_total           = Utilities::MPI::sum(eta_total, comm);
    }
  }

  unsigned int
  AdaptiveRefinement::mark_above_delta()
  {
    ddcontact::mark_above_delta(body.get_triangulation(), eta, parameters);
    return apply_caps();
  }

  unsigned int
  AdaptiveRefinement::mark_above(const double threshold)
  {
    for (const auto &cell : body.get_triangulation().active_cell_iterators())
    {
      cell->clear_refine_flag();
      const double contribution =
        refinable_contributions(cell->active_cell_index());
      if (contribution > 0 && contribution >= threshold)
        cell->set_refine_flag();
    }
    return apply_caps();
  }

  unsigned int
  AdaptiveRefinement::apply_caps()
  {
    auto        &tria   = body.get_triangulation();
    unsigned int marked = 0;
    capped              = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (body.computes(cell) && cell->refine_flag_set())
      {
        if (static_cast<unsigned int>(cell->level()) >= parameters.max_level)
        {
          cell->clear_refine_flag();
          ++capped;
        }
        else
          ++marked;
      }
    if (body.is_mesh_distributed())
    {
      marked = Utilities::MPI::sum(marked, tria.get_communicator());
      capped = Utilities::MPI::sum(capped, tria.get_communicator());
    }
    // Each refined cell, quadrilateral or triangle, becomes four (the
    // one-irregularity closure adds a few more, not counted here).
    const unsigned int n_cells = body.n_active_cells();
    if (n_cells + 3 * marked <= parameters.max_cells)
      return marked;
    // Over Max cells: an adaptive step keeps the flagged cells with the
    // largest error contributions that fit (dropping them all stalled one
    // body while the other went on), ties in the order of the cells' ids,
    // so that a p4est mesh keeps the cells one process keeps; uniform
    // refinement refines all or nothing.
    const unsigned int  budget = (parameters.mode == AdaptationMode::uniform ||
                                 n_cells >= parameters.max_cells)
                                   ? 0
                                   : (parameters.max_cells - n_cells) / 3;
    std::vector<double> contributions;
    std::vector<CellId> ids;
    for (const auto &cell : tria.active_cell_iterators())
      if (body.computes(cell) && cell->refine_flag_set())
      {
        contributions.push_back(
          parameters.mode == AdaptationMode::uniform
            ? 0.
            : refinable_contributions(cell->active_cell_index()));
        ids.push_back(cell->id());
      }
    const auto keep = keep_largest(
      contributions,
      ids,
      budget,
      body.is_mesh_distributed() ? tria.get_communicator() : MPI_COMM_SELF);
    unsigned int k = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (body.computes(cell) && cell->refine_flag_set() && !keep[k++])
        cell->clear_refine_flag();
    const unsigned int kept = std::min<unsigned int>(budget, marked);
    capped += marked - kept;
    return kept;
  }

  unsigned int
  AdaptiveRefinement::mark_all()
  {
    auto &tria = body.get_triangulation();
    for (const auto &cell : tria.active_cell_iterators())
      if (body.computes(cell))
        cell->set_refine_flag();
    // Uniform refinement obeys Max level and Max cells like the other
    // modes (it quadrupled the mesh every cycle until memory ran out).
    return apply_caps();
  }

  void
  AdaptiveRefinement::refine()
  {
    body.refine_and_transfer();
  }

  std::map<std::string, Vector<double>>
  AdaptiveRefinement::cell_data() const
  {
    const auto diameters = element_diameters(body.get_triangulation());
    std::map<std::string, Vector<double>> data;
    data["D_e"] = diameters.D;
    data["d_e"] = diameters.d;
    data["K_e"] = diameters.K;
    if (eta.size() == body.get_triangulation().n_active_cells())
      data["eta"] = eta;
    return data;
  }
  double
  relative_energy_error_estimate(
    const std::vector<std::unique_ptr<AdaptiveRefinement>> &adaptations)
  {
    double error2 = 0, norm2 = 0;
    bool   any = false;
    for (const auto &a : adaptations)
      if (const auto *estimator = a->fem_bem())
      {
        any = true;
        error2 += std::pow(estimator->energy_norm_error(), 2);
        norm2 += std::pow(estimator->energy_norm_of_stress(), 2);
      }
    return (!any) ? -1. : (norm2 > 0 ? std::sqrt(error2 / norm2) : 0.);
  }

} // namespace ddcontact
