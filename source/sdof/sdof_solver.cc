#include <greentread/base/exceptions.h>
#include <greentread/base/progress.h>
#include <greentread/contact/contact_law.h>
#include <greentread/sdof/sdof_solver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

namespace greentread
{
  namespace sdof
  {
    std::unique_ptr<convolution::Convolution>
    make_convolution(const Oscillator                         &oscillator,
                     const convolution::ConvolutionParameters &parameters,
                     const double                              dt,
                     const unsigned int                        n_steps,
                     const modal::ModalModel                  *model)
    {
      if (model)
        return convolution::create(parameters, *model, dt, n_steps);
      // The oscillator's own: its closed-form g(t) for the direct method.
      const convolution::ImpulseResponse exact{[&oscillator](double t) {
                                                 return oscillator.green(t);
                                               },
                                               [&oscillator](double t) {
                                                 return oscillator.green_derivative(t);
                                               },
                                               oscillator.natural_frequency() *
                                                 (oscillator.damping_ratio() + 1.)};
      return convolution::create(parameters, oscillator.modal_model(), dt, n_steps, &exact);
    }



    IdentifiedGreen
    identify_green(const Oscillator                      &oscillator,
                   const OscillatorParameters            &parameters,
                   const modal::IdentificationParameters &identification)
    {
      auto frf =
        frequency_response(oscillator, parameters.frf_max_frequency, parameters.frf_line_spacing);
      auto       identified = modal::identify(frf, identification);
      const auto exact      = oscillator.modal_model().terms()[0].lambda;
      double     pole_error = INFINITY;
      for (const auto &term : identified.model.terms())
        pole_error = std::min(pole_error, std::abs(term.lambda - exact) / std::abs(exact));
      return {std::move(frf), std::move(identified), pole_error};
    }



    base::FrequencyResponse
    frequency_response(const Oscillator &oscillator, const double f_max, const double df)
    {
      base::FrequencyResponse frf;
      frf.df               = df;
      const unsigned int n = static_cast<unsigned int>(std::llround(f_max / df)) + 1;
      for (unsigned int k = 0; k < n; ++k)
        frf.values.push_back(oscillator.frequency_response(2. * M_PI * k * df));
      return frf;
    }



    SdofRun
    solve(const Oscillator                 &oscillator,
          const road::RoadTrack            &road,
          convolution::Convolution         &convolution,
          const contact::ContactParameters &contact,
          const bool                        show_progress)
    {
      using convolution::Response;
      using convolution::StepLoad;

      const double       dt      = convolution.time_step();
      const unsigned int n_steps = contact.n_steps();
      const double       weight  = oscillator.mass() * oscillator.gravity();
      const auto        &psi     = convolution.influence();
      // No physical motion of this problem leaves the band of the road's
      // amplitude, the static deflection and the swing that the road's
      // fastest motion can launch (an elastic bounce at most doubles it); ten
      // times that band means the time integration has diverged.
      double road_speed = 0.;
      for (unsigned int i = 0; i < 64; ++i)
        road_speed = std::max(
          road_speed,
          std::abs(road.velocity(i * road.profile.shortest_wavelength() / (64. * road.speed))));
      const double bound =
        10. * (road.profile.amplitude() + std::abs(oscillator.static_deflection()) +
               road_speed / oscillator.natural_frequency()) +
        1e-9;

      // The convolution starts from rest at u = 0, which is Eq. (33),
      // u(0) = u_r(0), only for a road that starts at height 0.
      if (std::abs(road.height(0.)) > 1e-12 * std::max(road.profile.amplitude(), 1e-300))
        throw InputError("the 1-DoF scene starts from rest at u(0) = u_r(0) = 0, but the road "
                         "starts at height " +
                         format_short(road.height(0.)) + " m");

      SdofRun run;
      run.time_step = dt;
      run.method    = convolution.name();
      run.size      = convolution.size();
      for (auto *x : {&run.t, &run.u, &run.v, &run.F})
        x->resize(n_steps + 1);
      for (auto *x : {&run.u_start, &run.v_start, &run.v_end})
        x->resize(n_steps);
      run.t[0] = 0.;
      run.u[0] = road.height(0.);
      run.v[0] = 0.;
      run.F[0] = 0.;

      const auto law = contact::create(contact, psi, oscillator.stiffness(), oscillator.mass());
      const convolution::StepLoad gravity{0., -weight, -weight, 0.};
      base::Progress              progress("sdof time steps", n_steps);
      const auto                  start = std::chrono::steady_clock::now();

      for (unsigned int n = 0; n < n_steps; ++n)
        {
          const double                t1      = (n + 1) * dt;
          const convolution::Response history = convolution.history();
          double                      ur, vr;
          road.height_and_velocity(t1, ur, vr);

          const contact::ContactStep  step = law->step(history, gravity, ur, vr);
          const convolution::StepLoad load = step.load;
          if (step.branch >= 0)
            {
              ++run.branch_count[static_cast<unsigned int>(step.branch)];
              run.branches = true;
            }

          convolution::StepLoad total = gravity;
          total += load;
          convolution.advance(total);

          const convolution::Response total_response = psi.of(total);
          const convolution::Response state          = {history.u + total_response.u,
                                                        history.v + total_response.v};
          convolution::StepLoad       before_end     = total;
          before_end.impulse_end                     = 0.;
          run.u_start[n]                             = run.u[n] + psi.u[3] * total.impulse_start;
          run.v_start[n]                             = run.v[n] + psi.v[3] * total.impulse_start;
          run.v_end[n]                               = history.v + psi.of(before_end).v;
          run.t[n + 1]                               = t1;
          run.u[n + 1]                               = state.u;
          run.v[n + 1]                               = state.v;
          run.F[n + 1]                               = load.impulse(dt) / dt;
          if (load.impulse(dt) > 0.)
            ++run.contact_steps;

          if (!std::isfinite(state.u) || !std::isfinite(state.v) || std::abs(state.u) > bound)
            {
              const std::string hint = law->divergence_hint(dt);
              throw NumericalError("the 1-DoF run diverged at t = " + format_short(t1) +
                                   " s (step " + std::to_string(n + 1) +
                                   "): |u| = " + format_short(std::abs(state.u)) + " m exceeds " +
                                   format_short(bound) +
                                   " m, ten times the largest physical swing." + hint);
            }
          if (show_progress)
            progress.update(n + 1);
        }
      run.run_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (show_progress)
        progress.finish();
      return run;
    }



