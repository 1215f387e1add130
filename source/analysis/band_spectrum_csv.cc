#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>

#include <algorithm>
#include <cmath>
#include <string>

// A band spectrum's CSV file (analysis/third_octave.h): its levels, standard
// errors, the run each band came from, and its error bars.

namespace greentread
{
  namespace analysis
  {
    void
    write_band_spectrum_csv(const std::filesystem::path &file,
                            const BandSpectrum          &s,
                            const std::string           &quantity_and_unit)
    {
      const std::size_t B = s.bands.size();
      if (s.rms.size() != B || s.level.size() != B)
        throw InputError("band spectrum file '" + file.string() + "': " + std::to_string(B) +
                         " bands but " + std::to_string(s.rms.size()) + " rms values and " +
                         std::to_string(s.level.size()) + " levels");
      std::string what = quantity_and_unit;
      std::replace(what.begin(), what.end(), '\n', ' ');
      std::replace(what.begin(), what.end(), '\r', ' ');

      base::AtomicFile out(file);
      auto            &o = out.stream();
      o << "# one-third-octave band spectrum (IEC 61260-1, base 10) of " << what
        << "; level_dB = 20 log10(rms / reference), reference = " << format_number(s.reference)
        << " (unit of rms); levels of an rms <= 1e-10 reference are floored at " << level_floor
        << " dB\n";
      const bool errors = !s.standard_error.empty();
      if (errors &&
          (s.standard_error.size() != B || s.predicted_error.size() != B || s.segments.size() != B))
        throw InputError("band spectrum file '" + file.string() + "': " + std::to_string(B) +
                         " bands but " + std::to_string(s.standard_error.size()) +
                         " standard errors");
      const bool sources = s.time_step.size() == B && s.duration.size() == B;
      const bool bars    = errors && sources && s.total_error.size() == B;
      o << "nominal_Hz,centre_Hz,lower_Hz,upper_Hz,rms,level_dB"
        << (errors ? ",standard_error_dB,predicted_error_dB,segments" : "")
        << (errors && sources ? ",time_step_s,record_s" : "") << (bars ? ",total_error_dB" : "");
      for (const auto &e : bars ? s.discretisation_error : decltype(s.discretisation_error)())
        o << ',' << e.first << "_dB";
      o << '\n';
      for (std::size_t b = 0; b < B; ++b)
        {
          o << s.bands[b].nominal << ',' << s.bands[b].centre << ',' << s.bands[b].lower << ','
            << s.bands[b].upper << ',' << s.rms[b] << ',' << s.level[b];
          if (errors)
            o << ',' << s.standard_error[b] << ',' << s.predicted_error[b] << ',' << s.segments[b];
          if (errors && sources)
            o << ',' << s.time_step[b] << ',' << s.duration[b];
          if (bars)
            {
              o << ',' << s.total_error[b];
              for (const auto &e : s.discretisation_error)
                if (std::isnan(e.second[b]))
                  o << ','; // not estimated in this band
                else
                  o << ',' << e.second[b];
            }
          o << '\n';
        }
      out.commit();
    }
  } // namespace analysis
} // namespace greentread
