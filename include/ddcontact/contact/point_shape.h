#ifndef ddcontact_point_shape_h
#define ddcontact_point_shape_h

#include <deal.II/dofs/dof_handler.h>

#include <ddcontact/body/elastic_body.h>

#include <string>
#include <vector>

// The shape functions of a body at the contact points, as
// ContactPair::setup() gathers them into ContactPoint.
namespace ddcontact
{
  using namespace dealii;

  struct ContactPoint;

  /**
   * What the cell holding a point knows of it: the cell's dofs, the
   * value of every shape function at the point (of its one nonzero
   * component), and the body's constraint of every dof (n_entries[i] < 0:
   * none; otherwise that many entries of masters/weights, none for a
   * Dirichlet dof). Sent between processes by RemotePointEvaluation.
   */
  struct PointShape
  {
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  values;
    std::vector<int>                     n_entries;
    std::vector<types::global_dof_index> masters;
    std::vector<double>                  weights;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &dofs &values &n_entries &masters &weights;
    }
  };

  /** PointShape at @p points, given in real coordinates, of one @p cell. */
  std::vector<PointShape>
  point_shapes_at(const ElasticBody<2>                      &body,
                  const DoFHandler<2>::active_cell_iterator &cell,
                  const std::vector<Point<2>>               &points);

  /** PointShape at @p points of a distributed mesh: the owners of the
   * cells around the points evaluate and send (collective). InputError
   * naming @p section where a point lies in no cell. */
  std::vector<PointShape>
  remote_point_shapes(const ElasticBody<2>        &body,
                      const std::vector<Point<2>> &points,
                      const std::string           &section);

  /** The coefficients and loads of @p p from the shapes of both bodies
   * there (see ContactPoint), and with friction the tangent's and the
   * law's coefficient g or mu (@p friction, InputError naming @p entry
   * where it is < 0 or not finite). */
  void
  couple_point(ContactPoint         &p,
               const PointShape     &shape_1,
               const PointShape     &shape_2,
               const ElasticBody<2> &body_1,
               const ElasticBody<2> &body_2,
               const Function<2>    *friction,
               const std::string    &entry);
} // namespace ddcontact

#endif
