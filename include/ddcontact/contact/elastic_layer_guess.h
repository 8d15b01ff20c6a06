#ifndef ddcontact_elastic_layer_guess_h
#define ddcontact_elastic_layer_guess_h

#include <ddcontact/contact/contact_problem.h>

namespace ddcontact
{
  /** An initial iterate for the contact solvers, and whether it was kept. */
  struct ElasticLayerGuess
  {
    ContactProblem::Iterate u;
    /** False if the model started worse than zero and u is the zero
     * iterate. */
    bool accepted = true;
    /** The first DD step from the model's iterate over the step from zero
     * (l2 norms of the displacements of all bodies). */
    double step_ratio = 0;
  };

  /**
   * The elastic-layer (Winkler) model of the contact zones: each body acts
   * on its zone S like a bed of springs of stiffness E' / H (E' = E / (1 -
   * nu^2), H its thickness across S), in series with the penalty. The
   * pressure of this model, applied to the gap of the contact-free
   * solution, loads the bodies' first solve (20), whose solution is the
   * guess. The model knows neither bending nor chains of contacts, so the
   * guess is dropped (zero returned) when one step of (20) moves it ten
   * times more than it moves the zero iterate. Costs two or three solves of
   * every body.
   */
  ElasticLayerGuess
  elastic_layer_guess(const ContactProblem &problem);
} // namespace ddcontact

#endif
