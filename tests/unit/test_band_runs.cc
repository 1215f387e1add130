// Multi-rate estimation (analysis/band_runs.h) and the prediction it plans
// with:
// - the standard errors predicted without a record equal those
//   welch_band_spectrum() predicts from one (a second computation of the
//   same formula, on the signal's own segments);
// - the record samples_for_error() returns meets the target and one sample
//   less does not (the smallest);
// - the plan: the low-rate run exists only when the run at the scene's
//   step misses the target in the low bands; its step is the factor times
//   the scene's; too coarse a step is refused naming the parameter and the
//   largest factor allowed;
// - the merge takes each band from the run that gave it;
// - the multi-rate estimate of a signal sampled at two rates agrees with
//   the single-rate one within the standard errors (a Gaussian process
//   whose spectrum is known in closed form);
// - a run extended to its observed standard errors ('Spectra/Extend runs')
//   meets the target: on Gaussian noise at about the record the Gaussian
//   prediction gives in closed form, on gated noise (whose band power
//   scatters more) at a longer one, and never past its longest.
#include <greentread/analysis/band_runs.h>
#include <greentread/analysis/spectra_parameters.h>
#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>

#include <boost/test/unit_test.hpp>

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <string>

using namespace greentread;

BOOST_AUTO_TEST_SUITE(band_runs)

BOOST_AUTO_TEST_CASE(predicted_errors_without_a_record_equal_welchs)
{
  std::mt19937                     random(7);
  std::normal_distribution<double> normal(0., 1.);
  for (const std::size_t N : {3000ul, 5209ul, 23000ul})
    for (const double dt : {15.36e-6, 27.65e-6, 98.7e-6})
      {
        std::vector<double> x(N);
        for (auto &v : x)
          v = normal(random);
        const double top = dt > 5e-5 ? 1000. : 5000.;
        const auto   s   = analysis::welch_band_spectrum(x, dt, 1., 100., top, 8);
        const auto   p   = analysis::predicted_standard_errors(N, dt, s.bands, 8);
        for (std::size_t b = 0; b < s.bands.size(); ++b)
          BOOST_TEST(p[b] == s.predicted_error[b],
                     N << " samples, dt " << dt << ", " << s.bands[b].nominal << " Hz");
      }
}

BOOST_AUTO_TEST_CASE(the_record_for_a_target_is_the_shortest)
{
  const double dt    = 76.8e-6; // 90 km/h, 5 road samples of 384 um per step
  const auto   bands = analysis::third_octave_bands(250., 1000.);
  for (const double target : {0.5, 1., 2.})
    {
      const std::size_t N     = analysis::samples_for_error(dt, bands, 8, target, 100, 10000000);
      const auto        met   = analysis::predicted_standard_errors(N, dt, bands, 8);
      double            worst = 0.;
      for (const double e : met)
        worst = std::max(worst, e);
      BOOST_TEST(worst <= target);
      // One sample less misses it somewhere (bisection on a prediction that
      // does not rise with the record).
      const auto short_of    = analysis::predicted_standard_errors(N - 1, dt, bands, 8);
      double     worst_short = 0.;
      for (const double e : short_of)
        worst_short = std::max(worst_short, e);
      BOOST_TEST(worst_short > target);
      BOOST_TEST_MESSAGE("target " << target << " dB from 250 Hz to 1 kHz at dt = 76.8 us: " << N
                                   << " samples, " << N * dt << " s, " << N * dt * 25.
                                   << " m at 90 km/h");
    }
  // Out of reach within the limit: the limit plus one.
  BOOST_TEST(analysis::samples_for_error(dt, bands, 8, 0.1, 100, 1000) == 1001u);
}

