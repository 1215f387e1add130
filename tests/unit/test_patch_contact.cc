// Multi-point rolling contact (contact/patch_contact.h): checked against the
// 1-DoF exact solution, the direct convolution, the static contact solution
// and the momentum balance, and run on stiff and extreme cases.

#include "complementarity.h"
#include "patch_rolling.h"
#include "synthetic_patch.h"
#include "test_helpers.h"

#include <greentread/base/exceptions.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/road/texture.h>
#include <greentread/sdof/exact_solution.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>

using namespace greentread;
using test::ring_radius;
using test::synthetic_patch;
using test::tread_height;

namespace
{
  double
  max_abs(const Eigen::VectorXd &v)
  {
    return v.cwiseAbs().maxCoeff();
  }

  /// Every step's contact solve converged. (Penetration and the sign of
  /// the forces are checked independently of the solve's own matrices in
  /// stiff_and_extreme_cases_stay_sound, patch_rolling.h.)
  void
  check_converged(const contact::RollingSummary &s)
  {
    BOOST_TEST(s.failed_steps == 0u,
               "failed steps: " << s.failed_steps << ", first " << s.first_failure);
  }
  /// A 2 cm sinusoid of 0.3 mm rolled at @p V [m/s], lifted by @p offset,
  /// under the tread heights @p tread: the demand d, dd of contact::roll().
  std::function<void(double, Eigen::VectorXd &, Eigen::VectorXd &)>
  sinusoid_demand(const modal::PatchModel &model,
                  const Eigen::VectorXd   &tread,
                  const double             V,
                  const double             offset)
  {
    return [&model, tread, V, offset](const double t, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
      for (unsigned int p = 0; p < model.n_points(); ++p)
        {
          const double a = 2. * M_PI * (model.points[p][0] + V * t) / 0.02;
          d[p]           = offset + 3e-4 * std::sin(a) - tread[p];
          dd[p]          = 3e-4 * std::cos(a) * 2. * M_PI * V / 0.02;
        }
    };
  }

  /// The same run from rest with the modal recursion and with the direct
  /// convolution: both summaries and the largest force difference.
  struct ConvolutionComparison
  {
    contact::RollingSummary modal, direct;
    double                  difference = 0., peak = 0.;
  };

