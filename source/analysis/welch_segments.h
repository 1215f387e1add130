#pragma once

// The machinery of Welch's one-third-octave spectra that third_octave.cc and
// welch_channels.cc share: the checks, the windows, each band's Fourier
// lines, the segments and the statistics of their powers. Internal to
// source/analysis.

#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/convolution/fft_length.h>

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <string>
#include <vector>

namespace greentread
{
  namespace analysis
  {
    namespace welch
    {
      /// "the 100 Hz band [89.13, 112.2) Hz"
      inline std::string
      describe(const FrequencyBand &band)
      {
        return "the " + format_number(band.nominal) + " Hz band [" + format_short(band.lower) +
               ", " + format_short(band.upper) + ") Hz";
      }

      /**
       * The checks both estimators share (throwing the errors documented at
       * third_octave_spectrum()): the spectrum's bands and reference, with
       * nothing estimated yet.
       */
      inline BandSpectrum
      checked_bands(const std::size_t N,
                    const double      dt,
                    const double      reference,
                    const double      f_low,
                    const double      f_high)
      {
        if (!(dt > 0.) || !std::isfinite(dt))
          throw InputError("one-third-octave spectrum: the sample interval dt = " +
                           format_number(dt) + " s must be finite and > 0");
        if (!(reference > 0.) || !std::isfinite(reference))
          throw InputError("one-third-octave spectrum: the reference = " +
                           format_number(reference) + " (the rms of 0 dB) must be finite and > 0");

        BandSpectrum s;
        s.bands     = third_octave_bands(f_low, f_high);
        s.reference = reference;

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
        const double         duration = N * dt;
        const FrequencyBand &bottom   = s.bands.front();
        const double         needed   = 1. / (bottom.upper - bottom.lower);
        if (!(duration >= needed * (1. - 1e-12)))
          throw InputError(
            "one-third-octave spectrum: the record of " + std::to_string(N) +
            " samples at dt = " + format_number(dt) + " s lasts " + format_short(duration) +
            " s, too short for " + describe(bottom) + ": its Fourier lines would be " +
            (N > 0 ? format_short(1. / duration) + " Hz" : std::string("infinitely")) +
            " apart, and the band " + format_short(bottom.upper - bottom.lower) +
            " Hz wide could hold none; a record of at least " + format_short(needed) + " s (" +
            std::to_string(static_cast<std::size_t>(std::ceil(needed / dt * (1. - 1e-12)))) +
            " samples) is needed, or a higher f_low");
        return s;
      }

      /// The same, and every sample of @p x finite (@p what names it).
      inline BandSpectrum
      checked_spectrum(const std::vector<double> &x,
                       const double               dt,
                       const double               reference,
                       const double               f_low,
                       const double               f_high,
                       const std::string         &what = "the signal")
      {
        BandSpectrum      s = checked_bands(x.size(), dt, reference, f_low, f_high);
        const std::size_t N = x.size();
        for (std::size_t n = 0; n < N; ++n)
          if (!std::isfinite(x[n]))
            throw NumericalError("one-third-octave spectrum: sample " + std::to_string(n) +
                                 " (t = " + format_short(n * dt) + " s) of " + what + " is " +
                                 (std::isnan(x[n]) ? "NaN" : "infinite") +
                                 "; the signal must be finite everywhere");
        return s;
      }



      /// The periodic Hann window of @p n samples.
      inline std::vector<double>
      hann(const std::size_t n)
      {
        std::vector<double> w(n);
        for (std::size_t m = 0; m < n; ++m)
          w[m] = 0.5 * (1. - std::cos(2. * M_PI * double(m) / double(n)));
        return w;
      }



      /// The Fourier lines of one segment that fall in one band: the first,
      /// and the share of each line's cell that lies in the band.
      struct BandLines
      {
        std::size_t         first = 0;
        std::vector<double> weight;
      };



      /**
       * The Fourier lines of a segment zero padded to @p M samples that fall
       * in each of @p bands (increasing): each line's share of its cell
       * [f - df / 2, f + df / 2) that lies in [lower, upper), so that a flat
       * spectrum gives the band's width exactly, whatever its number of
       * lines (an edge line is shared by two bands); lines above the last
       * band are not needed.
       */
      inline std::vector<BandLines>
      band_lines(const std::size_t M, const double dt, const std::vector<FrequencyBand> &bands)
      {
        const std::size_t      B  = bands.size();
        const double           df = 1. / (double(M) * dt);
        std::vector<BandLines> lines(B);
        std::size_t            b = 0;
        for (std::size_t k = 1; 2 * k <= M && b < B; ++k)
          {
            const double lo = (double(k) - 0.5) * df, hi = (double(k) + 0.5) * df;
            while (b < B && bands[b].upper <= lo)
              ++b;
            for (std::size_t c = b; c < B && bands[c].lower < hi; ++c)
              {
                const double share =
                  (std::min(hi, bands[c].upper) - std::max(lo, bands[c].lower)) / df;
                if (share <= 0.)
                  continue;
                if (lines[c].weight.empty())
                  lines[c].first = k;
                lines[c].weight.push_back(share);
              }
          }
        return lines;
      }



