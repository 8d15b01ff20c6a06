#ifndef ddcontact_parameter_tools_h
#define ddcontact_parameter_tools_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <cstddef>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * An error in the user's input: a parameter, a file or a value. main()
   * prints its message as one line and exits with a non-zero code. The
   * message names the parameter (with its section) or the file.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /** Named constants usable in every expression ("r0=1e-3, Delta=..."). */
  using Constants = std::map<std::string, double>;

  /**
   * The entry values of an option and their enum values: the one table
   * that the entry's Patterns::Selection (selection_pattern()), the parser
   * (parse_selection()) and the printing (selection_name()) share, so that
   * a string is turned into an enum value once, when the file is read.
   * Each parameter header declares the tables of its enums with
   * DDCONTACT_DECLARE_SELECTION, its source defines them with
   * DDCONTACT_SELECTION.
   */
  template <typename Enum>
  const std::vector<std::pair<std::string, Enum>> &
  selection_names();

#define DDCONTACT_DECLARE_SELECTION(Enum) \
  template <>                             \
  const std::vector<std::pair<std::string, Enum>> &selection_names<Enum>();

#define DDCONTACT_SELECTION(Enum, ...)                                     \
  template <>                                                              \
  const std::vector<std::pair<std::string, Enum>> &selection_names<Enum>() \
  {                                                                        \
    static const std::vector<std::pair<std::string, Enum>> names = {       \
      __VA_ARGS__};                                                        \
    return names;                                                          \
  }

  /** Patterns::Selection("a|b|...") of the entry values of @p Enum, in the
   * order of its table. */
  template <typename Enum>
  Patterns::Selection
  selection_pattern()
  {
    std::string names;
    for (const auto &entry : selection_names<Enum>())
      names += (names.empty() ? "" : "|") + entry.first;
    return Patterns::Selection(names);
  }

  /** Whether @p value is one of the entry values of @p Enum. */
  template <typename Enum>
  bool
  is_selection(const std::string &value)
  {
    for (const auto &entry : selection_names<Enum>())
      if (entry.first == value)
        return true;
    return false;
  }

  /** The enum value of an entry that a Patterns::Selection has checked
   * already. */
  template <typename Enum>
  Enum
  parse_selection(const std::string &value)
  {
    for (const auto &[name, e] : selection_names<Enum>())
      if (name == value)
        return e;
    AssertThrow(false, ExcMessage("unexpected selection '" + value + "'"));
    return Enum();
  }

  /** The entry value of @p value, as the file and the messages write it. */
  template <typename Enum>
  std::string
  selection_name(const Enum value)
  {
    for (const auto &[name, e] : selection_names<Enum>())
      if (e == value)
        return name;
    return "";
  }

  /** Refuse a body, pair or scene name that is not safe as part of a file
   * name; `what` names the entry. */
  void
  check_name(const std::string &name, const std::string &what);

  /** The contents of a regular file of at most @p max_bytes, read without
   * reading further (devices and pipes are refused); `what` names the
   * file's role in errors ("parameter file", "Body a/Mesh/File"). */
  std::string
  read_bounded_file(const std::string &filename,
                    std::size_t        max_bytes,
                    const std::string &what);

  /** Parse "x1, x2" into a point; `what` names the entry in errors. */
  Point<2>
  parse_point(const std::string &text, const std::string &what);

  /** Parse "name=value, name=value". */
  Constants
  parse_constants(const std::string &text, const std::string &what);

  /** A vector-valued FunctionParser in x, y, checked; `what` names the
   * entry in the error message if the expression does not parse. With
   * @p time_dependent also in the load parameter t (Loading/Steps), whose
   * value is the function's time, 1 until set. */
  std::shared_ptr<Function<2>>
  make_function(const std::string &expression,
                unsigned int       n_components,
                const Constants   &constants,
                const std::string &what,
                bool               time_dependent = false);

  /** Small pieces of the parsers of the parameter structs. */
  namespace parsing
  {
    /** The non-empty, trimmed parts of @p text between the delimiters. */
    std::vector<std::string>
    split(const std::string &text, char delimiter);

    /** A boundary id 0..254; `what` names the entry in errors. */
    unsigned int
    parse_boundary_id(const std::string &text, const std::string &what);

    /** A finite number; `what` names the entry in errors. */
    double
    parse_double(const std::string &text, const std::string &what);

    /** The size of MPI_COMM_WORLD, or 1 if MPI was never initialized. */
    unsigned int
    n_world_processes();

    /** The message of @p e on one line (deal.II's span several). */
    std::string
    message_of(const std::exception &e);

    /** The edit distance of @p a and @p b, ignoring case (the closest
     * name to a misspelled one). */
    unsigned int
    edit_distance(const std::string &a, const std::string &b);
  } // namespace parsing
} // namespace ddcontact

#endif
