#include <greentread/base/exceptions.h>
#include <greentread/contact/tread_pattern.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace greentread
{
  namespace contact
  {
    namespace
    {
      /// The next token of a PGM header, past white space and # comments.
      std::string
      pgm_token(std::istream &in)
      {
        std::string token;
        while (in && token.empty())
          {
            const int c = in.get();
            if (c == '#')
              {
                std::string comment;
                std::getline(in, comment);
              }
            else if (c != EOF && !std::isspace(c))
              {
                token.push_back(char(c));
                while (in && !std::isspace(in.peek()) && in.peek() != EOF)
                  token.push_back(char(in.get()));
              }
            else if (c == EOF)
              break;
          }
        return token;
      }

      /// A PGM image (P2 or P5) as rows of grooves: a pixel darker than half
      /// the largest grey.
      std::vector<std::vector<unsigned char>>
      read_footprint(const std::string &file)
      {
        std::ifstream in(file, std::ios::binary);
        if (!in)
          throw InputError("cannot open footprint image '" + file +
                           "' ('Tread pattern/Footprint image')");
        const std::string magic = pgm_token(in);
        if (magic != "P2" && magic != "P5")
          throw InputError("footprint image '" + file + "' starts with '" + magic.substr(0, 8) +
                           "'; allowed: a PGM image (P2 or P5)");
        long width = 0, height = 0, grey = 0;
        try
          {
            width  = std::stol(pgm_token(in));
            height = std::stol(pgm_token(in));
            grey   = std::stol(pgm_token(in));
          }
        catch (const std::exception &)
          {
            throw InputError("footprint image '" + file + "' has a malformed PGM header");
          }
        if (width < 1 || height < 1 || width * height > 100000000L || grey < 1 || grey > 65535)
          throw InputError("footprint image '" + file + "' is " + std::to_string(width) + " x " +
                           std::to_string(height) + " pixels with grey " + std::to_string(grey) +
                           "; allowed: 1 to 1e8 pixels, grey 1 to 65535");
        std::vector<std::vector<unsigned char>> rows(height, std::vector<unsigned char>(width, 0));
        if (magic == "P5")
          in.get(); // the one white-space character before the data
        for (long r = 0; r < height; ++r)
          for (long c = 0; c < width; ++c)
            {
              long value = 0;
              if (magic == "P2")
                {
                  const std::string t = pgm_token(in);
                  if (t.empty())
                    throw InputError("footprint image '" + file + "' ends after " +
                                     std::to_string(r * width + c) + " of " +
                                     std::to_string(width * height) + " pixels");
                  value = std::stol(t);
                }
              else
                {
                  const int hi = in.get();
                  const int lo = grey > 255 ? in.get() : 0;
                  if (!in)
                    throw InputError("footprint image '" + file + "' ends after " +
                                     std::to_string(r * width + c) + " of " +
                                     std::to_string(width * height) + " pixels");
                  value = grey > 255 ? hi * 256 + lo : hi;
                }
              rows[r][c] = 2 * value < grey ? 1 : 0;
            }
        return rows;
      }
    } // namespace



    TreadPattern::TreadPattern(const TreadPatternParameters &parameters, const double radius)
        : groove_depth(parameters.groove_depth)
    {
      std::vector<unsigned int> sequence = parameters.sequence;
      if (sequence.empty())
        sequence.push_back(1);
      sequence_length  = unsigned(sequence.size());
      double one_round = 0.;
      for (const unsigned int i : sequence)
        one_round += parameters.pitch_lengths.at(i - 1);
      total = 2. * M_PI * radius;
      if (one_round > total * (1. + 1e-9))
        throw InputError("parameter 'Tread pattern/Pitch sequence' spans " +
                         format_short(one_round) + " m, longer than the tyre's circumference " +
                         format_short(total) + " m; allowed: a sequence that fits round it");
      repeats   = std::max(1u, unsigned(std::lround(total / one_round)));
      factor    = total / (repeats * one_round);
      double at = 0.;
      for (unsigned int r = 0; r < repeats; ++r)
        for (const unsigned int i : sequence)
          {
            starts.push_back(at);
            lengths.push_back(parameters.pitch_lengths[i - 1] * factor);
            at += lengths.back();
          }
      if (parameters.pattern == "image")
        {
          footprint.image       = read_footprint(parameters.footprint_image);
          footprint.image_width = parameters.footprint_width;
        }
      else
        {
          footprint.lateral_groove_width = parameters.lateral_groove_width;
          for (const double c : parameters.circumferential_centres)
            footprint.circumferential.push_back({{c, parameters.circumferential_width}});
        }
    }



    TreadPattern::Place
    TreadPattern::locate(const double sigma) const
    {
      double s = std::fmod(sigma, total);
      if (s < 0.)
        s += total;
      const std::size_t k = std::max<std::ptrdiff_t>(
        0, std::upper_bound(starts.begin(), starts.end(), s) - starts.begin() - 1);
      return {k, s - starts[k]};
    }



    bool
    TreadPattern::in_groove(const double sigma, const double y) const
    {
      const auto [k, along] = locate(sigma);
      if (!footprint.image.empty())
        {
          const auto  &rows = footprint.image;
          const double u    = (y / footprint.image_width + 0.5) * double(rows[0].size());
          if (u < 0. || u >= double(rows[0].size()))
            return false;
          const std::size_t r =
            std::min(rows.size() - 1, std::size_t(along / lengths[k] * double(rows.size())));
          return rows[r][std::size_t(u)] != 0;
        }
      if (along < footprint.lateral_groove_width)
        return true;
      for (const auto &[centre, width] : footprint.circumferential)
        if (std::abs(y - centre) < 0.5 * width)
          return true;
      return false;
    }



    void
    TreadPattern::recess(const std::vector<std::array<double, 3>> &points,
                         const double                              s,
                         Eigen::VectorXd                          &z) const
    {
      for (std::size_t p = 0; p < points.size(); ++p)
        if (in_groove(s + points[p][0], points[p][1]))
          z[p] -= groove_depth;
    }



    std::string
    TreadPattern::summary() const
    {
      const auto [shortest, longest] = std::minmax_element(lengths.begin(), lengths.end());
      std::ostringstream out;
      out << lengths.size() << " pitches round the tyre (a sequence of " << sequence_length
          << (repeats > 1 ? ", " + std::to_string(repeats) + " times" : std::string()) << "), "
          << format_printf("%.2f", 1e3 * *shortest) << " to "
          << format_printf("%.2f", 1e3 * *longest) << " mm after scaling by "
          << format_printf("%.5f", factor) << " to fill the circumference "
          << format_printf("%.4f", total) << " m; grooves " << format_number(1e3 * groove_depth)
          << " mm deep";
      return out.str();
    }



    void
    check_pattern(const TreadPatternParameters &parameters,
                  const TreadPattern           &pattern,
                  const double                  tread_width,
                  const double                  tread_thickness,
                  const double                  dx,
                  const double                  dy,
                  const unsigned int            subdivisions)
    {
      const std::string grid =
        " mm ('Contact grid/Subdivisions' = " + std::to_string(subdivisions) + ")";
      if (!(parameters.groove_depth > 0.) || parameters.groove_depth > tread_thickness)
        throw InputError(
          "parameter 'Tread pattern/Groove depth' = " + format_number(parameters.groove_depth) +
          " m; allowed: above 0 and at most the tread's thickness " +
          format_number(tread_thickness) + " m ('Geometry/Tread thickness')");
      const double shortest = *std::min_element(pattern.pitches().begin(), pattern.pitches().end());
      if (parameters.pattern == "image")
        {
          if (parameters.footprint_width > tread_width * (1. + 1e-9) ||
              !(parameters.footprint_width > 0.))
            throw InputError("parameter 'Tread pattern/Footprint width' = " +
                             format_number(parameters.footprint_width) +
                             " m is wider than the tread; allowed: above 0 and up to " +
                             format_number(tread_width) + " m ('Geometry/Tread width')");
          if (shortest < 4. * dx)
            throw InputError("parameter 'Tread pattern/Pitch lengths': the shortest pitch is " +
                             format_printf("%.3g", 1e3 * shortest) +
                             " mm after scaling, too short for the contact grid's rectangles "
                             "of " +
                             format_printf("%.3g", 1e3 * dx) + grid +
                             "; allowed: at least 4 rectangles");
          return;
        }
      const double w = parameters.lateral_groove_width;
      if (w > 0. && w < dx * (1. - 1e-9))
        throw InputError(
          "parameter 'Tread pattern/Lateral groove width' = " + format_printf("%.3g", 1e3 * w) +
          " mm, narrower than a contact rectangle along, " + format_printf("%.3g", 1e3 * dx) +
          grid + "; allowed: 0 or at least one rectangle");
      if (shortest - w < dx * (1. - 1e-9))
        throw InputError("parameter 'Tread pattern/Pitch lengths': the shortest pitch is " +
                         format_printf("%.3g", 1e3 * shortest) +
                         " mm after scaling, which leaves a block shorter than a contact "
                         "rectangle of " +
                         format_printf("%.3g", 1e3 * dx) + grid + " beside its lateral groove of " +
                         format_printf("%.3g", 1e3 * w) +
                         " mm; allowed: pitches at least the groove plus one rectangle");
      for (const double c : parameters.circumferential_centres)
        if (std::abs(c) + 0.5 * parameters.circumferential_width > 0.5 * tread_width * (1. + 1e-9))
          throw InputError("parameter 'Tread pattern/Circumferential grooves' gives a groove at " +
                           format_number(1e3 * c) + " mm, " +
                           format_number(1e3 * parameters.circumferential_width) +
                           " mm wide, beyond the tread; allowed: within +-" +
                           format_number(0.5e3 * tread_width) + " mm ('Geometry/Tread width')");
      if (!parameters.circumferential_centres.empty() &&
          parameters.circumferential_width < dy * (1. - 1e-9))
        throw InputError("parameter 'Tread pattern/Circumferential groove width' = " +
                         format_printf("%.3g", 1e3 * parameters.circumferential_width) +
                         " mm, narrower than a contact rectangle across, " +
                         format_printf("%.3g", 1e3 * dy) + grid +
                         "; allowed: at least one rectangle");
    }
  } // namespace contact
} // namespace greentread
