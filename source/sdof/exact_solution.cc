#include <greentread/base/exceptions.h>
#include <greentread/sdof/exact_solution.h>

#include <deal.II/base/quadrature_lib.h>

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace greentread
{
  namespace sdof
  {
    namespace
    {
      /// The root of f in [a, b] (f(a), f(b) of opposite sign or zero) to
      /// round-off, by TOMS 748. Returns the end of the final bracket where f
      /// has the sign of f(b), so that the event has surely happened there.
      template <typename F>
      double
      locate(const F &f, double a, double b)
      {
        const double fa = f(a), fb = f(b);
        if (fb == 0.)
          return b;
        if (fa == 0.)
          return a;
        std::uintmax_t iterations = 200;
        const auto     bracket    = boost::math::tools::toms748_solve(
                 f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(52), iterations);
        return bracket.second;
      }

      /// The minimum of f in [a, b] given f'(a) < 0 < f'(b), located on f'.
      template <typename DF>
      double
      locate_minimum(const DF &df, double a, double b)
      {
        std::uintmax_t iterations = 200;
        const auto     bracket    = boost::math::tools::toms748_solve(
                 df, a, b, boost::math::tools::eps_tolerance<double>(52), iterations);
        return 0.5 * (bracket.first + bracket.second);
      }
    } // namespace



    ExactSolution::ExactSolution(const Oscillator      &oscillator_,
                                 const road::RoadTrack &road_,
                                 const double           end_time_)
        : oscillator(oscillator_)
        , road(road_)
        , end_time(end_time_)
    {
      const double period_oscillator =
        2. * M_PI / oscillator.natural_frequency() / std::max(1., oscillator.damping_ratio());
      const double period_road = road.profile.shortest_wavelength() / road.speed;
      scan_step                = std::min(period_oscillator, period_road) / 64.;
      const dealii::QGauss<1> rule(12);
      for (unsigned int q = 0; q < rule.size(); ++q)
        gauss.emplace_back(rule.point(q)[0], rule.weight(q));
      gap_tolerance = 64. * std::numeric_limits<double>::epsilon() *
                      (road.profile.amplitude() + std::abs(oscillator.static_deflection()) +
                       road.speed * end_time * 1e-6 + 1e-9);

      // Initial state, Eqs. (33)-(34).
      double t = 0., u = road.height(0.), v = 0.;
      while (t < end_time)
        {
          if (phases.size() > 1000000)
            throw NumericalError("exact 1-DoF solution: more than 10^6 contact events before t = " +
                                 format_short(t) + " s (a Zeno sequence of impacts?)");

          // On the road: a plastic impact if the road moves up faster.
          const bool on_road = std::abs(u - road.height(t)) <= gap_tolerance;
          if (on_road && v < road.velocity(t))
            {
              impacts.push_back({t, oscillator.mass() * (road.velocity(t) - v)});
              u = road.height(t);
              v = road.velocity(t);
            }
          const bool contact = on_road && v == road.velocity(t) && force_in_contact(t) > 0.;
          if (contact)
            {
              const double t_lift = find_lift_off(t);
              phases.push_back({t, t_lift, true, road.height(t), road.velocity(t)});
              t = t_lift;
              u = road.height(t);
              v = road.velocity(t);
            }
          else
            {
              const double t_hit = find_impact(t, u, v);
              phases.push_back({t, t_hit, false, u, v});
              double u1, v1;
              oscillator.free_motion(u, v, t_hit - t, u1, v1);
              t = t_hit;
              u = road.height(t); // the impact sets u exactly on the road
              v = v1;
            }
        }
    }



    double
    ExactSolution::force_in_contact(const double t) const
    {
      return oscillator.mass() * road.acceleration(t) + oscillator.damping() * road.velocity(t) +
             oscillator.stiffness() * road.height(t) + oscillator.mass() * oscillator.gravity();
    }



    double
    ExactSolution::find_lift_off(const double t0) const
    {
      const auto force = [&](double t) {
        return force_in_contact(t);
      };
      const auto rate = [&](double t) {
        return oscillator.mass() * road.jerk(t) + oscillator.damping() * road.acceleration(t) +
               oscillator.stiffness() * road.velocity(t);
      };
      for (double a = t0; a < end_time;)
        {
          const double b = std::min(a + scan_step, end_time);
          if (force(b) < 0.)
            return locate(force, a, b);
          if (rate(a) < 0. && rate(b) > 0.)
            {
              const double m = locate_minimum(rate, a, b);
              if (force(m) < 0.)
                return locate(force, a, m);
            }
          a = b;
        }
      return end_time;
    }



    double
    ExactSolution::find_impact(const double t0, const double u0, const double v0) const
    {
      const auto gap = [&](double t) {
        double u, v;
        oscillator.free_motion(u0, v0, t - t0, u, v);
        return u - road.height(t);
      };
      const auto gap_rate = [&](double t) {
        double u, v;
        oscillator.free_motion(u0, v0, t - t0, u, v);
        return v - road.velocity(t);
      };
      for (double a = t0; a < end_time;)
        {
          const double b = std::min(a + scan_step, end_time);
          if (gap(b) < -gap_tolerance)
            return locate(gap, a, b);
          if (gap_rate(a) < 0. && gap_rate(b) > 0.)
            {
              const double m = locate_minimum(gap_rate, a, b);
              if (m > t0 && gap(m) < -gap_tolerance)
                return locate(gap, a, m);
            }
          a = b;
        }
      return end_time;
    }



    const ExactSolution::Phase &
    ExactSolution::phase_at(const double t) const
    {
      // The last phase that begins at or before t.
      auto it = std::upper_bound(phases.begin(), phases.end(), t, [](double time, const Phase &p) {
        return time < p.t_begin;
      });
      if (it != phases.begin())
        --it;
      return *it;
    }



    void
    ExactSolution::state(const double t, double &u, double &v) const
    {
      const Phase &p = phase_at(t);
      if (p.contact)
        road.height_and_velocity(t, u, v);
      else
        oscillator.free_motion(p.u0, p.v0, t - p.t_begin, u, v);
    }



    double
    ExactSolution::displacement(const double t) const
    {
      double u, v;
      state(t, u, v);
      return u;
    }



    double
    ExactSolution::velocity(const double t) const
    {
      double u, v;
      state(t, u, v);
      return v;
    }



    double
    ExactSolution::contact_force(const double t) const
    {
      return phase_at(t).contact ? force_in_contact(t) : 0.;
    }



    bool
    ExactSolution::in_contact(const double t) const
    {
      return phase_at(t).contact;
    }



    double
    ExactSolution::impulse(const double t_a, const double t_b) const
    {
      double total = 0.;
      // An impact at t = 0 belongs to the first step, (0, dt] (see has_impact()).
      for (const auto &i : impacts)
        if ((i.t > t_a || (i.t == 0. && t_a == 0.)) && i.t <= t_b)
          total += i.impulse;

      // Only the phases that overlap (t_a, t_b]: binary search for the first.
      auto first =
        std::upper_bound(phases.begin(), phases.end(), t_a, [](double time, const Phase &p) {
          return time < p.t_end;
        });
      for (auto p = first; p != phases.end() && p->t_begin < t_b; ++p)
        {
          if (!p->contact)
            continue;
          const double a = std::max(p->t_begin, t_a), b = std::min(p->t_end, t_b);
          if (b <= a)
            continue;
          for (const auto &[x, w] : gauss)
            total += w * (b - a) * force_in_contact(a + x * (b - a));
        }
      return total;
    }



    bool
    ExactSolution::has_impact(const double t_a, const double t_b) const
    {
      for (const auto &i : impacts)
        if ((i.t > t_a || (i.t == 0. && t_a == 0.)) && i.t <= t_b)
          return true;
      return false;
    }



    double
    ExactSolution::contact_time() const
    {
      double total = 0.;
      for (const auto &p : phases)
        if (p.contact)
          total += std::min(p.t_end, end_time) - p.t_begin;
      return total;
    }



    double
    ExactSolution::max_contact_force() const
    {
      double largest = 0.;
      for (const auto &p : phases)
        if (p.contact)
          for (unsigned int i = 0; i <= 64; ++i)
            largest =
              std::max(largest, force_in_contact(p.t_begin + (p.t_end - p.t_begin) * i / 64.));
      return largest;
    }
  } // namespace sdof
} // namespace greentread
