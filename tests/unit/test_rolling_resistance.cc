// The rolling resistance a texture adds, measured by the work the contact
// forces do (analysis/rolling_resistance.h), against an independent
// integration of the synthetic patch's modes driven by the same forces: the
// work equals the change of the modes' energy plus what their damping
// dissipates, and over a long run the dissipation alone. A second method,
// the forces on the road's slopes, and a flat road that takes no power. The
// time step's error bar against a run at an eighth of the step, and the
// contact grid's against a grid four times as fine.
#include "grid_rolling.h"
#include "patch_rolling.h"
#include "synthetic_patch.h"

#include <greentread/analysis/rolling_resistance.h>
#include <greentread/road/texture.h>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <vector>

using namespace greentread;

namespace
{
  /// The modes of a pure modal model with real shapes (residues
  /// psi psi^T / (2 j w_d), the synthetic patch's), driven by a force linear
  /// within each step from @p ends[n] to @p ends[n+1], integrated by
  /// fourth-order Runge-Kutta with 16 substeps a step from the static state
  /// under @p ends[0]: each mode's eta'' + 2 zeta w eta' + w^2 eta = psi . f.
  /// At every step's end, the energy the modes store and what their damping
  /// has dissipated since the start [J].
  struct ModalEnergy
  {
    std::vector<double> stored, dissipated;
  };

  ModalEnergy
  integrate_modes(const modal::PatchModel            &model,
                  const std::vector<Eigen::VectorXd> &ends,
                  const double                        dt)
  {
    ModalEnergy e;
    e.stored.assign(ends.size(), 0.);
    e.dissipated.assign(ends.size(), 0.);
    for (std::size_t k = 0; k < model.lambda.size(); ++k)
      {
        const double w = std::abs(model.lambda[k]), zeta = -model.lambda[k].real() / w;
        const double wd = model.lambda[k].imag();
        // residue(p, q) 2 j w_d = psi_p psi_q
        const Eigen::MatrixXd product =
          (model.residues[k] * std::complex<double>(0., 2. * wd)).real();
        const Eigen::VectorXd psi   = product.col(0) / std::sqrt(product(0, 0));
        const auto            force = [&](const std::size_t n, const double s) {
          return (1. - s) * psi.dot(ends[n]) + s * psi.dot(ends[n + 1]);
        };
        // State: eta, its rate, the energy dissipated.
        using State      = std::array<double, 3>;
        const auto slope = [&](const State &y, const double load) {
          return State{
            {y[1], load - 2. * zeta * w * y[1] - w * w * y[0], 2. * zeta * w * y[1] * y[1]}};
        };
        const auto add = [](const State &a, const State &b, const double c) {
          return State{{a[0] + c * b[0], a[1] + c * b[1], a[2] + c * b[2]}};
        };
        State              y   = {{psi.dot(ends[0]) / (w * w), 0., 0.}};
        const unsigned int sub = 16;
        const double       h   = dt / sub;
        for (std::size_t n = 0; n < ends.size(); ++n)
          {
            e.stored[n] += 0.5 * (y[1] * y[1] + w * w * y[0] * y[0]);
            e.dissipated[n] += y[2];
            if (n + 1 == ends.size())
              break;
            for (unsigned int m = 0; m < sub; ++m)
              {
                const double s0 = double(m) / sub, s1 = double(m + 1) / sub, sh = 0.5 * (s0 + s1);
                const State  k1 = slope(y, force(n, s0));
                const State  k2 = slope(add(y, k1, 0.5 * h), force(n, sh));
                const State  k3 = slope(add(y, k2, 0.5 * h), force(n, sh));
                const State  k4 = slope(add(y, k3, h), force(n, s1));
                for (int i = 0; i < 3; ++i)
                  y[i] += h / 6. * (k1[i] + 2. * k2[i] + 2. * k3[i] + k4[i]);
              }
          }
      }
    return e;
  }