      /**
       * The mean square in each band of @p lines (band_lines() for the
       * padded length @p M) of the segment x[start, start + n): its mean
       * removed, the Hann window @p w, zero padded to @p M
       * (third_octave_spectrum()).
       */
      inline std::vector<double>
      segment_mean_squares(const std::vector<double>    &x,
                           const std::size_t             start,
                           const std::vector<double>    &w,
                           const std::size_t             M,
                           const std::vector<BandLines> &lines)
      {
        const std::size_t n    = w.size();
        double            mean = 0.;
        for (std::size_t m = 0; m < n; ++m)
          mean += x[start + m];
        mean /= double(n);
        std::vector<double> y(M, 0.);
        double              window_energy = 0.;
        for (std::size_t m = 0; m < n; ++m)
          {
            y[m] = w[m] * (x[start + m] - mean);
            window_energy += w[m] * w[m];
          }
        Eigen::FFT<double>                fft;
        std::vector<std::complex<double>> Y;
        fft.fwd(Y, y);
        // One-sided power of each line times its share of the band.
        std::vector<double> mean_square(lines.size(), 0.);
        const double        scale = 1. / (double(M) * window_energy);
        for (std::size_t c = 0; c < lines.size(); ++c)
          for (std::size_t i = 0; i < lines[c].weight.size(); ++i)
            {
              const std::size_t k = lines[c].first + i;
              mean_square[c] += lines[c].weight[i] * (2 * k == M ? 1. : 2.) * std::norm(Y[k]);
            }
        for (auto &p : mean_square)
          p *= scale;
        return mean_square;
      }



      /**
       * Welch's segments of one band in a record of @p N samples: @p n
       * samples each (the shorter of the record and the length that puts
       * @p lines_per_segment lines in the band), @p K of them, @p hop
       * apart, the first at @p start (they end with the record).
       */
      struct SegmentLayout
      {
        std::size_t n = 0, hop = 1, start = 0;
        unsigned    K = 1;
      };

      inline SegmentLayout
      segment_layout(const std::size_t    N,
                     const double         dt,
                     const FrequencyBand &band,
                     const unsigned int   lines_per_segment)
      {
        SegmentLayout l;
        const double  want = std::ceil(lines_per_segment / ((band.upper - band.lower) * dt));
        l.n                = want >= double(N) ? N : std::max<std::size_t>(2, std::size_t(want));
        l.hop              = std::max<std::size_t>(1, l.n / 2);
        l.K                = l.n == N ? 1u : unsigned(1 + (N - l.n) / l.hop);
        l.start            = N - (l.n + (l.K - 1) * l.hop);
        return l;
      }



      /**
       * The correlation of a segment's Hann-windowed Fourier coefficients d
       * lines apart on the padded length M, for a white signal:
       * r(d) = sum_m w_m^2 e^{-2 pi i d m / M} / sum_m w_m^2, by one FFT.
       */
      inline std::vector<std::complex<double>>
      line_correlation(const std::vector<double> &w, const std::size_t M)
      {
        std::vector<double> w2(M, 0.);
        for (std::size_t m = 0; m < w.size(); ++m)
          w2[m] = w[m] * w[m];
        Eigen::FFT<double>                fft;
        std::vector<std::complex<double>> r;
        fft.fwd(r, w2);
        const double energy = r[0].real();
        for (auto &v : r)
          v /= energy;
        return r;
      }



      /**
       * The relative variance of a band's power from one segment, for a
       * Gaussian signal flat across the band: its lines, weighted by their
       * shares a_k of the band, correlate as @p r (line_correlation()), so
       * it is sum_{k,k'} a_k a_k' |r(k - k')|^2 / (sum_k a_k)^2.
       */
      inline double
      gaussian_relative_variance(const std::vector<std::complex<double>> &r,
                                 const std::vector<double>               &a)
      {
        double sum = 0., total = 0.;
        for (std::size_t k = 0; k < a.size(); ++k)
          {
            total += a[k];
            for (std::size_t l = 0; l < a.size(); ++l)
              sum += a[k] * a[l] * std::norm(r[k > l ? k - l : l - k]);
          }
        return sum / (total * total);
      }



      /// Welch's factor on the variance of the mean of @p K segments of the
      /// window @p w, @p hop samples apart: 1 + 2 sum_j (1 - j / K) rho_j^2.
      inline double
      overlap_factor(const std::vector<double> &w, const std::size_t hop, const unsigned K)
      {
        double energy = 0.;
        for (const double v : w)
          energy += v * v;
        double factor = 1.;
        for (unsigned j = 1; j < K && j * hop < w.size(); ++j)
          {
            double rho = 0.;
            for (std::size_t m = 0; m + j * hop < w.size(); ++m)
              rho += w[m] * w[m + j * hop];
            rho /= energy;
            factor += 2. * (1. - double(j) / K) * rho * rho;
          }
        return factor;
      }



