#include <greentread/analysis/band_runs.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace analysis
  {
    namespace
    {
      /// The bands whose nominal centres lie in [f_low, f_high] (none if f_low > f_high).
      std::vector<FrequencyBand>
      bands_between(const double f_low, const double f_high)
      {
        if (f_low > f_high * (1. + 1e-9))
          return {};
        return third_octave_bands(f_low, f_high);
      }

      /// The samples of a run of @p distance at speed V and step dt.
      std::size_t
      samples(const double distance, const double V, const double dt)
      {
        return static_cast<std::size_t>(std::ceil(distance / (V * dt) * (1. - 1e-9)));
      }
    } // namespace



    double
    top_band_for_step(const double dt)
    {
      double top = 0.;
      for (const auto &band : third_octave_bands(lowest_band, highest_band))
        if (band.upper <= 0.5 / dt)
          top = band.nominal;
      if (top == 0.)
        throw InputError(
          "parameter 'Time stepping/Time step' = " + format_short(dt) +
          " s: the spectra need frequencies up to at least " +
          format_printf("%.0f", third_octave_bands(lowest_band, lowest_band)[0].upper) +
          " Hz (the " + format_number(lowest_band) + " Hz band); allowed: a time step <= " +
          format_short(0.5 / third_octave_bands(lowest_band, lowest_band)[0].upper) + " s");
      return top;
    }



    std::vector<BandRun>
    plan_band_runs(const SpectraParameters &spectra,
                   const double             V,
                   const double             dt,
                   const double             distance,
                   const double             top_band)
    {
      // The most steps a run may extend to: 'Longest distance', and
      // longest_extension times its plan, but never fewer than planned.
      const auto longest_steps = [&](const BandRun &run) -> unsigned int {
        if (!spectra.extend_runs)
          return 0;
        const double cap =
          std::min(spectra.longest_distance, SpectraParameters::longest_extension * run.distance);
        return std::max(run.steps, unsigned(std::floor(cap / (V * run.time_step))));
      };
      BandRun fine;
      fine.time_step     = dt;
      fine.distance      = distance;
      fine.steps         = unsigned(samples(distance, V, dt));
      fine.f_high        = top_band;
      fine.longest_steps = longest_steps(fine);
      const double split = std::min(spectra.low_bands_up_to, top_band);
      if (spectra.low_band_time_step <= dt * (1. + 1e-9) || split < 100.)
        return {fine};

      BandRun low;
      low.name                        = "low-rate";
      low.time_step                   = spectra.low_band_time_step;
      low.f_high                      = split;
      const FrequencyBand highest_low = third_octave_bands(split, split).back();
      if (highest_low.upper > 0.5 / low.time_step)
        {
          throw InputError(
            "parameter 'Spectra/Low-band time step' = " + format_short(low.time_step) +
            " s resolves up to " + format_short(0.5 / low.time_step) +
            " Hz, below the upper edge of the " + format_number(split) +
            " Hz band ('Spectra/Low bands up to'); allowed: at most " +
            format_short(0.5 / highest_low.upper) + " s");
        }

      // The low-rate run's record: what the target needs in its bands.
      const auto        targeted = bands_between(spectra.target_from, split);
      const std::size_t at_least = samples(distance, V, low.time_step);
      // The cap rounds down: the run must fit the road it is given.
      const std::size_t at_most =
        static_cast<std::size_t>(std::floor(spectra.longest_distance / (V * low.time_step)));
      std::size_t N = samples_for_error(low.time_step, targeted, spectra.lines_per_segment,
                                        spectra.target_error, at_least, at_most);
      if (N > at_most)
        {
          low.target_out_of_reach = true;
          N                       = at_most;
        }
      // Nothing gained: the run at the scene's step meets the target there.
      const auto fine_errors =
        targeted.empty() ?
          std::vector<double>() :
          predicted_standard_errors(fine.steps, dt, targeted, spectra.lines_per_segment);
      if (std::all_of(fine_errors.begin(), fine_errors.end(), [&](const double e) {
            return e <= spectra.target_error;
          }))
        return {fine};
      low.distance = double(N) * V * low.time_step;
      // No longer than the run at the step (a texture file too short for
      // the target): the coarser step would gain nothing.
      if (low.distance <= distance * (1. + 1e-9))
        return {fine};
      low.steps         = unsigned(samples(low.distance, V, low.time_step));
      low.longest_steps = low.target_out_of_reach ? 0 : longest_steps(low);
      const auto above  = third_octave_bands(split, 2. * split);
      fine.f_low        = above.size() > 1 ? above[1].nominal : top_band;
      return {fine, low};
    }



    unsigned int
    more_steps_for_target(const SpectraParameters &spectra,
                          const BandRun           &run,
                          const BandSpectrum      &stress,
                          const BandSpectrum      &force,
                          const unsigned int       steps_done)
    {
      if (steps_done == 0 || steps_done >= run.longest_steps)
        return 0;
      const double from  = std::max(spectra.target_from, run.f_low);
      double       worst = 0.;
      for (const BandSpectrum *s : {&stress, &force})
        for (std::size_t b = 0; b < s->bands.size(); ++b)
          {
            const double f = s->bands[b].nominal;
            if (f >= from * (1. - 1e-9) && f <= run.f_high * (1. + 1e-9))
              worst = std::max(worst, s->standard_error[b]);
          }
      if (!(worst > spectra.target_error))
        return 0;
      const double ratio  = worst / spectra.target_error;
      const double wanted = std::ceil(1.05 * steps_done * ratio * ratio);
      return unsigned(std::min<double>(wanted, run.longest_steps)) - steps_done;
    }



    std::string
    low_rate_disagreement(const BandSpectrum &fine,
                          const BandSpectrum &low_spectrum,
                          const BandRun      &low)
    {
      std::string worst;
      double      largest = 0.;
      for (std::size_t c = 0; c < low_spectrum.bands.size(); ++c)
        {
          const double f = low_spectrum.bands[c].nominal;
          if (f < low.f_low * (1. - 1e-9) || f > low.f_high * (1. + 1e-9))
            continue;
          for (std::size_t b = 0; b < fine.bands.size(); ++b)
            if (std::abs(fine.bands[b].nominal - f) <= 1e-9 * f)
              {
                const double d = std::abs(low_spectrum.level[c] - fine.level[b]);
                const double se =
                  std::hypot(low_spectrum.standard_error[c], fine.standard_error[b]);
                if (d > low_rate_tolerance * se && d / se > largest)
                  {
                    largest = d / se;
                    worst   = "the " + format_number(f) +
                            " Hz band: " + format_printf("%.1f", low_spectrum.level[c]) +
                            " against " + format_printf("%.1f", fine.level[b]) + " dB, " +
                            format_printf("%.1f", largest) + " combined standard errors apart";
                  }
              }
        }
      return worst;
    }



    BandSpectrum
    merge_band_spectra(const BandSpectrum &fine,
                       const BandSpectrum &low_spectrum,
                       const BandRun      &low)
    {
      BandSpectrum merged = fine;
      for (std::size_t b = 0; b < merged.bands.size(); ++b)
        {
          const double f = merged.bands[b].nominal;
          if (f < low.f_low * (1. - 1e-9) || f > low.f_high * (1. + 1e-9))
            continue;
          const auto it = std::find_if(low_spectrum.bands.begin(), low_spectrum.bands.end(),
                                       [&](const FrequencyBand &band) {
                                         return std::abs(band.nominal - f) <= 1e-9 * f;
                                       });
          if (it == low_spectrum.bands.end())
            throw InputError("merging band spectra: the low-rate run has no " + format_number(f) +
                             " Hz band");
          const std::size_t c       = it - low_spectrum.bands.begin();
          merged.rms[b]             = low_spectrum.rms[c];
          merged.level[b]           = low_spectrum.level[c];
          merged.standard_error[b]  = low_spectrum.standard_error[c];
          merged.predicted_error[b] = low_spectrum.predicted_error[c];
          merged.segments[b]        = low_spectrum.segments[c];
          merged.time_step[b]       = low_spectrum.time_step[c];
          merged.duration[b]        = low_spectrum.duration[c];
          if (b == 0)
            merged.lines_in_lowest_band = low_spectrum.lines_in_lowest_band;
        }
      return merged;
    }
  } // namespace analysis
} // namespace greentread
