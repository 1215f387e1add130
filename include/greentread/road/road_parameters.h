#pragma once

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

/**
 * @file
 * Subsections "Road" and "Road/Sinusoid": which road profile, and the
 * sinusoid's amplitude and wavelength (road::SinusoidParameters,
 * road::RoadParameters); the profiles themselves are in
 * greentread/road/road_profile.h. Implemented in
 * source/road/road_parameters.cc.
 */

namespace greentread
{
  namespace road
  {
    class RoadProfile; // greentread/road/road_profile.h, which includes this file

    /**
     * @brief Subsection "Road/Sinusoid": the one sinusoidal road, read by the
     * 1-DoF scene (its only profile) and by the rolling scene (its road
     * 'sinusoid'). Declaring it twice is harmless.
     */
    struct SinusoidParameters
    {
      double amplitude  = 5e-3;
      double wavelength = 1e-2;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * @brief Subsection "Road": which profile, and its parameters (those of
     * the sinusoid, Road/Sinusoid, inherited).
     */
    struct RoadParameters : SinusoidParameters
    {
      std::string profile = "sinusoid";

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Build the profile these parameters describe.
      std::unique_ptr<RoadProfile>
      create() const;
    };
  } // namespace road
} // namespace greentread
