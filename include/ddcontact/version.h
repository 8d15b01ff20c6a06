#ifndef ddcontact_version_h
#define ddcontact_version_h

#include <string>

namespace ddcontact
{
  /** The short git revision the code was built from, "-modified" if its
   * tracked files differed from it ("unknown" outside a repository). */
  std::string
  git_revision();

  /** One line naming ddcontact's git revision, deal.II's version and the
   * number of threads, printed at the start of every run. */
  std::string
  version_banner();
} // namespace ddcontact

#endif
