#include <greentread/analysis/error_bars.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <map>

/**
 * @file
 * The spectra of a study, per road and per speed: write_spectra() of
 * rolling_output.h, its CSV files, plots and printed summary.
 */

namespace greentread
{
  namespace analysis
  {
    namespace
    {
      /// The discretisations estimated in any run, in the order of the first.
      std::vector<std::string>
      estimate_labels(const std::vector<RunSpectrum> &results)
      {
        std::vector<std::string> labels;
        for (const auto &r : results)
          for (const auto &e : r.spectrum.discretisation_error)
            if (std::find(labels.begin(), labels.end(), e.first) == labels.end())
              labels.push_back(e.first);
        return labels;
      }



      /// spectra.csv or spectra_force.csv (@p name): every run's spectrum
      /// @p which, a row per band, with its standard error and estimates.
      void
      write_spectra_csv(const std::filesystem::path    &directory,
                        const std::vector<RunSpectrum> &results,
                        const double                    f_max,
                        const SpectraParameters        &spectra,
                        const base::ParameterRecord    &record,
                        const std::string              &name,
                        const std::string              &what,
                        const BandSpectrum RunSpectrum::*which)
      {
        const std::vector<std::string> labels = estimate_labels(results);
        base::AtomicFile               f(directory / name);
        auto                          &o = f.stream();
        o << "# one-third-octave levels " << what << "; IEC 61260-1 base-10 bands; the Green's "
          << "functions end at " << format_number(f_max) << " Hz; Welch's average over "
          << "segments of " << spectra.lines_per_segment << " lines per band, standard_error_dB "
          << "one standard error of the level (the segments' scatter with " << min_observed_segments
          << " or more, and at least a Gaussian signal's below " << floor_segments
          << "; a Gaussian signal's with fewer)\n"
          << "; time_step_us and record_m: the run each band came from (the low-rate run "
          << "of 'Spectra/Low bands up to', or the run at the scene's step)"
          << (labels.empty() ? "" :
                               "; <discretisation>_dB: the error bars' estimate of that "
                               "discretisation's error (analysis/error_bars.h; empty: not "
                               "estimated in the band), total_error_dB: the standard error and "
                               "the estimates in quadrature")
          << "\nroad,speed_kmh,band_Hz,level_dB,standard_error_dB,segments,time_step_us,record_m"
          << (labels.empty() ? "" : ",total_error_dB");
        for (const auto &l : labels)
          o << ',' << l << "_dB";
        o << '\n';
        for (const auto &r : results)
          {
            const BandSpectrum &s = r.*which;
            for (std::size_t b = 0; b < s.bands.size(); ++b)
              {
                o << r.road << ',' << r.speed_kmh << ',' << s.bands[b].nominal << ',' << s.level[b]
                  << ',' << s.standard_error[b] << ',' << s.segments[b] << ','
                  << 1e6 * s.time_step[b] << ',' << s.duration[b] * r.speed_kmh / 3.6;
                if (!labels.empty())
                  o << ',' << (s.total_error.empty() ? s.standard_error[b] : s.total_error[b]);
                for (const auto &l : labels)
                  {
                    double value = std::numeric_limits<double>::quiet_NaN();
                    for (const auto &[name, error] : s.discretisation_error)
                      if (name == l)
                        value = error[b];
                    o << ',';
                    if (!std::isnan(value)) // empty: not estimated in this band
                      o << value;
                  }
                o << '\n';
              }
          }
        record.write_comments(o);
        f.commit();
      }



      /// A road's name in a plot's (enhanced) text: its label with its
      /// underscores shown as such, a slick_road()'s as "<label> slick".
      std::string
      plot_label(const std::string &road)
      {
        const std::string texture = texture_of_road(road);
        std::string       label;
        for (const char c : road_label(texture))
          label += c == '_' ? std::string("\\_") : std::string(1, c);
        return texture != road ? label + " slick" : label;
      }



      /// A plot of the runs that @p take selects, from their spectrum files
      /// `<kind><run>.csv`.
      void
      plot_spectra(const std::filesystem::path                    &directory,
                   const std::vector<RunSpectrum>                 &results,
                   const base::ParameterRecord                    &record,
                   const std::filesystem::path                    &png,
                   const std::string                              &title,
                   const std::string                              &kind,
                   const std::string                              &ylabel,
                   const std::function<bool(const RunSpectrum &)> &take)
      {
        // Each curve over its band of +- one standard error (or its error
        // bar: the standard error and the discretisation estimates), in its
        // colour.
        std::string bands, curves;
        unsigned    colour = 0;
        for (const auto &r : results)
          if (take(r))
            {
              const std::string csv = base::gnuplot_quote(
                directory / (kind + road_label(r.road) + "_" + speed_label(r.speed_kmh) + ".csv"));
              const std::string lc = " lc " + std::to_string(++colour);
              const std::string e  = r.spectrum.total_error.empty() ? "$7" : "$12";
              bands += (bands.empty() ? "plot " : ", ") + csv + " skip 2 using 1:($6-" + e +
                       "):($6+" + e + ") with filledcurves fs transparent solid 0.2 noborder" + lc +
                       " notitle";
              curves += ", " + csv + " skip 2 using 1:6 with linespoints lw 2" + lc + " title '" +
                        plot_label(r.road) + ", " + format_number(r.speed_kmh) + " km/h'";
            }
        const std::string plot = bands + curves;
        base::plot_png(
          png,
          "set datafile separator ','\nset datafile commentschars '#'\nset grid\n"
          "set logscale x\nset xrange [90:5600]\nset xtics (100,200,500,1000,2000,5000)\n"
          "set xlabel 'one-third-octave band [Hz]'\nset ylabel '" +
            ylabel + "'\nset key left bottom\nset title '" + title + "'\n" + plot + "\n",
          record);
      }