BOOST_AUTO_TEST_CASE(the_plan_adds_a_low_rate_run_only_where_it_is_needed)
{
  analysis::SpectraParameters spectra; // 1 dB from 250 Hz, 76.8 us up to 1 kHz
  const double                V    = 25.;
  const double                dt   = 0.384e-3 / V;
  const auto                  plan = analysis::plan_band_runs(spectra, V, dt, 2., 5000.);
  BOOST_TEST_REQUIRE(plan.size() == 2u);
  BOOST_TEST(plan[0].name.empty());
  BOOST_TEST(plan[0].time_step == dt);
  BOOST_TEST(plan[0].distance == 2.);
  BOOST_TEST(plan[0].f_low == 1250.);
  BOOST_TEST(plan[1].name == "low-rate");
  BOOST_TEST(plan[1].time_step == 76.8e-6);
  BOOST_TEST(plan[1].f_high == 1000.);
  BOOST_TEST(plan[1].distance > 2.);
  BOOST_TEST(!plan[1].target_out_of_reach);
  // The low run's record meets the target by the prediction.
  const auto errors = analysis::predicted_standard_errors(
    plan[1].steps, plan[1].time_step, analysis::third_octave_bands(250., 1000.), 8);
  for (const double e : errors)
    BOOST_TEST(e <= 1.);
  BOOST_TEST_MESSAGE("90 km/h, 1 dB from 250 Hz: the low-rate run rolls "
                     << plan[1].distance << " m, " << plan[1].steps << " steps");

  // A distance that already meets the target: one run.
  const auto long_enough = analysis::plan_band_runs(spectra, V, dt, plan[1].distance, 5000.);
  BOOST_TEST(long_enough.size() == 1u);
  // One rate asked for: one run.
  spectra.low_bands_up_to = 0.;
  BOOST_TEST(analysis::plan_band_runs(spectra, V, dt, 2., 5000.).size() == 1u);
  // A low-rate step no coarser than the scene's: one run.
  spectra.low_bands_up_to    = 1000.;
  spectra.low_band_time_step = dt;
  BOOST_TEST(analysis::plan_band_runs(spectra, V, dt, 2., 5000.).size() == 1u);
  // Out of reach within the longest distance: flagged, at that distance.
  spectra.low_band_time_step = 76.8e-6;
  spectra.longest_distance   = 3.;
  const auto capped          = analysis::plan_band_runs(spectra, V, dt, 2., 5000.);
  BOOST_TEST_REQUIRE(capped.size() == 2u);
  BOOST_TEST(capped[1].target_out_of_reach);
  BOOST_TEST(capped[1].distance == 3., boost::test_tools::tolerance(1e-3));
  // No longer than the run at the step (a texture file too short): one run.
  spectra.longest_distance = 1.5;
  BOOST_TEST(analysis::plan_band_runs(spectra, V, dt, 2., 5000.).size() == 1u);

  // Too coarse a step for the low bands: refused, naming the parameter and
  // the largest step (the 1 kHz band ends at 1122 Hz: dt <= 445.6 us).
  spectra.longest_distance   = 50.;
  spectra.low_band_time_step = 614.4e-6;
  try
    {
      analysis::plan_band_runs(spectra, V, dt, 2., 5000.);
      BOOST_TEST(false, "a step of 614 us was accepted for the 1 kHz band");
    }
  catch (const InputError &e)
    {
      const std::string message = e.what();
      BOOST_TEST_MESSAGE(message);
      BOOST_TEST(message.find("'Spectra/Low-band time step' = ") != std::string::npos);
      BOOST_TEST(message.find("allowed: at most 0.0004456 s") != std::string::npos);
    }
}

