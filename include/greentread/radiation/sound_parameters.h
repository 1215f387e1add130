#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

/**
 * @file
 * The parameters of the sound (subsection "Sound"): the bands, the boundary
 * element mesh's cell size and the microphones. The method is in
 * radiation/sound_model.h and doc/methods/radiation.md.
 */

namespace greentread
{
  namespace radiation
  {
    /// Subsection "Sound".
    struct SoundParameters
    {
      /// The nominal centres of the lowest and highest bands [Hz]; a top
      /// band of 0: no sound.
      double lowest_band = 250., top_band = 0.;
      /// The boundary element mesh's cell size [m]; the error bar's coarser
      /// level has cells sqrt(2) times this.
      double cell_size = 0.03;
      /// "cpx" (the ISO 11819-2 positions), or the named positions given.
      std::string microphones_given = "cpx";
      /// The named positions [m] ('Microphones' not "cpx").
      std::vector<std::pair<std::string, dealii::Point<3>>> microphones;

      /// The cells to a wavelength at the top band's centre that the
      /// mesh must have: 12, where the tyre_sound benchmark measured the
      /// refinement move the levels by 0.5 dB.
      static constexpr double cells_per_wavelength = 12.;
      /// The error bar's coarser cells over the scene's.
      static constexpr double coarser_ratio = 1.4142135623730951;

      bool
      enabled() const
      {
        return top_band > 0.;
      }

      /**
       * @brief Checks the microphones against the tyre before anything is
       * computed: each above the road, and outside the unloaded tyre of
       * outer radius @p outer_radius and width @p width [m] standing on the
       * road with its mid-plane at y = 0.
       * @throws InputError naming 'Sound/Microphones', the microphone and
       * what is allowed.
       */
      void
      check_microphones(double outer_radius, double width) const;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace radiation
} // namespace greentread
