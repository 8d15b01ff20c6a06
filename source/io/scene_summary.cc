#include <ddcontact/io/scene_summary.h>

#include <iomanip>
#include <sstream>

namespace ddcontact
{
  std::string
  describe_body(const ElasticBody<2> &body)
  {
    std::ostringstream s;
    s << "  body " << std::setw(10) << std::left << body.name() << std::right
      << std::setw(9) << body.n_active_cells() << " cells " << std::setw(9)
      << body.n_dofs() << " dofs  ("
      << (body.is_simplex() ? "triangles" : "quadrilaterals")
      << (body.is_mesh_distributed() ? ", p4est" : "") << ", "
      << body.get_fe().get_name() << ")\n";
    for (const auto &circle : body.get_mesh().circular_boundaries())
      s << "    " << body.name() << ", curved boundary " << circle << '\n';
    if (body.get_mesh().n_merged_vertices() > 0)
      s << "    " << body.name() << ", merged "
        << body.get_mesh().n_merged_vertices()
        << " coincident vertices of its mesh file (Mesh/Merge coincident "
           "vertices)\n";
    return s.str();
  }

  std::string
  describe_contact_pair(const ContactPair &pair, const bool exact_contact)
  {
    std::ostringstream s;
    const auto        &found = pair.search_report();
    s << "  contact pair " << pair.name() << ": " << pair.get_body_1().name()
      << " -> " << pair.get_body_2().name() << ", " << found.n_points << " of "
      << found.n_examined
      << " points of S_1 face S_2 within the search distance "
      << found.search_distance;
    if (found.n_points > 0)
    {
      s << ", initial gap " << found.min_gap - found.interference << " to "
        << found.max_gap - found.interference;
      if (found.interference != 0)
        s << " (with the Interference " << found.interference << ")";
    }
    if (!exact_contact)
      s << ", theta = " << pair.penalty();
    s << '\n';
    for (const auto &warning : pair.setup_warnings())
      s << "warning: " << warning << '\n';
    return s.str();
  }
} // namespace ddcontact
