// The tread's small-scale losses (analysis/tread_losses.h) against
// independent references: the power a hysteretic layer dissipates under
// harmonic forces, in closed form; what a cycle of ramps and holds
// dissipates in the chain, in closed form; and, on a rolling run of the
// synthetic patch's contact grid, the same power from the spectra of the
// forces and the local displacements (a second method, by FFT over the
// whole record). The chain's loss factor against the constant it stands
// for, and the cases at the edges: a constant force, tiny and huge steps.
#include "grid_rolling.h"

#include <greentread/analysis/rolling_resistance.h>
#include <greentread/analysis/tread_losses.h>
#include <greentread/base/exceptions.h>

#include <boost/test/unit_test.hpp>

#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <memory>
#include <vector>

using namespace greentread;

namespace
{
  /// A symmetric positive definite local compliance of three points [m/N].
  Eigen::MatrixXd
  three_point_compliance()
  {
    Eigen::MatrixXd L(3, 3);
    L << 4e-6, 1e-6, 0.5e-6, 1e-6, 3e-6, 1e-6, 0.5e-6, 1e-6, 5e-6;
    return L;
  }

  /// Two tones on three points: each point's static force plus
  /// Re(a_p e^{j w1 t}) + Re(b_p e^{j w2 t}) [N].
  struct TwoTones
  {
    double               w1 = 0., w2 = 0.;
    Eigen::VectorXd      f0 = Eigen::Vector3d(100., 120., 80.);
    Eigen::VectorXcd     a  = Eigen::Vector3cd({3., 1.}, {-2., 0.5}, {1., -1.});
    Eigen::VectorXcd     b  = Eigen::Vector3cd({0., 2.}, {1.5, 0.}, {-1., -2.});
    Eigen::VectorXd
    at(const double t) const
    {
      const std::complex<double> e1 = std::exp(std::complex<double>(0., w1 * t)),
                                 e2 = std::exp(std::complex<double>(0., w2 * t));
      return f0 + (a * e1).real() + (b * e2).real();
    }
  };

  /// The meter's mean power over @p periods of the slower tone after
  /// @p settle of them, at @p per_period steps per period of the faster one
  /// (the force's step mean: the trapezoid of its ends).
  double
  metered_power(const TwoTones &tones,
                const double    eta,
                const double    per_period,
                const double    settle,
                const double    periods)
  {
    const Eigen::MatrixXd L     = three_point_compliance();
    const double          dt    = 2. * M_PI / (std::max(tones.w1, tones.w2) * per_period);
    const double          slow  = 2. * M_PI / std::min(tones.w1, tones.w2);
    const auto            first = static_cast<unsigned int>(std::lround(settle * slow / dt));
    const auto            steps = static_cast<unsigned int>(std::lround(periods * slow / dt));
    analysis::TreadLossMeter meter(eta, dt, tones.at(0.), L * tones.at(0.));
    double                   work = 0.;
    for (unsigned int n = 0; n < first + steps; ++n)
      {
        const Eigen::VectorXd f0 = tones.at(n * dt), f1 = tones.at((n + 1) * dt);
        const double          w  = meter.add(f1, L * f1);
        if (n >= first)
          work += w;
      }
    return work / (steps * dt);
  }

  /// A hysteretic layer's power under the tones: sum over them of
  /// omega eta Re(A^H L A) / 2.
  double
  hysteretic_power(const TwoTones &tones, const double eta)
  {
    const Eigen::MatrixXcd L = three_point_compliance().cast<std::complex<double>>();
    return 0.5 * eta *
           (tones.w1 * (tones.a.adjoint() * L * tones.a)(0).real() +
            tones.w2 * (tones.b.adjoint() * L * tones.b)(0).real());
  }
} // namespace

BOOST_AUTO_TEST_SUITE(tread_losses)

BOOST_AUTO_TEST_CASE(the_chains_loss_factor_is_the_constant)
{
  // The sum of Debye peaks against eta over the band the chain is made for.
  const analysis::TreadLossMeter meter(0.1, 1e-5, Eigen::VectorXd::Zero(1),
                                       Eigen::VectorXd::Zero(1));
  double                         worst = 0.;
  for (double f = 10.; f <= 20e3 * (1. + 1e-9); f *= std::pow(10., 0.05))
    worst = std::max(worst, std::abs(meter.loss_factor(f) / 0.1 - 1.));
  BOOST_TEST_MESSAGE("the chain's loss factor from 10 Hz to 20 kHz: within " << worst
                                                                             << " of eta");
  // Measured 7.8e-3 (at 20 kHz, the chain's edge); the file documentation
  // says within 1%.
  BOOST_TEST(worst < 0.01);
  BOOST_TEST(worst > 0.0026);
  BOOST_TEST(std::abs(meter.loss_factor(316.22776601683796) / 0.1 - 1.) < 1e-12);
}

