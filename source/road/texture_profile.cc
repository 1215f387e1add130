#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/road/texture_files.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

namespace greentread
{
  namespace road
  {
    namespace
    {
      /// The key of a header line 'key: value', or "" if it is not one.
      std::string
      header_key(const std::string &line)
      {
        const auto colon = line.find(':');
        if (colon == std::string::npos || colon == 0)
          return "";
        const std::string key  = base::trim(line.substr(0, colon));
        const bool        word = std::all_of(key.begin(), key.end(), [](const unsigned char c) {
          return std::isalnum(c) || c == '_';
        });
        return word && !std::isdigit(static_cast<unsigned char>(key[0])) ? key : "";
      }
    } // namespace



    bool
    is_text_profile(const std::string &bytes)
    {
      std::istringstream in(bytes.substr(0, 4096));
      std::string        line;
      while (std::getline(in, line))
        {
          if (base::trim(line).empty())
            continue;
          const std::string key = header_key(line);
          return key == "profile_name" || key == "sample_spacing_mm";
        }
      return false;
    }



    Texture
    read_text_profile(const std::string &bytes, const std::string &file)
    {
      std::istringstream  in(bytes);
      std::string         line;
      unsigned int        number  = 0;
      double              spacing = 0.;
      bool                header  = true;
      std::vector<double> z;
      while (std::getline(in, line))
        {
          ++number;
          const std::string text = base::trim(line);
          if (text.empty())
            continue;
          const std::string where =
            "profile file '" + file + "', line " + std::to_string(number) + ": ";
          if (header && !header_key(text).empty())
            {
              const std::string key   = header_key(text);
              const std::string value = base::trim(text.substr(text.find(':') + 1));
              if (key == "sample_spacing_mm")
                {
                  char *end = nullptr;
                  spacing   = std::strtod(value.c_str(), &end);
                  if (end == value.c_str() || *end != '\0' || !(spacing > 0.) ||
                      !std::isfinite(spacing))
                    throw InputError(where + "sample_spacing_mm = '" + value +
                                     "'; allowed: a spacing > 0 in mm");
                }
              continue;
            }
          header = false;
          if (spacing == 0.)
            throw InputError(where + "the heights begin before a line 'sample_spacing_mm: "
                                     "<spacing>' (the ISO 13473-1 profile's header)");
          char        *end = nullptr;
          const double v   = std::strtod(text.c_str(), &end);
          if (end == text.c_str() || *end != '\0')
            throw InputError(where + "'" + text +
                             "' is not a height (one height in mm per line, NaN for a dropout)");
          z.push_back(std::isfinite(v) ? 1e-3 * v : std::numeric_limits<double>::quiet_NaN());
        }
      if (spacing == 0.)
        throw InputError("profile file '" + file + "' has no line 'sample_spacing_mm: <spacing>'");
      if (z.size() < 2)
        throw InputError("profile file '" + file + "' holds " + std::to_string(z.size()) +
                         " heights; allowed: at least 2");

      Texture t;
      t.dx = t.dy = 1e-3 * spacing;
      t.nx        = z.size();
      t.ny        = 1;
      t.z         = std::move(z);
      fill_missing(t, file);
      // A road's texture spans micrometres to centimetres: heights written
      // in m or um instead of mm fall outside by a factor of 1000.
      const auto [lo, hi]         = std::minmax_element(t.z.begin(), t.z.end());
      const double peak_to_valley = *hi - *lo;
      if (!(peak_to_valley >= 1e-5) || peak_to_valley > 0.1)
        throw InputError("profile file '" + file + "': its heights span " +
                         format_short(1e3 * peak_to_valley) +
                         " mm from valley to peak; allowed: 0.01 mm to 100 mm (heights in mm, "
                         "as ISO 13473-1 profiles give them)");
      return t;
    }



    std::size_t
    fill_missing(Texture &t, const std::string &file)
    {
      std::size_t missing = 0;
      for (const double z : t.z)
        missing += !std::isfinite(z);
      if (missing == 0)
        return 0;
      if (10 * missing > t.z.size())
        throw InputError("texture file '" + file + "': " + std::to_string(missing) + " of its " +
                         std::to_string(t.z.size()) +
                         " heights are missing; allowed: at most 10% (ISO 13473-1)");
      for (unsigned int j = 0; j < t.ny; ++j)
        {
          double *p    = t.z.data() + std::size_t(j) * t.nx;
          int     last = -1; // the last valid point
          for (unsigned int i = 0; i <= t.nx; ++i)
            {
              if (i < t.nx && !std::isfinite(p[i]))
                continue;
              if (i == t.nx && last < 0)
                throw InputError("texture file '" + file + "': profile " + std::to_string(j) +
                                 " has no valid height");
              // Fill the gap (last, i): linearly, or flat at an end.
              for (unsigned int g = last + 1; g < i; ++g)
                p[g] = last < 0  ? p[i] :
                       i == t.nx ? p[last] :
                                   p[last] + (p[i] - p[last]) * double(g - last) / (i - last);
              last = i;
            }
        }
      return missing;
    }
  } // namespace road
} // namespace greentread
