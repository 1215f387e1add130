#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/sdof/oscillator_parameters.h>

namespace greentread
{
  namespace sdof
  {
    void
    OscillatorParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Oscillator");
      {
        using base::RangePattern;
        prm.declare_entry("Mass", "1", base::RangePattern::positive("kg"),
                          "Mass M. Unit: kg. Table A.1: 1 kg.");
        prm.declare_entry("Stiffness", "4e5", base::RangePattern::positive("N/m"),
                          "Spring stiffness K. Unit: N/m. Table A.1: 4e5 N/m.");
        prm.declare_entry("Damping ratio", "0.02", base::RangePattern::closed(0., 1000., ""),
                          "Viscous damping ratio xi = C / (2 sqrt(K M)); xi < 0 would feed "
                          "energy in. Values >= 1 give real poles. Unit: 1. Table A.1: 0.02.");
        prm.declare_entry("Gravity", "9.81", base::RangePattern::non_negative("m/s^2"),
                          "Gravitational acceleration g pressing the mass onto the road "
                          "(the load -M g of Eq. 30). Unit: m/s^2.");
        prm.declare_entry("Speed (kph)", "0.36", base::RangePattern::positive("km/h"),
                          "Speed V0 at which the oscillator travels over the road. "
                          "Unit: km/h, as every speed of GreenTread. Paper, Section 3: "
                          "0.1 m/s = 0.36 km/h.");
        prm.declare_entry("Green's function", "analytic",
                          dealii::Patterns::Selection("analytic|identified"),
                          "'analytic': the closed-form g(t) and its exact modal form. "
                          "'identified': the modal model that LSCE (subsection "
                          "Identification) finds from the oscillator's own FRF, sampled "
                          "from 0 to 'FRF maximum frequency'; the scene then also reports "
                          "the difference from the run with the exact modal form.");
        prm.declare_entry("FRF maximum frequency", "1000", base::RangePattern::positive("Hz"),
                          "Highest line of the FRF identified when Green's function = "
                          "identified. Unit: Hz.");
        prm.declare_entry("FRF line spacing", "1", base::RangePattern::positive("Hz"),
                          "Line spacing of that FRF. Unit: Hz.");
      }
      prm.leave_subsection();
    }



    void
    OscillatorParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Oscillator");
      {
        mass          = prm.get_double("Mass");
        stiffness     = prm.get_double("Stiffness");
        damping_ratio = prm.get_double("Damping ratio");
        gravity       = prm.get_double("Gravity");
        speed         = prm.get_double("Speed (kph)") * 1000. / 3600.; // m/s (0.36 -> 0.1 exactly)
        identified_green  = prm.get("Green's function") == "identified";
        frf_max_frequency = prm.get_double("FRF maximum frequency");
        frf_line_spacing  = prm.get_double("FRF line spacing");
      }
      prm.leave_subsection();
      require_parameter(frf_line_spacing <= 0.5 * frf_max_frequency &&
                          frf_max_frequency / frf_line_spacing <= 1e6,
                        "Oscillator/FRF line spacing", frf_line_spacing,
                        "a spacing that gives from 2 to 1e6 lines up to 'FRF maximum "
                        "frequency' = " +
                          format_number(frf_max_frequency) + " Hz");
    }
  } // namespace sdof
} // namespace greentread
