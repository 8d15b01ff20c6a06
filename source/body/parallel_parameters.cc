#include <ddcontact/body/parallel_parameters.h>

#include <cctype>

#include <algorithm>
#include <cmath>

namespace ddcontact
{
  using parsing::n_world_processes;
  using parsing::parse_double;
  using parsing::split;

  // "list" is no entry value: any other text is read as the list.
  DDCONTACT_SELECTION(BodyOwners,
                      {"auto", BodyOwners::automatic},
                      {"all", BodyOwners::all})
  DDCONTACT_SELECTION(MeshPartition,
                      {"auto", MeshPartition::automatic},
                      {"shared", MeshPartition::shared},
                      {"distributed", MeshPartition::distributed})

  void
  ParallelParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Body owners",
      "auto",
      Patterns::Anything(),
      "Under mpirun: the processes that solve each body's problem (20). "
      "'auto': with at most as many processes as bodies, each body on one "
      "process (balancing the dofs, again after every refinement); with more "
      "processes, every body on its own group of processes, the group sizes "
      "in proportion to the dofs. 'all': every body on all processes, one "
      "body after the other. Or a list 'name: 0, name: 1-3' for every body "
      "(a process or a range of processes). A body on several processes has "
      "its mesh partitioned between them and is solved by a distributed "
      "solver (Trilinos: Amesos MUMPS, or CG with ML AMG).");
    prm.declare_entry(
      "Mesh",
      "auto",
      selection_pattern<MeshPartition>(),
      "How the mesh of a body solved by several processes is split. "
      "'distributed': parallel::distributed::Triangulation (p4est), each "
      "process of the body's group keeps only its cells and a ghost layer, "
      "the other processes none; for quadrilateral bodies. "
      "'shared': parallel::shared::Triangulation, every process keeps the "
      "whole mesh and assembles its part. 'auto': distributed where "
      "possible, shared elsewhere.");
  }

  bool
  ParallelParameters::distributed_mesh(const BodyParameters &body,
                                       const unsigned int    n_processes) const
  {
    if (n_processes <= 1 || mesh == MeshPartition::shared)
      return false;
    return body.cell_type == CellType::quadrilateral;
  }

  MeshKind
  ParallelParameters::mesh_kind(const BodyParameters &body,
                                const unsigned int    n_processes,
                                const unsigned int    n_bodies) const
  {
    if (!process_groups(n_processes, n_bodies))
      return MeshKind::serial;
    return distributed_mesh(body, n_processes) ? MeshKind::distributed
                                               : MeshKind::shared;
  }

  bool
  ParallelParameters::process_groups(const unsigned int n_processes,
                                     const unsigned int n_bodies) const
  {
    if (n_processes <= 1)
      return false;
    if (mode == BodyOwners::all)
      return true;
    if (mode == BodyOwners::automatic)
      return n_processes > n_bodies;
    for (const auto &[name, group] : body_groups)
      if (group.size() > 1)
        return true;
    return false;
  }

  void
  ParallelParameters::parse(ParameterHandler               &prm,
                            const std::vector<std::string> &body_names)
  {
    body_groups.clear();
    mesh                   = parse_selection<MeshPartition>(prm.get("Mesh"));
    const std::string text = prm.get("Body owners");
    if (is_selection<BodyOwners>(text))
    {
      mode = parse_selection<BodyOwners>(text);
      return;
    }
    mode                           = BodyOwners::list;
    const unsigned int n_processes = n_world_processes();
    const auto         rank        = [&](const std::string &entry,
                          const std::string &what) -> unsigned int
    {
      const double r = parse_double(entry, what);
      if (r < 0 || r != std::floor(r) || r >= n_processes)
        throw InputError(what + ": process " + entry +
                         " does not exist in a run on " +
                         std::to_string(n_processes) + " processes");
      return static_cast<unsigned int>(r);
    };
    // Empty items ("a: 0,, b: 1") are refused, not skipped.
    {
      std::string joined;
      for (const char c : text)
        if (!std::isspace(static_cast<unsigned char>(c)))
          joined += c;
      if (joined.find(",,") != std::string::npos || joined.front() == ',' ||
          joined.back() == ',')
        throw InputError("Parallel/Body owners: '" + text +
                         "' has an empty item between its commas");
    }
    for (const auto &item : split(text, ','))
    {
      const auto what  = "Parallel/Body owners: '" + item + "'";
      const auto parts = split(item, ':');
      if (parts.size() != 2)
        throw InputError(what + " is not 'body: process' or "
                                "'body: first-last'");
      if (Utilities::trim(parts[1]).rfind('-', 0) == 0)
        throw InputError(what + ": a process number cannot be negative");
      if (body_groups.count(parts[0]))
        throw InputError(what + ": body '" + parts[0] +
                         "' is listed twice; give each body once");
      if (std::find(body_names.begin(), body_names.end(), parts[0]) ==
          body_names.end())
        throw InputError(what + ": '" + parts[0] +
                         "' is not one of the Bodies");
      const auto         range = split(parts[1], '-');
      const unsigned int first = rank(range[0], what);
      const unsigned int last =
        range.size() == 2 ? rank(range[1], what) : first;
      if (range.size() > 2 || last < first)
        throw InputError(what + ": '" + parts[1] +
                         "' is not a process or a range first-last");
      auto &group = body_groups[parts[0]];
      group.clear();
      for (unsigned int r = first; r <= last; ++r)
        group.push_back(r);
    }
    for (const auto &name : body_names)
      if (body_groups.count(name) == 0)
        throw InputError("Parallel/Body owners: body '" + name +
                         "' is not listed");
  }

} // namespace ddcontact
