#pragma once

#include <greentread/analysis/band_runs.h>
#include <greentread/analysis/error_bar_parameters.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/analysis/spectra_parameters.h>
#include <greentread/analysis/study.h>
#include <greentread/base/output.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/elastic_layer.h>
#include <greentread/contact/rolling.h>
#include <greentread/contact/rolling_parameters.h>
#include <greentread/contact/tread_block.h>
#include <greentread/contact/tread_pattern.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/modal/identification.h>
#include <greentread/modal/patch_model.h>
#include <greentread/modal/patch_model_stage.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/radiation/sound_parameters.h>
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

      // The results of the stages that run() hands from one to the next.

      /// A coarser level of the patch model, for the mode cut-off's error
      /// bar, and the factor that scales its difference into an estimate.
      struct CoarserModel
      {
        modal::PatchModel model;
        double            cutoff = 0.; ///< [Hz]
        double            factor = 0.;
      };

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

      /// The tread pattern of every level's runs, and its finite blocks.
      struct TreadStage
      {
        std::unique_ptr<contact::TreadPattern>    pattern;
        std::unique_ptr<contact::BlockCompliance> blocks; ///< with finite blocks
        /// With 'Error bars/Estimates' holding 'block mesh': the blocks on
        /// the mesh analysis::block_mesh_ratio times as coarse.
        std::unique_ptr<contact::BlockCompliance> coarser_blocks;
        /// Per road of run_roads: the pattern, or nullptr (slick).
        std::vector<const contact::TreadPattern *> of_road;
      };

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

      /// When 'Error bars/Estimates' holds 'ring section' (and the patch
      /// model is the ring's own modes on the section's harmonics): the
      /// coarser section's Green's functions and modes, stages of their own
      /// under @p directory/coarser_section, saved and reused as the run's.
      std::optional<CoarserSection>
      coarser_section(const std::filesystem::path &directory,
                      const base::ParameterRecord &record) const;

      /// The tread's layer under the contact points ('Materials/Tread ...',
      /// 'Geometry/Tread thickness').
      contact::ElasticLayer
      tread_layer() const;

      /// The spacing of road @p road_name's samples [m]: a texture file's,
      /// or 'Road texture/Spacing'.
      double
      road_spacing(const std::string &road_name) const;

      /// Throws InputError naming @p what (a texture file, or 'Road
      /// texture/Spacing') unless its samples @p dx along and @p dy across
      /// (0: one profile) are at most 4 contact rectangles apart: coarser,
      /// the grid would refine straight facets between samples, and no error
      /// bar would cover the road's sampling.
      void
      check_road_spacing(const std::string &what, double dx, double dy) const;

      /// Prints the contact grid, its solver, the reporting cell, and how far
      /// @p model's static compliance is from the structure's @p G0.
      void
      report_contact_setup(const contact::ContactGrid &grid,
                           const modal::PatchModel    &model,
                           const Eigen::MatrixXd      &G0) const;

      /// Stage contact: every job of @p study on its level of @p levels,
      /// side by side on the threads; their spectra in the order of the jobs.
      std::vector<analysis::RunSpectrum>
      roll_study(const analysis::Study       &study,
                 const analysis::RunLevels   &levels,
                 const std::filesystem::path &directory,
                 const base::ParameterRecord &record) const;

      /// Stage radiation: the sound of every road and speed from its runs'
      /// forces at the Green's-function points (@p job_spectra, one per job
      /// of @p study), at the points of @p model.
      void
      sound_stage(const analysis::Study                    &study,
                  const std::vector<analysis::RunSpectrum> &job_spectra,
                  const modal::PatchModel                  &model,
                  const std::filesystem::path              &directory,
                  const base::ParameterRecord              &record) const;

      /// The roads of the study, with how far their runs may roll on @p grid.
      std::vector<analysis::StudyRoad>
      study_roads(const contact::ContactGrid &grid) const;

      /// The pattern on the contact points' @p radius [m], and its blocks'
      /// compliance (once for every level: it does not depend on the contact
      /// grid), and their coarser level for the error bar; each printed.
      /// Empty when the tyre is slick.
      TreadStage
      tread_stage(double radius) const;

      /// Stage road: each road of @p study (a texture file, or made as long
      /// as its runs need), its report written in @p directory, and its
      /// profiles under @p grid's points (in @p fine_roads) and, when
      /// @p coarser, under its points too (in @p coarser_roads); each
      /// road's MPD in @p mpd.
      void
      make_roads(const analysis::Study                         &study,
                 const contact::ContactGrid                    &grid,
                 const contact::ContactGrid                    *coarser,
                 const std::filesystem::path                   &directory,
                 const base::ParameterRecord                   &record,
                 std::vector<std::unique_ptr<road::PatchRoad>> &fine_roads,
                 std::vector<std::unique_ptr<road::PatchRoad>> &coarser_roads,
                 std::vector<double>                           &mpd) const;

      /// The texture a road of run_roads rolls on ('Road texture/Roads'):
      /// @p run_road itself unless the scene rolls the slick tyre beside a
      /// pattern.
      std::string
      texture_of(const std::string &run_road) const;

      /// Whether a road of run_roads rolls the patterned tyre.
      bool
      patterned(const std::string &run_road) const;

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
      contact::TreadPatternParameters tread_pattern;
      radiation::SoundParameters      sound;
      /// The study's roads: each of 'Road texture/Roads', and with a tread
      /// pattern and 'Tread pattern/Compare with slick' each again rolled
      /// by the slick tyre (analysis::slick_road()).
      std::vector<std::string> run_roads;
      /// The texture files among the roads, read (and checked against the
      /// patch and the distance) when the scene is set up, before the
      /// Green's functions.
      std::map<std::string, road::Texture> texture_files;
    };
  } // namespace scenes
} // namespace greentread
