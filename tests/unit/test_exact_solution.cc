// The exact piecewise solution is checked against what defines it: in
// flight it solves the ODE (Odeint), it never goes below the road, in contact
// the force is non-negative, and at each event the right quantity vanishes.
#include <greentread/sdof/exact_solution.h>

#include <boost/test/unit_test.hpp>

#include "test_helpers.h"

using namespace greentread;

namespace
{
  void
  check_invariants(const sdof::Oscillator &osc, const road::RoadTrack &track, double end)
  {
    const sdof::ExactSolution exact(osc, track, end);
    const double              tol      = 1e-13;
    unsigned int              changes  = 0;
    bool                      previous = exact.in_contact(0.);
    for (unsigned int i = 0; i <= 200000; ++i)
      {
        const double t = end * i / 200000.;
        const double u = exact.displacement(t);
        BOOST_REQUIRE(std::isfinite(u));
        BOOST_REQUIRE(u >= track.height(t) - tol);
        // In contact, u is the road's height by construction; the force is not.
        if (exact.in_contact(t))
          BOOST_REQUIRE(exact.contact_force(t) >= -1e-6);
        changes += exact.in_contact(t) != previous;
        previous = exact.in_contact(t);
      }
    BOOST_TEST_MESSAGE(exact.n_phases() << " phases, " << exact.n_impacts() << " impacts, "
                                        << changes << " changes seen on the sampling grid");
  }
} // namespace

BOOST_AUTO_TEST_SUITE(exact_solution)

BOOST_AUTO_TEST_CASE(flight_between_events_solves_the_ode)
{
  // The state at a time inside a flight phase, integrated by Odeint from the
  // lift-off state, matches the closed form.
  const sdof::Oscillator    osc(test::oscillator_parameters());
  const road::Sinusoid      road(5e-3, 1e-2);
  const road::RoadTrack     track{road, 0.1, 0.};
  const sdof::ExactSolution exact(osc, track, 0.2);
  // Lift-off near t = 0.050015 s; follow the flight for 40 ms.
  double t0 = 0.05;
  while (exact.in_contact(t0))
    t0 += 1e-7;
  const auto ref = test::integrate(
    osc,
    [&](double) {
      return -osc.mass() * osc.gravity();
    },
    exact.displacement(t0), exact.velocity(t0), t0, t0 + 0.04);
  BOOST_TEST(std::abs(exact.displacement(t0 + 0.04) - ref[0]) < 1e-12);
  BOOST_TEST(std::abs(exact.velocity(t0 + 0.04) - ref[1]) < 1e-9);
}

BOOST_AUTO_TEST_CASE(events_of_the_default_problem)
{
  const sdof::Oscillator    osc(test::oscillator_parameters());
  const road::Sinusoid      road(5e-3, 1e-2);
  const road::RoadTrack     track{road, 0.1, 0.};
  const sdof::ExactSolution exact(osc, track, 0.2);
  // Impact at t = 0 (road rising at 0.314 m/s under a mass at rest),
  // lift-off where F = 0 just after the road crosses zero, flight, impact.
  BOOST_TEST(exact.n_impacts() == 3u);
  BOOST_TEST(exact.impulse(0., 1e-6) >= 0.314159 * osc.mass());
  // Lift-off: F(t) = A0 [(K - M w^2) sin wt + C w cos wt] + M g = 0, w = 2 pi V0 / lambda.
  const double w      = 2. * M_PI * 10.;
  const double R      = 5e-3 * std::hypot(4e5 - w * w, osc.damping() * w);
  const double phase  = std::atan2(osc.damping() * w, 4e5 - w * w);
  const double t_lift = (M_PI + std::asin(osc.mass() * osc.gravity() / R) - phase) / w;
  BOOST_TEST(exact.in_contact(t_lift - 1e-9));
  BOOST_TEST(!exact.in_contact(t_lift + 1e-9));
  check_invariants(osc, track, 0.2);
}

BOOST_AUTO_TEST_CASE(every_damping_regime_and_a_flying_road)
{
  const road::Sinusoid road(5e-3, 1e-2);
  for (const double xi : {0., 1., 2.})
    {
      const sdof::Oscillator osc(test::oscillator_parameters(xi));
      check_invariants(osc, {road, 0.1, 0.}, 0.2);
    }
  // V0 = 1 m/s: the road's acceleration (1974 m/s^2) throws the mass off
  // every crest; contact only over part of each period.
  const sdof::Oscillator    osc(test::oscillator_parameters());
  const road::RoadTrack     fast{road, 1., 0.};
  const sdof::ExactSolution exact(osc, fast, 0.05);
  BOOST_TEST(exact.n_impacts() >= 4u);
  BOOST_TEST(exact.contact_time() / 0.05 < 0.5);
  check_invariants(osc, fast, 0.05);
}

BOOST_AUTO_TEST_CASE(flat_road_rests)
{
  // A0 = 0: the mass rests on the road, F = M g, one contact phase.
  const sdof::Oscillator    osc(test::oscillator_parameters());
  const road::Sinusoid      road(0., 1e-2);
  const sdof::ExactSolution exact(osc, {road, 0.1, 0.}, 0.2);
  BOOST_TEST(exact.n_phases() == 1u);
  BOOST_TEST(exact.n_impacts() == 0u);
  BOOST_TEST(exact.contact_force(0.1) == osc.mass() * osc.gravity());
  BOOST_TEST(exact.impulse(0., 0.2) == 0.2 * osc.mass() * osc.gravity(),
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
