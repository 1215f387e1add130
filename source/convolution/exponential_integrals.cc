#include <greentread/convolution/exponential_integrals.h>

#include <cmath>
#include <limits>

namespace greentread
{
  namespace convolution
  {
    std::array<std::complex<double>, 4>
    exponential_moments(const std::complex<double> z)
    {
      std::array<std::complex<double>, 4> psi;
      if (std::abs(z) < 1.0)
        {
          for (unsigned int m = 0; m < 4; ++m)
            {
              std::complex<double> sum  = 0.;
              std::complex<double> term = 1.; // z^n / n!
              for (unsigned int n = 0; n < 40; ++n)
                {
                  const std::complex<double> contribution = term / double(n + m + 1);
                  sum += contribution;
                  if (std::abs(contribution) <=
                      0.25 * std::numeric_limits<double>::epsilon() * std::abs(sum))
                    break;
                  term *= z / double(n + 1);
                }
              psi[m] = sum;
            }
          return psi;
        }
      const std::complex<double> ez = std::exp(z);
      psi[0]                        = (ez - 1.) / z;
      for (unsigned int m = 1; m < 4; ++m)
        psi[m] = (ez - double(m) * psi[m - 1]) / z;
      return psi;
    }
  } // namespace convolution
} // namespace greentread
