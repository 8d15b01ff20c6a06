// Cost of ContactPair::setup(), the search of the contact points on S_1 and
// of their closest points P(x) on S_2 (section 1 of doc/method.md), against
// the number of contact points: two bodies (0, 1) x (0, h) and (0, 1) x
// (h, 2h), one row of cells each, with N and N + 1 faces on the zone (non-
// matching) and the zone of the upper body bent upwards by a parabola (a
// geometric gap up to 2e-3, oblique faces). Two Gauss points per piece of
// the common refinement: about 4 N contact points. Times setup() only (the
// bodies' dofs and constraints are built before).
// Writes one CSV row per size to the file given as first argument (or to
// stdout); a second argument gives one number of contact points. The last
// column is a checksum of every point's position, weight, gap, projection
// and body-2 coefficients: equal checksums mean bit for bit equal points.
// Run in Release (doc/contact-setup.md).
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/grid/grid_tools.h>

#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/segment_search.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>

using namespace ddcontact;

namespace
{
  /** FNV-1a over the bytes of @p value, into @p hash. */
  template <typename T>
  void
  mix(std::uint64_t &hash, const T &value)
  {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (const unsigned char byte : bytes)
      hash = (hash ^ byte) * 1099511628211ULL;
  }

  std::uint64_t
  checksum(const std::vector<ContactPoint> &points)
  {
    std::uint64_t hash = 14695981039346656037ULL;
    for (const auto &p : points)
    {
      for (unsigned int c = 0; c < 2; ++c)
      {
        mix(hash, p.x[c]);
        mix(hash, p.projection[c]);
      }
      mix(hash, p.JxW);
      mix(hash, p.gap);
      for (const auto dof : p.dofs_2)
        mix(hash, dof);
      for (const double b : p.b)
        mix(hash, b);
    }
    return hash;
  }

  BodyParameters
  block(const std::string &name,
        const double       y0,
        const double       y1,
        const unsigned int n,
        const std::string &dirichlet,
        const std::string &contact_id)
  {
    BodyParameters p;
    p.name         = name;
    p.corner_1     = Point<2>(0., y0);
    p.corner_2     = Point<2>(1., y1);
    p.subdivisions = {n, 1};
    p.dirichlet    = dirichlet;
    p.contact_ids  = contact_id;
    return p;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    file;
  if (argc > 1)
    file.open(argv[1]);
  std::ostream &csv = (argc > 1) ? file : std::cout;

  std::vector<unsigned int> targets = {1000, 10000, 100000, 1000000};
  if (argc > 2)
    targets = {static_cast<unsigned int>(std::stoul(argv[2]))};

  csv << "contact_points,faces_1,faces_2,setup_s,search_s,checksum"
      << std::endl;
  for (const unsigned int target : targets)
  {
    const unsigned int n = std::max(1u, target / 4);
    const double       h = 0.01;
    ElasticBody<2>     lower(block("lower", 0., h, n, "2: xy: 0; 0", "3"),
                         Constants());
    ElasticBody<2> upper(block("upper", h, 2 * h, n + 1, "3: xy: 0; 0", "2"),
                         Constants());
    lower.make_mesh();
    upper.make_mesh();
    GridTools::transform(
      [&](const Point<2> &x)
      { return Point<2>(x[0], x[1] + 8e-3 * x[0] * (1. - x[0])); },
      upper.get_triangulation());
    lower.setup_system();
    upper.setup_system();

    ContactPairParameters parameters;
    parameters.name          = "S";
    parameters.body_1        = "lower";
    parameters.body_2        = "upper";
    parameters.boundary_id_1 = 3;
    parameters.boundary_id_2 = 2;
    parameters.gap_type      = GapType::geometric;
    parameters.n_gauss       = 2;
    ContactPair pair(parameters, lower, upper, Constants());

    Timer timer;
    pair.setup();
    const double seconds = timer.wall_time();

    std::vector<std::array<Point<2>, 2>> segments_2;
    for (const auto &face : upper.get_triangulation().active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == 2)
        segments_2.push_back({{face->vertex(0), face->vertex(1)}});
    timer.restart();
    const SegmentSearch search(segments_2);
    std::size_t         found = 0;
    for (const auto &p : pair.points())
      found += search.closest_point(p.x).first;
    for (const auto &[a, b] : pair.zone_faces_1())
      found += search.end_points_over(a, b).size();
    const double search_seconds = timer.wall_time();
    AssertThrow(found > 0, ExcInternalError());

    csv << pair.points().size() << ',' << n << ',' << n + 1 << ','
        << std::setprecision(4) << seconds << ',' << search_seconds << ','
        << std::hex << checksum(pair.points()) << std::dec << std::endl;
  }
  return 0;
}
