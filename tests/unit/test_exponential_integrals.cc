// psi_m(z) = int_0^1 s^m e^{zs} ds against references in 50 decimal digits
// (Boost.Multiprecision): Gauss-Legendre quadrature of the integral for
// |z| < 2, the closed form with its upward recurrence beyond (there it
// amplifies errors by at most 3/2 per step).
#include <greentread/convolution/exponential_integrals.h>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/test/unit_test.hpp>

#include <complex>

namespace
{
  using Real = boost::multiprecision::cpp_bin_float_50;

  std::array<std::complex<double>, 4>
  reference(const std::complex<double> z)
  {
    const Real x = z.real(), y = z.imag();
    if (std::abs(z) < 2.)
      {
        std::array<std::complex<double>, 4> psi;
        for (int m = 0; m < 4; ++m)
          {
            using Gauss   = boost::math::quadrature::gauss<Real, 40>;
            const Real re = Gauss::integrate(
              [&](const Real &s) {
                return pow(s, m) * exp(x * s) * cos(y * s);
              },
              Real(0), Real(1));
            const Real im = Gauss::integrate(
              [&](const Real &s) {
                return pow(s, m) * exp(x * s) * sin(y * s);
              },
              Real(0), Real(1));
            psi[m] = {static_cast<double>(re), static_cast<double>(im)};
          }
        return psi;
      }
    // e^z and 1/z in 50 digits, complex arithmetic by hand.
    const Real                          er = exp(x) * cos(y), ei = exp(x) * sin(y);
    const Real                          d  = x * x + y * y;
    const Real                          ir = x / d, ii = -y / d;
    std::array<std::complex<double>, 4> psi;
    Real                                pr = (er - 1) * ir - ei * ii, pi = (er - 1) * ii + ei * ir;
    psi[0] = {static_cast<double>(pr), static_cast<double>(pi)};
    for (int m = 1; m < 4; ++m)
      {
        const Real ar = er - m * pr, ai = ei - m * pi;
        const Real nr = ar * ir - ai * ii, ni = ar * ii + ai * ir;
        pr     = nr;
        pi     = ni;
        psi[m] = {static_cast<double>(pr), static_cast<double>(pi)};
      }
    return psi;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(exponential_integrals)

BOOST_AUTO_TEST_CASE(against_fifty_digit_closed_form)
{
  // Tiny steps (where (e^z-1-z)/z^2 cancels), the series/recurrence switch at
  // |z| = 1, oscillatory and strongly damped poles, and a huge stiff step.
  const std::complex<double> points[] = {
    {1e-12, 0.}, {-1e-9, 3e-9}, {-6.3e-6, 6.3e-4}, {-0.0126, 0.632}, {-0.3, 0.},
    {0., 0.99},  {0., 1.01},    {-0.999, 0.01},    {-1.001, 0.},     {-2.5, 4.},
    {0., 20.},   {-50., 0.},    {-1e3, 2e3},       {-1e5, 0.},       {-7.07e-3, -0.7}};
  for (const auto z : points)
    {
      const auto psi = greentread::convolution::exponential_moments(z);
      const auto ref = reference(z);
      for (unsigned int m = 0; m < 4; ++m)
        {
          const double error = std::abs(psi[m] - ref[m]) / std::abs(ref[m]);
          BOOST_TEST_CONTEXT("z = " << z << ", m = " << m << ": " << psi[m] << " vs " << ref[m])
          BOOST_TEST(error < 1e-14);
        }
    }
}

BOOST_AUTO_TEST_CASE(limits_at_zero)
{
  // psi_m(0) = 1 / (m + 1) exactly.
  const auto psi = greentread::convolution::exponential_moments({0., 0.});
  for (unsigned int m = 0; m < 4; ++m)
    BOOST_TEST(std::abs(psi[m] - 1. / (m + 1.)) < 1e-16);
}

BOOST_AUTO_TEST_SUITE_END()