BOOST_AUTO_TEST_CASE(multi_rate_agrees_with_one_rate_within_the_error_bars)
{
  // A Gaussian process limited to 1.9 kHz (white noise shaped in Fourier
  // space: a resonance at 400 Hz over a floor), sampled at 20 kHz. The
  // one-rate estimate is one 4 s record; the multi-rate one takes the bands
  // up to 1 kHz from every 5th sample of another 4 s record (4 kHz: no
  // aliasing, the process has nothing above 1.9 kHz) and the bands above
  // from 0.5 s of a third at the full rate. Each band's two levels agree
  // within 3 combined standard errors, and the merged spectrum carries each
  // band's own step and duration.
  const double dt      = 5e-5;
  const auto   process = [&](const unsigned seed, const std::size_t N) {
    std::mt19937                      random(seed);
    std::normal_distribution<double>  normal(0., 1.);
    std::vector<std::complex<double>> X(N);
    for (auto &v : X)
      v = normal(random);
    Eigen::FFT<double>                fft;
    std::vector<std::complex<double>> spectrum, back;
    fft.fwd(spectrum, X);
    for (std::size_t k = 0; k < N; ++k)
      {
        const double f = std::min(k, N - k) / (N * dt);
        spectrum[k] *= f > 1900. ? 0. : 0.2 + 1. / std::sqrt(1. + std::pow((f - 400.) / 80., 2));
      }
    fft.inv(back, spectrum);
    std::vector<double> x(N);
    for (std::size_t n = 0; n < N; ++n)
      x[n] = back[n].real();
    return x;
  };
  const auto one_rate    = analysis::welch_band_spectrum(process(1, 80000), dt, 1., 100., 1600., 8);
  const auto fine        = analysis::welch_band_spectrum(process(2, 10000), dt, 1., 100., 1600., 8);
  const auto long_record = process(3, 80000);
  std::vector<double> coarse;
  for (std::size_t n = 0; n < long_record.size(); n += 5)
    coarse.push_back(long_record[n]);
  const auto        low = analysis::welch_band_spectrum(coarse, 5. * dt, 1., 100., 1000., 8);
  analysis::BandRun low_run;
  low_run.name      = "low-rate";
  low_run.f_high    = 1000.;
  const auto merged = analysis::merge_band_spectra(fine, low, low_run);
  BOOST_TEST_REQUIRE(merged.bands.size() == one_rate.bands.size());
  for (std::size_t b = 0; b < merged.bands.size(); ++b)
    {
      const bool   from_low = merged.bands[b].nominal <= 1000.;
      const double se       = std::hypot(merged.standard_error[b], one_rate.standard_error[b]);
      BOOST_TEST_MESSAGE(merged.bands[b].nominal << " Hz: multi-rate " << merged.level[b] << " +- "
                                                 << merged.standard_error[b] << " dB, one rate "
                                                 << one_rate.level[b] << " +- "
                                                 << one_rate.standard_error[b] << " dB");
      BOOST_TEST(std::abs(merged.level[b] - one_rate.level[b]) <= 3. * se,
                 merged.bands[b].nominal << " Hz");
      BOOST_TEST(merged.time_step[b] == (from_low ? 5. * dt : dt));
      BOOST_TEST(merged.duration[b] == (from_low ? 16000 * 5. * dt : 10000 * dt),
                 boost::test_tools::tolerance(1e-12));
      // The long record's low bands are the better estimate.
      if (from_low && merged.bands[b].nominal >= 250.)
        BOOST_TEST(merged.standard_error[b] < fine.standard_error[b]);
    }
  // The check of the low-rate run against the run at the step: these two
  // independent estimates of one process agree within its tolerance; a
  // low-rate band 10 dB off (a coarse step that rings) is named.
  low_run.f_high = 1000.;
  BOOST_TEST(analysis::low_rate_disagreement(fine, low, low_run).empty(),
             analysis::low_rate_disagreement(fine, low, low_run));
  auto       ringing = low;
  const auto at_800  = std::find_if(ringing.bands.begin(), ringing.bands.end(),
                                    [](const analysis::FrequencyBand &band) {
                                     return band.nominal == 800.;
                                   }) -
                      ringing.bands.begin();
  ringing.level[at_800] += 10.;
  const std::string named = analysis::low_rate_disagreement(fine, ringing, low_run);
  BOOST_TEST_MESSAGE("a low-rate band 10 dB off: " << named);
  BOOST_TEST(named.find("the 800 Hz band") != std::string::npos, named);
  // A low-rate spectrum that lacks a band it should give is refused.
  low_run.f_high = 1600.;
  BOOST_CHECK_THROW(analysis::merge_band_spectra(fine, low, low_run), InputError);
}

