#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

/**
 * @file
 * Subsection "Tread pattern" of the tyre-road-contact scene: the tyre's
 * grooves and pitch sequence (contact::TreadPatternParameters); the pattern
 * itself and how it enters the contact are in
 * greentread/contact/tread_pattern.h. Implemented in
 * source/contact/tread_pattern_parameters.cc.
 */

namespace greentread
{
  namespace contact
  {
    /// Subsection "Tread pattern".
    struct TreadPatternParameters
    {
      /// `Pattern`: `slick` (none), `blocks` (from the parameters below) or
      /// `image` (a footprint image of one pitch).
      std::string pattern = "slick";
      /// `Pitch lengths` [m], before they are scaled to the circumference.
      std::vector<double> pitch_lengths = {0.03};
      /// `Pitch sequence`: 1-based indices into the lengths; empty: the
      /// first length repeated.
      std::vector<unsigned int> sequence;
      double                    groove_depth         = 0.006;
      double                    lateral_groove_width = 0.005;
      /// `Circumferential grooves`: their centres across the tread [m].
      std::vector<double> circumferential_centres;
      double              circumferential_width = 0.008;
      std::string         footprint_image;
      double              footprint_width = 0.12;
      /// `Compare with slick`: each road also rolled by the slick tyre.
      bool compare_with_slick = true;

      bool
      enabled() const
      {
        return pattern != "slick";
      }

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace contact
} // namespace greentread
