#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>

namespace greentread
{
  namespace base
  {
    std::string
    trim(const std::string &s)
    {
      const auto begin = s.find_first_not_of(" \t\r\n");
      if (begin == std::string::npos)
        return "";
      const auto end = s.find_last_not_of(" \t\r\n");
      return s.substr(begin, end - begin + 1);
    }



    namespace
    {



      std::string
      collapse_whitespace(const std::string &s)
      {
        std::string out;
        bool        in_space = false;
        for (const char c : s)
          if (c == ' ' || c == '\t' || c == '\n' || c == '\r')
            in_space = true;
          else
            {
              if (in_space && !out.empty())
                out += ' ';
              out += c;
              in_space = false;
            }
        return out;
      }



      void
      collect(const boost::property_tree::ptree &tree,
              const std::string                 &prefix,
              std::vector<ParameterEntry>       &entries)
      {
        for (const auto &[name, child] : tree)
          {
            const std::string path = prefix.empty() ? name : prefix + "/" + name;
            if (child.find("value") != child.not_found() &&
                child.find("pattern_description") != child.not_found())
              entries.push_back({path, child.get<std::string>("value"),
                                 child.get<std::string>("default_value"),
                                 child.get<std::string>("documentation"),
                                 child.get<std::string>("pattern_description")});
            else
              collect(child, path, entries);
          }
      }



      /**
       * The subsection path that is open just before line @p line_number of
       * @p text, following the "subsection"/"end" statements.
       */
      std::string
      subsection_at_line(const std::string &text, const unsigned int line_number)
      {
        std::vector<std::string> stack;
        std::istringstream       in(text);
        std::string              line;
        for (unsigned int n = 1; n < line_number && std::getline(in, line); ++n)
          {
            line = trim(line.substr(0, line.find('#')));
            if (line.rfind("subsection ", 0) == 0)
              stack.push_back(trim(line.substr(11)));
            else if (line == "end" && !stack.empty())
              stack.pop_back();
          }
        std::string path;
        for (const auto &s : stack)
          path += s + "/";
        return path;
      }



      /**
       * Turn a deal.II ParameterHandler exception into a message that names
       * the parameter by its full path and proposes the closest name.
       */
      std::string
      explain_parse_error(const dealii::ExceptionBase    &error,
                          const std::string              &text,
                          const std::string              &source,
                          const dealii::ParameterHandler &prm)
      {
        std::ostringstream info_stream;
        error.print_info(info_stream);
        const std::string info = collapse_whitespace(info_stream.str());

        std::vector<std::string> paths;
        for (const auto &e : list_parameters(prm))
          paths.push_back(e.path);

        std::smatch      m;
        unsigned int     line = 0;
        const std::regex line_regex("Line <([0-9]+)>");
        if (std::regex_search(info, m, line_regex))
          line = std::stoul(m[1]);
        // A --set override is one line of generated text: its line number
        // means nothing to the user.
        const bool        is_file = source.rfind("--set", 0) != 0;
        const std::string where =
          source + (line > 0 && is_file ? ", line " + std::to_string(line) : "");
        const std::string section = line > 0 ? subsection_at_line(text, line) : "";

        const std::regex undeclared("No entry with name <(.*)> was declared");
        const std::regex mismatch(
          "The entry value (.*) for the entry named (.*) does not match the given pattern: (.*)$");
        const std::regex no_section("There is no such subsection to be entered: (.*)$");

        if (std::regex_search(info, m, undeclared))
          {
            const std::string path    = section + trim(m[1]);
            const std::string nearest = closest_name(path, paths);
            return where + ": unknown parameter '" + path + "'" +
                   (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)") +
                   "; 'greentread --print-parameters' lists them all";
          }
        if (std::regex_search(info, m, mismatch))
          return where + ": parameter '" + section + trim(m[2]) + "' = " + trim(m[1]) +
                 " is not allowed; allowed: " + trim(m[3]);
        if (std::regex_search(info, m, no_section))
          {
            std::vector<std::string> sections;
            for (const auto &p : paths)
              for (auto slash = p.find('/'); slash != std::string::npos;
                   slash      = p.find('/', slash + 1))
                sections.push_back(p.substr(0, slash));
            const std::string path    = section + trim(m[1]);
            const std::string nearest = closest_name(path, sections);
            return where + ": unknown subsection '" + path + "'" +
                   (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)");
          }
        return where + ": " + info;
      }