BOOST_AUTO_TEST_CASE(harmonic_forces_dissipate_what_a_hysteretic_layer_does)
{
  // Two tones, 40 steps a period of the faster: the meter against the closed
  // form of a layer with a constant loss factor.
  for (const auto &[f1, f2] : {std::pair{100., 1000.}, std::pair{700., 5000.}})
    {
      TwoTones tones;
      tones.w1              = 2. * M_PI * f1;
      tones.w2              = 2. * M_PI * f2;
      const double metered  = metered_power(tones, 0.1, 40., 20., 50.);
      const double expected = hysteretic_power(tones, 0.1);
      BOOST_TEST_MESSAGE("tones at " << f1 << " and " << f2 << " Hz: " << metered << " W against "
                                     << expected << " W (relative "
                                     << metered / expected - 1. << ")");
      // The chain's ripple (below 0.3% in this band) and the force's linear
      // interpolation over a step, O((omega dt)^2) / 12 = 2e-3: measured
      // -3.7e-3 and -6.0e-3.
      BOOST_TEST(std::abs(metered / expected - 1.) < 0.012);
    }
  // Halving the step moves the power by the step's share, to second order.
  TwoTones tones;
  tones.w1               = 2. * M_PI * 700.;
  tones.w2               = 2. * M_PI * 5000.;
  const double coarse    = metered_power(tones, 0.1, 20., 20., 50.);
  const double fine      = metered_power(tones, 0.1, 40., 20., 50.);
  const double finer     = metered_power(tones, 0.1, 80., 20., 50.);
  const double order     = std::log2((coarse - fine) / (fine - finer));
  BOOST_TEST_MESSAGE("the power at 20, 40, 80 steps a period: " << coarse << ", " << fine << ", "
                                                               << finer << " (order " << order
                                                               << ")");
  BOOST_TEST(order > 1.8); // measured 1.97
  BOOST_TEST(order < 2.2);
  // No loss factor, no loss.
  BOOST_TEST(metered_power(tones, 0., 40., 1., 2.) == 0.);
}

BOOST_AUTO_TEST_CASE(constant_forces_steps_and_extreme_time_steps)
{
  const Eigen::MatrixXd L  = three_point_compliance();
  const Eigen::VectorXd f0 = Eigen::Vector3d(100., 120., 80.), f1 = Eigen::Vector3d(50., 150., 80.);
  const double          eta = 0.1;
  // The chain's weights c_j = c, from its loss factor at one frequency.
  const std::vector<double> relaxation = analysis::TreadLossMeter::relaxation_frequencies();
  const auto                debye      = [&](const double f) {
    double sum = 0.;
    for (const double fj : relaxation)
      sum += (f / fj) / (1. + (f / fj) * (f / fj));
    return sum;
  };
  const double c =
    analysis::TreadLossMeter(eta, 1e-5, f0, L * f0).loss_factor(1e3) / debye(1e3);
  const double energy = (f1 - f0).dot(L * (f1 - f0));
  for (const double dt : {1e-9, 1e-5, 1.})
    {
      // A constant force from the start: nothing, exactly.
      analysis::TreadLossMeter still(eta, dt, f0, L * f0);
      double                   work = 0.;
      for (int n = 0; n < 100; ++n)
        work += still.add(f0, L * f0);
      BOOST_TEST(std::abs(work) < 1e-14 * f0.dot(L * f0));
      if (dt < 1e-6)
        continue; // 20 s of holds would take 2e10 steps
      // A ramp over one step to f1, held 20 s (12 times the slowest
      // element's time), and back: the elastic energy returns, so the work
      // is what the elements dissipate. For a ramp of length T on an element
      // of time tau, the closed form is c (f1 - f0)^T L (f1 - f0) times
      // 2 (tau / T)(1 - (tau / T)(1 - e^{-T / tau})) / 2 (a sudden step
      // dissipates half the work the force does), twice (there and back).
      analysis::TreadLossMeter cycle(eta, dt, f0, L * f0);
      double                   lost  = 0.;
      const auto               holds = static_cast<long>(std::ceil(20. / dt));
      for (const auto &[from, to] : {std::pair{f0, f1}, std::pair{f1, f0}})
        {
          lost += cycle.add(to, L * to);
          for (long k = 0; k < holds; ++k)
            lost += cycle.add(to, L * to);
        }
      double expected = 0.;
      for (const double fj : relaxation)
        {
          const double r = 1. / (2. * M_PI * fj * dt); // tau / T
          expected += c * energy * 2. * r * (1. + r * std::expm1(-1. / r));
        }
      BOOST_TEST_MESSAGE("dt = " << dt << " s: a cycle of the force dissipates " << lost
                                 << " J, the closed form " << expected << " J (relative "
                                 << lost / expected - 1. << ")");
      BOOST_TEST(std::isfinite(lost));
      BOOST_TEST(lost > 0.);
      // The work over a step is integrated exactly: what is left is
      // round-off over 4 million and 40 steps (measured 3.0e-7 and 1.1e-6).
      BOOST_TEST(std::abs(lost / expected - 1.) < 1e-5);
    }
  BOOST_CHECK_THROW(analysis::TreadLossMeter(-0.1, 1e-5, f0, L * f0), InputError);
  BOOST_CHECK_THROW(analysis::TreadLossMeter(NAN, 1e-5, f0, L * f0), InputError);
}

