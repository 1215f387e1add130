#pragma once

#include <deal.II/base/parameter_handler.h>

/**
 * @file
 * Subsection "Spectra": how the tyre-road-contact scene estimates its band
 * levels and their standard errors (analysis::welch_band_spectrum()).
 * Implemented in source/analysis/spectra_parameters.cc.
 */

namespace greentread
{
  namespace analysis
  {
    /// Subsection "Spectra".
    struct SpectraParameters
    {
      unsigned int lines_per_segment = 8;
      double       target_error      = 1.;   ///< [dB]
      double       target_from       = 250.; ///< the lowest band the target covers [Hz]
      /// Multi-rate: the highest band of the low-rate run [Hz] (0: one rate),
      /// its time step [s], and its longest distance [m].
      double low_bands_up_to    = 1000.;
      double low_band_time_step = 76.8e-6;
      double longest_distance   = 50.;
      /// Runs roll on until their observed standard errors meet the target
      /// (at most longest_distance and longest_extension times the plan).
      bool extend_runs = true;
      /// The longest record a run extends to, as a multiple of its planned one.
      static constexpr double longest_extension = 3.;
      /// The reporting cell along x and across y [m]; 0: the Green's-function rectangle.
      double reporting_along = 0., reporting_across = 0.;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// @throws InputError naming 'Spectra/Target from' or 'Low bands up to'
      /// if it is no band's nominal centre from 100 Hz to 5 kHz (or 0 for the latter).
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace analysis
} // namespace greentread
