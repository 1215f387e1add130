#pragma once

#include <greentread/analysis/band_runs.h>
#include <greentread/analysis/error_bar_parameters.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/analysis/spectra_parameters.h>
#include <greentread/base/output.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/rolling.h>
#include <greentread/contact/rolling_parameters.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/modal/identification.h>
#include <greentread/modal/patch_model.h>
#include <greentread/modal/patch_model_stage.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/road/patch_road.h>
#include <greentread/scenes/scene.h>
#include <greentread/scenes/tyre_cell_scene.h>

#include <deal.II/base/parameter_handler.h>

#include <optional>

#include <Eigen/Core>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace greentread::periodic
{
  struct InflatedTyre;
}

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief Scene 'tyre-road-contact': geometry -> fe -> periodic -> modal ->
     * contact -> analysis, for each road and speed (Section 5).
     */
    class TyreRoadContactScene : public Scene
    {
    public:
      TyreRoadContactScene(dealii::ParameterHandler &prm, const GlobalParameters &global);

      void
      run() override;

    private:
      /// Stages geometry, fe, periodic: the Green's functions of the tyre of
      /// @p tyre_geometry at the lines of @p lines, read from @p h5 when its
      /// key is @p key, computed and saved otherwise. When it computes them,
      /// the inflated tyre it built is left in @p tyre, for the modal stage.
      /// Implemented, with the modal stage, in tyre_road_contact_stages.cc.
      base::FrequencyResponseMatrix
      green_stage(const geometry::GeometryParameters      &tyre_geometry,
                  const periodic::GreenParameters         &lines,
                  const std::filesystem::path             &h5,
                  const std::string                       &key,
                  const base::ParameterRecord             &record,
                  std::unique_ptr<periodic::InflatedTyre> &tyre) const;

      /// A coarser level of the patch model, for the mode cut-off's error
      /// bar, and the factor that scales its difference into an estimate.
      struct CoarserModel
      {
        modal::PatchModel model;
        double            cutoff = 0.; ///< [Hz]
        double            factor = 0.;
      };
      /// Stage modal: the patch model from 'Patch model/Source', the LSCE fit
      /// or the ring's own modes, each saved in @p directory and reused when
      /// its key matches. With @p coarser (the ring's modes only), also the
      /// model of the modes up to 'Error bars/Coarser mode cutoff' times the
      /// cut-off. @p tyre: the Green's stage's inflated tyre, if it built
      /// one (else the modes build their own).
      modal::PatchModel
      modal_stage(const geometry::GeometryParameters  &tyre_geometry,
                  const base::FrequencyResponseMatrix &G,
                  const std::string                   &green_key,
                  const std::filesystem::path         &directory,
                  const base::ParameterRecord         &record,
                  const periodic::InflatedTyre        *tyre,
                  std::optional<CoarserModel>         *coarser = nullptr) const;

      /// The ring section's coarser level, for its error bar: the patch
      /// model and static compliance of the section with 'Geometry/Mesh
      /// size' doubled, and the factor that scales the level difference.
      struct CoarserSection
      {
        modal::PatchModel model;
        Eigen::MatrixXd   G0;
        double            mesh_size = 0.; ///< [m]
        double            factor    = 0.;
      };
      /// When 'Error bars/Estimates' holds 'ring section' (and the patch
      /// model is the ring's own modes on the section's harmonics): the
      /// coarser section's Green's functions and modes, stages of their own
      /// under @p directory/coarser_section, saved and reused as the run's.
      std::optional<CoarserSection>
      coarser_section(const std::filesystem::path &directory,
                      const base::ParameterRecord &record) const;

      /// One run: road @p road_name at @p speed_kmh, at the time step and over
      /// the distance of @p band_run, on the contact points of
      /// @p grid, from the static contact (the structure's static
      /// compliance @p G0 between the Green's functions' points, which the
      /// grid splits), with its outputs; returns its spectrum. Its modal
      /// convolution runs on @p threads threads. Runs may go side by side:
      /// a run prints its lines in whole blocks. Without @p write_outputs (a
      /// coarser run of the error bars) it keeps its histories only.
      analysis::RunSpectrum
      roll(const modal::PatchModel      &model,
           const contact::ContactGrid   &grid,
           const Eigen::MatrixXd        &G0,
           const Eigen::VectorXd        &tread,
           const analysis::PatchLattice &lattice,
           const road::PatchRoad        &patch_road,
           const std::string            &road_name,
           double                        speed_kmh,
           const analysis::BandRun      &band_run,
           const std::filesystem::path  &directory,
           const base::ParameterRecord  &record,
           unsigned int                  threads,
           bool                          write_outputs = true) const;

      dealii::ParameterHandler       &prm;
      GlobalParameters                global;
      geometry::GeometryParameters    geometry;
      fe::MaterialParameters          materials;
      fe::InflationParameters         inflation;
      periodic::GreenParameters       green;
      modal::IdentificationParameters identification;
      modal::PatchModelParameters     patch_model;
      road::RoadTextureParameters     roads;
      contact::RollingParameters      rolling;
      analysis::SpectraParameters     spectra;
      analysis::ErrorBarParameters    error_bars;
      contact::ContactGridParameters  contact_grid;
      /// The texture files among the roads, read (and checked against the
      /// patch and the distance) when the scene is set up, before the
      /// Green's functions.
      std::map<std::string, road::Texture> texture_files;
    };
  } // namespace scenes
} // namespace greentread
