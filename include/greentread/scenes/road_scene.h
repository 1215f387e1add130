#pragma once

#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/modal/identification.h>
#include <greentread/modal/patch_model.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/road/texture.h>
#include <greentread/scenes/scene.h>
#include <greentread/scenes/tyre_cell_scene.h>

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace greentread
{
  namespace scenes
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
      double                   amplitude = 1e-3, wavelength = 0.05;
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

      /// The texture named @p road: a preset, "sinusoid", "flat" or a file.
      road::Texture
      make(const std::string &road, double width) const;

    private:
      /// make() before the height scale.
      road::Texture
      make_unscaled(const std::string &road, double width) const;
    };

    /// Subsection "Rolling".
    struct RollingParameters
    {
      std::vector<double> speeds = {50., 70., 90.}; // km/h
      double              distance = 2.;
      double              time_step = 0.; // 0: the road sampling interval / V
      double              static_load = 600.;
      double              indentation = 0.;
      bool                static_start = true;
      std::string         convolution = "modal-recursive";
      unsigned int        direct_kernel = 0;
      unsigned int        frames = 40;
      double              stress_reference = 100.;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
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
      PatchRoad(const road::Texture &texture, const std::vector<std::array<double, 3>> &points,
                RoadSampling sampling, const std::string &name);

      /// The road height under point @p p at patch position @p s along the texture, and its slope.
      void
      height(unsigned int p, double s, double &z, double &slope) const;

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

    /**
     * @brief The key saved with patch_model.h5: the Green's stage's key
     * (green_stage_key()), a digest of the modal sources, and the
     * parameters of "Identification" and "Patch model". Not the git
     * revision: a commit elsewhere keeps the fit.
     */
    std::string
    patch_model_stage_key(const dealii::ParameterHandler &prm, const std::string &green_key);

    /**
     * @brief Scene 'tire-road-contact': geometry -> fe -> periodic -> modal ->
     * contact -> analysis, for each road and speed (Section 5).
     */
    class RoadContactScene : public Scene
    {
    public:
      RoadContactScene(dealii::ParameterHandler &prm, const GlobalParameters &global);

      void
      run() override;

    private:
      dealii::ParameterHandler          &prm;
      GlobalParameters                   global;
      geometry::GeometryParameters       geometry;
      fe::MaterialParameters             materials;
      InflationParameters                inflation;
      periodic::GreenParameters          green;
      modal::IdentificationParameters    identification;
      modal::PatchModelParameters        patch_model;
      RoadTextureParameters              roads;
      RollingParameters                  rolling;
      /// The texture files among the roads, read (and checked against the
      /// patch and the distance) when the scene is set up, before the
      /// Green's functions.
      std::map<std::string, road::Texture> texture_files;
    };
  } // namespace scenes
} // namespace greentread
