#include <greentread/base/parameters.h>
#include <greentread/road/road_parameters.h>
#include <greentread/road/road_profile.h>

#include <memory>

namespace greentread
{
  namespace road
  {
    void
    RoadParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Road");
      {
        prm.declare_entry("Profile", "sinusoid", dealii::Patterns::Selection("sinusoid"),
                          "The road under the contact point. 'sinusoid': "
                          "u_r(x) = A0 sin(2 pi x / lambda_r), Eq. (29).");
      }
      prm.leave_subsection();
      SinusoidParameters::declare_parameters(prm);
    }



    void
    RoadParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Road");
      {
        profile = prm.get("Profile");
      }
      prm.leave_subsection();
      SinusoidParameters::parse_parameters(prm);
    }



    void
    SinusoidParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Road");
      prm.enter_subsection("Sinusoid");
      {
        prm.declare_entry("Amplitude", "0.005", base::RangePattern::closed(0., 0.05, "m"),
                          "Amplitude A0 of the sinusoidal road u_r(x) = A0 sin(2 pi x / "
                          "lambda_r), Eq. (29): the 1-DoF scene's road, and the rolling "
                          "scene's road 'sinusoid'. Unit: m. Paper, Section 3: 5 mm.");
        prm.declare_entry("Wavelength", "0.01", base::RangePattern::closed(1e-3, 10., "m"),
                          "Wavelength lambda_r of the sinusoidal road. Unit: m. "
                          "Paper, Section 3: 10 mm.");
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    void
    SinusoidParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Road");
      prm.enter_subsection("Sinusoid");
      {
        amplitude  = prm.get_double("Amplitude");
        wavelength = prm.get_double("Wavelength");
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    std::unique_ptr<RoadProfile>
    RoadParameters::create() const
    {
      return std::make_unique<Sinusoid>(amplitude, wavelength);
    }
  } // namespace road
} // namespace greentread