  ConvolutionComparison
  compare_convolutions(
    const modal::PatchModel                                                 &model,
    const double                                                             dt,
    const unsigned int                                                       n_steps,
    const std::function<void(double, Eigen::VectorXd &, Eigen::VectorXd &)> &demand)
  {
    std::vector<Eigen::VectorXd> forces[2];
    unsigned int                 run     = 0;
    const auto                   observe = [&](const contact::RollingStep &s) {
      forces[run].push_back(s.force);
    };
    ConvolutionComparison c;
    auto                  modal = convolution::make_modal_patch_convolution(model, dt, 2);
    auto direct = convolution::make_direct_patch_convolution(model, dt, n_steps + 1);
    c.modal     = contact::roll(*modal, demand, n_steps, Eigen::VectorXd(), observe);
    run         = 1;
    c.direct    = contact::roll(*direct, demand, n_steps, Eigen::VectorXd(), observe);
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        c.difference = std::max(c.difference, max_abs(forces[0][n] - forces[1][n]));
        c.peak       = std::max(c.peak, max_abs(forces[1][n]));
      }
    return c;
  }

  /// One wavelength of sinusoid_demand() at @p V from the static contact
  /// that carries 150 N: the largest difference of the step forces (every
  /// 97th step) to the static solution of each position, and its scale.
  struct SlowRoll
  {
    contact::RollingSummary summary;
    double                  error = 0., peak = 0.;
  };

  SlowRoll
  slow_roll(const modal::PatchModel &model,
            const Eigen::VectorXd   &tread,
            const double             V,
            const double             dt)
  {
    const Eigen::MatrixXd G0   = model.static_compliance();
    const auto            road = sinusoid_demand(model, tread, V, 0.);
    Eigen::VectorXd       d0(model.n_points()), dd0(model.n_points());
    road(0., d0, dd0);
    const auto eq     = contact::solve_static_contact(G0, d0, 150., 0.);
    const auto demand = [&](const double t, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
      road(t, d, dd);
      d.array() += eq.delta;
    };
    SlowRoll   r;
    const auto observe = [&](const contact::RollingStep &s) {
      if (s.step % 97 != 0)
        return;
      const auto ref = contact::solve_static_contact(G0, s.d, 0., 0.);
      r.error        = std::max(r.error, max_abs(s.force - ref.q));
      r.peak         = std::max(r.peak, max_abs(ref.q));
    };
    auto conv = convolution::make_modal_patch_convolution(model, dt);
    r.summary =
      contact::roll(*conv, demand, static_cast<unsigned int>(0.02 / V / dt), eq.q, observe);
    return r;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(patch_contact)

BOOST_AUTO_TEST_CASE(a_whole_number_of_steps_is_not_rounded_up)
{
  // k steps of dt cover k V dt, for every k, speed and dt a multiple of the
  // road's sampling (the time-step study's dt): plain ceil() of the
  // floating-point ratio gives k + 1 in about 5% of these cases, a record one
  // step longer and other Fourier lines. A ratio just above a whole number
  // is still rounded up.
  unsigned int wrong = 0, cases = 0;
  for (const double kmh : {50., 70., 90., 130.})
    for (const double f : {0.05, 0.2, 0.5, 1., 2., 5., 20.})
      {
        const double V = kmh / 3.6, dt = 0.000384 / V * f;
        for (unsigned int k = 1; k < 4000; ++k, ++cases)
          wrong += contact::steps_to_cover(k * 0.000384 * f, V, dt) != k;
        BOOST_TEST(contact::steps_to_cover(1.000001 * 0.000384 * f, V, dt) == 2u);
      }
  BOOST_TEST(wrong == 0u, wrong << " of " << cases << " distances of k steps not k steps");
  BOOST_TEST(contact::steps_to_cover(1.2, 25., 7.68e-6) == 6250u);
  BOOST_TEST(contact::steps_to_cover(1.2, 25., 3.072e-5) == 1563u);
  BOOST_TEST(contact::steps_to_cover(2., 25., 1.536e-5) == 5209u);
}

BOOST_AUTO_TEST_CASE(one_point_with_one_mode_is_the_1dof_exact_solution)
{
  // The 1-DoF problem of Section 3 on a sinusoid, run through the patch
  // code with one point: the mass's height is its flight (free motion with
  // gravity from rest on the road) plus g * F, so the road asks g * F >= d
  // with d = u_r - u_flight.
  const sdof::Oscillator    osc(test::oscillator_parameters());
  const road::Sinusoid      profile(5e-3, 1e-2);
  const road::RoadTrack     track{profile, test::oscillator_parameters().speed};
  const double              dt = 1e-5, end_time = 0.2;
  const sdof::ExactSolution exact(osc, track, end_time);

  modal::PatchModel model;
  model.points        = {{{0., 0., ring_radius}}};
  const auto one_mode = osc.modal_model();
  for (const auto &term : one_mode.terms())
    {
      BOOST_REQUIRE(term.kind == modal::ModalTerm::Kind::complex_pair);
      model.lambda.push_back(term.lambda);
      model.real.push_back(false);
      model.residues.push_back(Eigen::MatrixXcd::Constant(1, 1, term.residue));
    }
  model.errors      = Eigen::MatrixXd::Zero(1, 1);
  auto       conv   = convolution::make_modal_patch_convolution(model, dt);
  const auto flight = [&](const double t, double &u, double &v) {
    osc.free_motion(track.height(0.), 0., t, u, v);
  };
  const auto demand = [&](const double t, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
    double uf, vf;
    flight(t, uf, vf);
    d[0]  = track.height(t) - uf;
    dd[0] = track.velocity(t) - vf;
  };
  double     error   = 0.;
  const auto observe = [&](const contact::RollingStep &s) {
    double uf, vf;
    flight(s.time, uf, vf);
    error = std::max(error, std::abs(s.u[0] + uf - exact.displacement(s.time)));
  };
  const auto summary = contact::roll(*conv, demand, static_cast<unsigned int>(end_time / dt),
                                     Eigen::VectorXd(), observe);
  BOOST_TEST_MESSAGE("one point, one mode: max |u - u_exact| = " << error << " m");
  BOOST_TEST(error < 2.5e-9); // measured 7.9e-10 m, as the 1-DoF scene
  BOOST_TEST(std::abs(summary.impulse - exact.impulse(0., end_time)) <
             1e-6 * exact.impulse(0., end_time));
  BOOST_TEST(summary.failed_steps == 0u);
}

BOOST_AUTO_TEST_CASE(direct_and_modal_recursive_convolutions_agree)
{
  // The same patch on a sinusoid with both convolutions: the recursion is
  // exact, so the runs agree to round-off (far inside any fit error).
  const auto model = synthetic_patch();
  const auto c =
    compare_convolutions(model, 2e-5, 3000, sinusoid_demand(model, tread_height(model), 20., 2e-4));
  BOOST_TEST_MESSAGE("direct vs modal-recursive: max force difference " << c.difference << " N of "
                                                                        << c.peak << " N");
  check_converged(c.modal);
  check_converged(c.direct);
  BOOST_TEST(c.modal.min_contact_fraction < 1.); // the sinusoid lifts points off
  BOOST_TEST(c.modal.max_contact_fraction > 0.);
  // Measured 1.4e-14 of the peak: round-off, which differs between
  // machines and BLAS kernels, so 7 times that.
  BOOST_TEST(c.difference < 1e-13 * c.peak);
}

BOOST_AUTO_TEST_CASE(flat_road_from_the_static_equilibrium_stays_there)
{
  const auto            model = synthetic_patch();
  const Eigen::VectorXd tread = tread_height(model);
  const Eigen::MatrixXd G0    = model.static_compliance();
  const auto            eq    = contact::solve_static_contact(G0, -tread, 100., 0.);
  BOOST_TEST(std::abs(eq.q.sum() - 100.) < 1e-9 * 100.);
  // Complementarity of the static solution, measured here from G0, the
  // demand and the force (the force itself is non-negative by construction:
  // the solver returns its projection). Bounds: the pivoting solver's
  // tolerance, 1e-10 of the scale.
  const test::Complementarity c =
    test::complementarity(G0, -(-tread.array() + eq.delta).matrix(), eq.q);
  BOOST_TEST_MESSAGE("static contact: gap down to " << c.gap << ", complementarity " << c.natural
                                                    << " and " << c.product);
  BOOST_TEST(c.gap >= -2e-10);
  BOOST_TEST(c.natural <= 2e-10);
  BOOST_TEST(c.product <= 2e-10);
  BOOST_TEST(eq.n_contact < model.n_points()); // the tread's curvature lifts the ends

  auto       conv   = convolution::make_modal_patch_convolution(model, 1e-5);
  const auto demand = [&](double, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
    d  = (-tread.array() + eq.delta).matrix();
    dd = Eigen::VectorXd::Zero(d.size());
  };
  double     drift   = 0.;
  const auto observe = [&](const contact::RollingStep &s) {
    drift = std::max(drift, max_abs(s.force - eq.q));
  };
  const auto s = contact::roll(*conv, demand, 5000, eq.q, observe);
  BOOST_TEST_MESSAGE("flat road from equilibrium: largest force change " << drift << " N");
  BOOST_TEST(drift < 5e-14); // measured 5e-15 N of 100 N: round-off, which varies by machine
  check_converged(s);
}

BOOST_AUTO_TEST_CASE(slow_roll_follows_the_static_solution)
{
  // Over a 2 cm sinusoid at 5 and 1 cm/s (2.5 and 0.5 Hz against modes from
  // 120 Hz) the forces follow the static solution of each position; what is
  // left is the damping force, first order in the speed.
  const auto            model = synthetic_patch();
  const Eigen::VectorXd tread = tread_height(model);
  std::vector<double>   errors;
  for (const double V : {0.05, 0.01})
    {
      const auto r = slow_roll(model, tread, V, 1e-4);
      BOOST_TEST_MESSAGE("slow roll at " << V << " m/s: largest difference to the static "
                                         << "solution " << r.error << " N of " << r.peak << " N");
      check_converged(r.summary);
      BOOST_TEST(r.summary.min_contact_fraction <
                 r.summary.max_contact_fraction); // the active set moves
      errors.push_back(r.error / r.peak);
    }
  BOOST_TEST(errors[1] < 1e-3);
  // It falls with the speed (measured: 3.2 times for 5 times slower; the
  // start-up ringing also counts).
  BOOST_TEST(errors[0] / errors[1] > 2.);
}

BOOST_AUTO_TEST_CASE(multi_point_contact_with_a_real_residual_pole)
{
  // `Residual flexibility = real pole`: no G_r, the local compliance carried
  // by a first-order lag at 3 kHz (its static compliance the same matrix), so
  // the contact of a step is the iterative impulse rule of every point.
  // Checked on the 12 points against two references: the direct
  // convolution (to round-off) and, rolled slowly, the static solution of
  // each position.
  auto                  model = synthetic_patch(0.05, false);
  const double          fr    = 3000.;
  const Eigen::MatrixXd local = synthetic_patch().instantaneous;
  model.lambda.emplace_back(-2. * M_PI * fr, 0.);
  model.real.push_back(true);
  model.residues.push_back((2. * M_PI * fr * local).cast<std::complex<double>>());
  BOOST_TEST_REQUIRE(model.instantaneous.size() == 0);
  const Eigen::VectorXd tread = tread_height(model);

  // Direct against modal-recursive on a 2 cm sinusoid at 20 m/s.
  const auto c = compare_convolutions(model, 2e-5, 2000, sinusoid_demand(model, tread, 20., 2e-4));
  BOOST_TEST_MESSAGE("real residual pole, direct vs modal-recursive: "
                     << c.difference << " N of " << c.peak << " N; steps not converged "
                     << c.modal.failed_steps);
  // Known limit, reported and bounded here: at the impacts of this road the
  // iteration of the load shapes does not settle on 12 of the 2000 steps
  // (it cycles between two impact branches; README, 'Checks'). Those steps
  // keep their last non-negative iterate, identically in both runs.
  BOOST_TEST(c.modal.failed_steps == c.direct.failed_steps);
  BOOST_TEST(c.modal.failed_steps <= 20u);
  BOOST_TEST(c.modal.min_contact_fraction < 1.);
  BOOST_TEST(c.modal.max_contact_fraction > 0.);
  BOOST_TEST(c.difference < 1e-9 * c.peak);

  // Slowly (1 cm/s) over one wavelength from the static contact: the forces
  // of each step are the static solution of its position.
  const auto r = slow_roll(model, tread, 0.01, 1e-4);
  BOOST_TEST_MESSAGE("real residual pole, slow roll: largest difference to the static solution "
                     << r.error << " N of " << r.peak << " N");
  check_converged(r.summary);
  BOOST_TEST(r.summary.min_contact_fraction < r.summary.max_contact_fraction);
  BOOST_TEST(r.error < 1e-2 * r.peak);
}

BOOST_AUTO_TEST_CASE(impulse_is_static_load_times_duration_after_the_start)
{
  // Dropped onto a flat road at a fixed indentation from rest (an impact
  // start), the patch rings down to the static solution: after the
  // start-up, the impulse is the static load times the time.
  const auto            model = synthetic_patch();
  const Eigen::VectorXd tread = tread_height(model);
  const auto         eq = contact::solve_static_contact(model.static_compliance(), -tread, 80., 0.);
  const double       dt = 2e-5, t_settle = 0.2;
  const unsigned int n_steps = 20000; // 0.4 s; the slowest mode decays in 1/(0.05 * 2 pi 120 Hz)
  const auto         demand  = [&](double, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
    d  = (-tread.array() + eq.delta).matrix();
    dd = Eigen::VectorXd::Zero(d.size());
  };
  double     late_impulse = 0., first_peak = 0.;
  const auto observe = [&](const contact::RollingStep &s) {
    if (s.time > t_settle)
      late_impulse += s.force.sum() * dt;
    else
      first_peak = std::max(first_peak, s.force.sum());
  };
  auto         conv     = convolution::make_modal_patch_convolution(model, dt);
  const auto   s        = contact::roll(*conv, demand, n_steps, Eigen::VectorXd(), observe);
  const double expected = 80. * (n_steps * dt - t_settle);
  BOOST_TEST_MESSAGE("impulse after the start-up " << late_impulse << " N s, static load times "
                                                   << "duration " << expected
                                                   << " N s; start-up peak " << first_peak << " N");
  check_converged(s);
  BOOST_TEST(first_peak > 80.); // there was a transient to settle
  BOOST_TEST(std::abs(late_impulse - expected) < 1e-4 * expected);
}

BOOST_AUTO_TEST_CASE(stiff_and_extreme_cases_stay_sound)
{
  // A patch on a synthetic road-A texture, envelope sampling as in the
  // scene, under the extremes of patch_rolling.h.
  const auto                        model = synthetic_patch(0.02);
  const Eigen::VectorXd             tread = tread_height(model);
  std::vector<road::WavelengthBand> bands;
  std::vector<double>               levels;
  road::texture_preset("road-A", bands, levels);
  const double  spacing = 3.84e-4;
  road::Texture texture = road::synthetic_texture(bands, levels, spacing, 2048, 96, 7);

  test::RollingCase base; // 100 N over 30 cm at 90 km/h, one road sample per step
  base.load     = 100.;
  base.distance = 0.3;
  // Measured at most 1.2e-7 of the displacement change (dt = 20 samples).
  test::check_extreme_cases(model, tread, texture, base, 0.3, 3.5e-7);
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused)
{
  const auto model = synthetic_patch();
  BOOST_CHECK_THROW(convolution::make_modal_patch_convolution(model, 0.), InputError);
  BOOST_CHECK_THROW(convolution::make_modal_patch_convolution(model, NAN), InputError);
  auto       conv   = convolution::make_modal_patch_convolution(model, 1e-5);
  const auto demand = [&](double, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
    d  = Eigen::VectorXd::Constant(d.size(), NAN);
    dd = Eigen::VectorXd::Zero(d.size());
  };
  BOOST_CHECK_THROW(contact::roll(*conv, demand, 3, Eigen::VectorXd(), {}), NumericalError);
  BOOST_CHECK_THROW(contact::roll(*conv, demand, 3, Eigen::VectorXd::Zero(5), {}), InputError);
  // A static load no indentation can carry (no point can reach the road).
  BOOST_CHECK_THROW(
    contact::solve_static_contact(Eigen::MatrixXd::Zero(2, 2), Eigen::VectorXd::Zero(2), 10., 0.),
    NumericalError);
}

BOOST_AUTO_TEST_SUITE_END()
