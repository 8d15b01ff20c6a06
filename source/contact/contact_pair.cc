#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <ddcontact/contact/contact_pair.h>
#include <ddcontact/contact/contact_search.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace ddcontact
{
  std::string
  point_coordinates(const Point<2> &x)
  {
    std::ostringstream s;
    s << std::setprecision(std::numeric_limits<double>::max_digits10) << '('
      << x[0] << ", " << x[1] << ')';
    return s.str();
  }

  ContactPair::ContactPair(const ContactPairParameters &parameters,
                           const ElasticBody<2>        &body_1,
                           const ElasticBody<2>        &body_2,
                           const Constants             &constants)
    : parameters(parameters)
    , body_1(body_1)
    , body_2(body_2)
  {
    if (parameters.gap_type == GapType::expression)
      gap_function = make_function(parameters.gap_expression,
                                   1,
                                   constants,
                                   "Contact pair " + parameters.name + "/Gap");
    if (has_friction())
      friction_function = make_function(parameters.friction_expression(),
                                        1,
                                        constants,
                                        parameters.friction_entry());
  }

  double
  ContactPair::default_search_distance(const double h_max) const
  {
    const auto diameter = [](const ElasticBody<2> &body)
    {
      const auto x = body.get_mesh().extent_along(Tensor<1, 2>({1., 0.}));
      const auto y = body.get_mesh().extent_along(Tensor<1, 2>({0., 1.}));
      return std::hypot(x.second - x.first, y.second - y.first);
    };
    return std::max(0.1 * std::min(diameter(body_1), diameter(body_2)),
                    2. * h_max);
  }

  std::vector<std::string>
  ContactPair::setup_warnings() const
  {
    std::vector<std::string> warnings;
    const std::string        pair = "contact pair " + parameters.name + ": ";
    std::ostringstream       s;
    s << std::setprecision(3);
    // Entries the chosen law or gap leaves unused: said, so that a run
    // meant with friction or with a gap expression is not taken silently
    // for one without (issue 60).
    const auto unused = [&](const std::string &entry,
                            const std::string &value,
                            const std::string &because)
    {
      if (Utilities::trim(value) != "0")
        warnings.push_back(pair + entry + " = " + value +
                           " is not used: " + because);
    };
    if (parameters.friction != FrictionLaw::tresca)
      unused("Friction bound",
             parameters.friction_bound,
             "Friction = " + selection_name(parameters.friction) +
               " (tresca uses it)");
    if (parameters.friction != FrictionLaw::coulomb)
      unused("Friction coefficient",
             parameters.friction_coefficient,
             "Friction = " + selection_name(parameters.friction) +
               " (coulomb uses it)");
    if (parameters.gap_type == GapType::geometric)
      unused("Gap",
             parameters.gap_expression,
             "Gap type = geometric measures the gap between the meshes "
             "(Gap type = expression uses it)");
    if (report.n_points == 0)
    {
      s << pair << "no point of the zone of '" << body_1.name()
        << "' (boundary id " << parameters.boundary_id_1
        << ") faces the zone of '" << body_2.name() << "' (boundary id "
        << parameters.boundary_id_2 << ") within the search distance "
        << report.search_distance
        << ": the zones face away from each other or lie farther apart, and "
           "the pair carries no force (raise Contact pair "
        << parameters.name
        << "/Search distance if a wider gap is meant to close)";
      warnings.push_back(s.str());
      return warnings;
    }
    if (report.min_gap <
        -ContactSearchReport::overlap_per_face * report.min_gap_face_length)
    {
      s << pair
        << "initial overlap: at x = " << point_coordinates(report.min_gap_at)
        << " the gap is " << report.min_gap << ", "
        << (gap_function ? "the Gap expression puts" : "the meshes put")
        << " body '" << body_1.name() << "' that deep inside body '"
        << body_2.name()
        << "' before any load, and the contact pushes them apart by as much "
           "(an interference fit if meant; otherwise check the meshes' "
           "positions"
        << (gap_function ? " and the Gap" : "") << ")";
      warnings.push_back(s.str());
      s.str("");
    }
    if (report.worst_excess > 0)
    {
      s << pair << "the Gap expression '" << parameters.gap_expression
        << "' gives " << report.worst_expression
        << " at x = " << point_coordinates(report.worst_excess_at)
        << ", where the meshes are " << report.worst_geometric
        << " apart along the normal (geometric gap): the expression lets the "
           "bodies touch across empty space; use Gap type = geometric, or a "
           "Gap that matches the meshes";
      warnings.push_back(s.str());
      s.str("");
    }
    if (report.hidden_overlap > 0)
    {
      s << pair << "the meshes overlap by " << report.hidden_overlap
        << " at x = " << point_coordinates(report.hidden_overlap_at)
        << ", which the Gap expression '" << parameters.gap_expression << "' ("
        << report.hidden_expression
        << " there) leaves out: the bodies start inside each other by more "
           "than the gap says; use Gap type = geometric, or place the meshes "
           "where the Gap puts them";
      warnings.push_back(s.str());
      s.str("");
    }
    // A law whose bound vanishes on the whole zone is frictionless: said,
    // not solved silently (a sweep over mu may mean it).
    if (has_friction() &&
        std::all_of(contact_points.begin(),
                    contact_points.end(),
                    [](const ContactPoint &p) { return p.friction == 0; }))
    {
      s << pair << parameters.friction_entry()
        << " is 0 on the whole zone: the contact is frictionless (Friction "
           "= none solves the same without tangential unknowns)";
      warnings.push_back(s.str());
    }
    return warnings;
  }

  double
  ContactPair::multiplier_side_ratio() const
  {
    // A cell of body 2 by the dofs its points couple to.
    std::set<unsigned int>                         faces_1;
    std::set<std::vector<types::global_dof_index>> cells_2;
    for (const auto &p : contact_points)
    {
      faces_1.insert(p.face);
      cells_2.insert(p.dofs_2);
    }
    return cells_2.empty() ? 0. : double(faces_1.size()) / cells_2.size();
  }

  void
  ContactPair::normal_displacements(const BodyVector    &u_1,
                                    const BodyVector    &u_2,
                                    std::vector<double> &u_1n,
                                    std::vector<double> &u_2n) const
  {
    u_1n.resize(contact_points.size());
    u_2n.resize(contact_points.size());
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto &p  = contact_points[q];
      double      v1 = 0, v2 = 0;
      for (unsigned int i = 0; i < p.a.size(); ++i)
        v1 += p.a[i] * u_1(p.dofs_1[i]);
      for (unsigned int i = 0; i < p.b.size(); ++i)
        v2 += p.b[i] * u_2(p.dofs_2[i]);
      u_1n[q] = v1;
      u_2n[q] = v2;
    }
  }

  std::vector<double>
  ContactPair::slips(const BodyVector &u_1, const BodyVector &u_2) const
  {
    std::vector<double> s(contact_points.size());
    if (!has_friction())
      return s;
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto &p = contact_points[q];
      for (unsigned int i = 0; i < p.at.size(); ++i)
        s[q] += p.at[i] * u_1(p.dofs_1[i]);
      for (unsigned int i = 0; i < p.bt.size(); ++i)
        s[q] += p.bt[i] * u_2(p.dofs_2[i]);
    }
    return s;
  }

  std::pair<Tensor<1, 2>, Tensor<1, 2>>
  ContactPair::add_friction_loads(const std::vector<double> &t,
                                  BodyVector                &load_1,
                                  BodyVector                &load_2) const
  {
    AssertDimension(t.size(), contact_points.size());
    Tensor<1, 2> force_1, force_2;
    if (!has_friction())
      return {force_1, force_2};
    const auto &fe_1 = body_1.get_fe();
    const auto &fe_2 = body_2.get_fe();
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      if (t[q] == 0.)
        continue;
      // The traction -t tau_a on body a, as sigma_n n_a for the normal.
      const auto  &p = contact_points[q];
      const double s = -t[q] * p.JxW;
      for (unsigned int i = 0; i < p.at.size(); ++i)
        force_1[fe_1.system_to_component_index(i).first] += s * p.at[i];
      for (unsigned int i = 0; i < p.bt.size(); ++i)
        force_2[fe_2.system_to_component_index(i).first] += s * p.bt[i];
      for (unsigned int i = 0; i < p.load_t1.size(); ++i)
        load_1(p.load_dofs_1[i]) += s * p.load_t1[i];
      for (unsigned int i = 0; i < p.load_t2.size(); ++i)
        load_2(p.load_dofs_2[i]) += s * p.load_t2[i];
    }
    return {force_1, force_2};
  }

  std::pair<Tensor<1, 2>, Tensor<1, 2>>
  ContactPair::add_contact_loads(const std::vector<double> &sigma_n,
                                 BodyVector                &load_1,
                                 BodyVector                &load_2) const
  {
    AssertDimension(sigma_n.size(), contact_points.size());
    const auto  &fe_1 = body_1.get_fe();
    const auto  &fe_2 = body_2.get_fe();
    Tensor<1, 2> force_1, force_2;
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      if (sigma_n[q] == 0.)
        continue;
      const auto  &p = contact_points[q];
      const double s = sigma_n[q] * p.JxW;
      for (unsigned int i = 0; i < p.a.size(); ++i)
        force_1[fe_1.system_to_component_index(i).first] += s * p.a[i];
      for (unsigned int i = 0; i < p.b.size(); ++i)
        force_2[fe_2.system_to_component_index(i).first] += s * p.b[i];
      // The constraints are resolved in the load coefficients.
      for (unsigned int i = 0; i < p.load_1.size(); ++i)
        load_1(p.load_dofs_1[i]) += s * p.load_1[i];
      for (unsigned int i = 0; i < p.load_2.size(); ++i)
        load_2(p.load_dofs_2[i]) += s * p.load_2[i];
    }
    return {force_1, force_2};
  }

  void
  ContactPair::add_unconstrained_contact_load(
    const std::vector<double> &sigma_n,
    const ElasticBody<2>      &body,
    BodyVector                &load) const
  {
    AssertDimension(sigma_n.size(), contact_points.size());
    Assert(&body == &body_1 || &body == &body_2, ExcInternalError());
    const bool on_body_1 = (&body == &body_1);
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto  &p            = contact_points[q];
      const double s            = sigma_n[q] * p.JxW;
      const auto  &dofs         = on_body_1 ? p.dofs_1 : p.dofs_2;
      const auto  &coefficients = on_body_1 ? p.a : p.b;
      for (unsigned int i = 0; i < dofs.size(); ++i)
        load(dofs[i]) += s * coefficients[i];
    }
  }

  void
  ContactPair::add_unconstrained_friction_load(const std::vector<double> &t,
                                               const ElasticBody<2>      &body,
                                               BodyVector &load) const
  {
    if (t.empty())
      return;
    AssertDimension(t.size(), contact_points.size());
    Assert(&body == &body_1 || &body == &body_2, ExcInternalError());
    const bool on_body_1 = (&body == &body_1);
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto  &p            = contact_points[q];
      const double s            = -t[q] * p.JxW;
      const auto  &dofs         = on_body_1 ? p.dofs_1 : p.dofs_2;
      const auto  &coefficients = on_body_1 ? p.at : p.bt;
      for (unsigned int i = 0; i < dofs.size(); ++i)
        load(dofs[i]) += s * coefficients[i];
    }
  }

  void
  ContactPair::add_traction_samples(const std::vector<double> &sigma_n,
                                    const ElasticBody<2>      &body,
                                    BoundaryTractionSamples   &samples,
                                    const std::vector<double> &t) const
  {
    AssertDimension(sigma_n.size(), contact_points.size());
    Assert(&body == &body_1 || &body == &body_2, ExcInternalError());
    const bool on_body_1 = (&body == &body_1);
    for (unsigned int q = 0; q < contact_points.size(); ++q)
    {
      const auto &p = contact_points[q];
      samples.points.push_back(on_body_1 ? p.x : p.projection);
      samples.weights.push_back(p.JxW);
      Tensor<1, 2> traction = sigma_n[q] * p.normal;
      if (!t.empty())
        traction -= t[q] * Tensor<1, 2>({-p.normal[1], p.normal[0]});
      samples.traction.push_back(on_body_1 ? traction : -traction);
    }
  }
} // namespace ddcontact
