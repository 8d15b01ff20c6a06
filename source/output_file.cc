#include <ddcontact/output_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace ddcontact
{
  OutputFile::OutputFile(const std::string &filename)
    : filename(filename)
    , temporary(filename + ".partial")
    , out(temporary)
  {
    if (!out)
      throw WriteError("cannot write '" + filename +
                       "': " + std::strerror(errno));
  }

  OutputFile::~OutputFile()
  {
    if (!committed)
    {
      out.close();
      std::remove(temporary.c_str());
    }
  }

  void
  OutputFile::commit()
  {
    out.flush();
    const bool written = static_cast<bool>(out);
    out.close();
    // A full disk shows as a failed flush or close; rename() only once the
    // whole file is there.
    if (!written || out.fail() ||
        std::rename(temporary.c_str(), filename.c_str()) != 0)
    {
      const std::string reason = std::strerror(errno);
      std::remove(temporary.c_str());
      committed = true;
      throw WriteError("cannot write '" + filename + "' (" + reason +
                       "); is the disk full or the directory read-only?");
    }
    committed = true;
  }
} // namespace ddcontact
