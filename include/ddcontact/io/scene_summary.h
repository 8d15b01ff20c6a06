#ifndef ddcontact_scene_summary_h
#define ddcontact_scene_summary_h

#include <ddcontact/body/elastic_body.h>
#include <ddcontact/contact/contact_pair.h>

#include <string>

namespace ddcontact
{
  /** The console lines that describe a body as set up: cells, dofs,
   * element, and its curved boundaries and merged vertices. */
  std::string
  describe_body(const ElasticBody<2> &body);

  /** The console lines that describe a contact pair as set up: what the
   * contact search found, theta under the penalty (not with
   * @p exact_contact), and the setup's warnings. */
  std::string
  describe_contact_pair(const ContactPair &pair, bool exact_contact);
} // namespace ddcontact

#endif
