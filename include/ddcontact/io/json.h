#ifndef ddcontact_io_json_h
#define ddcontact_io_json_h

#include <nlohmann/json.hpp>

#include <string>

namespace ddcontact
{
  /**
   * A JSON value for summary.json: nlohmann's JSON with the keys of an
   * object kept in insertion order, so that the file reads in the order the
   * run produced it. nlohmann writes non-finite numbers as null, never as
   * an invalid token (tests/json.cc checks it).
   */
  using Json = nlohmann::ordered_json;

  /**
   * Write @p json to @p filename with two-space indentation and a final
   * newline; throws std::runtime_error naming the file if it cannot.
   */
  void
  write_json_file(const Json &json, const std::string &filename);
} // namespace ddcontact

#endif