      /// The band of the highest level and the spectral centroid of @p spectrum.
      std::string
      summarise(const BandSpectrum &spectrum)
      {
        std::size_t peak  = 0;
        double      power = 0., moment = 0.;
        for (std::size_t b = 0; b < spectrum.bands.size(); ++b)
          {
            if (spectrum.level[b] > spectrum.level[peak])
              peak = b;
            const double p = spectrum.rms[b] * spectrum.rms[b];
            power += p;
            moment += p * std::log10(spectrum.bands[b].centre);
          }
        if (!(power > 0.))
          return std::string("nothing in any band");
        return "highest band " + format_number(spectrum.bands[peak].nominal) + " Hz (" +
               format_printf("%.1f", spectrum.level[peak]) + " dB), spectral centroid " +
               format_printf("%.0f", std::pow(10., moment / power)) + " Hz";
      }



      /// The standard errors against the target: the bands that miss it,
      /// and the distance that would meet it (the error falls as 1 / sqrt(T)).
      void
      print_standard_errors(const std::vector<RunSpectrum> &results,
                            const SpectraParameters        &spectra)
      {
        std::cout << "Standard errors of the band levels from "
                  << format_number(spectra.target_from) << " Hz (target "
                  << format_number(spectra.target_error)
                  << " dB, 'Spectra/Standard error target'):\n";
        bool all_met = true;
        for (const auto &r : results)
          for (const auto &[what, s] :
               {std::pair<const char *, const BandSpectrum *>{"stress", &r.spectrum},
                {"force", &r.force_spectrum}})
            {
              double      largest = 0.;
              std::string missed;
              // Per run that gave a band (by its time step): the distance that
              // would meet the target in its bands.
              std::map<double, double> needed;
              for (std::size_t b = 0; b < s->bands.size(); ++b)
                if (s->bands[b].nominal >= spectra.target_from * (1. - 1e-9))
                  {
                    largest = std::max(largest, s->standard_error[b]);
                    if (s->standard_error[b] > spectra.target_error)
                      {
                        missed += (missed.empty() ? "" : ", ") + format_number(s->bands[b].nominal);
                        const double ratio = s->standard_error[b] / spectra.target_error;
                        double      &d     = needed[s->time_step[b]];
                        d = std::max(d, s->duration[b] * r.speed_kmh / 3.6 * ratio * ratio);
                      }
                  }
              std::cout << "  " << road_label(r.road) << " at " << format_number(r.speed_kmh)
                        << " km/h, " << what << ": largest " << format_printf("%.2f", largest)
                        << " dB";
              if (missed.empty())
                std::cout << ", target met\n";
              else
                {
                  all_met = false;
                  std::cout << "; above the target in the " << missed << " Hz bands";
                  const double fine_step = s->time_step.back();
                  // With 'Extend runs' a run misses only at its longest.
                  for (const auto &[step, d] : needed)
                    std::cout << "; "
                              << (step > fine_step * (1. + 1e-9) ? "a low-rate run of " :
                                  spectra.extend_runs            ? "a run at the scene's step of " :
                                                                   "'Rolling/Distance' = ")
                              << format_printf("%.3g", d) << " m would meet it"
                              << (spectra.extend_runs ?
                                    " (the run stopped at its longest: 'Spectra/Longest "
                                    "distance', 3 times its plan, or the road's length)" :
                                  step > fine_step * (1. + 1e-9) ?
                                    " ('Spectra/Longest distance', 'Spectra/Extend runs')" :
                                    "");
                  std::cout << '\n';
                }
            }
        if (!all_met)
          std::cout << "  (spectra.csv and spectra_force.csv give every band's standard error)\n";
      }



