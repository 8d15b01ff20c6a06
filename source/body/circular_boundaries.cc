#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ddcontact/body/circular_boundaries.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** The circle through @p x in the least-squares sense of Kasa's
     * algebraic fit (|x|^2 + a x_1 + b x_2 + c = 0), if every point lies
     * on it to 1e-8 of its radius. */
    bool
    fit_circle(const std::vector<Point<2>> &x, Point<2> &centre, double &radius)
    {
      // Points on a line (to round-off) span no circle.
      Point<2> mean;
      for (const auto &p : x)
        mean += p / static_cast<double>(x.size());
      double sxx = 0, sxy = 0, syy = 0;
      for (const auto &p : x)
      {
        sxx += (p[0] - mean[0]) * (p[0] - mean[0]);
        sxy += (p[0] - mean[0]) * (p[1] - mean[1]);
        syy += (p[1] - mean[1]) * (p[1] - mean[1]);
      }
      const double trace = sxx + syy;
      const double det   = sxx * syy - sxy * sxy;
      if (trace == 0 || det <= 1e-16 * trace * trace)
        return false;

      // Normal equations of the linear least-squares problem in (a, b, c),
      // in coordinates relative to the mean (for conditioning).
      FullMatrix<double> A(3, 3);
      Vector<double>     rhs(3), abc(3);
      for (const auto &p : x)
      {
        const double row[3] = {p[0] - mean[0], p[1] - mean[1], 1.};
        const double r2     = row[0] * row[0] + row[1] * row[1];
        for (unsigned int i = 0; i < 3; ++i)
        {
          for (unsigned int j = 0; j < 3; ++j)
            A(i, j) += row[i] * row[j];
          rhs(i) -= row[i] * r2;
        }
      }
      A.gauss_jordan();
      A.vmult(abc, rhs);
      centre          = mean + Point<2>(-abc(0) / 2, -abc(1) / 2);
      const double r2 = abc(0) * abc(0) / 4 + abc(1) * abc(1) / 4 - abc(2);
      if (!(r2 > 0) || !std::isfinite(r2))
        return false;
      radius = std::sqrt(r2);
      for (const auto &p : x)
        if (std::abs(p.distance(centre) - radius) > 1e-8 * radius)
          return false;
      return true;
    }
  } // namespace

  void
  CircularBoundaries::find(const Triangulation<2> &tria)
  {
    circles.clear();
    std::map<types::boundary_id, std::set<unsigned int>> vertices;
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        for (const unsigned int v : face->vertex_indices())
          vertices[face->boundary_id()].insert(face->vertex_index(v));
    for (const auto &[id, indices] : vertices)
    {
      if (indices.size() < 3)
        continue;
      std::vector<Point<2>> x;
      for (const unsigned int i : indices)
        x.push_back(tria.get_vertices()[i]);
      Circle circle{id, Point<2>(), 0.};
      if (fit_circle(x, circle.centre, circle.radius))
        circles.push_back(circle);
    }
  }

  void
  CircularBoundaries::snap(Triangulation<2> &tria) const
  {
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        for (const auto &circle : circles)
          if (face->boundary_id() == circle.id)
            for (const unsigned int v : face->vertex_indices())
            {
              Point<2>          &x = face->vertex(v);
              const Tensor<1, 2> r = x - circle.centre;
              x = circle.centre + (circle.radius / r.norm()) * r;
            }
  }

  std::vector<std::string>
  CircularBoundaries::describe() const
  {
    std::vector<std::string> lines;
    for (const auto &circle : circles)
    {
      std::ostringstream line;
      line << "id " << static_cast<unsigned int>(circle.id)
           << ": circle of radius " << circle.radius << " around ("
           << circle.centre << ")";
      lines.push_back(line.str());
    }
    return lines;
  }
} // namespace ddcontact
