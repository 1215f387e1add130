#pragma once

// The spread of band levels over independent records against the standard
// errors the records predict for themselves: shared by the checks of the
// estimator on synthetic signals (test_third_octave.cc) and on rolling
// contact (test_spectrum_statistics.cc).

#include <greentread/analysis/third_octave.h>

#include <cmath>
#include <vector>

namespace test
{
  /// Per band, over the records added: the levels' mean and standard
  /// deviation, and the rms of the records' standard errors.
  struct BandSpread
  {
    std::vector<double>   sum, sum2, se2;
    std::vector<unsigned> segments; ///< of the last record
    unsigned              records = 0;

    void
    add(const greentread::analysis::BandSpectrum &s)
    {
      sum.resize(s.bands.size(), 0.);
      sum2.resize(s.bands.size(), 0.);
      se2.resize(s.bands.size(), 0.);
      segments = s.segments;
      for (std::size_t b = 0; b < s.bands.size(); ++b)
        {
          sum[b] += s.level[b];
          sum2[b] += s.level[b] * s.level[b];
          se2[b] += s.standard_error[b] * s.standard_error[b];
        }
      ++records;
    }

    double
    mean(const std::size_t b) const
    {
      return sum[b] / records;
    }

    /// The rms of the standard errors the records predict [dB].
    double
    standard_error(const std::size_t b) const
    {
      return std::sqrt(se2[b] / records);
    }

    /// The observed spread (standard deviation) over the predicted standard error.
    double
    ratio(const std::size_t b) const
    {
      const double var = (sum2[b] - sum[b] * sum[b] / records) / (records - 1);
      return std::sqrt(var) / standard_error(b);
    }
  };
} // namespace test
