#ifndef ddcontact_io_json_h
#define ddcontact_io_json_h

#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace ddcontact
{
  /**
   * A small JSON value for summary.json: null, number, bool, string, array
   * or object (keys kept in insertion order so that the file reads in the
   * order the run produced it). Non-finite numbers are written as null,
   * never as an invalid token.
   */
  class Json
  {
  public:
    Json();
    Json(double number);
    Json(int number);
    Json(unsigned int number);
    Json(unsigned long number);
    Json(bool flag);
    Json(const char *text);
    Json(const std::string &text);

    static Json
    array();

    static Json
    object();

    /** Append to an array. */
    Json &
    push_back(const Json &value);

    /** Set (or replace) a key of an object. */
    Json &
    set(const std::string &key, const Json &value);

    /** Whether an object has @p key. */
    bool
    has(const std::string &key) const;

    /** The value of @p key of an object; throws std::out_of_range. */
    const Json &
    get(const std::string &key) const;

    /** Item @p i of an array; throws std::out_of_range. */
    const Json &
    at(unsigned int i) const;

    /** The value of a number (0 for anything else). */
    double
    as_number() const
    {
      return number;
    }

    /** Write with two-space indentation. */
    void
    write(std::ostream &out, unsigned int indent = 0) const;

    /** Write to a file; throws std::runtime_error if it cannot. */
    void
    write_file(const std::string &filename) const;

  private:
    enum class Kind
    {
      null,
      number,
      boolean,
      string,
      array,
      object
    };
    Kind                                      kind;
    double                                    number = 0;
    bool                                      flag   = false;
    std::string                               text;
    std::vector<Json>                         items;
    std::vector<std::pair<std::string, Json>> members;
  };

  /** A JSON array of numbers. */
  Json
  json_array(const std::vector<double> &values);
} // namespace ddcontact

#endif