BOOST_AUTO_TEST_CASE(a_run_extends_until_its_observed_errors_meet_the_target)
{
  // The plan's caps: 3 times each run's planned record, at most 'Longest
  // distance'; none without 'Extend runs'.
  analysis::SpectraParameters spectra;
  const double                V = 25., dt = 0.384e-3 / V;
  auto                        plan = analysis::plan_band_runs(spectra, V, dt, 2., 5000.);
  BOOST_TEST_REQUIRE(plan.size() == 2u);
  BOOST_TEST(plan[0].longest_steps == unsigned(std::floor(6. / (V * dt))));
  BOOST_TEST(plan[1].longest_steps ==
             unsigned(std::floor(std::min(50., 3. * plan[1].distance) / (V * 76.8e-6))));
  spectra.extend_runs = false;
  plan                = analysis::plan_band_runs(spectra, V, dt, 2., 5000.);
  BOOST_TEST(plan[0].longest_steps == 0u);
  BOOST_TEST(plan[1].longest_steps == 0u);
  spectra.extend_runs = true;

  // The rule on signals sampled at the low-rate step, from the record the
  // Gaussian prediction plans (as the program does): extended until the
  // bands from 250 Hz to 1 kHz meet 1 dB.
  const double       h     = 76.8e-6;
  const auto         bands = analysis::third_octave_bands(250., 1000.);
  const unsigned int gaussian_record =
    analysis::samples_for_error(h, bands, 8, 1., 100, 10000000); // the closed form
  analysis::BandRun run;
  run.time_step     = h;
  run.f_low         = 100.;
  run.f_high        = 1000.;
  run.longest_steps = 400000;
  std::mt19937                          random(11);
  std::normal_distribution<double>      normal(0., 1.);
  std::exponential_distribution<double> on_off(1. / 0.05); // 50 ms on and off, on average
  for (const bool gated : {false, true})
    {
      std::vector<double> x(run.longest_steps);
      bool                on        = true;
      double              switch_at = on_off(random);
      for (std::size_t n = 0; n < x.size(); ++n)
        {
          if (gated && n * h > switch_at)
            {
              on = !on;
              switch_at += on_off(random);
            }
          x[n] = on ? normal(random) : 0.01 * normal(random);
        }
      unsigned int N = gaussian_record, rounds = 0;
      for (;; ++rounds)
        {
          const auto s = analysis::welch_band_spectrum(
            std::vector<double>(x.begin(), x.begin() + N), h, 1., 100., 1000., 8);
          const unsigned int more = analysis::more_steps_for_target(spectra, run, s, s, N);
          if (more == 0)
            {
              double worst = 0.;
              for (std::size_t b = 0; b < s.bands.size(); ++b)
                if (s.bands[b].nominal >= 250.)
                  worst = std::max(worst, s.standard_error[b]);
              BOOST_TEST_MESSAGE((gated ? "gated" : "Gaussian")
                                 << " noise: extended to " << N << " samples in " << rounds
                                 << " rounds (the Gaussian prediction " << gaussian_record
                                 << "), largest standard error " << worst << " dB");
              BOOST_TEST(worst <= 1.);
              break;
            }
          BOOST_TEST_REQUIRE(N + more <= run.longest_steps);
          N += more;
          BOOST_TEST_REQUIRE(rounds < 6u);
        }
      if (gated)
        BOOST_TEST(N > 1.5 * gaussian_record);
      else
        BOOST_TEST(N < 1.6 * gaussian_record); // the plan, or a round of the 10% margin
    }

  // At its longest the run stops, met or not; nothing asked of no record.
  run.longest_steps = 3000;
  std::vector<double> short_record(2000);
  for (auto &v : short_record)
    v = normal(random);
  const auto s = analysis::welch_band_spectrum(short_record, h, 1., 100., 1000., 8);
  BOOST_TEST(analysis::more_steps_for_target(spectra, run, s, s, 2000) == 1000u);
  BOOST_TEST(analysis::more_steps_for_target(spectra, run, s, s, 3000) == 0u);
  BOOST_TEST(analysis::more_steps_for_target(spectra, run, s, s, 0) == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