      /// The error bars: the largest in the bands that carry the most
      /// energy, and what to change to lower it.
      void
      print_error_bars(const std::vector<RunSpectrum> &results, const SpectraParameters &spectra)
      {
        constexpr double leading = 10.;
        std::cout << "Error bars from " << format_number(spectra.target_from)
                  << " Hz (the standard error and the discretisation estimates, 'Error "
                     "bars/Estimates'; in the bands within "
                  << format_number(leading) << " dB of the highest, the largest contributor):\n";
        for (const auto &r : results)
          for (const auto &[what, s] :
               {std::pair<const char *, const BandSpectrum *>{"stress", &r.spectrum},
                {"force", &r.force_spectrum}})
            {
              double largest = 0., band = 0.;
              for (std::size_t b = 0; b < s->bands.size(); ++b)
                if (s->bands[b].nominal >= spectra.target_from * (1. - 1e-9) &&
                    !s->total_error.empty() && s->total_error[b] > largest)
                  {
                    largest = s->total_error[b];
                    band    = s->bands[b].nominal;
                  }
              const Contributor c = largest_contributor(*s, spectra.target_from, leading);
              std::cout << "  " << road_label(r.road) << " at " << format_number(r.speed_kmh)
                        << " km/h, " << what << ": largest " << format_printf("%.2f", largest)
                        << " dB (" << format_number(band) << " Hz); leading bands: "
                        << (c.what == "statistics" ? "the standard error" :
                                                     "the " + c.what + "'s estimate")
                        << ", " << format_printf("%.2f", c.error) << " dB at "
                        << format_number(c.band) << " Hz: " << c.parameter << '\n';
            }
      }
    } // namespace



    void
    write_spectra(const std::filesystem::path    &directory,
                  const std::vector<RunSpectrum> &results,
                  const std::vector<std::string> &roads,
                  const std::vector<double>      &speeds,
                  const double                    stress_reference,
                  const double                    f_max,
                  const SpectraParameters        &spectra,
                  const base::ParameterRecord    &record)
    {
      // Each run's spectra, each band from the run that gave it.
      for (const auto &r : results)
        {
          const std::string run = road_label(r.road) + "_" + speed_label(r.speed_kmh);
          write_band_spectrum_csv(directory / ("spectrum_" + run + ".csv"), r.spectrum,
                                  "contact stress at the patch centre (the mean over the "
                                  "reporting cell), Pa");
          write_band_spectrum_csv(directory / ("spectrum_force_" + run + ".csv"), r.force_spectrum,
                                  "total contact force, N");
        }
      write_spectra_csv(directory, results, f_max, spectra, record, "spectra.csv",
                        "L_f = 20 log10(sigma_rms / sigma0) of the contact stress at the patch "
                        "centre (the mean over the reporting cell), sigma0 = " +
                          format_number(stress_reference) + " Pa",
                        &RunSpectrum::spectrum);
      write_spectra_csv(directory, results, f_max, spectra, record, "spectra_force.csv",
                        "L_F = 20 log10(F_rms / 1 N) of the total contact force",
                        &RunSpectrum::force_spectrum);
      const auto plot = [&](const std::filesystem::path &png, const std::string &title,
                            const std::string &kind, const std::string &ylabel,
                            const std::function<bool(const RunSpectrum &)> &take) {
        plot_spectra(directory, results, record, png, title, kind, ylabel, take);
      };
      const std::string stress_label = "L_f [dB re " + format_number(stress_reference) + " Pa]";
      for (const auto &road_name : roads)
        {
          const auto take = [&](const RunSpectrum &r) {
            return r.road == road_name;
          };
          plot(directory / ("spectra_" + road_label(road_name) + ".png"),
               "Contact stress at the patch centre, road " + plot_label(road_name) +
                 " (Figure A.14)",
               "spectrum_", stress_label, take);
          plot(directory / ("spectra_force_" + road_label(road_name) + ".png"),
               "Total contact force, road " + plot_label(road_name), "spectrum_force_",
               "L_F [dB re 1 N]", take);
        }
      for (const double v : speeds)
        {
          const auto take = [&](const RunSpectrum &r) {
            return r.speed_kmh == v;
          };
          plot(directory / ("spectra_" + speed_label(v) + ".png"),
               "Contact stress at the patch centre, " + format_number(v) + " km/h (Figure A.15)",
               "spectrum_", stress_label, take);
          plot(directory / ("spectra_force_" + speed_label(v) + ".png"),
               "Total contact force, " + format_number(v) + " km/h", "spectrum_force_",
               "L_F [dB re 1 N]", take);
        }

      // The band of the highest level per run: does it rise with the speed?
      std::cout << "Spectra (one-third octaves of the contact stress at the patch centre, dB re "
                << format_number(stress_reference) << " Pa; of the total force, dB re 1 N):\n";
      for (const auto &r : results)
        std::cout << "  " << road_label(r.road) << " at " << format_number(r.speed_kmh)
                  << " km/h: stress " << summarise(r.spectrum) << "; force "
                  << summarise(r.force_spectrum) << '\n';

      print_standard_errors(results, spectra);
      if (!estimate_labels(results).empty())
        print_error_bars(results, spectra);
    }
  } // namespace analysis
} // namespace greentread
