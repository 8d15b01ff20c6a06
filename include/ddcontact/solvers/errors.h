#ifndef ddcontact_errors_h
#define ddcontact_errors_h

#include <stdexcept>

namespace ddcontact
{
  /** An iteration diverged or stopped short of its tolerance; the message
   * says what to change. The executable exits with code 4. */
  class DivergenceError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace ddcontact

#endif
