#ifndef ddcontact_parameter_messages_h
#define ddcontact_parameter_messages_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The words of a parameter mistake (issue 60): what deal.II's
   * ParameterHandler reports in its own terms ("No entry with name <X> was
   * declared", "does not match the given pattern: [Double ...]",
   * "unequal numbers of 'subsection' and 'end'") said in the user's: the
   * entry with its section, the value, why it is refused and what to write
   * instead ("did you mean", the subsection an entry belongs in, a number
   * without units, a decimal point, the list of a selection, the line of a
   * subsection without its `end`). Each function returns the part of the
   * line after the location, which the caller names.
   */
  namespace parameter_messages
  {
    /** The keyword of a parameter-file line (lower case: "subsection",
     * "set", "end", ...) and the rest of the line, comments removed. */
    std::pair<std::string, std::string>
    split_keyword(const std::string &line);

    /** Follow one line (split_keyword()) through the subsections: @p path
     * gains the subsection the line opens and loses the one it ends. */
    void
    follow_sections(std::vector<std::string>                  &path,
                    const std::pair<std::string, std::string> &line);

    /** "A/B/C" of @p path. */
    std::string
    joined(const std::vector<std::string> &path);

    /** "a, b or c" of @p names (empty if there are none): the choices a
     * message offers, e.g. the solvers or estimators that can take a
     * scene. */
    std::string
    alternatives(const std::vector<std::string> &names);

    /** The subsection @p name, which @p prm does not declare in @p parent
     * (a path, empty: the top level), with the declared sibling closest
     * to it if one is close. */
    std::string
    unknown_subsection(const std::string      &parent,
                       const std::string      &name,
                       const ParameterHandler &prm);

    /** The entry @p entry, which @p prm does not declare in @p section: the
     * closest entry of the section if one is close ("did you mean"), else
     * the subsections that declare an entry of that name ("an entry of
     * 'Contact pair S'"). */
    std::string
    unknown_entry(const std::string      &section,
                  const std::string      &entry,
                  const ParameterHandler &prm);

    /** The @p value of entry @p entry in @p section that does not match
     * deal.II's pattern @p pattern ("[Double 0...MAX_DOUBLE (inclusive)]",
     * "[Selection a|b ]", ...): why, and what to write. */
    std::string
    bad_value(const std::string &section,
              const std::string &entry,
              const std::string &value,
              const std::string &pattern);

    /** deal.II's complaint @p message about a value split into the entry,
     * the value and the pattern; false if it is not of that form. Knows
     * "The entry value V for the entry named N does not match the given
     * pattern: P" (a file) and "The string <V> does not match the given
     * pattern <P>" (ParameterHandler::set(), N left empty). */
    bool
    split_value_message(const std::string &message,
                        std::string       &entry,
                        std::string       &value,
                        std::string       &pattern);

    /** In @p text, whose subsections and ends do not balance, the line
     * (from 1) of the subsection that misses its `end` (or of an `end`
     * without a subsection) and what is wrong there; @p prm tells
     * which subsections can hold which. */
    std::pair<unsigned int, std::string>
    unbalanced_sections(const std::string &text, const ParameterHandler &prm);
  } // namespace parameter_messages
} // namespace ddcontact

#endif
