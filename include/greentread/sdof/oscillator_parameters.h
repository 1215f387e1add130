#pragma once

#include <deal.II/base/parameter_handler.h>

/**
 * @file
 * Subsection "Oscillator": the single-degree-of-freedom oscillator of the
 * paper's Section 3 (Table A.1), its speed and where its Green's function
 * comes from (sdof::OscillatorParameters); the oscillator itself is in
 * greentread/sdof/oscillator.h. Implemented in
 * source/sdof/oscillator_parameters.cc.
 */

namespace greentread
{
  namespace sdof
  {
    /**
     * @brief Subsection "Oscillator" (Table A.1).
     */
    struct OscillatorParameters
    {
      double mass          = 1.;
      double stiffness     = 4e5;
      double damping_ratio = 0.02;
      double gravity       = 9.81;
      double speed         = 0.1;
      /// Take the Green's function from LSCE of the oscillator's own FRF.
      bool   identified_green  = false;
      double frf_max_frequency = 1000.;
      double frf_line_spacing  = 1.;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace sdof
} // namespace greentread
