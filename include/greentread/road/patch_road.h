#pragma once

#include <greentread/road/road_profile.h>
#include <greentread/road/texture.h>

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

/**
 * @file
 * The road as the points of a contact patch see it: the roads a scene names
 * (subsection "Road texture") and the heights under each point as the patch
 * rolls along a texture. Implemented in source/road/patch_road.cc.
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
      std::vector<std::string> roads = {"road-A", "road-B"};
      unsigned int             seed  = 1;
      double                   length = 2.304;
      double                   spacing = 0.384e-3;
      SinusoidParameters       sinusoid; ///< the road 'sinusoid' (Road/Sinusoid)
      /// Factor on every road's heights.
      double                   height_scale = 1.;
      RoadSampling             sampling = RoadSampling::envelope;

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

    /**
     * @brief The road heights the points of a patch see as it rolls: per row
     * of points across the tread, a profile along x (sampled as the texture),
     * either the envelope of the tributary rectangle or the line under the
     * points.
     */
    class PatchRoad
    {
    public:
      PatchRoad(const Texture &texture, const std::vector<std::array<double, 3>> &points,
                RoadSampling sampling, const std::string &name);

      /// The road height under point @p p at patch position @p s along the texture, and its slope.
      void
      height(unsigned int p, double s, double &z, double &slope) const;

      /// height() of every point at once (@p z and @p slope are resized).
      void
      heights(double s, Eigen::VectorXd &z, Eigen::VectorXd &slope) const;

      /// The x range the points can use: [0, usable_length()].
      double
      usable_length() const
      {
        return usable;
      }

      double dx_points = 0., dy_points = 0.;

    private:
      double                           spacing;
      std::vector<std::vector<double>> rows; // one profile per row of points
      std::vector<unsigned int>        row_of;
      std::vector<double>              x_of;
      double                           x_offset = 0., usable = 0.;
    };
  } // namespace road
} // namespace greentread
