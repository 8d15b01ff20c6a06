#ifndef ddcontact_version_h
#define ddcontact_version_h

#include <string>

namespace ddcontact
{
  /** One line naming ddcontact's git revision, deal.II's version and the
   * number of threads, printed at the start of every run. */
  std::string
  version_banner();
} // namespace ddcontact

#endif
