#pragma once

#include <algorithm>
#include <cstddef>

/**
 * @file
 * FFT-friendly lengths, shared by the spectra (zero padding) and the
 * synthetic road textures (their grid size).
 */

namespace greentread
{
  namespace convolution
  {
    /// The smallest length >= n whose only prime factors are 2, 3 and 5:
    /// Eigen's FFT (kissfft) is fast on such lengths and slow on a length
    /// with a large prime factor (3646 = 2 x 1823).
    inline std::size_t
    fast_fft_length(const std::size_t n)
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
  } // namespace convolution
} // namespace greentread
