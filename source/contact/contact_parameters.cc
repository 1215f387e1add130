#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/contact/contact_parameters.h>

#include <cmath>
#include <cstdlib>

namespace greentread
{
  namespace contact
  {
    std::string
    to_string(const ContactLaw law)
    {
      return law == ContactLaw::kinematic ? "kinematic" : "penalty";
    }



    void
    ContactParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      {
        prm.declare_entry(
          "Law", "kinematic", dealii::Patterns::Selection("kinematic|penalty"),
          "Contact law. 'kinematic': Eqs. (16)-(28), the point rides on the road with its "
          "displacement and velocity matched; impacts by the impulse-completion rule "
          "(doc/methods/contact.md). 'penalty': Eq. (37), F = kc (u_r - u_h) where the predicted "
          "position "
          "penetrates the road.");
        prm.declare_entry("Contact stiffness", "1e7", base::RangePattern::positive("N/m"),
                          "Penalty stiffness kc (Law = penalty only). Unit: N/m. "
                          "Paper: 1e6, 1e7 and 1e8 N/m in Figures A.2-A.4.");
      }
      prm.leave_subsection();

      prm.enter_subsection("Time stepping");
      {
        prm.declare_entry("Time step", "auto", dealii::Patterns::Anything(),
                          "Time step dt: a number from 1e-8 to 1e-2, or 'auto', the scene's own "
                          "choice: in tyre-road-contact the road's sampling interval divided by "
                          "the speed (one road sample per step, as the paper); in sdof 1e-5 s "
                          "(Table A.2 uses 1e-4 and 1e-5 s). Unit: s.");
        prm.declare_entry("End time", "0.2", base::RangePattern::positive("s"),
                          "Scene sdof: the duration of the run, at least one time step and at "
                          "most 2e8 of them (tyre-road-contact rolls 'Rolling/Distance'). "
                          "Unit: s. 0.2 s is two road periods of Section 3.");
      }
      prm.leave_subsection();
    }



    void
    ContactParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      {
        law = prm.get("Law") == "kinematic" ? ContactLaw::kinematic : ContactLaw::penalty;
        contact_stiffness = prm.get_double("Contact stiffness");
      }
      prm.leave_subsection();
      prm.enter_subsection("Time stepping");
      {
        end_time = prm.get_double("End time");
      }
      prm.leave_subsection();
      time_step = read_time_step(prm);
      if (time_step == 0.)
        time_step = 1e-5;

      require_parameter(end_time >= time_step && std::isfinite(end_time), "Time stepping/End time",
                        end_time,
                        "an end time >= the time step, " + format_number(time_step) + " s");
      require_parameter(end_time / time_step <= 2e8, "Time stepping/End time", end_time,
                        "at most 2e8 time steps (dt = " + format_number(time_step) + " s)");
    }



    double
    read_time_step(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      const std::string value = prm.get("Time step");
      prm.leave_subsection();
      if (value == "auto")
        return 0.;
      char        *end = nullptr;
      const double dt  = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !(dt >= 1e-8 && dt <= 1e-2))
        throw InputError("parameter 'Time stepping/Time step' = " + value +
                         " is not allowed; allowed: 'auto' or a number from 1e-8 to 1e-2 (s)");
      return dt;
    }



    std::string
    ContactParameters::describe() const
    {
      return law == ContactLaw::penalty ?
               "penalty (kc = " + format_number(contact_stiffness) + " N/m)" :
               to_string(law);
    }



    unsigned int
    ContactParameters::n_steps() const
    {
      return static_cast<unsigned int>(std::llround(end_time / time_step));
    }
  } // namespace contact
} // namespace greentread
