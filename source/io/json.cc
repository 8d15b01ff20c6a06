#include <ddcontact/io/json.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace ddcontact
{
  Json::Json()
    : kind(Kind::null)
  {
  }

  Json::Json(const double number)
    : kind(Kind::number)
    , number(number)
  {
  }

  Json::Json(const int number)
    : Json(static_cast<double>(number))
  {
  }

  Json::Json(const unsigned int number)
    : Json(static_cast<double>(number))
  {
  }

  Json::Json(const unsigned long number)
    : Json(static_cast<double>(number))
  {
  }

  Json::Json(const bool flag)
    : kind(Kind::boolean)
    , flag(flag)
  {
  }

  Json::Json(const char *text)
    : kind(Kind::string)
    , text(text)
  {
  }

  Json::Json(const std::string &text)
    : kind(Kind::string)
    , text(text)
  {
  }

  Json
  Json::array()
  {
    Json j;
    j.kind = Kind::array;
    return j;
  }

  Json
  Json::object()
  {
    Json j;
    j.kind = Kind::object;
    return j;
  }

  Json &
  Json::push_back(const Json &value)
  {
    if (kind != Kind::array)
      throw std::logic_error("Json::push_back on a non-array");
    items.push_back(value);
    return *this;
  }

  Json &
  Json::set(const std::string &key, const Json &value)
  {
    if (kind != Kind::object)
      throw std::logic_error("Json::set on a non-object");
    for (auto &m : members)
      if (m.first == key)
      {
        m.second = value;
        return *this;
      }
    members.emplace_back(key, value);
    return *this;
  }

  namespace
  {
    void
    write_string(std::ostream &out, const std::string &s)
    {
      out << '"';
      for (const char c : s)
        switch (c)
        {
          case '"':
            out << "\\\"";
            break;
          case '\\':
            out << "\\\\";
            break;
          case '\n':
            out << "\\n";
            break;
          case '\t':
            out << "\\t";
            break;
          default:
            if (static_cast<unsigned char>(c) < 0x20)
              out << "\\u" << std::hex << std::setw(4) << std::setfill('0')
                  << static_cast<int>(c) << std::dec;
            else
              out << c;
        }
      out << '"';
    }
  } // namespace

  void
  Json::write(std::ostream &out, const unsigned int indent) const
  {
    const std::string pad(indent + 2, ' '), end_pad(indent, ' ');
    switch (kind)
    {
      case Kind::null:
        out << "null";
        break;
      case Kind::number:
        if (std::isfinite(number))
        {
          std::ostringstream s;
          s << std::setprecision(std::numeric_limits<double>::max_digits10)
            << number;
          out << s.str();
        }
        else
          out << "null";
        break;
      case Kind::boolean:
        out << (flag ? "true" : "false");
        break;
      case Kind::string:
        write_string(out, text);
        break;
      case Kind::array:
      {
        // Short arrays of scalars on one line.
        bool scalars = items.size() <= 4;
        for (const auto &i : items)
          scalars = scalars && i.kind != Kind::array && i.kind != Kind::object;
        out << '[';
        for (unsigned int i = 0; i < items.size(); ++i)
        {
          out << (i ? "," : "");
          if (scalars)
            out << (i ? " " : "");
          else
            out << '\n' << pad;
          items[i].write(out, indent + 2);
        }
        if (!scalars && !items.empty())
          out << '\n' << end_pad;
        out << ']';
        break;
      }
      case Kind::object:
        out << '{';
        for (unsigned int i = 0; i < members.size(); ++i)
        {
          out << (i ? ",\n" : "\n") << pad;
          write_string(out, members[i].first);
          out << ": ";
          members[i].second.write(out, indent + 2);
        }
        if (!members.empty())
          out << '\n' << end_pad;
        out << '}';
        break;
    }
  }

  void
  Json::write_file(const std::string &filename) const
  {
    std::ofstream out(filename);
    if (!out)
      throw std::runtime_error("cannot write '" + filename + "'");
    write(out);
    out << '\n';
  }

  Json
  json_array(const std::vector<double> &values)
  {
    Json a = Json::array();
    for (const double v : values)
      a.push_back(v);
    return a;
  }
  bool
  Json::has(const std::string &key) const
  {
    for (const auto &[k, v] : members)
      if (k == key)
        return true;
    return false;
  }

  const Json &
  Json::get(const std::string &key) const
  {
    for (const auto &[k, v] : members)
      if (k == key)
        return v;
    throw std::out_of_range("summary.json has no key '" + key + "'");
  }

  const Json &
  Json::at(const unsigned int i) const
  {
    return items.at(i);
  }
} // namespace ddcontact
