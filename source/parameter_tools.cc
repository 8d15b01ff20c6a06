#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <ddcontact/parameter_tools.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace ddcontact
{
  namespace
  {
    /** deal.II's exception texts span several lines; we want one. */
    std::string
    one_line(const std::string &text)
    {
      std::string out;
      bool        space = false;
      for (const char c : text)
        if (c == '\n' || c == '\r' || c == '\t' || c == ' ')
          space = !out.empty();
        else
        {
          if (space)
            out += ' ';
          out += c;
          space = false;
        }
      return out;
    }

  } // namespace

  namespace parsing
  {
    std::string
    message_of(const std::exception &e)
    {
      if (const auto *dealii_exc = dynamic_cast<const ExceptionBase *>(&e))
      {
        std::ostringstream s;
        dealii_exc->print_info(s);
        return one_line(s.str());
      }
      return one_line(e.what());
    }

    unsigned int
    n_world_processes()
    {
      // A program that never initialized MPI (a test) is one process.
      return Utilities::MPI::job_supports_mpi()
               ? Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
               : 1;
    }

    std::vector<std::string>
    split(const std::string &text, const char delimiter)
    {
      std::vector<std::string> parts;
      for (const auto &p : Utilities::split_string_list(text, delimiter))
        if (!p.empty())
          parts.push_back(p);
      return parts;
    }

    unsigned int
    parse_boundary_id(const std::string &text, const std::string &what)
    {
      try
      {
        const int id = Utilities::string_to_int(Utilities::trim(text));
        if (id < 0 || id >= 255)
          throw InputError("");
        return static_cast<unsigned int>(id);
      }
      catch (...)
      {
        throw InputError(what + ": '" + text +
                         "' is not a boundary id (a non-negative integer)");
      }
    }

    double
    parse_double(const std::string &text, const std::string &what)
    {
      try
      {
        std::size_t  pos   = 0;
        const auto   t     = Utilities::trim(text);
        const double value = std::stod(t, &pos);
        if (pos != t.size() || !std::isfinite(value))
          throw InputError("");
        return value;
      }
      catch (...)
      {
        throw InputError(what + ": '" + text + "' is not a finite number");
      }
    }

    unsigned int
    edit_distance(const std::string &a, const std::string &b)
    {
      const auto lower = [](const char c)
      { return std::tolower(static_cast<unsigned char>(c)); };
      std::vector<unsigned int> row(b.size() + 1);
      for (unsigned int j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (unsigned int i = 1; i <= a.size(); ++i)
      {
        unsigned int diagonal = row[0];
        row[0]                = i;
        for (unsigned int j = 1; j <= b.size(); ++j)
        {
          const unsigned int above = row[j];
          row[j]                   = std::min({row[j] + 1,
                                               row[j - 1] + 1,
                                               diagonal + (lower(a[i - 1]) != lower(b[j - 1]))});
          diagonal                 = above;
        }
      }
      return row[b.size()];
    }
  } // namespace parsing

  void
  check_name(const std::string &name, const std::string &what)
  {
    // Names become file names (<body>-NNNN.vtu, contact_<pair>.csv) and
    // subsection names: a '/' or '..' would write elsewhere, and very long
    // names exceed the file system's limit.
    const bool safe =
      !name.empty() && name.size() <= 64 && name[0] != '.' &&
      std::all_of(name.begin(),
                  name.end(),
                  [](const char c)
                  {
                    return std::isalnum(static_cast<unsigned char>(c)) ||
                           c == '_' || c == '-' || c == '.';
                  });
    if (!safe)
      throw InputError(what + ": '" + name.substr(0, 80) +
                       (name.size() > 80 ? "...'" : "'") +
                       " is not a usable name (1 to 64 letters, digits, '_', "
                       "'-' or '.', not starting with '.')");
  }

  std::string
  read_bounded_file(const std::string &filename,
                    const std::size_t  max_bytes,
                    const std::string &what)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    // Devices, pipes and directories have no size to check in advance
    // (/dev/zero never ends): only regular files are read.
    if (!fs::is_regular_file(filename, error))
      throw InputError(what + " '" + filename + "' " +
                       (fs::exists(filename, error)
                          ? "is not a regular file"
                          : "does not exist or cannot be read"));
    const auto size = fs::file_size(filename, error);
    if (error || size > max_bytes)
      throw InputError(what + " '" + filename + "' has " +
                       std::to_string(size) + " bytes, more than the " +
                       std::to_string(max_bytes) + " bytes allowed");
    std::ifstream in(filename, std::ios::binary);
    if (!in)
      throw InputError(what + " '" + filename + "' cannot be read");
    std::string text(size, '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(in.gcount()));
    return text;
  }

  Point<2>
  parse_point(const std::string &text, const std::string &what)
  {
    const auto parts = Utilities::split_string_list(text, ',');
    if (parts.size() != 2)
      throw InputError(what + ": '" + text + "' is not a point 'x1, x2'");
    return Point<2>(parsing::parse_double(parts[0], what),
                    parsing::parse_double(parts[1], what));
  }

  Constants
  parse_constants(const std::string &text, const std::string &what)
  {
    Constants constants;
    for (const auto &item : parsing::split(text, ','))
    {
      const auto eq = item.find('=');
      if (eq == std::string::npos)
        throw InputError(what + ": '" + item + "' is not 'name=value'");
      const std::string name = Utilities::trim(item.substr(0, eq));
      if (name.empty() || name == "x" || name == "y")
        throw InputError(what + ": '" + item + "' has no usable name");
      constants[name] = parsing::parse_double(item.substr(eq + 1), what);
    }
    return constants;
  }

  std::shared_ptr<Function<2>>
  make_function(const std::string &expression,
                const unsigned int n_components,
                const Constants   &constants,
                const std::string &what,
                const bool         time_dependent)
  {
    const auto parts = Utilities::split_string_list(expression, ';');
    if (parts.size() != n_components)
      throw InputError(what + ": '" + expression + "' must have " +
                       std::to_string(n_components) +
                       " expression(s) separated by ';'");
    auto function = std::make_shared<FunctionParser<2>>(n_components);
    // muparser compiles lazily: evaluate once so that a syntax error shows
    // up here, with the entry's name, and not in a worker thread. deal.II
    // prints muparser's diagnosis to std::cerr before it throws; capture it
    // for our one-line message instead.
    std::ostringstream diagnosis;
    auto *const        cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
    try
    {
      // The load parameter t (Loading/Steps) is 1 unless a load step sets
      // it (Function::set_time()).
      // pi in every expression, unless the scene defines its own.
      Constants with_pi = constants;
      with_pi.emplace("pi", numbers::PI);
      function->initialize(
        time_dependent ? "x,y,t" : "x,y", parts, with_pi, time_dependent);
      function->set_time(1);
      Vector<double> values(n_components);
      function->vector_value(Point<2>(0.123, 0.456), values);
    }
    catch (...)
    {
      std::cerr.rdbuf(cerr_buffer);
      std::string message = diagnosis.str();
      const auto  start   = message.find("Message:");
      message =
        (start == std::string::npos)
          ? ""
          : message.substr(start + 8, message.find('\n', start) - start - 8);
      // A name muparser does not know: the load parameter t where the
      // entry has none, or a constant nobody defined.
      const std::string token = "Unexpected token \"";
      const auto        at    = message.find(token);
      if (at != std::string::npos)
      {
        const auto        close = message.find('"', at + token.size());
        const std::string name =
          message.substr(at + token.size(), close - at - token.size());
        if (name == "t" && !time_dependent)
          throw InputError(
            what + ": '" + expression +
            "' uses the load parameter t, which this entry does not have; t "
            "is defined in the Dirichlet and Neumann conditions and the body "
            "force (Body <name>/Boundary conditions) only");
        if (!name.empty() &&
            (std::isalpha(static_cast<unsigned char>(name[0])) ||
             name[0] == '_'))
          throw InputError(what + ": '" + expression + "' uses '" + name +
                           "', which is not defined: x, y" +
                           (time_dependent ? ", t" : "") +
                           ", pi and the scene's Constants are");
      }
      throw InputError(what + ": cannot parse '" + expression + "'" +
                       (message.empty() ? "" : ": " + one_line(message)));
    }
    std::cerr.rdbuf(cerr_buffer);
    return function;
  }

} // namespace ddcontact