      /**
       * Refuse a scene text that sets one parameter twice: deal.II would keep
       * the last value without a word. Lines continued by a backslash are
       * joined first, as deal.II joins them.
       */
      void
      check_no_entry_twice(const std::string &text, const std::string &source)
      {
        std::vector<std::string>            stack;
        std::map<std::string, unsigned int> first_line;
        std::istringstream                  in(text);
        std::string                         line, joined;
        unsigned int                        n = 0, start = 0;
        while (std::getline(in, line))
          {
            ++n;
            if (joined.empty())
              start = n;
            const std::string code = line.substr(0, line.find('#'));
            if (!code.empty() && code.back() == '\\')
              {
                joined += code.substr(0, code.size() - 1);
                continue;
              }
            joined += code;
            const std::string entry = trim(joined);
            joined.clear();
            if (entry.rfind("subsection ", 0) == 0)
              stack.push_back(trim(entry.substr(11)));
            else if (entry == "end" && !stack.empty())
              stack.pop_back();
            else if (entry.rfind("set ", 0) == 0 && entry.find('=') != std::string::npos)
              {
                std::string path;
                for (const auto &s : stack)
                  path += s + "/";
                path += collapse_whitespace(trim(entry.substr(4, entry.find('=') - 4)));
                const auto [it, added] = first_line.emplace(path, start);
                if (!added)
                  throw InputError(source + ", line " + std::to_string(start) + ": parameter '" +
                                   path + "' is set a second time (first on line " +
                                   std::to_string(it->second) +
                                   "); allowed: one 'set' per parameter in a scene file (a "
                                   "--set option on the command line overrides it)");
              }
          }
      }



      void
      parse_text(dealii::ParameterHandler &prm, const std::string &text, const std::string &source)
      {
        try
          {
            prm.parse_input_from_string(text, source);
          }
        catch (const dealii::ExceptionBase &e)
          {
            throw InputError(explain_parse_error(e, text, source, prm));
          }
      }
    } // namespace



    RangePattern::RangePattern(const double lower_,
                               const Bound  lower_kind_,
                               const double upper_,
                               const Bound  upper_kind_,
                               std::string  unit_)
        : lower(lower_)
        , upper(upper_)
        , lower_kind(lower_kind_)
        , upper_kind(upper_kind_)
        , unit(std::move(unit_))
    {
    }



    RangePattern
    RangePattern::positive(const std::string &unit)
    {
      return {0., Bound::exclusive, 0., Bound::none, unit};
    }



    RangePattern
    RangePattern::non_negative(const std::string &unit)
    {
      return {0., Bound::inclusive, 0., Bound::none, unit};
    }



    RangePattern
    RangePattern::closed(const double lower, const double upper, const std::string &unit)
    {
      return {lower, Bound::inclusive, upper, Bound::inclusive, unit};
    }



    bool
    RangePattern::match(const std::string &test_string) const
    {
      const std::string text = trim(test_string);
      if (text.empty())
        return false;
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || trim(end) != "" || !std::isfinite(value))
        return false;
      if ((lower_kind == Bound::inclusive && !(value >= lower)) ||
          (lower_kind == Bound::exclusive && !(value > lower)))
        return false;
      if ((upper_kind == Bound::inclusive && !(value <= upper)) ||
          (upper_kind == Bound::exclusive && !(value < upper)))
        return false;
      return true;
    }



    std::string
    RangePattern::description(const OutputStyle) const
    {
      std::string range;
      const auto  number = [](double x) {
        return format_number(x);
      };
      if (lower_kind != Bound::none && upper_kind != Bound::none)
        range = std::string(lower_kind == Bound::inclusive ? "[" : "(") + number(lower) + ", " +
                number(upper) + (upper_kind == Bound::inclusive ? "]" : ")");
      else if (lower_kind != Bound::none)
        range = std::string(lower_kind == Bound::inclusive ? ">= " : "> ") + number(lower);
      else if (upper_kind != Bound::none)
        range = std::string(upper_kind == Bound::inclusive ? "<= " : "< ") + number(upper);
      std::string d = "[a finite number";
      if (!range.empty())
        d += (range[0] == '[' || range[0] == '(' ? " in " : " ") + range;
      if (!unit.empty())
        d += ", in " + unit;
      return d + "]";
    }



    std::unique_ptr<dealii::Patterns::PatternBase>
    RangePattern::clone() const
    {
      return std::make_unique<RangePattern>(*this);
    }



    std::vector<ParameterEntry>
    list_parameters(const dealii::ParameterHandler &prm)
    {
      std::stringstream json;
      prm.print_parameters(
        json, dealii::ParameterHandler::OutputStyle(
                dealii::ParameterHandler::JSON | dealii::ParameterHandler::KeepDeclarationOrder));
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      std::vector<ParameterEntry> entries;
      collect(tree, "", entries);
      return entries;
    }



    void
    parse_scene_file(dealii::ParameterHandler &prm, const std::string &filename)
    {
      std::ifstream in(filename);
      if (!in)
        throw InputError("scene file '" + filename +
                         "' cannot be opened: it does not exist or is not readable");
      std::stringstream text;
      text << in.rdbuf();
      check_no_entry_twice(text.str(), filename);
      parse_text(prm, text.str(), filename);
    }



    void
    apply_override(dealii::ParameterHandler &prm, const std::string &assignment)
    {
      const auto equal = assignment.find('=');
      if (equal == std::string::npos)
        throw InputError("--set '" + assignment + "': expected the form \"Section/Name=value\"");
      const std::string path  = trim(assignment.substr(0, equal));
      const std::string value = trim(assignment.substr(equal + 1));

      std::vector<std::string> parts;
      std::size_t              begin = 0;
      for (auto slash = path.find('/'); slash != std::string::npos; slash = path.find('/', begin))
        {
          parts.push_back(trim(path.substr(begin, slash - begin)));
          begin = slash + 1;
        }
      parts.push_back(trim(path.substr(begin)));

      // Build the same text a scene file would contain, so that file and
      // command line share one parser and one set of messages.
      std::string text;
      for (std::size_t i = 0; i + 1 < parts.size(); ++i)
        text += "subsection " + parts[i] + "\n";
      text += "set " + parts.back() + " = " + value + "\n";
      for (std::size_t i = 0; i + 1 < parts.size(); ++i)
        text += "end\n";
      parse_text(prm, text, "--set '" + assignment + "'");
    }



