#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>

namespace greentread
{
  namespace analysis
  {
    namespace
    {
      /// The nominal values of a decade of one-third-octave bands, x 100.
      constexpr int nominal_decade[10] = {100, 125, 160, 200, 250, 315, 400, 500, 630, 800};

      /// The nominal centre [Hz] of band k (exact centre 1000 x 10^(k/10) Hz),
      /// the double nearest the decimal label.
      double
      nominal_of(const int k)
      {
        const int floor_div = (k >= 0 ? k / 10 : -((-k + 9) / 10));
        const int label     = nominal_decade[k - 10 * floor_div];
        // label x 10^(floor_div + 1) Hz; powers of 10 up to 1e22 are exact,
        // so one correctly rounded operation.
        const int e = floor_div + 1;
        return e >= 0 ? label * std::pow(10., e) : label / std::pow(10., -e);
      }

      /// The smallest length >= n whose only prime factors are 2, 3 and 5.
      std::size_t
      fast_length(const std::size_t n)
      {
        for (std::size_t m = std::max<std::size_t>(n, 1);; ++m)
          {
            std::size_t r = m;
            for (const std::size_t p : {2, 3, 5})
              while (r % p == 0)
                r /= p;
            if (r == 1)
              return m;
          }
      }

      /// "the 100 Hz band [89.13, 112.2) Hz"
      std::string
      describe(const FrequencyBand &band)
      {
        return "the " + format_number(band.nominal) + " Hz band [" + format_short(band.lower) +
               ", " + format_short(band.upper) + ") Hz";
      }
    } // namespace



    std::vector<FrequencyBand>
    third_octave_bands(const double f_low, const double f_high)
    {
      if (!(f_low > 0.) || !(f_high >= f_low) || !std::isfinite(f_high))
        throw InputError("one-third-octave bands from f_low = " + format_number(f_low) +
                         " Hz to f_high = " + format_number(f_high) +
                         " Hz: allowed 0 < f_low <= f_high, finite");
      // A few bands beyond the limits each way, filtered by nominal centre.
      const int k_min = static_cast<int>(std::floor(10. * std::log10(f_low / 1000.))) - 2;
      const int k_max = static_cast<int>(std::ceil(10. * std::log10(f_high / 1000.))) + 2;
      std::vector<FrequencyBand> bands;
      for (int k = k_min; k <= k_max; ++k)
        {
          const double nominal = nominal_of(k);
          if (nominal < f_low * (1. - 1e-9) || nominal > f_high * (1. + 1e-9))
            continue;
          // Edges from the same expression, 1000 x 10^(j/20) with j = 2k -+ 1,
          // so that neighbours share theirs exactly.
          bands.push_back({nominal, 1000. * std::pow(10., k / 10.),
                           1000. * std::pow(10., (2 * k - 1) / 20.),
                           1000. * std::pow(10., (2 * k + 1) / 20.)});
        }
      if (bands.empty())
        throw InputError("one-third-octave bands from f_low = " + format_number(f_low) +
                         " Hz to f_high = " + format_number(f_high) +
                         " Hz: no nominal band centre (..., 100, 125, 160, 200, 250, 315, 400, "
                         "500, 630, 800, 1000, ... Hz) lies in that range");
      return bands;
    }



