#pragma once

// Shared set-up for the unit tests: the paper's 1-DoF problem (Table A.1,
// Section 3) with a few parameters changed.

#include <greentread/contact/contact_parameters.h>
#include <greentread/road/road_profile.h>
#include <greentread/sdof/oscillator.h>

#include <boost/numeric/odeint.hpp>

#include <array>
#include <functional>

namespace test
{
  inline greentread::sdof::OscillatorParameters
  oscillator_parameters(double damping_ratio = 0.02, double speed = 0.1)
  {
    greentread::sdof::OscillatorParameters p;
    p.mass          = 1.;
    p.stiffness     = 4e5;
    p.damping_ratio = damping_ratio;
    p.gravity       = 9.81;
    p.speed         = speed;
    return p;
  }

  inline greentread::contact::ContactParameters
  contact_parameters(
    double                          dt,
    double                          end_time = 0.2,
    greentread::contact::ContactLaw law      = greentread::contact::ContactLaw::kinematic,
    double                          kc       = 1e7)
  {
    greentread::contact::ContactParameters p;
    p.law               = law;
    p.contact_stiffness = kc;
    p.time_step         = dt;
    p.end_time          = end_time;
    return p;
  }

  /**
   * Independent reference: integrate M u'' + C u' + K u = f(t) from (u0, v0)
   * over [t0, t1] with Boost.Odeint's adaptive Dormand-Prince 5(4) at
   * tolerances near round-off.
   */
  inline std::array<double, 2>
  integrate(const greentread::sdof::Oscillator  &osc,
            const std::function<double(double)> &force,
            double                               u0,
            double                               v0,
            double                               t0,
            double                               t1)
  {
    using State = std::array<double, 2>;
    State      x{{u0, v0}};
    const auto rhs = [&](const State &y, State &dy, double t) {
      dy[0] = y[1];
      dy[1] = (force(t) - osc.damping() * y[1] - osc.stiffness() * y[0]) / osc.mass();
    };
    namespace odeint = boost::numeric::odeint;
    auto stepper     = odeint::make_controlled(1e-14, 1e-14, odeint::runge_kutta_dopri5<State>());
    odeint::integrate_adaptive(stepper, rhs, x, t0, t1, (t1 - t0) / 1000.);
    return x;
  }
} // namespace test