  /// The synthetic patch with eight more modes, from 600 Hz to 6.7 kHz, of a
  /// tenth of its modes' mass and with the loss a stiffness-proportional
  /// damping gives (zeta = 0.05 f / 450 Hz), as the tyre's ring has above a
  /// few hundred hertz: the power these take, the most of it, is what a
  /// coarse step misses.
  modal::PatchModel
  patch_with_high_modes()
  {
    modal::PatchModel  m = test::synthetic_patch(0.05);
    const unsigned int n = m.n_points();
    for (unsigned int k = 0; k < 8; ++k)
      {
        const double    f = 600. * std::pow(1.41, k), w = 2. * M_PI * f;
        const double    zeta = 0.05 * f / 450., wd = w * std::sqrt(1. - zeta * zeta), mass = 0.2;
        Eigen::VectorXd phi(n);
        for (unsigned int p = 0; p < n; ++p)
          {
            // Along the patch (x, 4 points 6 mm apart) and across (y, 3 points 7 mm apart).
            const double x = m.points[p][0] / 6e-3, y = m.points[p][1] / 7e-3;
            phi[p] = std::cos(M_PI * (1 + k % 3) * (x + 2.) / 4.) *
                     std::cos(M_PI * (k / 3) * (y + 1.5) / 3.);
          }
        m.lambda.emplace_back(-zeta * w, wd);
        m.real.push_back(false);
        m.residues.push_back((phi * phi.transpose()).cast<std::complex<double>>() /
                             std::complex<double>(0., 2. * mass * wd));
      }
    m.f_max = 10000.;
    return m;
  }

  struct Run
  {
    std::vector<Eigen::VectorXd> ends; ///< the force at each step's end, and at the start
    analysis::RollingResistance  value;
    std::vector<double>          step_work; ///< the meter's record
    double                       work = 0., slope_work = 0., dt = 0.;
  };

