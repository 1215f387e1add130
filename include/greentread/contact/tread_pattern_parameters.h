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
      /// `Block compliance`: `auto` (finite blocks with `blocks`, the endless
      /// layer with `image`), `endless layer` or `finite blocks`
      /// (greentread/contact/tread_block.h).
      std::string block_compliance = "auto";
      /// `Block mesh size` [m]: the finite blocks' table and mesh.
      double block_mesh_size = 0.002;

      /// Whether the blocks' own compliance is in the contact.
      bool
      finite_blocks() const
      {
        return enabled() && (block_compliance == "finite blocks" ||
                             (block_compliance == "auto" && pattern == "blocks"));
      }

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
