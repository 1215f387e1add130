#pragma once

#include <greentread/periodic/contact_patch.h>
#include <greentread/periodic/harmonic_ring.h>

#include <deal.II/base/parameter_handler.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * Subsection "Green's functions": the periodic stage's frequency grid, method,
 * contact patch and written pairs (periodic::GreenParameters); the stage
 * itself is in greentread/periodic/green_functions.h. Implemented in
 * source/periodic/green_parameters.cc.
 */

namespace greentread
{
  namespace periodic
  {
    /**
     * @brief Subsection "Green's functions".
     */
    struct GreenParameters
    {
      double      max_frequency  = 4000.;
      double      frequency_step = 15.625;
      std::string method         = "bloch";
      /// 'Harmonic tolerance': the harmonic method's tail bound.
      double       harmonic_tolerance = 1e-3;
      PatchRequest patch;
      /// "auto" or "i,j; i,j; ...".
      std::string pairs = "auto";
      /// Frequency of the operating deflection shape [Hz], < 0 for none.
      double deflection_frequency = 500.;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Lines 0, df, ..., f_max.
      unsigned int
      n_lines() const;

      /// What the `harmonic` method needs, or nothing for another method.
      std::optional<HarmonicOptions>
      harmonic() const;

      /// The pairs (i, j) to write as CSV for @p patch.
      std::vector<std::pair<unsigned int, unsigned int>>
      csv_pairs(const ContactPatch &patch) const;
    };
  } // namespace periodic
} // namespace greentread
