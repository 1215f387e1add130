#pragma once

#include <greentread/road/road_parameters.h>

/**
 * @file
 * Road profiles: the height of a rigid road along the rolling direction.
 */

namespace greentread
{
  namespace road
  {
    /**
     * @brief A road height \f$u^r(x)\f$ along the rolling direction x, with
     * its first three derivatives (the exact 1-DoF reference needs them).
     */
    class RoadProfile
    {
    public:
      virtual ~RoadProfile() = default;

      /// Height [m] at x [m].
      virtual double
      height(double x) const = 0;

      /// \f$d u^r / dx\f$.
      virtual double
      slope(double x) const = 0;

      /// Height and slope at once (one call per time step in the solvers).
      virtual void
      height_and_slope(double x, double &height_value, double &slope_value) const
      {
        height_value = height(x);
        slope_value  = slope(x);
      }

      /// \f$d^2 u^r / dx^2\f$ [1/m].
      virtual double
      curvature(double x) const = 0;

      /// \f$d^3 u^r / dx^3\f$ [1/m^2].
      virtual double
      third_derivative(double x) const = 0;

      /// The shortest wavelength in the profile [m], which sets how finely
      /// events have to be searched for.
      virtual double
      shortest_wavelength() const = 0;

      /// Largest |height| [m].
      virtual double
      amplitude() const = 0;
    };

    /**
     * @brief Eq. (29): \f$u^r(x) = A_0 \sin(2\pi x / \lambda_r)\f$.
     */
    class Sinusoid : public RoadProfile
    {
    public:
      Sinusoid(double amplitude, double wavelength);

      double
      height(double x) const override;
      double
      slope(double x) const override;
      void
      height_and_slope(double x, double &height_value, double &slope_value) const override;
      double
      curvature(double x) const override;
      double
      third_derivative(double x) const override;
      double
      shortest_wavelength() const override
      {
        return wavelength;
      }
      double
      amplitude() const override
      {
        return a0;
      }

    private:
      double a0, wavelength, k;
    };

    /**
     * @brief A road seen from a point that moves at constant speed:
     * \f$u^r(t) = u^r(x_0 + V t)\f$ and its time derivatives.
     */
    struct RoadTrack
    {
      const RoadProfile &profile;
      double             speed;
      double             x0 = 0.;

      double
      height(double t) const
      {
        return profile.height(x0 + speed * t);
      }
      double
      velocity(double t) const
      {
        return speed * profile.slope(x0 + speed * t);
      }
      double
      acceleration(double t) const
      {
        return speed * speed * profile.curvature(x0 + speed * t);
      }
      /// Height and vertical velocity at t, in one evaluation.
      void
      height_and_velocity(double t, double &height_value, double &velocity_value) const
      {
        double slope_value;
        profile.height_and_slope(x0 + speed * t, height_value, slope_value);
        velocity_value = speed * slope_value;
      }
      double
      jerk(double t) const
      {
        return speed * speed * speed * profile.third_derivative(x0 + speed * t);
      }
    };
  } // namespace road
} // namespace greentread
