#include <greentread/road/road_profile.h>

#include <cmath>

namespace greentread
{
  namespace road
  {
    Sinusoid::Sinusoid(const double amplitude_, const double wavelength_)
        : a0(amplitude_)
        , wavelength(wavelength_)
        , k(2. * M_PI / wavelength_)
    {
    }



    double
    Sinusoid::height(const double x) const
    {
      return a0 * std::sin(k * x);
    }



    double
    Sinusoid::slope(const double x) const
    {
      return a0 * k * std::cos(k * x);
    }



    void
    Sinusoid::height_and_slope(const double x, double &height_value, double &slope_value) const
    {
      double s, c;
      ::sincos(k * x, &s, &c);
      height_value = a0 * s;
      slope_value  = a0 * k * c;
    }



    double
    Sinusoid::curvature(const double x) const
    {
      return -a0 * k * k * std::sin(k * x);
    }



    double
    Sinusoid::third_derivative(const double x) const
    {
      return -a0 * k * k * k * std::cos(k * x);
    }
  } // namespace road
} // namespace greentread
