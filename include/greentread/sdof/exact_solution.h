#pragma once

#include <greentread/road/road_profile.h>
#include <greentread/sdof/oscillator.h>

#include <vector>

namespace greentread
{
  namespace sdof
  {
    /**
     * @brief The exact solution of the 1-DoF contact problem of Section 3,
     * piecewise in closed form: the reference every error is measured against.
     *
     * - Free flight: Eq. (35), with gravity (Oscillator::free_motion()).
     * - Contact: u = u_r, so F = M a_r + C v_r + K u_r + M g.
     * - Impact (flight reaches the road while approaching it): perfectly
     *   plastic, the velocity jumps to the road's, impulse M (v_r - v).
     *   Contact follows if F > 0 just after, otherwise flight resumes.
     * - Lift-off: where F would turn negative.
     *
     * Event times are bracketed on a scan with a step of 1/64 of the shortest
     * period (oscillator or road), with dips between two samples found from
     * the sign change of the derivative, and then located with TOMS 748
     * (Boost.Math) to round-off. A flight that only grazes the road by less
     * than a relative 64 epsilon is not an impact.
     *
     * The initial state is u(0) = u_r(0), v(0) = 0 (Eqs. 33-34).
     */
    class ExactSolution
    {
    public:
      /**
       * @param[in] road The road under the mass; its profile must outlive
       * this object.
       * @throws NumericalError if more than 10^6 events are found (a Zeno
       * sequence of impacts).
       */
      ExactSolution(const Oscillator &oscillator, const road::RoadTrack &road, double end_time);

      /// u(t) [m] and v(t) [m/s] (just after any impact at t).
      void
      state(double t, double &u, double &v) const;

      /// u(t) [m].
      double
      displacement(double t) const;

      /// v(t) [m/s], just after any impact at t.
      double
      velocity(double t) const;

      /// Contact force F(t) [N] outside impacts (0 in flight).
      double
      contact_force(double t) const;

      /// Whether the mass is on the road at t.
      bool
      in_contact(double t) const;

      /// \f$\int F\,dt\f$ over \f$(t_a, t_b]\f$, impacts included [N s].
      double
      impulse(double t_a, double t_b) const;

      /// Whether an impact happens in \f$(t_a, t_b]\f$ (or at t = 0 = t_a).
      bool
      has_impact(double t_a, double t_b) const;

      /// Total time spent in contact [s].
      double
      contact_time() const;

      /// Number of impacts up to the end time.
      unsigned int
      n_impacts() const
      {
        return static_cast<unsigned int>(impacts.size());
      }

      /// Number of phases (contact or flight).
      unsigned int
      n_phases() const
      {
        return static_cast<unsigned int>(phases.size());
      }

      /// The largest smooth contact force reached [N].
      double
      max_contact_force() const;

    private:
      struct Phase
      {
        double t_begin;
        double t_end;
        bool   contact;
        double u0, v0; // state at t_begin (after any impact)
      };
      struct Impact
      {
        double t;
        double impulse;
      };

      // Copies: small value types (the track refers to its profile, which
      // must outlive this object).
      const Oscillator      oscillator;
      const road::RoadTrack road;
      double                end_time;
      std::vector<Phase>    phases;
      std::vector<Impact>   impacts;

      double
      force_in_contact(double t) const;

      const Phase &
      phase_at(double t) const;

      /// First time in (t0, end] where contact force turns negative.
      double
      find_lift_off(double t0) const;

      /// First time in (t0, end] where the flight from (u0,v0) reaches the road.
      double
      find_impact(double t0, double u0, double v0) const;

      double scan_step;
      double gap_tolerance;
      /// 12-point Gauss-Legendre on [0,1] for the contact impulse.
      std::vector<std::pair<double, double>> gauss;
    };
  } // namespace sdof
} // namespace greentread
