#include <ddcontact/io/json.h>
#include <ddcontact/output_file.h>

#include <fstream>
#include <stdexcept>

namespace ddcontact
{
  void
  write_json_file(const Json &json, const std::string &filename)
  {
    OutputFile file(filename);
    // Names from the input that are not valid UTF-8 are written with
    // U+FFFD instead of failing the run at its very end.
    file.stream() << json.dump(2, ' ', false, Json::error_handler_t::replace)
                  << '\n';
    file.commit();
  }
} // namespace ddcontact
