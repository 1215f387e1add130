// The oscillator's Green's function in its three forms (closed form, modal
// model, frequency response) against independent references: the dynamic
// stiffness inverse of Eq. (3), and Boost.Odeint integration of the ODE.
#include <greentread/modal/modal_model.h>
#include <greentread/sdof/oscillator.h>

#include <boost/test/unit_test.hpp>

#include "test_helpers.h"

using greentread::sdof::Oscillator;

namespace
{
  /// Relative accuracy of the modal model: round-off, except near xi = 1
  /// where the two real poles are merged into a double pole on purpose, an
  /// approximation of relative size |xi - 1| (Oscillator::modal_model()).
  double
  model_tolerance(const double xi, const double round_off)
  {
    const double merge = std::abs(xi - 1.);
    return merge > 0. && merge <= 1e-8 ? round_off + 10. * merge : round_off;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(modal_model)

BOOST_AUTO_TEST_CASE(frequency_response_is_inverse_dynamic_stiffness)
{
  for (const double xi : {0., 0.02, 0.5, 1., 1. + 1e-9, 2., 30.})
    {
      const Oscillator osc(test::oscillator_parameters(xi));
      const auto       model = osc.modal_model();
      BOOST_TEST(model.n_modes() == (xi > 1. + 1e-8 ? 2u : 1u));
      for (const double f : {0., 1., 50., 100.66, 101., 400., 4000.})
        {
          const double               w = 2. * M_PI * f;
          const std::complex<double> ref =
            1. / std::complex<double>(4e5 - w * w, w * osc.damping());
          if (xi == 0. && std::abs(f - 100.66) < 0.1)
            continue; // at resonance the undamped response is infinite
          BOOST_TEST_CONTEXT("xi = " << xi << ", f = " << f)
          BOOST_TEST(std::abs(model.frequency_response(w) - ref) / std::abs(ref) <
                     model_tolerance(xi, 1e-12));
        }
    }
}

BOOST_AUTO_TEST_CASE(impulse_response_against_odeint)
{
  // g solves M g'' + C g' + K g = 0 with g(0) = 0, g'(0) = 1/M.
  for (const double xi : {0., 0.02, 0.7, 1., 1. - 1e-9, 2., 30.})
    {
      const Oscillator osc(test::oscillator_parameters(xi));
      const auto       model = osc.modal_model();
      for (const double t : {1e-6, 1e-3, 7.7e-3, 0.05})
        {
          const auto ref = test::integrate(
            osc,
            [](double) {
              return 0.;
            },
            0., 1., 0., t);
          const double scale = 1. / osc.natural_frequency(); // |g| <= 1 / (M omega_0)
          const double tol   = model_tolerance(xi, 1e-10);
          BOOST_TEST_CONTEXT("xi = " << xi << ", t = " << t)
          {
            BOOST_TEST(std::abs(osc.green(t) - ref[0]) < 1e-10 * scale);
            BOOST_TEST(std::abs(model.impulse_response(t) - ref[0]) < tol * scale);
            BOOST_TEST(std::abs(osc.green_derivative(t) - ref[1]) < 1e-10);
            BOOST_TEST(std::abs(model.impulse_response_derivative(t) - ref[1]) < tol);
          }
        }
      BOOST_TEST(model.impulse_response(0.) == 0., boost::test_tools::tolerance(1e-15));
      BOOST_TEST(std::abs(model.impulse_response_derivative(0.) - 1.) < 1e-9);
    }
}

BOOST_AUTO_TEST_CASE(free_motion_against_odeint)
{
  // Eq. (35) with gravity, from an arbitrary state, for every damping regime.
  for (const double xi : {0., 0.02, 1., 2., 30.})
    {
      const Oscillator osc(test::oscillator_parameters(xi));
      for (const double t : {1e-5, 3e-3, 0.04, 2.})
        {
          double u, v;
          osc.free_motion(1e-3, -0.3, t, u, v);
          const auto ref = test::integrate(
            osc,
            [&](double) {
              return -osc.mass() * osc.gravity();
            },
            1e-3, -0.3, 0., t);
          BOOST_TEST_CONTEXT("xi = " << xi << ", t = " << t)
          {
            BOOST_TEST(std::isfinite(u));
            BOOST_TEST(std::abs(u - ref[0]) < 1e-12);
            BOOST_TEST(std::abs(v - ref[1]) < 1e-9);
          }
        }
    }
}

BOOST_AUTO_TEST_CASE(no_overflow_for_long_overdamped_times)
{
  // e^{-sigma t} cosh(beta t) must not become inf * 0 = NaN.
  const Oscillator osc(test::oscillator_parameters(2.));
  for (const double t : {1., 10., 1e3, 1e6})
    {
      BOOST_TEST(std::isfinite(osc.green(t)));
      BOOST_TEST(std::isfinite(osc.damped_cos(t)));
      BOOST_TEST(osc.green(t) >= 0.);
    }
}

BOOST_AUTO_TEST_SUITE_END()
