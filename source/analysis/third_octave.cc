#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/convolution/fft_length.h>

#include "welch_segments.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>

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
      BandSpectrum      s     = welch::checked_spectrum(x, dt, reference, f_low, f_high);
      const std::size_t B     = s.bands.size();
      const std::size_t M     = convolution::fast_fft_length(x.size());
      const auto        lines = welch::band_lines(M, dt, s.bands);
      const auto mean_square  = welch::segment_mean_squares(x, 0, welch::hann(x.size()), M, lines);
      s.rms.resize(B);
      s.level.resize(B);
      for (std::size_t c = 0; c < B; ++c)
        {
          // A line in every band is guaranteed by the duration checked.
          if (lines[c].weight.empty())
            throw NumericalError("one-third-octave spectrum: " + welch::describe(s.bands[c]) +
                                 " holds no line");
          s.rms[c]   = std::sqrt(mean_square[c]);
          s.level[c] = welch::level_of(s.rms[c], reference, s.bands[c]);
        }
      s.lines_in_lowest_band = lines[0].weight.size();
      return s;
    }



    BandSpectrum
    welch_band_spectrum(const std::vector<double> &x,
                        const double               dt,
                        const double               reference,
                        const double               f_low,
                        const double               f_high,
                        const unsigned int         lines_per_segment)
    {
      if (lines_per_segment == 0)
        throw InputError("one-third-octave spectrum: lines per segment = 0; allowed: >= 1");
      BandSpectrum      s = welch::checked_spectrum(x, dt, reference, f_low, f_high);
      const std::size_t N = x.size();
      welch::resize_for_welch(s, N, dt);

      // The bands that share a segment length share their segments.
      for (const auto &by_length :
           welch::bands_by_segment_length(N, dt, s.bands, lines_per_segment))
        {
          const auto                      &which = by_length.second;
          const welch::SegmentGroup        g(N, dt, s.bands, which, lines_per_segment);
          const unsigned                   K = g.layout.K;
          std::vector<std::vector<double>> power(K);
          for (unsigned k = 0; k < K; ++k)
            power[k] = welch::segment_mean_squares(x, g.layout.start + k * g.layout.hop, g.window,
                                                   g.M, g.lines);
          for (std::size_t c = 0; c < which.size(); ++c)
            {
              std::vector<double> of_band(K);
              for (unsigned k = 0; k < K; ++k)
                of_band[k] = power[k][c];
              welch::band_statistics(s, which[c], g, c, of_band);
            }
        }
      return s;
    }



    std::vector<double>
    predicted_standard_errors(const std::size_t                 n_samples,
                              const double                      dt,
                              const std::vector<FrequencyBand> &bands,
                              const unsigned int                lines_per_segment)
    {
      if (lines_per_segment == 0 || n_samples < 2 || !(dt > 0.))
        throw InputError("predicted standard errors: " + std::to_string(n_samples) +
                         " samples, dt = " + format_short(dt) + " s, " +
                         std::to_string(lines_per_segment) +
                         " lines per segment; allowed: >= 2 samples, dt > 0, >= 1 line");
      std::vector<double> error(bands.size(), INFINITY);
      for (const auto &by_length :
           welch::bands_by_segment_length(n_samples, dt, bands, lines_per_segment))
        {
          const auto               &which = by_length.second;
          const welch::SegmentGroup g(n_samples, dt, bands, which, lines_per_segment);
          for (std::size_t c = 0; c < which.size(); ++c)
            if (!g.lines[c].weight.empty())
              error[which[c]] = g.predicted_error(c);
        }
      return error;
    }



    std::size_t
    samples_for_error(const double                      dt,
                      const std::vector<FrequencyBand> &bands,
                      const unsigned int                lines_per_segment,
                      const double                      target,
                      const std::size_t                 at_least,
                      const std::size_t                 at_most)
    {
      const auto meets = [&](const std::size_t N) {
        for (const double e : predicted_standard_errors(N, dt, bands, lines_per_segment))
          if (!(e <= target))
            return false;
        return true;
      };
      std::size_t lo = std::max<std::size_t>(2, at_least);
      if (bands.empty() || meets(lo))
        return lo;
      std::size_t hi = std::max(lo, at_most);
      if (!meets(hi))
        return hi + 1;
      // The prediction does not rise with the record (a band's segment
      // count and its lines only grow), so bisection finds the smallest N.
      while (hi - lo > 1)
        {
          const std::size_t mid  = lo + (hi - lo) / 2;
          (meets(mid) ? hi : lo) = mid;
        }
      return hi;
    }
  } // namespace analysis
} // namespace greentread
