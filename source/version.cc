#include <deal.II/base/multithread_info.h>
#include <deal.II/base/revision.h>

#include <ddcontact/git_revision.h>
#include <ddcontact/version.h>

#include <sstream>

namespace ddcontact
{
  std::string
  git_revision()
  {
    return DDCONTACT_GIT_REVISION;
  }

  std::string
  version_banner()
  {
    std::ostringstream s;
    s << "ddcontact (git " << git_revision() << "), deal.II "
      << DEAL_II_PACKAGE_VERSION << ", "
#ifdef DEBUG
      << "debug build, "
#else
      << "release build, "
#endif
      << dealii::MultithreadInfo::n_threads() << " threads";
    return s.str();
  }
} // namespace ddcontact