    void
    print_parameter_reference(const dealii::ParameterHandler &prm, std::ostream &out)
    {
      out << "# GreenTread parameters: path = default, what is allowed, and what it means.\n"
          << "# Set them in a scene file (subsection ... end) or with --set \"Path=value\".\n";
      for (const auto &e : list_parameters(prm))
        {
          if (e.documentation.rfind("Deprecated:", 0) == 0)
            continue;
          out << '\n' << e.path << " = " << e.default_value << '\n';
          out << "    allowed: " << e.allowed << '\n';
          std::istringstream words(e.documentation);
          std::string        word, line = "   ";
          while (words >> word)
            {
              if (line.size() + word.size() + 1 > 88)
                {
                  out << line << '\n';
                  line = "   ";
                }
              line += ' ' + word;
            }
          if (line.size() > 3)
            out << line << '\n';
        }
    }



    void
    print_parameter_markdown(const dealii::ParameterHandler &prm, std::ostream &out)
    {
      const auto cell = [](std::string text) {
        std::string escaped;
        for (const char c : text)
          escaped += c == '|'  ? std::string("\\|") :
                     c == '\n' ? std::string(" ") :
                                 std::string(1, c);
        return escaped;
      };
      const auto is_deprecated = [](const ParameterEntry &e) {
        return e.documentation.rfind("Deprecated:", 0) == 0;
      };
      const auto entries = list_parameters(prm);
      out
        << "# Parameters\n\n"
        << "<!-- Generated by `build/greentread --print-parameters=markdown > doc/parameters.md`;\n"
        << "     do not edit: the test layout/parameters_doc fails when this file is stale. -->\n\n"
        << "Every parameter GreenTread reads, with its default, what is allowed (and its unit), "
           "and what it means.\n"
        << "Set them in a scene file (`subsection ... end`) or on the command line with "
           "`--set \"Subsection/Name=value\"`.\n"
        << "Which subsections a scene reads: [getting-started.md](getting-started.md#scenes); "
           "a value set in a subsection\nthe scene does not read is refused.\n";
      std::string section = "-";
      for (const auto &e : entries)
        {
          if (is_deprecated(e))
            continue;
          const auto        slash = e.path.rfind('/');
          const std::string here  = slash == std::string::npos ? "" : e.path.substr(0, slash);
          if (here != section)
            {
              section = here;
              out << "\n## " << (here.empty() ? std::string("Top level") : here) << "\n\n"
                  << "| name | default | allowed | meaning |\n| --- | --- | --- | --- |\n";
            }
          out << "| `" << cell(e.path.substr(slash == std::string::npos ? 0 : slash + 1)) << "` | `"
              << cell(e.default_value) << "` | " << cell(e.allowed) << " | "
              << cell(e.documentation) << " |\n";
        }
      out << "\n## Deprecated spellings\n\n"
          << "Still read in this release, with a warning that names the new spelling.\n\n"
          << "| old name | meaning |\n| --- | --- |\n";
      for (const auto &e : entries)
        if (is_deprecated(e))
          out << "| `" << cell(e.path) << "` | " << cell(e.documentation) << " |\n";
    }



    std::string
    closest_name(const std::string &name, const std::vector<std::string> &candidates)
    {
      const auto lower = [](std::string s) {
        std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) {
          return std::tolower(c);
        });
        return s;
      };
      const std::string a = lower(name);
      std::string       best;
      std::size_t       best_distance = std::string::npos;
      for (const auto &candidate : candidates)
        {
          const std::string        b = lower(candidate);
          std::vector<std::size_t> row(b.size() + 1);
          for (std::size_t j = 0; j <= b.size(); ++j)
            row[j] = j;
          for (std::size_t i = 1; i <= a.size(); ++i)
            {
              std::size_t diagonal = row[0];
              row[0]               = i;
              for (std::size_t j = 1; j <= b.size(); ++j)
                {
                  const std::size_t up = row[j];
                  row[j]               = std::min(
                                  {row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
                  diagonal = up;
                }
            }
          if (row[b.size()] < best_distance)
            {
              best_distance = row[b.size()];
              best          = candidate;
            }
        }
      // Only propose names that differ in at most a third of their letters.
      if (best_distance == std::string::npos || 3 * best_distance > a.size() + 2)
        return "";
      return best;
    }
    std::vector<std::string>
    split_list(const std::string &text)
    {
      std::vector<std::string> items;
      for (const auto &item : dealii::Utilities::split_string_list(text, ','))
        if (!item.empty())
          items.push_back(item);
      return items;
    }



  } // namespace base
} // namespace greentread
