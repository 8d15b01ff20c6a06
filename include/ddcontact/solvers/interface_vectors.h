#ifndef ddcontact_interface_vectors_h
#define ddcontact_interface_vectors_h

#include <ddcontact/contact/contact_problem.h>
#include <ddcontact/solvers/contact_interface.h>

namespace ddcontact
{
  /** x += a y, for the interface unknowns of dd-newton. */
  inline void
  add(PointVector &x, const double a, const PointVector &y)
  {
    for (unsigned int q = 0; q < x.size(); ++q)
      x[q] += a * y[q];
  }

  /** u += a v for the bodies' responses. */
  inline void
  add(ContactProblem::Iterate       &u,
      const double                   a,
      const ContactProblem::Iterate &v)
  {
    for (unsigned int b = 0; b < u.size(); ++b)
      u[b].add(a, v[b]);
  }

  /** x <- (1 - tau) x + tau y. */
  inline void
  blend(PointVector &x, const double tau, const PointVector &y)
  {
    for (unsigned int q = 0; q < x.size(); ++q)
      x[q] = (1 - tau) * x[q] + tau * y[q];
  }

  inline void
  blend(ContactProblem::Iterate       &u,
        const double                   tau,
        const ContactProblem::Iterate &v)
  {
    for (unsigned int b = 0; b < u.size(); ++b)
      u[b].sadd(1 - tau, tau, v[b]);
  }
} // namespace ddcontact

#endif
