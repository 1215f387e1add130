#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/contact/contact_parameters.h>
#include <greentread/contact/rolling_parameters.h>

namespace greentread
{
  namespace contact
  {
    void
    RollingParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using base::RangePattern;
      prm.enter_subsection("Rolling");
      {
        prm.declare_entry("Speeds (kph)", "50, 70, 90",
                          dealii::Patterns::List(dealii::Patterns::Double(1., 400.)),
                          "Rolling speeds V0 in km/h, a comma-separated list (1 to 400).");
        prm.declare_entry("Distance", "2", base::RangePattern::closed(0.01, 200., "m"),
                          "Distance rolled in each run at 'Time stepping/Time step' (the "
                          "paper: 2 m); the low bands' run of 'Spectra' may roll further.");
        prm.declare_entry("Static load", "600", base::RangePattern::closed(0., 1e5, "N"),
                          "Static load carried by the patch; the indentation that carries it is "
                          "found on the road where the run starts and then held (the rim does "
                          "not move). 0: use 'Indentation' instead.");
        prm.declare_entry("Indentation", "0", base::RangePattern::closed(-0.05, 0.05, "m"),
                          "Used when 'Static load' = 0: how far the road is pushed into the "
                          "tread, measured from the lowest tread point.");
        prm.declare_entry("Start from static equilibrium", "true", dealii::Patterns::Bool(),
                          "Start each run from the static contact (the loads applied for ever, "
                          "the tyre at rest) so that no impact transient pollutes the spectra; "
                          "'false' starts from an unloaded tyre suddenly indented.");
        prm.declare_entry("Direct kernel length", "0", dealii::Patterns::Integer(0),
                          "Steps kept by 'Convolution/Method' = direct (0: the whole run).");
        prm.declare_entry(
          "Frames", "40", dealii::Patterns::Integer(1, 10000),
          "Contact-stress maps written per run (VTU time series), evenly over its planned "
          "record; a run rolled on past it ('Spectra/Extend runs') keeps their spacing, "
          "so it writes more.");
        prm.declare_entry("Stress reference", "100", base::RangePattern::positive("Pa"),
                          "sigma0 of L_f = 20 log10(|sigma| / sigma0), Eq. (52): the paper "
                          "gives 10^2 (printed N/m; a stress is in N/m^2 = Pa).");
      }
      prm.leave_subsection();
    }



    void
    RollingParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Rolling");
      {
        speeds.clear();
        for (const auto &s : base::split_list(prm.get("Speeds (kph)")))
          speeds.push_back(std::stod(s));
        if (speeds.empty())
          throw InputError(
            "parameter 'Rolling/Speeds (kph)' is empty; allowed: a list of speeds in "
            "km/h from 1 to 400");
        distance    = prm.get_double("Distance");
        static_load = prm.get_double("Static load");
        indentation = prm.get_double("Indentation");
        if (static_load == 0. && indentation == 0.)
          throw InputError("parameter 'Rolling/Static load' = 0 with 'Rolling/Indentation' = 0 "
                           "loads the tyre with nothing (the road only touches its lowest "
                           "point); allowed: a load > 0 N, or 0 with an indentation other "
                           "than 0");
        static_start     = prm.get_bool("Start from static equilibrium");
        direct_kernel    = prm.get_integer("Direct kernel length");
        frames           = prm.get_integer("Frames");
        stress_reference = prm.get_double("Stress reference");
      }
      prm.leave_subsection();
      time_step = contact::read_time_step(prm);
      prm.enter_subsection("Convolution");
      convolution = convolution::parse_method(
        prm.get("Method"), {convolution::Method::direct, convolution::Method::modal_recursive},
        "in scene tyre-road-contact (the paper's modal form overflows over a rolling run)");
      shape_precision = prm.get("Shape precision") == "single" ?
                          convolution::ShapePrecision::single_precision :
                          convolution::ShapePrecision::double_precision;
      prm.leave_subsection();
    }
  } // namespace contact
} // namespace greentread
