#ifndef ddcontact_material_state_fields_h
#define ddcontact_material_state_fields_h

#include <deal.II/lac/vector.h>

#include <map>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  template <int dim>
  class ElasticBody;

  /** The scalars of a body's material state (MaterialLaw::
   * state_output_names(), e.g. the equivalent plastic strain) of the
   * current iterate, reduced over the body (and its processes). */
  struct MaterialStateSummary
  {
    /** The law's output names, and the largest value of each over the
     * body's quadrature points. */
    std::vector<std::string> names;
    std::vector<double>      largest;
    /** The area (plane strain, per unit thickness) or volume
     * (axisymmetric, 2 pi r dA) of the points whose output "yielded" is
     * positive: the plastic zone. 0 for a law without that output. */
    double yielded_measure = 0;
    /** The quadrature point where the first output is largest (where
     * plasticity starts: the depth of first yield). */
    std::vector<double> location_of_largest;

    /** Whether any point has yielded. */
    bool
    yielded() const
    {
      return yielded_measure > 0;
    }
  };

  /** The summary of @p body's current (trial) state: collective over the
   * processes of a distributed mesh. An empty summary for a law without
   * state outputs. */
  template <int dim>
  MaterialStateSummary
  summarize_material_state(const ElasticBody<dim> &body);

  /** Per active cell of @p body, the mean over its quadrature points of
   * each state output of the current state, by name (VTU cell data; zero
   * on cells this process does not compute). Empty without outputs. */
  template <int dim>
  std::map<std::string, Vector<double>>
  material_state_cell_fields(const ElasticBody<dim> &body);
} // namespace ddcontact

#endif
