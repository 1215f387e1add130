// The three convolution methods on the same load history: direct against
// modal-recursive (to 1e-10, the requirement), both against Odeint,
// and the paper's modal form against them within its quadrature error.
#include <greentread/base/exceptions.h>
#include <greentread/convolution/direct_convolution.h>
#include <greentread/convolution/modal_paper_convolution.h>
#include <greentread/convolution/modal_recursive_convolution.h>
#include <greentread/sdof/oscillator.h>

#include <boost/test/unit_test.hpp>

#include <random>

#include "test_helpers.h"

using namespace greentread;
using convolution::Response;
using convolution::StepLoad;

namespace
{
  /// A reproducible load history: linear loads on every step, a jump of the
  /// force between steps, and impulses now and then.
  std::vector<StepLoad>
  random_loads(const unsigned int n, const unsigned int seed)
  {
    std::mt19937                           random(seed);
    std::uniform_real_distribution<double> force(-50., 100.), unit(0., 1.);
    std::vector<StepLoad>                  loads(n);
    for (auto &load : loads)
      {
        load.start = force(random);
        load.end   = force(random);
        if (unit(random) < 0.05)
          load.impulse_start = 0.01 * unit(random);
        if (unit(random) < 0.05)
          load.impulse_end = 0.01 * unit(random);
      }
    return loads;
  }

  /// Run a convolution over the loads; the response at every t_{n+1}.
  std::vector<convolution::Response>
  run(convolution::Convolution &conv, const std::vector<StepLoad> &loads)
  {
    std::vector<convolution::Response> out;
    for (const auto &load : loads)
      {
        const convolution::Response h = conv.history();
        const convolution::Response c = conv.influence().of(load);
        conv.advance(load);
        out.push_back({h.u + c.u, h.v + c.v});
      }
    return out;
  }

  std::unique_ptr<convolution::DirectConvolution>
  direct(const sdof::Oscillator &osc, double dt, unsigned int n, double threshold = 0.)
  {
    const auto g = [&osc](double t) {
      return osc.green(t);
    };
    const auto dg = [&osc](double t) {
      return osc.green_derivative(t);
    };
    return std::make_unique<convolution::DirectConvolution>(
      g, dg, dt, convolution::truncation_length(g, dt, threshold, n), n,
      osc.natural_frequency() * (1. + osc.damping_ratio()));
  }
} // namespace

BOOST_AUTO_TEST_SUITE(convolution_methods)

BOOST_AUTO_TEST_CASE(direct_equals_modal_recursive)
{
  // No truncation: the two are the same discretisation, so they agree to
  // round-off whatever the damping regime.
  for (const double xi : {0., 0.02, 1., 2.})
    for (const double dt : {1e-6, 1e-4, 1e-3})
      {
        const sdof::Oscillator                 osc(test::oscillator_parameters(xi));
        const unsigned int                     n     = 3000;
        const auto                             loads = random_loads(n, 7);
        auto                                   d     = direct(osc, dt, n);
        convolution::ModalRecursiveConvolution m(osc.modal_model(), dt);
        const auto                             a = run(*d, loads), b = run(m, loads);
        double                                 u_max = 0., v_max = 0., du = 0., dv = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            u_max = std::max(u_max, std::abs(b[i].u));
            v_max = std::max(v_max, std::abs(b[i].v));
            du    = std::max(du, std::abs(a[i].u - b[i].u));
            dv    = std::max(dv, std::abs(a[i].v - b[i].v));
          }
        BOOST_TEST_CONTEXT("xi = " << xi << ", dt = " << dt)
        {
          BOOST_TEST(du <= 1e-10 * u_max);
          BOOST_TEST(dv <= 1e-10 * v_max);
        }
      }
}

