// The 1-DoF contact problem of Section 3 against its exact solution, and the
// stiff and extreme cases of the issue: every dt from 1 us to 1 ms, zero and
// over-critical damping, a flat road, a flying road, stiff penalty, and the
// overflow of the paper's modal form.
#include <greentread/base/exceptions.h>
#include <greentread/sdof/sdof_solver.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "test_helpers.h"

using namespace greentread;

namespace
{
  sdof::SdofOutcome
  simulate(const sdof::OscillatorParameters &op,
           const contact::ContactParameters &cp,
           convolution::Method               method    = convolution::Method::modal_recursive,
           double                            amplitude = 5e-3,
           double                            threshold = 0.01)
  {
    const road::Sinusoid               road(amplitude, 1e-2);
    convolution::ConvolutionParameters conv;
    conv.method               = method;
    conv.truncation_threshold = threshold;
    return sdof::simulate(op, road, cp, conv);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(sdof_contact)

BOOST_AUTO_TEST_CASE(kinematic_default_within_a_thousandth_of_A0)
{
  // The acceptance: dt = 0.01 ms over 0.2 s within 0.1% of A0.
  const auto o = simulate(test::oscillator_parameters(), test::contact_parameters(1e-5));
  BOOST_TEST_MESSAGE("max |u - u_exact| = " << o.errors.max_u_error << " m");
  // Measured 7.9e-10 m, far inside the acceptance (5e-6 m): bound 3 times that.
  BOOST_TEST(o.errors.max_u_error < 2.5e-9);
  BOOST_TEST(o.errors.impulse_error < 1e-6);
  BOOST_TEST(std::abs(o.errors.contact_fraction - o.errors.exact_contact_fraction) < 1e-3);
}

BOOST_AUTO_TEST_CASE(kinematic_converges_for_every_step_from_1us_to_1ms)
{
  // Steps incommensurate with the road period, so that events fall anywhere
  // inside a step. Bounded at every dt; second order overall (the README
  // reports 2.00; a rule that fell to first order would fail here). Where an
  // event falls inside its step makes the error of one dt jump by a factor of
  // 100 (an impact on the fallback branch), so the error at dt is the worst
  // of dt, 1.1 dt and 1.21 dt, as in benchmarks/sdof_convergence/sdof_convergence.cc.
  std::vector<double> dts = {1e-3, 3.7e-4, 1.37e-4, 3.7e-5, 1.37e-5, 3.7e-6, 1e-6};
  std::vector<double> errors, penetrations;
  for (const double dt : dts)
    {
      double error = 0., penetration = 0.;
      for (const double jitter : {1., 1.1, 1.21})
        {
          const auto o =
            simulate(test::oscillator_parameters(), test::contact_parameters(jitter * dt));
          BOOST_TEST_MESSAGE("dt = " << jitter * dt << ": max |u - u_exact| = "
                                     << o.errors.max_u_error << " m, penetration inside steps "
                                     << o.errors.max_penetration_step << " m, fallback steps "
                                     << o.run.branch_count[4]);
          BOOST_TEST(o.max_abs_u < 5e-3 + 1e-4);
          BOOST_TEST(o.errors.max_u_error < 1e-2 * 5e-3);
          error       = std::max(error, o.errors.max_u_error);
          penetration = std::max(penetration, o.errors.max_penetration_step);
        }
      errors.push_back(error);
      penetrations.push_back(penetration);
    }
  // Least-squares slope of log(error) against log(dt).
  double       sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = dts.size();
  for (unsigned int i = 0; i < dts.size(); ++i)
    {
      const double x = std::log(dts[i]), y = std::log(errors[i]);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
  const double order = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  BOOST_TEST_MESSAGE("observed order of convergence: " << order);
  BOOST_TEST(order >= 1.8); // the README reports 2.00
  BOOST_TEST(errors.back() < 1e-3 * errors.front());
  // The penetration inside steps vanishes with dt.
  BOOST_TEST(penetrations.back() < 1e-3 * penetrations.front());
  BOOST_TEST(penetrations.back() < 1e-10);
}

BOOST_AUTO_TEST_CASE(zero_critical_and_over_critical_damping)
{
  for (const double xi : {0., 1., 2.})
    {
      const auto o = simulate(test::oscillator_parameters(xi), test::contact_parameters(1e-5));
      BOOST_TEST_CONTEXT("xi = " << xi)
      {
        for (const double u : o.run.u)
          BOOST_REQUIRE(std::isfinite(u));
        BOOST_TEST(o.errors.max_u_error < 1e-5 * 5e-3);
      }
    }
}

BOOST_AUTO_TEST_CASE(flat_road_mass_rests_with_its_weight)
{
  const auto o = simulate(test::oscillator_parameters(), test::contact_parameters(1e-4),
                          convolution::Method::modal_recursive, 0.);
  for (unsigned int n = 1; n < o.run.F.size(); ++n)
    {
      BOOST_REQUIRE(std::abs(o.run.F[n] - 9.81) < 1e-9);
      BOOST_REQUIRE(std::abs(o.run.u[n]) < 1e-15);
    }
}

BOOST_AUTO_TEST_CASE(road_fast_enough_that_the_mass_flies)
{
  // V0 = 1 m/s: peak road acceleration 200 g; the mass is thrown off every
  // crest and lands further on.
  const auto o =
    simulate(test::oscillator_parameters(0.02, 1.), test::contact_parameters(1e-6, 0.05));
  BOOST_TEST(o.errors.exact_contact_fraction < 0.5);
  BOOST_TEST(std::abs(o.errors.contact_fraction - o.errors.exact_contact_fraction) < 1e-3);
  BOOST_TEST(o.errors.max_u_error < 1e-6 * 5e-3);
}

BOOST_AUTO_TEST_CASE(direct_and_modal_recursive_contact_runs_agree)
{
  // The whole nonlinear run, not only one load history: without truncation
  // the two methods choose the same contact loads and agree to round-off.
  const auto cp = test::contact_parameters(1e-4);
  const auto a = simulate(test::oscillator_parameters(), cp, convolution::Method::direct, 5e-3, 0.);
  const auto b = simulate(test::oscillator_parameters(), cp, convolution::Method::modal_recursive);
  double     du = 0.;
  for (unsigned int n = 0; n < a.run.u.size(); ++n)
    du = std::max(du, std::abs(a.run.u[n] - b.run.u[n]));
  BOOST_TEST(du < 1e-10 * 5e-3);
  // With the paper's 1% truncation the direct method is no longer exact.
  const auto c = simulate(test::oscillator_parameters(), test::contact_parameters(1e-4, 1.),
                          convolution::Method::direct, 5e-3, 0.01);
  BOOST_TEST(c.run.size < c.run.u.size());
}

BOOST_AUTO_TEST_CASE(stiff_penalty)
{
  // kc = 1e8 N/m: contact mode at 1595 Hz, omega_c dt = 1 at dt = 0.1 ms.
  using contact::ContactLaw;
  const auto coarse = simulate(test::oscillator_parameters(),
                               test::contact_parameters(1e-4, 0.2, ContactLaw::penalty, 1e8));
  const auto fine   = simulate(test::oscillator_parameters(),
                               test::contact_parameters(1e-6, 0.2, ContactLaw::penalty, 1e8));
  BOOST_TEST_MESSAGE("penalty 1e8: dt = 0.1 ms error " << coarse.errors.max_u_error
                                                       << " m, dt = 1 us error "
                                                       << fine.errors.max_u_error << " m");
  // Stable at dt = 0.1 ms: bounded like the fine run.
  BOOST_TEST(coarse.max_abs_u < 2. * fine.max_abs_u);
  // But not the exact solution, at any step: a penalty spring bounces
  // elastically where the exact (kinematic) impact is plastic.
  BOOST_TEST(coarse.errors.max_u_error > 0.05 * 5e-3);
  BOOST_TEST(fine.errors.max_u_error > 0.05 * 5e-3);
  BOOST_TEST(coarse.errors.max_u_error < 0.2 * 5e-3);
  // At dt = 0.2 ms (omega_c dt = 2) the explicit penalty diverges, and says so.
  BOOST_CHECK_THROW(simulate(test::oscillator_parameters(),
                             test::contact_parameters(2e-4, 0.2, ContactLaw::penalty, 1e8)),
                    NumericalError);
}

BOOST_AUTO_TEST_CASE(modal_paper_long_or_heavily_damped_run_reports_overflow)
{
  // xi = 0.5 over 1 s: exp(xi w0 t) = exp(316), far past 1/epsilon.
  bool said_overflow = false;
  try
    {
      simulate(test::oscillator_parameters(0.5), test::contact_parameters(1e-4, 1.),
               convolution::Method::modal_paper);
    }
  catch (const NumericalError &e)
    {
      said_overflow = std::string(e.what()).find("overflowed") != std::string::npos;
    }
  BOOST_TEST(said_overflow);
  // The same run with the recursive form is exact.
  const auto o = simulate(test::oscillator_parameters(0.5), test::contact_parameters(1e-4, 1.));
  BOOST_TEST(o.errors.max_u_error < 1e-5 * 5e-3);
}

BOOST_AUTO_TEST_SUITE_END()
