#include <greentread/analysis/spectra_parameters.h>
#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>

#include <cmath>
#include <string>
#include <utility>

namespace greentread
{
  namespace analysis
  {
    void
    SpectraParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Spectra");
      {
        prm.declare_entry(
          "Lines per segment", "8", dealii::Patterns::Integer(1, 1000),
          "The Fourier lines each one-third-octave band holds in one segment of Welch's "
          "average: each band is averaged over segments of its own length (overlapping by "
          "half), so a band's level comes from as many segments as the record holds, and its "
          "standard error from their scatter once there are 3 or more (at least a Gaussian "
          "signal's below 10). More lines: less leakage across the band's edges, fewer "
          "segments.");
        prm.declare_entry(
          "Standard error target", "1", base::RangePattern::closed(0.01, 20., "dB"),
          "The standard error each band's level should reach, from 'Target from' up. The run "
          "says which bands of each road and speed exceed it and the 'Rolling/Distance' that "
          "would meet it (the standard error falls as one over the square root of the record).");
        prm.declare_entry("Target from", "250",
                          base::RangePattern::closed(lowest_band, highest_band, "Hz"),
                          "The lowest one-third-octave band (its nominal centre) the standard "
                          "error target applies to.");
        prm.declare_entry(
          "Low bands up to", "1000", base::RangePattern::closed(0., highest_band, "Hz"),
          "Multi-rate estimation: the bands up to this one (its nominal centre) come from a "
          "second run of each road and speed at 'Low-band time step', as long as 'Standard "
          "error target' needs in those bands from 'Target from' (at most 'Longest "
          "distance'); the bands above it from the run at 'Time stepping/Time step' over "
          "'Rolling/Distance'. The grid stays as fine in both. 0: one rate, every band from "
          "the run at the scene's step.");
        prm.declare_entry(
          "Low-band time step", "7.68e-05", base::RangePattern::closed(1e-7, 1e-3, "s"),
          "The low-rate run's time step (the scene's step if that is coarser: then no "
          "low-rate run). Its error in a band grows as (f dt)^2, whatever the speed: the "
          "default, 76.8 us (5 road samples at 90 km/h), is the step "
          "benchmarks/multi_rate/multi_rate.sh "
          "measured against the scene's step on the same road (doc/benchmarks.md).");
        prm.declare_entry("Longest distance", "50", base::RangePattern::closed(0.1, 200., "m"),
                          "The longest run: the low-rate run's planned record, and any run's "
                          "record once extended ('Extend runs'). A target it cannot meet "
                          "within this is reported, with the distance it would need.");
        prm.declare_entry(
          "Extend runs", "true", dealii::Patterns::Bool(),
          "Each run rolls on past its planned record (the run at the scene's step past "
          "'Rolling/Distance', the low-rate run past its planned length) until the standard "
          "error observed in the bands it gives, from 'Target from' up, in the stress and in the "
          "force, meets 'Standard error target': the plan is a Gaussian signal's prediction, "
          "and the contact force scatters more than that. At most 'Longest distance', and 3 "
          "times the planned record. false: every run rolls its planned record only.");
        for (const char *direction : {"along", "across"})
          prm.declare_entry(
            std::string("Reporting cell ") + direction, "0", base::RangePattern::non_negative("mm"),
            std::string("The reporting cell's size ") + direction +
              " the road, in mm: the stress at the patch centre (its history and spectra) is "
              "the mean over this cell, centred at the patch centre, whatever the contact grid. "
              "0: the Green's-function rectangle ('Green's functions/Patch length' and 'Patch "
              "width' over 'Points along' and 'Points across'; 6 x 6.67 mm by default). A mean "
              "over a length a along the road at speed V has nulls at V / a and its multiples "
              "(a = 6 mm: 3.2 kHz at 70 km/h): set the size of the pressure sensor a run is "
              "compared with.");
      }
      prm.leave_subsection();
    }



    void
    SpectraParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Spectra");
      {
        lines_per_segment  = prm.get_integer("Lines per segment");
        target_error       = prm.get_double("Standard error target");
        target_from        = prm.get_double("Target from");
        low_bands_up_to    = prm.get_double("Low bands up to");
        low_band_time_step = prm.get_double("Low-band time step");
        longest_distance   = prm.get_double("Longest distance");
        extend_runs        = prm.get_bool("Extend runs");
        reporting_along    = 1e-3 * prm.get_double("Reporting cell along");
        reporting_across   = 1e-3 * prm.get_double("Reporting cell across");
      }
      prm.leave_subsection();
      for (const auto &[name, f] : {std::pair<const char *, double>{"Target from", target_from},
                                    {"Low bands up to", low_bands_up_to}})
        {
          bool is_band = std::string(name) == "Low bands up to" && f == 0.;
          for (const auto &band : third_octave_bands(lowest_band, highest_band))
            is_band = is_band || std::abs(band.nominal - f) < 1e-9 * f;
          if (!is_band)
            throw InputError("parameter 'Spectra/" + std::string(name) + "' = " + format_number(f) +
                             " Hz; allowed: " +
                             (std::string(name) == "Low bands up to" ? "0 (one rate) or " : "") +
                             "the nominal centre of a one-third-octave band from 100 Hz to 5 "
                             "kHz (100, 125, 160, 200, 250, 315, 400, 500, ... Hz)");
        }
    }
  } // namespace analysis
} // namespace greentread
