#include <greentread/analysis/third_octave.h>

#include "welch_segments.h"

namespace greentread
{
  namespace analysis
  {
    std::vector<BandSpectrum>
    welch_band_spectra(const std::vector<std::vector<double>> &signals,
                       const double                            dt,
                       const std::vector<double>              &references,
                       const double                            f_low,
                       const double                            f_high,
                       const unsigned int                      lines_per_segment,
                       const LinePowers                       &powers)
    {
      if (lines_per_segment == 0)
        throw InputError("one-third-octave spectrum: lines per segment = 0; allowed: >= 1");
      if (signals.empty() || references.empty())
        throw InputError("one-third-octave spectra of " + std::to_string(references.size()) +
                         " outputs from " + std::to_string(signals.size()) +
                         " signals; allowed: at least one of each");
      const std::size_t N = signals[0].size(), S = signals.size(), O = references.size();
      for (std::size_t i = 0; i < S; ++i)
        {
          if (signals[i].size() != N)
            throw InputError("one-third-octave spectra: signal " + std::to_string(i) + " has " +
                             std::to_string(signals[i].size()) + " samples, signal 0 has " +
                             std::to_string(N) + "; allowed: one length");
          welch::checked_spectrum(signals[i], dt, references[0], f_low, f_high,
                                  "signal " + std::to_string(i));
        }
      std::vector<BandSpectrum> out;
      for (const double reference : references)
        {
          out.push_back(welch::checked_bands(N, dt, reference, f_low, f_high));
          welch::resize_for_welch(out.back(), N, dt);
        }
      const auto &bands = out[0].bands;

      for (const auto &by_length : welch::bands_by_segment_length(N, dt, bands, lines_per_segment))
        {
          const auto               &which = by_length.second;
          const welch::SegmentGroup g(N, dt, bands, which, lines_per_segment);
          const unsigned            K = g.layout.K;
          const std::size_t         n = g.window.size();
          // The lines the group's bands hold, first to last.
          std::size_t first = g.M, last = 0;
          for (const auto &lines : g.lines)
            if (!lines.weight.empty())
              {
                first = std::min(first, lines.first);
                last  = std::max(last, lines.first + lines.weight.size() - 1);
              }
          if (first > last) // no line in any of the group's bands: report it
            welch::band_statistics(out[0], which[0], g, 0, std::vector<double>(K));
          std::vector<Eigen::MatrixXcd> coefficients(last - first + 1, Eigen::MatrixXcd(S, K));
          double                        window_energy = 0.;
          for (const double w : g.window)
            window_energy += w * w;
          Eigen::FFT<double>                fft;
          std::vector<double>               y(g.M);
          std::vector<std::complex<double>> Y;
          for (unsigned k = 0; k < K; ++k)
            for (std::size_t i = 0; i < S; ++i)
              {
                const std::size_t start = g.layout.start + k * g.layout.hop;
                double            mean  = 0.;
                for (std::size_t m = 0; m < n; ++m)
                  mean += signals[i][start + m];
                mean /= double(n);
                std::fill(y.begin(), y.end(), 0.);
                for (std::size_t m = 0; m < n; ++m)
                  y[m] = g.window[m] * (signals[i][start + m] - mean);
                fft.fwd(Y, y);
                for (std::size_t l = first; l <= last; ++l)
                  coefficients[l - first](i, k) = Y[l];
              }
          // Each band's power per segment and output, its lines weighted by
          // their shares and one-sided (welch::segment_mean_squares()).
          const double    scale = 1. / (double(g.M) * window_energy);
          Eigen::MatrixXd at_line(O, K);
          for (std::size_t c = 0; c < which.size(); ++c)
            {
              Eigen::MatrixXd band = Eigen::MatrixXd::Zero(O, K);
              for (std::size_t j = 0; j < g.lines[c].weight.size(); ++j)
                {
                  const std::size_t l = g.lines[c].first + j;
                  at_line.setZero();
                  powers(double(l) / (double(g.M) * dt), which[c], coefficients[l - first],
                         at_line);
                  band += g.lines[c].weight[j] * (2 * l == g.M ? 1. : 2.) * scale * at_line;
                }
              for (std::size_t o = 0; o < O; ++o)
                {
                  std::vector<double> power(K);
                  for (unsigned k = 0; k < K; ++k)
                    power[k] = band(o, k);
                  welch::band_statistics(out[o], which[c], g, c, power);
                }
            }
        }
      return out;
    }
  } // namespace analysis
} // namespace greentread
