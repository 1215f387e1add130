#pragma once

#include <greentread/road/road_parameters.h>
#include <greentread/road/texture.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

/**
 * @file
 * Subsection "Road texture": the roads of the tyre/road scene and how a
 * tread point sees them (road::RoadTextureParameters, road::RoadSampling); the
 * heights under a rolling patch are in greentread/road/patch_road.h.
 * Implemented in source/road/road_texture_parameters.cc.
 */

namespace greentread
{
  namespace road
  {
    /// How the road between tread points is seen by a point.
    enum class RoadSampling
    {
      envelope, ///< highest road point in the point's tributary rectangle
      point     ///< road height at the point (bilinear)
    };

    /// Subsection "Road texture": the roads of the tyre/road scene.
    struct RoadTextureParameters
    {
      std::vector<std::string> roads   = {"road-A", "road-B"};
      unsigned int             seed    = 1;
      double                   length  = 2.304;
      double                   spacing = 0.384e-3;
      SinusoidParameters       sinusoid; ///< the road 'sinusoid' (Road/Sinusoid)
      /// Factor on every road's heights.
      double       height_scale = 1.;
      RoadSampling sampling     = RoadSampling::envelope;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Whether @p road names a built-in road (a preset, "sinusoid", "flat")
      /// rather than a texture file.
      static bool
      is_built_in(const std::string &road)
      {
        return road == "road-A" || road == "road-B" || road == "sinusoid" || road == "flat";
      }

      /**
       * The texture named @p road: a preset, "sinusoid", "flat" or a file.
       * A built-in road is 'Length' long, or @p at_least [m] if longer; a
       * preset longer than 'Length' is made in pieces of that length
       * (independent realisations crossfaded over 0.2 m), so that its FFT
       * needs one piece's memory. Its length is rounded up to a sample
       * count with prime factors 2, 3 and 5 only.
       */
      Texture
      make(const std::string &road, double width, double at_least = 0.) const;

    private:
      /// make() before the height scale, @p road_length [m] long.
      Texture
      make_unscaled(const std::string &road, double width, double road_length) const;
    };
  } // namespace road
} // namespace greentread
