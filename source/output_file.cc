#include <ddcontact/output_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ddcontact
{
  OutputFile::OutputFile(const std::string &filename)
    : filename(filename)
    , temporary(filename + ".partial")
  {
    // Listed before it exists: a crash leaves nothing unlisted.
    run_manifest::record_temporary(temporary);
    out.open(temporary);
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
    if (written && !out.fail())
      run_manifest::record_file(temporary, filename);
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

  namespace run_manifest
  {
    namespace
    {
      // The manifest's directory and path; the path also as a C string
      // for the signal handler, which may not allocate.
      std::filesystem::path directory_path;
      std::string           manifest;
      char                  manifest_for_handler[4096] = "";

      /** Append @p line to the manifest in one write(). */
      void
      append(const std::string &line)
      {
        const int fd =
          ::open(manifest.c_str(), O_WRONLY | O_APPEND | O_CREAT, 0644);
        if (fd < 0)
          throw WriteError("cannot write '" + manifest +
                           "': " + std::strerror(errno));
        const bool complete = ::write(fd, line.data(), line.size()) ==
                              static_cast<ssize_t>(line.size());
        if (::close(fd) != 0 || !complete)
          throw WriteError("cannot write '" + manifest +
                           "'; is the disk full?");
      }

      /** The decimal digits of @p value at the end of @p buffer (for the
       * signal handler, without snprintf). */
      char *
      digits(long long value, char *end)
      {
        const bool         negative = value < 0;
        unsigned long long v =
          negative ? 0ull - static_cast<unsigned long long>(value) : value;
        do
        {
          *--end = static_cast<char>('0' + v % 10);
          v /= 10;
        } while (v > 0);
        if (negative)
          *--end = '-';
        return end;
      }
    } // namespace

    void
    open(const std::string &directory)
    {
      directory_path = std::filesystem::path(directory).lexically_normal();
      manifest       = directory + "/" + file_name;
      if (manifest.size() < sizeof(manifest_for_handler))
        std::strcpy(manifest_for_handler, manifest.c_str());
    }

    void
    close()
    {
      manifest_for_handler[0] = '\0';
      manifest.clear();
      directory_path.clear();
    }

    bool
    lists(const std::string &path)
    {
      if (manifest.empty())
        return false;
      const auto parent =
        std::filesystem::path(path).lexically_normal().parent_path();
      std::error_code error;
      return parent == directory_path ||
             std::filesystem::equivalent(parent, directory_path, error);
    }

    void
    record_temporary(const std::string &temporary)
    {
      if (lists(temporary))
        append("temp " + std::filesystem::path(temporary).filename().string() +
               '\n');
    }

    void
    record_file(const std::string &path, const std::string &name)
    {
      const std::string &listed = name.empty() ? path : name;
      if (!lists(listed))
        return;
      const auto [size, time] = stamp(path);
      std::ostringstream line;
      line << "file " << size << ' ' << time << ' '
           << std::filesystem::path(listed).filename().string() << '\n';
      append(line.str());
    }

    void
    record_file_from_signal_handler(const char *path)
    {
      struct stat status;
      if (manifest_for_handler[0] == '\0' || ::stat(path, &status) != 0)
        return;
      char  line[512];
      char *end = line + 200; // the numbers are written backwards to here
      char *start =
        digits(static_cast<long long>(status.st_mtim.tv_sec) * 1000000000ll +
                 status.st_mtim.tv_nsec,
               end);
      *--start = ' ';
      start    = digits(static_cast<long long>(status.st_size), start);
      const char prefix[] = "file ";
      start -= sizeof(prefix) - 1;
      std::memcpy(start, prefix, sizeof(prefix) - 1);
      const char *name         = std::strrchr(path, '/');
      name                     = name ? name + 1 : path;
      *end++                   = ' ';
      const std::size_t length = std::strlen(name);
      if (length > static_cast<std::size_t>(line + sizeof(line) - end - 1))
        return;
      std::memcpy(end, name, length);
      end += length;
      *end++ = '\n';
      const int fd =
        ::open(manifest_for_handler, O_WRONLY | O_APPEND | O_CREAT, 0644);
      if (fd < 0)
        return;
      [[maybe_unused]] const auto written = ::write(fd, start, end - start);
      ::close(fd);
    }

    Contents
    read(const std::string &directory)
    {
      Contents      contents;
      std::ifstream in(directory + "/" + file_name);
      std::string   line;
      while (std::getline(in, line))
      {
        std::istringstream fields(line);
        std::string        kind;
        fields >> kind;
        if (kind == "temp")
        {
          std::string name;
          std::getline(fields >> std::ws, name);
          if (!name.empty())
            contents.temporaries.insert(name);
        }
        else if (kind == "file")
        {
          std::uintmax_t size = 0;
          long long      time = 0;
          std::string    name;
          if (fields >> size >> time && std::getline(fields >> std::ws, name) &&
              !name.empty())
            contents.files[name].insert({size, time});
        }
      }
      return contents;
    }

    std::pair<std::uintmax_t, long long>
    stamp(const std::string &path)
    {
      struct stat status;
      if (::stat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode))
        return {0, -1};
      return {static_cast<std::uintmax_t>(status.st_size),
              static_cast<long long>(status.st_mtim.tv_sec) * 1000000000ll +
                status.st_mtim.tv_nsec};
    }
  } // namespace run_manifest
} // namespace ddcontact