BOOST_AUTO_TEST_CASE(a_rolling_run_against_the_spectra_of_its_forces)
{
  // The synthetic patch on 4 subdivisions over road-A for 0.1 s (2.5 m), at
  // four steps a road sample (resolved: the spectra's estimate reads the
  // samples as band-limited, the meter as linear over each step, and at one
  // step a road sample the two differ by 9%, the meter converging at order
  // 1.4 to within 2% of the spectra's):
  // the meter's tread losses after the first 20% against the same power
  // from the spectra of each point's end force and local displacement,
  // P = eta sum_k |omega_k| Re(F_k^* W_k) / (N sum h^2), Hann window h over
  // the same steps, each history's windowed mean removed.
  const double                                 eta = 0.1;
  std::unique_ptr<analysis::RollingPowerMeter> meter;
  Eigen::VectorXd                              start_force;
  std::vector<Eigen::VectorXd>                 forces, displacements;
  const contact::ContactGrid                  *grid_seen = nullptr;
  const test::GridRun                          run       = test::roll_grid(
    4, 0.25, 0.1,
    [&](const contact::ContactGrid &grid, const contact::RollingStep &step) {
      if (grid_seen == nullptr)
        meter->track_tread_losses(
          eta,
          [&grid](const Eigen::VectorXd &f, Eigen::VectorXd &w) {
            w.setZero(f.size());
            grid.add_local(f, w);
          },
          start_force);
      grid_seen = &grid;
      meter->add(step);
      Eigen::VectorXd w = Eigen::VectorXd::Zero(step.end_force.size());
      grid.add_local(step.end_force, w);
      forces.push_back(step.end_force);
      displacements.push_back(w);
    },
    [&](const contact::StaticContact &start, const double dt) {
      meter       = std::make_unique<analysis::RollingPowerMeter>(start.u, dt);
      start_force = start.q;
    });
  BOOST_TEST(run.failed_steps == 0u);
  BOOST_REQUIRE(grid_seen != nullptr);
  const analysis::RollingResistance tread =
    meter->result(run.speed, 0.2, 10, analysis::PowerPart::tread);

  const std::size_t   steps = forces.size();
  const std::size_t   first = static_cast<std::size_t>(std::ceil(0.2 * steps));
  const std::size_t   N     = steps - first;
  std::vector<double> h(N);
  double              h2 = 0., hsum = 0.;
  for (std::size_t n = 0; n < N; ++n)
    {
      h[n] = 0.5 - 0.5 * std::cos(2. * M_PI * (n + 0.5) / N);
      h2 += h[n] * h[n];
      hsum += h[n];
    }
  Eigen::FFT<double>                fft;
  std::vector<double>               x(N), y(N);
  std::vector<std::complex<double>> X, Y;
  double                            sum = 0.;
  for (Eigen::Index p = 0; p < forces.front().size(); ++p)
    {
      double mx = 0., my = 0.;
      for (std::size_t n = 0; n < N; ++n)
        {
          mx += h[n] * forces[first + n][p] / hsum;
          my += h[n] * displacements[first + n][p] / hsum;
        }
      for (std::size_t n = 0; n < N; ++n)
        {
          x[n] = h[n] * (forces[first + n][p] - mx);
          y[n] = h[n] * (displacements[first + n][p] - my);
        }
      fft.fwd(X, x);
      fft.fwd(Y, y);
      for (std::size_t k = 1; k < N; ++k)
        {
          const double omega = 2. * M_PI * double(std::min(k, N - k)) / (N * run.time_step);
          sum += omega * (std::conj(X[k]) * Y[k]).real();
        }
    }
  const double spectral = eta * sum / (double(N) * h2);
  BOOST_TEST_MESSAGE("the tread's losses over " << N << " steps: metered " << tread.power << " +- "
                                                << tread.power_error << " W, from the spectra "
                                                << spectral << " W (relative "
                                                << tread.power / spectral - 1. << ")");
  BOOST_TEST(tread.power > 0.);
  // Measured -3.2%: the chain's loss factor against the constant (within
  // 1%), the window and the step (the meter at 1, 1/2 and 1/4 of a road
  // sample: 105.7, 111.0 and 113.0 W, order 1.4; the spectra 115.8, 116.5
  // and 116.7 W).
  BOOST_TEST(std::abs(tread.power / spectral - 1.) < 0.06);
}

BOOST_AUTO_TEST_SUITE_END()
