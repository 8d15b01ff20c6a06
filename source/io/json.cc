#include <ddcontact/io/json.h>

#include <fstream>
#include <stdexcept>

namespace ddcontact
{
  void
  write_json_file(const Json &json, const std::string &filename)
  {
    std::ofstream out(filename);
    if (!out)
      throw std::runtime_error("cannot write '" + filename + "'");
    // Names from the input that are not valid UTF-8 are written with
    // U+FFFD instead of failing the run at its very end.
    out << json.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
  }
} // namespace ddcontact
