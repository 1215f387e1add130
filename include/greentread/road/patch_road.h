#pragma once

#include <greentread/road/road_profile.h>
#include <greentread/road/road_texture_parameters.h>
#include <greentread/road/texture.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

/**
 * @file
 * The road as the points of a contact patch see it: the roads a scene names
 * (subsection "Road texture", greentread/road/road_texture_parameters.h) and
 * the heights under each point as the patch rolls along a texture.
 * Implemented in source/road/patch_road.cc.
 */

namespace greentread
{
  namespace road
  {
    /**
     * @brief The road heights the points of a patch see as it rolls: per row
     * of points across the tread, a profile along x (sampled as the texture),
     * either the envelope of the tributary rectangle or the line under the
     * points.
     */
    class PatchRoad
    {
    public:
      PatchRoad(const Texture                            &texture,
                const std::vector<std::array<double, 3>> &points,
                RoadSampling                              sampling,
                const std::string                        &name);

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
