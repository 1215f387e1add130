#pragma once

#include <array>
#include <complex>

/**
 * @file
 * The moments of the exponential over the unit interval that give the exact
 * integration weights of the modal recursion.
 */

namespace greentread
{
  namespace convolution
  {
    /**
     * @brief \f$\psi_m(z) = \int_0^1 s^m e^{z s}\,ds\f$ for m = 0, 1, 2, 3.
     *
     * For \f$|z| < 1\f$ the power series
     * \f$\psi_m(z) = \sum_{n \ge 0} z^n / (n!\,(n+m+1))\f$ is summed, which is
     * free of the cancellation that ruins \f$(e^z - 1 - z)/z^2\f$ for tiny
     * time steps. Otherwise \f$\psi_0 = (e^z - 1)/z\f$ and the upward
     * recurrence \f$\psi_m = (e^z - m\,\psi_{m-1})/z\f$, which is stable there
     * (errors grow by at most m/|z| <= 3) and cannot overflow for
     * \f$\mathrm{Re}\,z \le 0\f$ (a stable pole times a positive step).
     */
    std::array<std::complex<double>, 4>
    exponential_moments(std::complex<double> z);
  } // namespace convolution
} // namespace greentread