    SdofErrors
    compare(const SdofRun &run, const ExactSolution &exact, const road::RoadTrack &road)
    {
      SdofErrors         e;
      const double       dt      = run.time_step;
      const unsigned int N       = static_cast<unsigned int>(run.t.size()) - 1;
      double             impulse = 0., exact_impulse = 0.;
      for (unsigned int n = 0; n <= N; ++n)
        {
          const double t = run.t[n];
          e.max_u_error  = std::max(e.max_u_error, std::abs(run.u[n] - exact.displacement(t)));
          // v[0] = 0 is the initial state, before the impact at t = 0.
          if (n > 0)
            e.max_v_error = std::max(e.max_v_error, std::abs(run.v[n] - exact.velocity(t)));
          e.max_penetration_grid = std::max(e.max_penetration_grid, road.height(t) - run.u[n]);
          if (n == 0)
            continue;
          const double step_impulse = exact.impulse(run.t[n - 1], t);
          // An impact's impulse is compared through the total impulse; the
          // force of its step (impulse / dt) says nothing about accuracy.
          if (!exact.has_impact(run.t[n - 1], t))
            e.max_force_error = std::max(e.max_force_error, std::abs(run.F[n] - step_impulse / dt));
          impulse += run.F[n] * dt;
          exact_impulse += step_impulse;

          // Inside the step: the cubic Hermite interpolant of the numerical
          // motion, which is smooth between the end impulses.
          const double u0 = run.u_start[n - 1], v0 = run.v_start[n - 1];
          const double u1 = run.u[n], v1 = run.v_end[n - 1];
          for (unsigned int k = 1; k < 10; ++k)
            {
              const double s   = k / 10.;
              const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
              const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
              const double u = h00 * u0 + h10 * dt * v0 + h01 * u1 + h11 * dt * v1;
              e.max_penetration_step =
                std::max(e.max_penetration_step, road.height(run.t[n - 1] + s * dt) - u);
            }
        }
      e.max_penetration_step = std::max(e.max_penetration_step, e.max_penetration_grid);
      e.impulse_error        = std::abs(impulse - exact_impulse) / std::max(exact_impulse, 1e-300);
      e.contact_fraction     = double(run.contact_steps) / N;
      e.exact_contact_fraction = exact.contact_time() / run.t[N];
      e.peak_contact_force     = exact.max_contact_force();
      return e;
    }



    SdofOutcome
    simulate(const OscillatorParameters               &oscillator_parameters,
             const road::RoadProfile                  &road,
             const contact::ContactParameters         &contact,
             const convolution::ConvolutionParameters &convolution,
             const bool                                show_progress,
             const modal::ModalModel                  *model)
    {
      const Oscillator      oscillator(oscillator_parameters);
      const road::RoadTrack track{road, oscillator_parameters.speed, 0.};
      auto                  conv =
        make_convolution(oscillator, convolution, contact.time_step, contact.n_steps(), model);
      SdofOutcome outcome;
      outcome.run = solve(oscillator, track, *conv, contact, show_progress);
      const ExactSolution exact(oscillator, track, contact.n_steps() * contact.time_step);
      outcome.errors        = compare(outcome.run, exact, track);
      outcome.exact_impacts = exact.n_impacts();
      for (const double u : outcome.run.u)
        outcome.max_abs_u = std::max(outcome.max_abs_u, std::abs(u));
      return outcome;
    }
  } // namespace sdof
} // namespace greentread
