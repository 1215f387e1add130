// The impact rule on its own: for an approach whose impact time is known,
// the rule's load is non-negative and meets both conditions exactly.
#include <greentread/contact/kinematic_contact.h>
#include <greentread/convolution/modal_recursive_convolution.h>
#include <greentread/sdof/oscillator.h>

#include <boost/test/unit_test.hpp>

#include "test_helpers.h"

using namespace greentread;
using contact::KinematicBranch;

BOOST_AUTO_TEST_SUITE(kinematic_rule)

BOOST_AUTO_TEST_CASE(branches_follow_the_impact_time)
{
  const sdof::Oscillator                       osc(test::oscillator_parameters());
  const double                                 dt = 1e-5;
  const convolution::ModalRecursiveConvolution conv(osc.modal_model(), dt);
  const auto                                  &psi = conv.influence();

  // A point hitting the road at tau before the step end with approach speed
  // dv leaves du = dv * tau to make up.
  const double dv = 0.3;
  struct Case
  {
    double          tau_over_dt;
    KinematicBranch expected;
  };
  for (const Case c :
       {Case{0.05, KinematicBranch::impact_late}, Case{0.2, KinematicBranch::impact_late},
        Case{0.5, KinematicBranch::riding}, Case{0.8, KinematicBranch::impact_early},
        Case{0.99, KinematicBranch::impact_early}})
    {
      const double du   = dv * c.tau_over_dt * dt;
      const auto   step = contact::solve_kinematic_step(psi, du, dv);
      const auto   r    = psi.of(step.load);
      BOOST_TEST_CONTEXT("tau / dt = " << c.tau_over_dt)
      {
        BOOST_TEST((step.branch == c.expected));
        // The loads are stored non-negative (kinematic_contact.cc clamps
        // them), so their sign is not asserted: that the clamp took nothing
        // away shows in both end conditions being met.
        BOOST_TEST(std::abs(r.u - du) < 1e-12 * du);
        BOOST_TEST(std::abs(r.v - dv) < 1e-12 * dv);
        // The impulse delivered is the momentum to remove, M dv, to first order.
        BOOST_TEST(std::abs(step.load.impulse(dt) - osc.mass() * dv) < 0.01 * osc.mass() * dv);
      }
    }
}

BOOST_AUTO_TEST_CASE(riding_with_a_constant_force)
{
  // Riding with relative acceleration a: du = a dt^2 / 2, dv = a dt, the
  // paper's two Gauss forces both equal M a.
  const sdof::Oscillator                       osc(test::oscillator_parameters());
  const double                                 dt = 1e-6;
  const convolution::ModalRecursiveConvolution conv(osc.modal_model(), dt);
  const double                                 a = 20.;
  const auto step = contact::solve_kinematic_step(conv.influence(), a * dt * dt / 2., a * dt);
  BOOST_TEST((step.branch == KinematicBranch::riding));
  BOOST_TEST(step.load.start == osc.mass() * a, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(step.load.end == osc.mass() * a, boost::test_tools::tolerance(1e-3));
}

BOOST_AUTO_TEST_CASE(separating_while_penetrating_falls_back)
{
  // Penetrating but already moving up faster than the road: no non-negative
  // load meets both; the displacement is restored by an impulse at t_n.
  const sdof::Oscillator                       osc(test::oscillator_parameters());
  const convolution::ModalRecursiveConvolution conv(osc.modal_model(), 1e-5);
  const auto step = contact::solve_kinematic_step(conv.influence(), 1e-9, -1e-3);
  BOOST_TEST((step.branch == KinematicBranch::fallback));
  BOOST_TEST(step.load.impulse_start > 0.);
  BOOST_TEST(std::abs(conv.influence().of(step.load).u - 1e-9) < 1e-21);
}

BOOST_AUTO_TEST_SUITE_END()
