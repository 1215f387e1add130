#include <greentread/analysis/rolling_output.h>
#include <greentread/analysis/sound_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>

#include <algorithm>
#include <iostream>

namespace greentread
{
  namespace analysis
  {
    void
    append_bands(BandSpectrum &a, const BandSpectrum &b)
    {
      if (a.bands.empty())
        {
          a = b;
          return;
        }
      if (!b.bands.empty() && b.bands.front().nominal <= a.bands.back().nominal)
        throw NumericalError(
          "append_bands: the bands from " + format_number(b.bands.front().nominal) +
          " Hz do not follow those up to " + format_number(a.bands.back().nominal) + " Hz");
      if (a.discretisation_error.size() != b.discretisation_error.size())
        throw NumericalError("append_bands: the spectra carry different estimates");
      const auto extend = [](auto &to, const auto &from) {
        to.insert(to.end(), from.begin(), from.end());
      };
      extend(a.bands, b.bands);
      extend(a.rms, b.rms);
      extend(a.level, b.level);
      extend(a.standard_error, b.standard_error);
      extend(a.predicted_error, b.predicted_error);
      extend(a.segments, b.segments);
      extend(a.time_step, b.time_step);
      extend(a.duration, b.duration);
      extend(a.total_error, b.total_error);
      for (std::size_t e = 0; e < a.discretisation_error.size(); ++e)
        {
          if (a.discretisation_error[e].first != b.discretisation_error[e].first)
            throw NumericalError("append_bands: the spectra carry different estimates");
          extend(a.discretisation_error[e].second, b.discretisation_error[e].second);
        }
      a.lines_in_lowest_band = std::min(a.lines_in_lowest_band, b.lines_in_lowest_band);
    }



    void
    write_sound(const std::filesystem::path  &directory,
                const std::vector<SoundCase> &cases,
                const base::ParameterRecord  &record)
    {
      for (const SoundCase &c : cases)
        {
          // Energy: checked before anything is written.
          const BandSpectrum &power  = c.spectra[c.quantities.size() - 2];
          const BandSpectrum &input  = c.spectra[c.quantities.size() - 1];
          double              margin = 1e300;
          for (std::size_t b = 0; b < power.level.size(); ++b)
            margin = std::min(margin, input.level[b] - power.level[b]);
          if (!(margin > 0.))
            throw NumericalError(
              "the radiated power of road " + c.road + " at " + format_number(c.speed_kmh) +
              " km/h exceeds the power the forces put in, by " + format_printf("%.2g", -margin) +
              " dB: the energy is not "
              "conserved");
          const std::string name = "sound_" + road_label(c.road) + "_" + speed_label(c.speed_kmh);
          {
            base::AtomicFile f(directory / (name + ".csv"));
            auto            &o = f.stream();
            o << "# one-third-octave sound of road " << c.road << " at "
              << format_number(c.speed_kmh)
              << " km/h: the pressure level at each microphone [dB re 20 uPa], the radiated power "
                 "and the power the contact forces put into the tyre (a lower bound) [dB re 1 pW]; "
                 "standard_error_dB from the forces' Welch segments, bem_mesh_dB the boundary "
                 "element mesh's estimate (the level on cells sqrt(2) larger), harmonics_dB the "
                 "harmonics' (the level from 3/4 of them), total_error_dB the three in "
                 "quadrature; time_step_us: the run each band came from\n"
              << "band_Hz,quantity,level_dB,standard_error_dB,bem_mesh_dB,harmonics_dB,"
                 "total_error_dB,time_step_us\n";
            for (std::size_t q = 0; q < c.quantities.size(); ++q)
              {
                const BandSpectrum &s = c.spectra[q];
                for (std::size_t b = 0; b < s.bands.size(); ++b)
                  o << s.bands[b].nominal << ',' << c.quantities[q] << ',' << s.level[b] << ','
                    << s.standard_error[b] << ',' << s.discretisation_error.at(0).second[b] << ','
                    << s.discretisation_error.at(1).second[b] << ',' << s.total_error[b] << ','
                    << 1e6 * s.time_step[b] << '\n';
              }
            record.write_comments(o);
            f.commit();
          }

          const std::string csv = base::gnuplot_quote(directory / (name + ".csv"));
          std::string       plot;
          for (std::size_t q = 0; q < c.quantities.size(); ++q)
            {
              const std::string &what = c.quantities[q];
              const std::string  title =
                what == "power" ? "radiated power [dB re 1 pW]" :
                 what == "input" ? "power put in by the forces (a lower bound) [dB re 1 pW]" :
                                   "microphone " + what + " [dB re 20 uPa]";
              plot += std::string(plot.empty() ? "plot " : ", ") + csv +
                      " using 1:((stringcolumn(2) eq '" + what +
                      "') ? $3 : NaN):7 with "
                      "yerrorlines lw 2 pt 7 " +
                      (what == "input" ? "dt 2 " : "") + "lc " + std::to_string(q + 1) +
                      " title '" + title + "'";
            }
          const double low  = c.spectra.front().bands.front().nominal;
          const double high = c.spectra.front().bands.back().nominal;
          base::plot_png(directory / (name + ".png"),
                         "set datafile separator ','\nset datafile commentschars '#'\n"
                         "set grid\nset logscale x\nset xrange [" +
                           format_number(0.85 * low) + ":" + format_number(1.18 * high) +
                           "]\nset xtics (100,125,160,200,250,315,400,500,630,800,1000,1250,1600,"
                           "2000,2500,3150,4000,5000)\nset xlabel 'one-third-octave band [Hz]'\n"
                           "set ylabel 'level [dB]'\nset key outside bottom center\n"
                           "set title 'GreenTread: sound of road " +
                           c.road + " at " + format_number(c.speed_kmh) +
                           " km/h (error bars: standard error, mesh and harmonics)'\n" +
                           "set datafile missing NaN\n" + plot + "\n",
                         record, 1000, 800);

          // The summary: the loudest band at each microphone, and the
          // energy margin.
          std::cout << "  sound of " << c.road << " at " << format_number(c.speed_kmh) << " km/h:";
          for (std::size_t q = 0; q + 2 < c.quantities.size(); ++q)
            {
              const BandSpectrum &s = c.spectra[q];
              const auto          b = static_cast<std::size_t>(
                std::max_element(s.level.begin(), s.level.end()) - s.level.begin());
              std::cout << " " << c.quantities[q] << " " << format_printf("%.1f", s.level[b])
                        << " +- " << format_printf("%.1f", s.total_error[b]) << " dB at "
                        << format_number(s.bands[b].nominal) << " Hz,";
            }
          std::cout << " radiated power at least " << format_printf("%.1f", margin)
                    << " dB below the power put in\n";
        }
    }
  } // namespace analysis
} // namespace greentread
