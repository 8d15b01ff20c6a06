#include <ddcontact/solvers/contact_interface.h>

#include <cmath>

namespace ddcontact
{
  ContactInterface::ContactInterface(const ContactProblem &problem)
    : problem(problem)
  {
  }

  void
  ContactInterface::reinit()
  {
    offsets = {0};
    weights.clear();
    thetas.clear();
    scales.clear();
    points.clear();
    for (const auto *pair : problem.get_pairs())
    {
      const double c = surface_compliance(pair->get_body_1()) +
                       surface_compliance(pair->get_body_2());
      for (const auto &point : pair->points())
      {
        weights.push_back(point.JxW);
        thetas.push_back(pair->penalty());
        scales.push_back(pair->penalty() + point.JxW * c);
        points.push_back(point.x);
      }
      offsets.push_back(weights.size());
    }
  }

  double
  ContactInterface::surface_compliance(const ElasticBody<2> &body)
  {
    const auto &m = body.get_material();
    return (1. - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
  }

  double
  ContactInterface::inner(const PointVector &x, const PointVector &y) const
  {
    AssertDimension(x.size(), size());
    AssertDimension(y.size(), size());
    double sum = 0;
    for (unsigned int q = 0; q < x.size(); ++q)
      sum += weights[q] * x[q] * y[q];
    return sum;
  }

  double
  ContactInterface::norm(const PointVector &x) const
  {
    return std::sqrt(inner(x, x));
  }

  std::vector<std::vector<double>>
  ContactInterface::normal_stresses(const PointVector &p) const
  {
    AssertDimension(p.size(), size());
    std::vector<std::vector<double>> sigma_n(offsets.size() - 1);
    for (unsigned int k = 0; k + 1 < offsets.size(); ++k)
      for (unsigned int q = offsets[k]; q < offsets[k + 1]; ++q)
        sigma_n[k].push_back(-p[q]);
    return sigma_n;
  }

  PointVector
  ContactInterface::jump(const ContactProblem::Iterate &u) const
  {
    PointVector d;
    for (const auto *pair : problem.get_pairs())
    {
      std::vector<double> u_1n, u_2n;
      pair->normal_displacements(u[problem.body_index(pair->get_body_1())],
                                 u[problem.body_index(pair->get_body_2())],
                                 u_1n,
                                 u_2n);
      for (unsigned int q = 0; q < u_1n.size(); ++q)
        d.push_back(u_1n[q] + u_2n[q]);
    }
    return d;
  }

  PointVector
  ContactInterface::penetration(const ContactProblem::Iterate &u) const
  {
    PointVector d = jump(u);
    for (unsigned int k = 0; k + 1 < offsets.size(); ++k)
      for (unsigned int q = offsets[k]; q < offsets[k + 1]; ++q)
        d[q] -= problem.law(k).shifted_gap(q - offsets[k]);
    return d;
  }

  void
  ContactInterface::apply(const PointVector       &x,
                          ContactProblem::Iterate &u,
                          PointVector             &Sx) const
  {
    problem.solve_bodies(normal_stresses(x), u, true);
    // A pressure pushes the bodies apart: the jump is -S x.
    Sx = jump(u);
    for (double &v : Sx)
      v = -v;
    ++applications;
  }
} // namespace ddcontact
