#include <deal.II/base/utilities.h>

#include <ddcontact/parameter_messages.h>
#include <ddcontact/parameter_tools.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace ddcontact
{
  namespace parameter_messages
  {
    using parsing::edit_distance;

    namespace
    {
      /** Every subsection (paths "Body a/Mesh") and every entry (its
       * section's path and its name) that @p prm declares. */
      struct Declared
      {
        std::vector<std::string>                         sections;
        std::vector<std::pair<std::string, std::string>> entries;
      };

      Declared
      declared(const ParameterHandler &prm)
      {
        std::ostringstream out;
        prm.print_parameters(out, ParameterHandler::ShortPRM);
        std::istringstream       lines(out.str());
        std::string              line;
        std::vector<std::string> path;
        Declared                 found;
        while (std::getline(lines, line))
        {
          const auto split = split_keyword(line);
          follow_sections(path, split);
          if (split.first == "subsection")
            found.sections.push_back(joined(path));
          else if (split.first == "set")
            found.entries.emplace_back(
              joined(path),
              Utilities::trim(split.second.substr(0, split.second.find('='))));
        }
        return found;
      }

      /** @p name without apostrophes: "Youngs modulus" is "Young's
       * modulus" misspelled by nothing but its apostrophe. */
      std::string
      plain(std::string name)
      {
        name.erase(std::remove(name.begin(), name.end(), '\''), name.end());
        return name;
      }

      /** The largest edit distance at which a name of @p size characters is
       * taken for a misspelling. */
      unsigned int
      close_enough(const std::size_t size)
      {
        return std::max<unsigned int>(2, size / 4);
      }

      /** Whether @p text is a finite number as a whole. */
      bool
      is_number(const std::string &text)
      {
        const std::string t = Utilities::trim(text);
        if (t.empty())
          return false;
        char        *end   = nullptr;
        const double value = std::strtod(t.c_str(), &end);
        return end == t.c_str() + t.size() && std::isfinite(value);
      }

      /** A number with something after it ("1000 MPa", "5mm"): the number,
       * or "" if @p text does not start with one. */
      std::string
      leading_number(const std::string &text)
      {
        const std::string t   = Utilities::trim(text);
        char             *end = nullptr;
        std::strtod(t.c_str(), &end);
        return end == t.c_str() ? "" : t.substr(0, end - t.c_str());
      }

      /** deal.II's "[Double 0...MAX_DOUBLE (inclusive)]" in words. */
      std::string
      number_range(const std::string &pattern, const std::string &kind)
      {
        // "[Double L...U (inclusive)]"
        const auto start = pattern.find(kind + " ");
        const auto dots  = pattern.find("...");
        if (start == std::string::npos || dots == std::string::npos)
          return "a number";
        std::string lower = Utilities::trim(pattern.substr(
          start + kind.size() + 1, dots - start - kind.size() - 1));
        // "[Integer range 0...254 (inclusive)]"
        if (lower.rfind("range ", 0) == 0)
          lower = Utilities::trim(lower.substr(6));
        const auto        close = pattern.find_first_of(" ]", dots + 3);
        const std::string upper = pattern.substr(dots + 3, close - dots - 3);
        const std::string what =
          (kind == "Integer") ? "a whole number" : "a number";
        const bool no_lower = lower.find("MAX") != std::string::npos;
        const bool no_upper = upper.find("MAX") != std::string::npos;
        if (no_lower && no_upper)
          return what;
        if (no_upper)
          return what + " >= " + lower;
        if (no_lower)
          return what + " <= " + upper;
        return what + " from " + lower + " to " + upper;
      }

      /** Why @p value is not a number, and what to write. */
      std::string
      not_a_number(const std::string &value)
      {
        const std::string v = Utilities::trim(value);
        if (!v.empty() && v.back() == '%' &&
            is_number(v.substr(0, v.size() - 1)))
        {
          std::ostringstream s;
          s << std::stod(v.substr(0, v.size() - 1)) / 100;
          return "a percentage is not read; write the fraction (" + s.str() +
                 ")";
        }
        if (v.find(',') != std::string::npos)
        {
          std::string point = v;
          std::replace(point.begin(), point.end(), ',', '.');
          if (is_number(point))
            return "a decimal comma is not read; write a decimal point (" +
                   point + ")";
        }
        const std::string number = leading_number(v);
        if (!number.empty())
          return "numbers are written without units (write " + number +
                 "; the code takes any consistent system of units, "
                 "doc/parameters.md)";
        return "it is not a number";
      }

      /** The options of "[Selection a|b|c ]". */
      std::vector<std::string>
      options_of(const std::string &pattern)
      {
        const auto start = pattern.find("Selection ");
        if (start == std::string::npos)
          return {};
        const auto close = pattern.rfind(']');
        return Utilities::split_string_list(
          pattern.substr(start + 10, close - start - 10), '|');
      }
    } // namespace

    std::pair<std::string, std::string>
    split_keyword(const std::string &line)
    {
      const std::string text = Utilities::trim(line.substr(0, line.find('#')));
      std::string       keyword = text.substr(0, text.find(' '));
      std::transform(keyword.begin(),
                     keyword.end(),
                     keyword.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      return {keyword, Utilities::trim(text.substr(keyword.size()))};
    }

    void
    follow_sections(std::vector<std::string>                  &path,
                    const std::pair<std::string, std::string> &line)
    {
      if (line.first == "subsection")
        path.push_back(line.second);
      else if (line.first == "end" && line.second.empty() && !path.empty())
        path.pop_back();
    }

    std::string
    joined(const std::vector<std::string> &path)
    {
      std::string section;
      for (const auto &p : path)
        section += (section.empty() ? "" : "/") + p;
      return section;
    }

    std::string
    alternatives(const std::vector<std::string> &names)
    {
      std::string list;
      for (unsigned int i = 0; i < names.size(); ++i)
        list += (i == 0                  ? ""
                 : i + 1 == names.size() ? " or "
                                         : ", ") +
                names[i];
      return list;
    }

    std::string
    unknown_subsection(const std::string      &parent,
                       const std::string      &name,
                       const ParameterHandler &prm)
    {
      const std::string prefix = parent.empty() ? "" : parent + "/";
      std::string       best;
      unsigned int      best_distance = close_enough(name.size()) + 1;
      for (const auto &section : declared(prm).sections)
        if (section.rfind(prefix, 0) == 0 &&
            section.find('/', prefix.size()) == std::string::npos)
        {
          const unsigned int d =
            edit_distance(name, section.substr(prefix.size()));
          if (d < best_distance)
          {
            best          = section;
            best_distance = d;
          }
        }
      std::vector<std::string> hints;
      if (!best.empty())
        hints.push_back("did you mean '" + best + "'?");
      if (parent.empty() &&
          (name.rfind("Body ", 0) == 0 || name.rfind("Contact pair ", 0) == 0))
        hints.push_back("a body or contact pair also needs its name in "
                        "Bodies or Contact pairs");
      if (hints.empty())
        hints.push_back("misspelled?");
      std::string hint;
      for (const auto &h : hints)
        hint += (hint.empty() ? "" : " ") + h;
      return "there is no subsection '" + prefix + name + "' (" + hint + ")";
    }

    std::string
    unknown_entry(const std::string      &section,
                  const std::string      &entry,
                  const ParameterHandler &prm)
    {
      const Declared    all = declared(prm);
      const std::string where =
        section.empty() ? "at the top level" : "in '" + section + "'";
      // The closest entry of the same subsection.
      std::string  best;
      unsigned int best_distance = close_enough(entry.size()) + 1;
      for (const auto &[s, e] : all.entries)
        if (s == section)
        {
          const unsigned int d = edit_distance(plain(entry), plain(e));
          if (d < best_distance)
          {
            best          = e;
            best_distance = d;
          }
        }
      const std::string head = "there is no entry '" + entry + "' " + where;
      if (!best.empty())
        return head + " (did you mean '" + best + "'?)";
      // The subsections that declare it (the same name up to case and
      // apostrophes), at most three.
      std::vector<std::string> homes;
      for (const auto &[s, e] : all.entries)
        if (s != section && edit_distance(plain(entry), plain(e)) == 0)
          homes.push_back(s.empty() ? "the top level" : "'" + s + "'");
      if (!homes.empty())
      {
        std::string list;
        for (unsigned int i = 0; i < homes.size() && i < 3; ++i)
          list += (i == 0 ? "" : ", ") + homes[i];
        if (homes.size() > 3)
          list += ", ...";
        return head + "; it is an entry of " + list + ": move it there";
      }
      return head + " (misspelled? doc/parameters.md lists every entry)";
    }

    bool
    split_value_message(const std::string &message,
                        std::string       &entry,
                        std::string       &value,
                        std::string       &pattern)
    {
      // A file: "The entry value V for the entry named N does not match
      // the given pattern: P".
      const std::string value_prefix = "The entry value ";
      const std::string named        = " for the entry named ";
      const std::string match        = " does not match the given pattern: ";
      const auto        v            = message.find(value_prefix);
      const auto        n            = message.find(named);
      const auto        m            = message.find(match);
      if (v != std::string::npos && n != std::string::npos &&
          m != std::string::npos && v < n && n < m)
      {
        value =
          message.substr(v + value_prefix.size(), n - v - value_prefix.size());
        entry   = message.substr(n + named.size(), m - n - named.size());
        pattern = message.substr(m + match.size());
        return true;
      }
      // ParameterHandler::set(): "The string <V> does not match the given
      // pattern <P>."
      const std::string string_prefix = "The string <";
      const std::string set_match     = "> does not match the given pattern <";
      const auto        s             = message.find(string_prefix);
      const auto        t             = message.find(set_match);
      if (s != std::string::npos && t != std::string::npos && s < t)
      {
        value = message.substr(s + string_prefix.size(),
                               t - s - string_prefix.size());
        entry.clear();
        const auto start = t + set_match.size();
        pattern          = message.substr(start, message.rfind('>') - start);
        return true;
      }
      return false;
    }

    std::string
    bad_value(const std::string &section,
              const std::string &entry,
              const std::string &value,
              const std::string &pattern)
    {
      const std::string name =
        (section.empty() ? "" : section + "/") + entry + " = '" + value + "': ";
      const std::string v = Utilities::trim(value);
      if (pattern.find("Selection") != std::string::npos)
      {
        const auto   options = options_of(pattern);
        std::string  list, best;
        unsigned int best_distance = close_enough(v.size()) + 1;
        for (const auto &o : options)
        {
          list += (list.empty() ? "" : ", ") + o;
          const unsigned int d = edit_distance(v, o);
          if (d < best_distance)
          {
            best          = o;
            best_distance = d;
          }
        }
        return name + "not one of " + list +
               (best.empty() ? std::string(" (written as listed)")
                             : " (did you mean '" + best + "'?)");
      }
      if (pattern.find("Bool") != std::string::npos)
        return name + "write true or false";
      if (pattern.find("Map of") != std::string::npos &&
          pattern.find(">=<") == std::string::npos)
      {
        // Another map ("body: x1, x2; body: x1, x2"): its separators.
        const auto        by = pattern.find("separated by <");
        const std::string items =
          (by == std::string::npos) ? "," : pattern.substr(by + 14, 1);
        const std::string pair =
          (pattern.find(">:<") != std::string::npos) ? ":" : "=";
        return name + "expected 'key" + pair + " value' items separated by '" +
               items + "' (the entry's documentation: --print-parameters)";
      }
      if (pattern.find("Map of") != std::string::npos)
      {
        // Constants: "name=number, name=number".
        if (v.find(';') != std::string::npos)
        {
          std::string commas = v;
          std::replace(commas.begin(), commas.end(), ';', ',');
          return name + "constants are separated by commas (" + commas + ")";
        }
        for (const auto &item : Utilities::split_string_list(v, ','))
        {
          const auto eq = item.find('=');
          if (eq == std::string::npos)
            return name + "'" + item + "' is not name=number";
          const std::string number = item.substr(eq + 1);
          if (!is_number(number))
          {
            const std::string why = not_a_number(number);
            return name + "'" + item +
                   "': the value of a constant is a number, not an "
                   "expression" +
                   (why == "it is not a number" ? "" : "; " + why);
          }
        }
        return name + "expected name=number pairs separated by commas";
      }
      if (pattern.find("List of") != std::string::npos)
      {
        // A list of numbers ("Contact ids = 0, zero"): the first item that
        // is not one.
        const std::string kind =
          pattern.find("Integer") != std::string::npos ? "Integer" : "Double";
        for (const auto &item : Utilities::split_string_list(v, ','))
          if ((pattern.find("[Integer") != std::string::npos ||
               pattern.find("[Double") != std::string::npos) &&
              !is_number(item))
          {
            // "a whole number from 0 to 254" -> "whole numbers from ..."
            std::string numbers = number_range(pattern, kind).substr(2);
            numbers.insert(numbers.find("number") + 6, "s");
            return name + "a list of " + numbers +
                   " separated by commas is expected; '" + item +
                   "': " + not_a_number(item);
          }
        return name + "does not match " + pattern;
      }
      for (const std::string kind : {"Double", "Integer"})
        if (pattern.find("[" + kind) != std::string::npos)
        {
          const std::string range = number_range(pattern, kind);
          if (is_number(v))
            return name + "out of range: " + range;
          return name + range + " is expected; " + not_a_number(v);
        }
      return name + "does not match " + pattern;
    }

    std::pair<unsigned int, std::string>
    unbalanced_sections(const std::string &text, const ParameterHandler &prm)
    {
      const auto sections = declared(prm).sections;
      const auto exists   = [&](const std::string &path) {
        return std::find(sections.begin(), sections.end(), path) !=
               sections.end();
      };
      std::istringstream lines(text);
      std::string        line;
      struct Open
      {
        std::string  name;
        unsigned int line;
        std::size_t  indent;
      };
      std::vector<Open> open;
      for (unsigned int n = 1; std::getline(lines, line); ++n)
      {
        const auto [keyword, rest] = split_keyword(line);
        if (keyword == "end")
        {
          if (open.empty())
            return {n, "an 'end' without its 'subsection'"};
          open.pop_back();
        }
        else if (keyword == "subsection")
        {
          // Indented files: a subsection indented no deeper than the open
          // one is its sibling, so the open one misses its end.
          const auto indent = [](const std::string &l)
          { return l.find_first_not_of(" \t"); };
          if (!open.empty() && indent(line) <= open.back().indent)
          {
            std::vector<std::string> path;
            for (const auto &o : open)
              path.push_back(o.name);
            return {open.back().line,
                    "subsection '" + joined(path) +
                      "' has no 'end' before line " + std::to_string(n) +
                      " ('subsection " + rest + "')"};
          }
          // A subsection that cannot stand where it is but could a few
          // levels up: the innermost of those levels misses its end.
          std::vector<std::string> path;
          for (const auto &o : open)
            path.push_back(o.name);
          if (!path.empty() && !exists(joined(path) + "/" + rest))
            for (unsigned int k = path.size(); k-- > 0;)
            {
              const std::vector<std::string> up(path.begin(), path.begin() + k);
              if (exists((k == 0 ? "" : joined(up) + "/") + rest))
              {
                return {open.back().line,
                        "subsection '" + joined(path) +
                          "' has no 'end' before line " + std::to_string(n) +
                          " ('subsection " + rest + "')"};
              }
            }
          open.push_back({rest, n, line.find_first_not_of(" \t")});
        }
      }
      if (!open.empty())
      {
        std::vector<std::string> path;
        for (const auto &o : open)
          path.push_back(o.name);
        return {open.front().line,
                "subsection '" + joined(path) +
                  "' has no 'end' before the end of the file"};
      }
      return {0, "the subsections and ends do not balance"};
    }
  } // namespace parameter_messages
} // namespace ddcontact