    BandSpectrum
    third_octave_spectrum(const std::vector<double> &x,
                          const double               dt,
                          const double               reference,
                          const double               f_low,
                          const double               f_high)
    {
      if (!(dt > 0.) || !std::isfinite(dt))
        throw InputError("one-third-octave spectrum: the sample interval dt = " +
                         format_number(dt) + " s must be finite and > 0");
      if (!(reference > 0.) || !std::isfinite(reference))
        throw InputError("one-third-octave spectrum: the reference = " + format_number(reference) +
                         " (the rms of 0 dB) must be finite and > 0");

      BandSpectrum s;
      s.bands             = third_octave_bands(f_low, f_high);
      s.reference         = reference;
      const std::size_t B = s.bands.size();

      // The highest band must lie below the Nyquist frequency.
      const FrequencyBand &top     = s.bands.back();
      const double         nyquist = 0.5 / dt;
      if (top.upper > nyquist)
        throw InputError(
          "one-third-octave spectrum: the sample interval dt = " + format_number(dt) +
          " s resolves frequencies up to 1 / (2 dt) = " + format_short(nyquist) +
          " Hz, below the upper edge of " + describe(top) +
          "; allowed: dt <= " + format_short(0.5 / top.upper) + " s, or a lower f_high");

      // Lines 1 / (N dt) apart fall in every band if they are no farther
      // apart than the lowest, narrowest band is wide.
      const std::size_t    N         = x.size();
      const double         duration  = N * dt;
      const FrequencyBand &bottom    = s.bands.front();
      const double         needed    = 1. / (bottom.upper - bottom.lower);
      const auto           too_short = [&]() {
        return InputError(
                    "one-third-octave spectrum: the record of " + std::to_string(N) +
                    " samples at dt = " + format_number(dt) + " s lasts " + format_short(duration) +
                    " s, too short for " + describe(bottom) + ": its Fourier lines would be " +
                    (N > 0 ? format_short(1. / duration) + " Hz" : std::string("infinitely")) +
                    " apart, and the band " + format_short(bottom.upper - bottom.lower) +
                    " Hz wide could hold none; a record of at least " + format_short(needed) + " s (" +
                    std::to_string(static_cast<std::size_t>(std::ceil(needed / dt * (1. - 1e-12)))) +
                    " samples) is needed, or a higher f_low");
      };
      if (!(duration >= needed * (1. - 1e-12)))
        throw too_short();

      double mean = 0.;
      for (std::size_t n = 0; n < N; ++n)
        {
          if (!std::isfinite(x[n]))
            throw NumericalError("one-third-octave spectrum: sample " + std::to_string(n) +
                                 " (t = " + format_short(n * dt) + " s) of the signal is " +
                                 (std::isnan(x[n]) ? "NaN" : "infinite") +
                                 "; the signal must be finite everywhere");
          mean += x[n];
        }
      mean /= N;

      // Mean removed, periodic Hann window, zero-padded to a fast length.
      const std::size_t   M = fast_length(N);
      std::vector<double> y(M, 0.);
      double              window_energy = 0.;
      for (std::size_t n = 0; n < N; ++n)
        {
          const double w = 0.5 * (1. - std::cos(2. * M_PI * double(n) / double(N)));
          y[n]           = w * (x[n] - mean);
          window_energy += w * w;
        }
      Eigen::FFT<double>                fft;
      std::vector<std::complex<double>> Y;
      fft.fwd(Y, y);

      // One-sided power of the lines in [lower, upper) of each band; the
      // bands are increasing and contiguous or not, lines above the last
      // band are not needed.
      std::vector<double>       mean_square(B, 0.);
      std::vector<unsigned int> lines(B, 0);
      std::size_t               b = 0;
      for (std::size_t k = 1; 2 * k <= M && b < B; ++k)
        {
          const double f = double(k) / (double(M) * dt);
          while (b < B && f >= s.bands[b].upper)
            ++b;
          if (b < B && f >= s.bands[b].lower)
            {
              mean_square[b] += (2 * k == M ? 1. : 2.) * std::norm(Y[k]);
              ++lines[b];
            }
        }

      s.rms.resize(B);
      s.level.resize(B);
      const double scale = 1. / (double(M) * window_energy);
      for (std::size_t c = 0; c < B; ++c)
        {
          // Guaranteed by the duration checked above; kept against rounding.
          if (lines[c] == 0)
            throw too_short();
          s.rms[c] = std::sqrt(mean_square[c] * scale);
          if (!std::isfinite(s.rms[c]))
            throw NumericalError("one-third-octave spectrum: the rms in " + describe(s.bands[c]) +
                                 " overflowed; scale the signal down");
          s.level[c] =
            s.rms[c] <= 1e-10 * reference ? level_floor : 20. * std::log10(s.rms[c] / reference);
        }
      s.lines_in_lowest_band = lines[0];
      return s;
    }



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
      o << "nominal_Hz,centre_Hz,lower_Hz,upper_Hz,rms,level_dB\n";
      for (std::size_t b = 0; b < B; ++b)
        o << s.bands[b].nominal << ',' << s.bands[b].centre << ',' << s.bands[b].lower << ','
          << s.bands[b].upper << ',' << s.rms[b] << ',' << s.level[b] << '\n';
      out.commit();
    }
  } // namespace analysis
} // namespace greentread