  Run
  roll(const modal::PatchModel &model, const road::Texture &texture, const test::RollingCase &c)
  {
    Run r;
    r.dt                                               = c.time_step(texture);
    const Eigen::VectorXd                        tread = test::tread_height(model);
    std::unique_ptr<analysis::RollingPowerMeter> meter;
    Eigen::VectorXd                              d_last;
    Eigen::VectorXd                              start;
    test::roll_on_texture(
      model, tread, texture, c,
      [&](const contact::RollingStep &s) {
        if (!meter)
          {
            // The static start: the model's static compliance under the
            // start forces (contact::start_contact).
            meter = std::make_unique<analysis::RollingPowerMeter>(model.static_compliance() * start,
                                                                  r.dt);
            r.ends.push_back(start);
            d_last = s.d; // the demand's change over the first step is not known: skipped
          }
        meter->add(s);
        // The step's force is the mean of its ends' (linear within it).
        r.ends.push_back(2. * s.force - r.ends.back());
        r.slope_work += s.force.dot(s.d - d_last);
        d_last = s.d;
      },
      &start);
    r.step_work = meter->step_work();
    for (const double w : r.step_work)
      r.work += w;
    r.value = meter->result(c.speed_kmh / 3.6);
    return r;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(rolling_resistance)

BOOST_AUTO_TEST_CASE(work_of_the_forces_is_what_the_modes_dissipate)
{
  const auto                        model = test::synthetic_patch(0.05);
  std::vector<road::WavelengthBand> bands;
  std::vector<double>               levels;
  road::texture_preset("road-A", bands, levels);
  const road::Texture texture = road::synthetic_texture(bands, levels, 3.84e-4, 8192, 64, 3);

  test::RollingCase c; // 3 m at 50 km/h, 600 N: eight decay times of the slowest mode
  c.speed_kmh         = 50.;
  c.distance          = 3.;
  const Run         r = roll(model, texture, c);
  const ModalEnergy e = integrate_modes(model, r.ends, r.dt);
  const std::size_t N = r.ends.size() - 1;

  // The local compliance G_r is elastic: it stores 1/2 f G_r f.
  const auto local = [&](const Eigen::VectorXd &f) {
    return 0.5 * f.dot(model.instantaneous * f);
  };
  const double balance = std::abs(
    r.work - (e.stored[N] - e.stored[0] + local(r.ends[N]) - local(r.ends[0]) + e.dissipated[N]));
  const double long_run = std::abs(r.work - e.dissipated[N]);
  BOOST_TEST_MESSAGE("work of the forces " << r.work << " J, dissipated " << e.dissipated[N]
                                           << " J, stored " << e.stored[0] << " -> " << e.stored[N]
                                           << " J; balance off by " << balance / r.work
                                           << ", work - dissipation " << long_run / r.work);
  // Measured 1.9e-4 (the step's work is exact to O((w dt)^2)) and 3.5e-3
  // (the energy stored at the end); the aim is 2%.
  BOOST_TEST(r.work > 0.);
  BOOST_TEST(balance <= 6e-4 * r.work);
  BOOST_TEST(long_run <= 1e-2 * r.work);

  // The meter's mean power over its window (after the skip, ten whole
  // segments) against the modes' balance over the same window.
  const std::size_t first = static_cast<std::size_t>(std::round(r.value.skipped / r.dt));
  const std::size_t last  = first + static_cast<std::size_t>(std::round(r.value.duration / r.dt));
  const double      window_power = (e.stored[last] - e.stored[first] + local(r.ends[last]) -
                               local(r.ends[first]) + e.dissipated[last] - e.dissipated[first]) /
                              r.value.duration;
  BOOST_TEST_MESSAGE("mean power " << r.value.power << " +- " << r.value.power_error
                                   << " W; the modes' over the window " << window_power << " W");
  BOOST_TEST(std::abs(r.value.power - window_power) <= 6e-4 * window_power); // measured 2.1e-4
  BOOST_TEST(r.value.power_error > 0.);
  BOOST_TEST(r.value.coefficient == r.value.force / r.value.load);
  BOOST_TEST(r.value.force == r.value.power / (c.speed_kmh / 3.6));

  // A second method: in contact the points follow the road, so the work is
  // that of the forces on the texture's slopes, up to where points leave
  // or touch the road within a step.
  BOOST_TEST_MESSAGE("work on the road's slopes " << r.slope_work << " J");
  BOOST_TEST(std::abs(r.slope_work - r.work) <= 0.1 * r.work); // measured 4.2%
}

BOOST_AUTO_TEST_CASE(rougher_road_more_flat_road_none)
{
  const auto                        model = test::synthetic_patch(0.05);
  std::vector<road::WavelengthBand> bands;
  std::vector<double>               levels;
  road::texture_preset("road-A", bands, levels);
  const road::Texture rough = road::synthetic_texture(bands, levels, 3.84e-4, 8192, 64, 5);
  road::texture_preset("road-B", bands, levels);
  const road::Texture smooth = road::synthetic_texture(bands, levels, 3.84e-4, 8192, 64, 5);

  test::RollingCase c; // 3 m at 50 km/h, 600 N
  c.speed_kmh        = 50.;
  c.distance         = 3.;
  const Run a        = roll(model, rough, c);
  const Run b        = roll(model, smooth, c);
  c.flat             = true;
  const Run    flat  = roll(model, rough, c);
  const double mpd_a = road::mean_profile_depth(rough), mpd_b = road::mean_profile_depth(smooth);
  BOOST_TEST_MESSAGE("C_RR " << a.value.coefficient << " +- " << a.value.coefficient_error
                             << " (MPD " << 1e3 * mpd_a << " mm), " << b.value.coefficient << " +- "
                             << b.value.coefficient_error << " (MPD " << 1e3 * mpd_b
                             << " mm), flat " << flat.value.coefficient);
  BOOST_TEST(mpd_a > mpd_b);
  BOOST_TEST(a.value.coefficient - b.value.coefficient >
             3. * std::hypot(a.value.coefficient_error, b.value.coefficient_error)); // 3.6
  // On a flat road the forces and the displacements stay at the static
  // start's: no work at all, to round-off.
  BOOST_TEST(std::abs(flat.value.power) <= 1e-9 * a.value.power);
  BOOST_TEST(flat.value.load == c.load, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(the_time_steps_error_bar_against_a_refined_step)
{
  // The scene's estimate: the level at half the step over a short window
  // from the same start (0.3 m, as the error bars' windows are), its
  // relative change of the power applied to the run's coefficient at order
  // 1. The reference: the same 3 m at 1/8 of a road sample per step. On the
  // patch with high modes, which take most of the power as the tyre's do.
  const auto                        model = patch_with_high_modes();
  std::vector<road::WavelengthBand> bands;
  std::vector<double>               levels;
  road::texture_preset("road-A", bands, levels);
  const road::Texture texture = road::synthetic_texture(bands, levels, 3.84e-4, 8192, 64, 3);

  test::RollingCase c; // 3 m at 50 km/h, 600 N, one road sample per step
  c.speed_kmh                  = 50.;
  c.distance                   = 3.;
  const Run         run        = roll(model, texture, c);
  test::RollingCase level      = c; // half the step over 0.3 m (21.6 ms)
  level.dt_factor              = 0.5;
  level.distance               = 0.3;
  const Run             finer  = roll(model, texture, level);
  const double          window = level.distance / (c.speed_kmh / 3.6);
  analysis::EstimateRun half_step; // the scene's level at half the step
  half_step.what        = analysis::Discretisation::time_step;
  half_step.ratio       = 2.;
  const double estimate = analysis::rolling_resistance_level_error(
    run.value, run.step_work, run.dt, finer.step_work, finer.dt, window,
    analysis::rolling_resistance_factor(half_step));
  BOOST_TEST(analysis::rolling_resistance_factor(half_step) == 2.);
  std::vector<double> refined_c;
  for (const double factor : {0.5, 0.25, 0.125})
    {
      test::RollingCase refined = c;
      refined.dt_factor         = factor;
      refined_c.push_back(roll(model, texture, refined).value.coefficient);
    }
  const double measured = std::abs(run.value.coefficient - refined_c.back());
  BOOST_TEST_MESSAGE("C_RR at 1, 1/2, 1/4, 1/8 road sample per step: "
                     << run.value.coefficient << ", " << refined_c[0] << ", " << refined_c[1]
                     << ", " << refined_c[2] << "; the error bar " << estimate
                     << ", the difference from 1/8: " << measured << " (ratio "
                     << estimate / measured << ")");
  // Measured 1.51: the levels converge at order 2 here (0.039, 0.011 and
  // 0.0028 x 1e-3 from each step to the next), above the order 1 assumed,
  // which the tyre's ring shows (benchmarks/rolling_resistance).
  BOOST_TEST(estimate / measured >= 0.75);
  BOOST_TEST(estimate / measured <= 3.);

  // mean_power: the steps that start in the interval, exactly.
  const std::vector<double> work = {1., 2., 3., 4.};
  BOOST_TEST(analysis::mean_power(work, 0.5, 0.5, 1.5) == 2.5 / 0.5);
  BOOST_CHECK_THROW(analysis::mean_power(work, 0.5, 2., 3.), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(the_contact_grids_error_bar_against_a_refined_grid)
{
  // The synthetic patch on a contact grid over road-A (grid_rolling.h): the
  // run on 4 subdivisions, its coarser level on 2 over a short window as the
  // scene rolls it, and the refined runs on 8 and 16. The error bar at order
  // 1 against the run's measured distance from the grid of 16.
  struct Power
  {
    std::vector<double>         work;
    analysis::RollingResistance value;
    double                      dt = 0.;
  };
  const auto roll = [](const unsigned int subdivisions, const double duration) {
    Power                                        p;
    std::unique_ptr<analysis::RollingPowerMeter> meter;
    const test::GridRun                          run = test::roll_grid(
                               subdivisions, 1., duration,
                               [&](const contact::ContactGrid &, const contact::RollingStep &step) {
        meter->add(step);
      },
                               [&](const contact::StaticContact &start, const double dt) {
        meter = std::make_unique<analysis::RollingPowerMeter>(start.u, dt);
      });
    BOOST_TEST(run.failed_steps == 0u);
    p.work  = meter->step_work();
    p.value = meter->result(run.speed);
    p.dt    = run.time_step;
    return p;
  };
  // 2.5 m, within the synthetic road's 3.07 m, and a window of 0.5 m, about
  // the scene's error bars' window on the main job (0.2 to 0.34 m).
  const double duration = 0.1, window = 0.02;
  const Power  run = roll(4, duration), coarser = roll(2, window);
  const Power  finer = roll(8, duration), finest = roll(16, duration);

  analysis::EstimateRun grid; // the scene's coarser grid: the subdivisions halved
  grid.what  = analysis::Discretisation::contact_grid;
  grid.ratio = 2.;
  const double estimate =
    analysis::rolling_resistance_level_error(run.value, run.work, run.dt, coarser.work, coarser.dt,
                                             window, analysis::rolling_resistance_factor(grid));
  const double measured = std::abs(run.value.coefficient - finest.value.coefficient);
  BOOST_TEST_MESSAGE("C_RR on 2 (over the window), 4, 8 and 16 subdivisions: "
                     << coarser.value.coefficient << ", " << run.value.coefficient << " +- "
                     << run.value.coefficient_error << ", " << finer.value.coefficient << ", "
                     << finest.value.coefficient << "; the error bar " << estimate
                     << ", the difference from 16: " << measured << " (ratio "
                     << estimate / measured << ")");
  // Measured 2.88: the coefficient converges at order 1.45 from 4 to 16
  // subdivisions (0.047 and 0.017 x 1e-3 from each grid to the next), above
  // the order 1 assumed, and the coarser level on 2 is further from its
  // limit than that order says.
  BOOST_TEST(estimate / measured >= 0.75);
  BOOST_TEST(estimate / measured <= 3.);
}

BOOST_AUTO_TEST_SUITE_END()
