#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/radiation/helmholtz_bem.h>
#include <greentread/radiation/sound_parameters.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>

namespace greentread
{
  namespace radiation
  {
    namespace
    {
      /// "name: x, y, z; name: x, y, z" into named points [m].
      std::vector<std::pair<std::string, dealii::Point<3>>>
      parse_microphones(const std::string &given)
      {
        const std::string allowed =
          "; allowed: 'cpx' or 'name: x, y, z' [m] per microphone, separated by ';' (x along "
          "the road from the patch centre, y across from the tyre's mid-plane, z up from the "
          "road)";
        std::vector<std::pair<std::string, dealii::Point<3>>> microphones;
        for (const auto &item : dealii::Utilities::split_string_list(given, ';'))
          {
            const auto colon = item.find(':');
            const auto name =
              colon == std::string::npos ? "" : dealii::Utilities::trim(item.substr(0, colon));
            const auto       xyz = colon == std::string::npos ?
                                     std::vector<std::string>() :
                                     dealii::Utilities::split_string_list(item.substr(colon + 1), ',');
            dealii::Point<3> p;
            bool             ok = !name.empty() && xyz.size() == 3;
            for (unsigned int d = 0; ok && d < 3; ++d)
              {
                std::istringstream in(xyz[d]);
                ok = static_cast<bool>(in >> p[d]) && (in >> std::ws).eof() && std::isfinite(p[d]);
              }
            if (!ok)
              throw InputError("parameter 'Sound/Microphones' = " + given + ": '" + item +
                               "' is not a named position" + allowed);
            for (const auto &m : microphones)
              if (m.first == name)
                throw InputError("parameter 'Sound/Microphones' = " + given + " names '" + name +
                                 "' twice; allowed: each name once");
            microphones.emplace_back(name, p);
          }
        if (microphones.empty())
          throw InputError("parameter 'Sound/Microphones' is empty" + allowed);
        return microphones;
      }
    } // namespace



    void
    SoundParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Sound");
      {
        prm.declare_entry(
          "Top band", "0", base::RangePattern::closed(0., 5000., "Hz"),
          "The nominal centre of the highest one-third-octave band of the sound [Hz]: the "
          "levels at the microphones and the radiated power, from the contact forces at the "
          "Green's-function points by the ring's modes and a boundary element method with the "
          "road as a rigid plane (doc/methods/radiation.md). 0: no sound.");
        prm.declare_entry("Lowest band", "250", base::RangePattern::closed(100., 5000., "Hz"),
                          "The nominal centre of the lowest band of the sound [Hz].");
        prm.declare_entry(
          "Cell size", "0.03", base::RangePattern::closed(0.002, 0.2, "m"),
          "The boundary element mesh's cell size on the tyre's surface [m]. It must give 12 "
          "cells to a wavelength at the top band's centre. The error bar's coarser level has "
          "cells sqrt(2) times this size.");
        prm.declare_entry(
          "Microphones", "cpx", dealii::Patterns::Anything(),
          "'cpx': the two close-proximity microphones of ISO 11819-2, 0.2 m ahead of and "
          "behind the axle, 0.2 m out from the tyre's side and 0.1 m above the road. Or named "
          "positions 'name: x, y, z; ...' [m]: x along the road from the patch centre, y "
          "across from the tyre's mid-plane, z up from the road; each above the road and "
          "outside the tyre.");
      }
      prm.leave_subsection();
    }



    void
    SoundParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Sound");
      {
        top_band          = prm.get_double("Top band");
        lowest_band       = prm.get_double("Lowest band");
        cell_size         = prm.get_double("Cell size");
        microphones_given = dealii::Utilities::trim(prm.get("Microphones"));
      }
      prm.leave_subsection();
      microphones.clear();
      if (microphones_given != "cpx")
        microphones = parse_microphones(microphones_given);
      if (!enabled())
        return;
      if (top_band < lowest_band)
        throw InputError("parameter 'Sound/Top band' = " + format_number(top_band) +
                         " Hz is below 'Sound/Lowest band' = " + format_number(lowest_band) +
                         " Hz; allowed: 0 (no sound) or at least the lowest band");
      const auto bands = analysis::third_octave_bands(lowest_band, top_band);
      if (std::abs(bands.back().nominal - top_band) > 1e-9 * top_band ||
          std::abs(bands.front().nominal - lowest_band) > 1e-9 * lowest_band)
        throw InputError("parameters 'Sound/Lowest band' = " + format_number(lowest_band) +
                         " Hz and 'Sound/Top band' = " + format_number(top_band) +
                         " Hz; allowed: nominal one-third-octave centres (..., 200, 250, 315, "
                         "400, 500, 630, 800, 1000, 1250, ... Hz)");
      const double largest =
        Air().sound_speed / (cells_per_wavelength * bands.back().centre) * (1. + 1e-9);
      if (cell_size > largest)
        throw InputError(
          "parameter 'Sound/Cell size' = " + format_number(1e3 * cell_size) +
          " mm is too coarse for the " + format_number(top_band) +
          " Hz band ('Sound/Top band'); allowed: at most " + format_printf("%.3g", 1e3 * largest) +
          " mm, " + format_number(cells_per_wavelength) + " cells to a wavelength at its centre");
    }



    void
    SoundParameters::check_microphones(const double outer_radius, const double width) const
    {
      for (const auto &[name, p] : microphones)
        {
          const std::string what = "parameter 'Sound/Microphones': microphone '" + name + "' at (" +
                                   format_number(p[0]) + ", " + format_number(p[1]) + ", " +
                                   format_number(p[2]) + ") m";
          if (!(p[2] > 0.))
            throw InputError(what + " is not above the road; allowed: z > 0");
          const double from_axle = std::hypot(p[0], p[2] - outer_radius);
          if (std::abs(p[1]) <= 0.5 * width && from_axle <= outer_radius)
            throw InputError(what + " is inside the tyre (radius " + format_short(outer_radius) +
                             " m, width " + format_short(width) +
                             " m); allowed: a point outside it, |y| > " +
                             format_short(0.5 * width) + " m or further than " +
                             format_short(outer_radius) + " m from the axle");
        }
    }
  } // namespace radiation
} // namespace greentread
