#pragma once

#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/modal/identification.h>
#include <greentread/modal/patch_model.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/road/patch_road.h>
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
      fe::InflationParameters                inflation;
      periodic::GreenParameters          green;
      modal::IdentificationParameters    identification;
      modal::PatchModelParameters        patch_model;
      road::RoadTextureParameters        roads;
      RollingParameters                  rolling;
      /// The texture files among the roads, read (and checked against the
      /// patch and the distance) when the scene is set up, before the
      /// Green's functions.
      std::map<std::string, road::Texture> texture_files;
    };
  } // namespace scenes
} // namespace greentread