      /// The level of @p rms, floored (third_octave_spectrum()); @throws
      /// NumericalError if it overflowed.
      inline double
      level_of(const double rms, const double reference, const FrequencyBand &band)
      {
        if (!std::isfinite(rms))
          throw NumericalError("one-third-octave spectrum: the rms in " + describe(band) +
                               " overflowed; scale the signal down");
        return rms <= 1e-10 * reference ? level_floor : 20. * std::log10(rms / reference);
      }

      /// The bands (indices into @p bands) that share a Welch segment
      /// length, by that length, in a record of @p N samples.
      inline std::map<std::size_t, std::vector<std::size_t>>
      bands_by_segment_length(const std::size_t                 N,
                              const double                      dt,
                              const std::vector<FrequencyBand> &bands,
                              const unsigned int                lines_per_segment)
      {
        std::map<std::size_t, std::vector<std::size_t>> by_length;
        for (std::size_t b = 0; b < bands.size(); ++b)
          by_length[segment_layout(N, dt, bands[b], lines_per_segment).n].push_back(b);
        return by_length;
      }

      constexpr double to_db = 10. / M_LN10;

      /// What the bands of one segment length share: their segments, the
      /// window, the padded length, the overlap's factor, the lines'
      /// correlation and each band's lines.
      struct SegmentGroup
      {
        SegmentLayout                     layout;
        std::vector<double>               window;
        std::size_t                       M       = 0;
        double                            overlap = 1.;
        std::vector<std::complex<double>> correlation;
        std::vector<BandLines>            lines;

        SegmentGroup(const std::size_t                 N,
                     const double                      dt,
                     const std::vector<FrequencyBand> &bands,
                     const std::vector<std::size_t>   &which,
                     const unsigned int                lines_per_segment)
            : layout(segment_layout(N, dt, bands[which[0]], lines_per_segment))
            , window(hann(layout.n))
            , M(convolution::fast_fft_length(layout.n))
            , overlap(overlap_factor(window, layout.hop, layout.K))
            , correlation(line_correlation(window, M))
        {
          std::vector<FrequencyBand> group;
          for (const std::size_t b : which)
            group.push_back(bands[b]);
          lines = band_lines(M, dt, group);
        }

        /// The Gaussian prediction of the standard error of the group's band @p c [dB].
        double
        predicted_error(const std::size_t c) const
        {
          return to_db * std::sqrt(gaussian_relative_variance(correlation, lines[c].weight) *
                                   overlap / layout.K);
        }
      };

      /// An empty spectrum of @p B bands with room for Welch's estimates.
      inline void
      resize_for_welch(BandSpectrum &s, const std::size_t N, const double dt)
      {
        const std::size_t B = s.bands.size();
        s.rms.resize(B);
        s.level.resize(B);
        s.standard_error.resize(B);
        s.predicted_error.resize(B);
        s.segments.resize(B);
        s.time_step.assign(B, dt);
        s.duration.assign(B, double(N) * dt);
      }

      /**
       * Band @p b of @p s from its power in each of the K segments of
       * @p g (its band @p c there): the level of the mean, and its standard
       * error from the segments' scatter or the Gaussian prediction
       * (welch_band_spectrum()).
       */
      inline void
      band_statistics(BandSpectrum              &s,
                      const std::size_t          b,
                      const SegmentGroup        &g,
                      const std::size_t          c,
                      const std::vector<double> &power)
      {
        if (g.lines[c].weight.empty())
          throw NumericalError("one-third-octave spectrum: " + describe(s.bands[b]) +
                               " holds no line");
        const unsigned K    = g.layout.K;
        double         mean = 0.;
        for (unsigned k = 0; k < K; ++k)
          mean += power[k];
        mean /= K;
        s.rms[b]             = std::sqrt(mean);
        s.level[b]           = level_of(s.rms[b], s.reference, s.bands[b]);
        s.segments[b]        = K;
        s.predicted_error[b] = g.predicted_error(c);
        if (K >= min_observed_segments && mean > 0.)
          {
            double scatter = 0.;
            for (unsigned k = 0; k < K; ++k)
              scatter += (power[k] - mean) * (power[k] - mean);
            scatter /= (K - 1);
            s.standard_error[b] = to_db * std::sqrt(scatter * g.overlap / K) / mean;
            // A few segments' scatter can come out low by chance: the
            // Gaussian prediction is its floor until there are enough.
            if (K < floor_segments)
              s.standard_error[b] = std::max(s.standard_error[b], s.predicted_error[b]);
          }
        else
          s.standard_error[b] = s.predicted_error[b];
        if (b == 0)
          s.lines_in_lowest_band = g.lines[c].weight.size();
      }
    } // namespace welch
  }   // namespace analysis
} // namespace greentread