BOOST_AUTO_TEST_CASE(modal_recursive_against_odeint)
{
  // Integrate the ODE step by step with the same piecewise-linear force and
  // impulses as velocity jumps: the recursion's weights are exact.
  for (const double xi : {0.02, 1., 2.})
    {
      const sdof::Oscillator                 osc(test::oscillator_parameters(xi));
      const double                           dt    = 2e-4;
      const unsigned int                     n     = 400;
      const auto                             loads = random_loads(n, 11);
      convolution::ModalRecursiveConvolution m(osc.modal_model(), dt);
      const auto                             r = run(m, loads);
      double                                 u = 0., v = 0., err_u = 0., err_v = 0., u_max = 0.;
      for (unsigned int i = 0; i < n; ++i)
        {
          const StepLoad &q  = loads[i];
          const double    t0 = i * dt;
          v += q.impulse_start / osc.mass();
          const auto x = test::integrate(
            osc,
            [&](double t) {
              return q.start + (q.end - q.start) * (t - t0) / dt;
            },
            u, v, t0, t0 + dt);
          u     = x[0];
          v     = x[1] + q.impulse_end / osc.mass();
          err_u = std::max(err_u, std::abs(u - r[i].u));
          err_v = std::max(err_v, std::abs(v - r[i].v));
          u_max = std::max(u_max, std::abs(u));
        }
      BOOST_TEST_CONTEXT("xi = " << xi)
      {
        BOOST_TEST(err_u < 1e-9 * u_max);
        BOOST_TEST(err_v < 1e-9 * u_max * osc.natural_frequency());
      }
    }
}

BOOST_AUTO_TEST_CASE(modal_paper_within_quadrature_error)
{
  // Eq. (15) with two Gauss points per step is 4th order in omega dt: at
  // omega dt = 0.063 it must agree with the exact recursion to about 1e-6.
  const sdof::Oscillator                 osc(test::oscillator_parameters(0.02));
  const double                           dt    = 1e-4;
  const unsigned int                     n     = 2000;
  const auto                             loads = random_loads(n, 3);
  convolution::ModalRecursiveConvolution m(osc.modal_model(), dt);
  convolution::ModalPaperConvolution     p(osc.modal_model(), dt);
  const auto                             a = run(m, loads), b = run(p, loads);
  double                                 du = 0., u_max = 0.;
  for (unsigned int i = 0; i < n; ++i)
    {
      du    = std::max(du, std::abs(a[i].u - b[i].u));
      u_max = std::max(u_max, std::abs(a[i].u));
    }
  BOOST_TEST(du < 1e-6 * u_max);
  BOOST_TEST(du > 1e-14 * u_max); // it is a different quadrature, not a copy
}

BOOST_AUTO_TEST_CASE(modal_paper_reports_its_overflow)
{
  // xi = 2: the fast pole -2360 rad/s makes exp(-lambda t) pass 1/epsilon at
  // t = 0.015 s. The method must stop with a NumericalError, not return inf.
  const sdof::Oscillator             osc(test::oscillator_parameters(2.));
  convolution::ModalPaperConvolution p(osc.modal_model(), 1e-4);
  bool                               thrown = false;
  try
    {
      for (unsigned int i = 0; i < 10000; ++i)
        {
          const convolution::Response h = p.history();
          BOOST_REQUIRE(std::isfinite(h.u));
          p.advance({0., 1., 1., 0.});
        }
    }
  catch (const NumericalError &e)
    {
      thrown = std::string(e.what()).find("overflowed") != std::string::npos;
      BOOST_TEST_MESSAGE("modal-paper said: " << e.what());
    }
  BOOST_TEST(thrown);
  BOOST_TEST(p.step() < 400u); // stopped near t = 0.015 s
}

BOOST_AUTO_TEST_CASE(truncation_by_the_paper_rule)
{
  // Envelope exp(-xi w0 t) falls to 1% at t = ln(100) / (xi w0) = 0.364 s.
  const sdof::Oscillator osc(test::oscillator_parameters(0.02));
  const auto             g = [&osc](double t) {
    return osc.green(t);
  };
  const double       dt      = 1e-4;
  const unsigned int ng      = convolution::truncation_length(g, dt, 0.01, 100000);
  double             largest = 0.;
  for (unsigned int m = 0; m < 100000; ++m)
    largest = std::max(largest, std::abs(g(m * dt)));
  BOOST_TEST(std::abs(g((ng - 1) * dt)) >= 0.01 * largest);
  for (unsigned int m = ng; m < 100000; ++m)
    BOOST_REQUIRE(std::abs(g(m * dt)) < 0.01 * largest);
  BOOST_TEST(std::abs(ng * dt - std::log(100.) / (0.02 * osc.natural_frequency())) < 0.011);
  BOOST_TEST(convolution::truncation_length(g, dt, 0., 500) == 501u);
}

BOOST_AUTO_TEST_CASE(unstable_model_is_refused)
{
  modal::ModalModel model;
  model.add_pair({+1., 100.}, {0., 1.});
  BOOST_CHECK_THROW(convolution::ModalRecursiveConvolution(model, 1e-4), NumericalError);
}

BOOST_AUTO_TEST_SUITE_END()
