#include <deal.II/numerics/data_component_interpretation.h>

#include <ddcontact/io/contact_zone_writer.h>
#include <ddcontact/io/vtk_flags.h>
#include <ddcontact/output_file.h>

#include <fstream>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace ddcontact
{
  namespace
  {
    /** The pairs of contact points joined by a line cell: neighbours on
     * one face (the points of a face are ordered from its first end to its
     * second), and the points next to an end shared by two faces. A point
     * joined to none (a zone of one point) is joined to itself. */
    std::vector<std::pair<unsigned int, unsigned int>>
    segments(const ContactPair &pair)
    {
      const auto &points = pair.points();
      const auto &faces  = pair.zone_faces_1();
      const auto  none   = numbers::invalid_unsigned_int;
      // The first and the last point of every face.
      std::vector<std::array<unsigned int, 2>>           ends(faces.size(),
                                                    {{none, none}});
      std::vector<std::pair<unsigned int, unsigned int>> joined;
      for (unsigned int q = 0; q < points.size(); ++q)
      {
        auto &end = ends[points[q].face];
        if (end[0] == none)
          end[0] = q;
        else
          joined.emplace_back(end[1], q);
        end[1] = q;
      }
      // Faces meet where they share an end point (the same doubles).
      std::map<std::pair<double, double>, std::vector<unsigned int>> at;
      for (unsigned int f = 0; f < faces.size(); ++f)
        if (ends[f][0] != none)
          for (unsigned int e = 0; e < 2; ++e)
            at[{faces[f][e][0], faces[f][e][1]}].push_back(ends[f][e]);
      for (const auto &[vertex, near] : at)
        if (near.size() == 2)
          joined.emplace_back(near[0], near[1]);
      std::vector<bool> has_cell(points.size(), false);
      for (const auto &[a, b] : joined)
        has_cell[a] = has_cell[b] = true;
      for (unsigned int q = 0; q < points.size(); ++q)
        if (!has_cell[q])
          joined.emplace_back(q, q);
      return joined;
    }
  } // namespace

  ContactZoneWriter::ContactZoneWriter(const std::string &directory)
    : directory(directory)
  {
  }

  std::vector<std::string>
  ContactZoneWriter::field_names(const bool with_multipliers,
                                 const bool with_friction)
  {
    std::vector<std::string> names = {
      "pressure", "gap", "penetration", "u_1n", "u_2n", "active"};
    if (with_multipliers)
      names.emplace_back("multiplier");
    if (with_friction)
      for (const auto *name :
           {"tangential_traction", "slip_increment", "slip", "slip_state"})
        names.emplace_back(name);
    names.insert(names.end(), 2, "displacement");
    return names;
  }

  std::vector<DataOutBase::Patch<1, 2>>
  ContactZoneWriter::build_patches(const ContactPair         &pair,
                                   const ContactState        &state,
                                   const std::vector<double> &multipliers)
  {
    const auto &points = pair.points();
    AssertDimension(state.sigma_n.size(), points.size());
    Assert(multipliers.empty() || multipliers.size() == points.size(),
           ExcDimensionMismatch(multipliers.size(), points.size()));
    const auto        &body_1   = pair.get_body_1();
    const auto        &u_1      = body_1.get_solution();
    const bool         friction = !state.t.empty();
    const unsigned int n_fields =
      field_names(!multipliers.empty(), friction).size();

    // The fields of point q, in the order of field_names().
    const auto fields = [&](const unsigned int q)
    {
      const auto         &p = points[q];
      std::vector<double> v = {-state.sigma_n[q],
                               p.gap,
                               state.u_1n[q] + state.u_2n[q] - p.gap,
                               state.u_1n[q],
                               state.u_2n[q],
                               state.sigma_n[q] < 0 ? 1. : 0.};
      if (!multipliers.empty())
        v.push_back(-multipliers[q]);
      if (friction)
      {
        v.push_back(state.t[q]);
        v.push_back(state.slip_increment[q]);
        v.push_back(state.slip[q]);
        v.push_back(static_cast<double>(state.slip_state[q]));
      }
      Tensor<1, 2> u;
      for (unsigned int i = 0; i < p.values_1.size(); ++i)
        u[body_1.get_fe().system_to_component_index(i).first] +=
          p.values_1[i] * u_1(p.dofs_1[i]);
      v.push_back(u[0]);
      v.push_back(u[1]);
      return v;
    };

    std::vector<DataOutBase::Patch<1, 2>> patches;
    for (const auto &[a, b] : segments(pair))
    {
      DataOutBase::Patch<1, 2> patch;
      patch.vertices[0]    = points[a].x;
      patch.vertices[1]    = points[b].x;
      patch.n_subdivisions = 1;
      patch.patch_index    = patches.size();
      patch.reference_cell = ReferenceCells::Line;
      patch.data.reinit(n_fields, 2);
      const auto at_a = fields(a), at_b = fields(b);
      for (unsigned int c = 0; c < n_fields; ++c)
      {
        patch.data(c, 0) = at_a[c];
        patch.data(c, 1) = at_b[c];
      }
      patches.push_back(patch);
    }
    return patches;
  }

  void
  ContactZoneWriter::write_step(const unsigned int         step,
                                const double               time,
                                const ContactPair         &pair,
                                const ContactState        &state,
                                const std::vector<double> &multipliers)
  {
    const auto names = field_names(!multipliers.empty(), !state.t.empty());
    const std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      vectors = {{names.size() - 2,
                  names.size() - 1,
                  "displacement",
                  DataComponentInterpretation::component_is_part_of_vector}};

    std::ostringstream name;
    name << "contact_" << pair.name() << '-' << std::setw(4)
         << std::setfill('0') << step << ".vtu";
    OutputFile out(directory + "/" + name.str());
    out.write(
      [&](std::ostream &s)
      {
        DataOutBase::write_vtu(build_patches(pair, state, multipliers),
                               names,
                               vectors,
                               vtk_flags(),
                               s);
      });
    out.commit();

    auto &pair_records = records[pair.name()];
    pair_records.emplace_back(time, name.str());
    OutputFile pvd(directory + "/contact_" + pair.name() + ".pvd");
    pvd.write([&](std::ostream &s)
              { DataOutBase::write_pvd_record(s, pair_records); });
    pvd.commit();
  }
} // namespace ddcontact
