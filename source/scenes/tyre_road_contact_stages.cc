#include <greentread/analysis/error_bars.h>
#include <greentread/analysis/mode_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/base/progress.h>
#include <greentread/modal/passivity.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/scenes/tyre_road_contact_scene.h>
#include <greentread/synthesis/mode_stage.h>
#include <greentread/synthesis/mode_synthesis.h>
#include <greentread/synthesis/mode_truncation.h>

#include <deal.II/base/multithread_info.h>

#include <chrono>
#include <cmath>
#include <iostream>

/**
 * @file
 * The saved stages of the tyre-road-contact scene: the Green's functions,
 * the patch model, and the error bars' coarser section with its own two.
 */

namespace greentread
{
  namespace scenes
  {
    base::FrequencyResponseMatrix
    TyreRoadContactScene::green_stage(const geometry::GeometryParameters      &tyre_geometry,
                                      const periodic::GreenParameters         &lines,
                                      const std::filesystem::path             &h5,
                                      const std::string                       &key,
                                      const base::ParameterRecord             &record,
                                      std::unique_ptr<periodic::InflatedTyre> &tyre) const
    {
      base::FrequencyResponseMatrix G;
      const bool green_cached = global.reuse && base::read_green_stage_key(h5.string()) == key &&
                                base::read_saved_stage(h5, [&] {
                                  G = base::read_green_hdf5(h5.string());
                                });
      if (green_cached)
        std::cout << "Reusing " << h5.string()
                  << ": same geometry, materials, inflation and Green's-function parameters\n";
      else
        {
          std::cout << "Stages geometry -> fe -> periodic: the Green's functions at "
                    << lines.patch.points_along * lines.patch.points_across << " points, 0 to "
                    << format_number(lines.max_frequency) << " Hz (" << lines.n_lines()
                    << " lines)\n";
          // With the ring's own modes, their cut-off is checked against the
          // harmonics as soon as they are chosen, before anything is written.
          auto harmonic = lines.harmonic();
          if (harmonic && patch_model.source == modal::PatchModelSource::fe_modes)
            harmonic->mode_cutoff = 2. * M_PI * patch_model.mode_cutoff;
          tyre = std::make_unique<periodic::InflatedTyre>(tyre_geometry, materials, inflation,
                                                          lines.patch, harmonic);
          std::cout << "  " << tyre->patch.describe() << '\n'
                    << (tyre->harmonic ? tyre->harmonic->describe() : std::string());
          const auto result = periodic::run_green_stage(*tyre, lines, key, h5, record, false,
                                                        global.print_timings, MPI_COMM_WORLD);
          G                 = result.green;
          std::cout << "  every solve checked: largest backward error "
                    << format_printf("%.2g", result.report.diagnostics.max_residual) << '\n';
        }
      return G;
    }



    modal::PatchModel
    TyreRoadContactScene::modal_stage(const geometry::GeometryParameters  &tyre_geometry,
                                      const base::FrequencyResponseMatrix &G,
                                      const std::string                   &green_key,
                                      const std::filesystem::path         &directory,
                                      const base::ParameterRecord         &record,
                                      const periodic::InflatedTyre        *tyre,
                                      std::optional<CoarserModel>         *coarser) const
    {
      if (patch_model.source == modal::PatchModelSource::identified)
        {
          modal::PatchModel model =
            modal::patch_model_stage(G, identification, patch_model, directory / "patch_model.h5",
                                     modal::patch_model_stage_key(prm, green_key), record,
                                     global.reuse, global.print_timings);
          const modal::Passivity passivity = modal::measure_passivity(model, G.df, G.n_lines - 1);
          modal::print_passivity(passivity, "the identified patch model");
          modal::check_passivity(passivity, patch_model.allow_non_passive,
                                 "the identified patch model");
          if (error_bars.estimates_any(analysis::Discretisation::mode_cutoff))
            std::cout << "  the mode cut-off's error bar needs the ring's own modes ('Patch "
                         "model/Source' = fe modes): not estimated\n";
          return model;
        }
      const synthesis::ModeStageInputs inputs{
        tyre_geometry,           materials,        inflation, green.patch,
        patch_model.mode_cutoff, green.harmonic(), tyre};
      // The modes' part at every line, when the stage computes it (not
      // when it is reused): compare() then only adds the residual.
      synthesis::ModalLines          lines;
      const synthesis::ModeSynthesis synthesis = synthesis::run_mode_stage(
        inputs, G, directory / "modal_model.h5", synthesis::mode_stage_key(prm, green_key), record,
        global.reuse, global.print_timings, MPI_COMM_WORLD, &lines);
      analysis::write_dispersion(directory, synthesis.dispersion, patch_model.mode_cutoff, record);
      const synthesis::SynthesisErrors errors = synthesis::compare(synthesis, G, &lines);
      analysis::report_synthesis(directory, synthesis, errors, record);
      modal::check_passivity({errors.passivity, errors.passivity_frequency, G.n_lines - 1},
                             patch_model.allow_non_passive, "the patch model of the ring's modes");
      const unsigned int n_p = G.n_points();
      Eigen::MatrixXd    E(n_p, n_p);
      for (unsigned int i = 0; i < n_p; ++i)
        for (unsigned int j = 0; j < n_p; ++j)
          E(i, j) = errors.pair_error[i * n_p + j];
      if (coarser && error_bars.estimates_any(analysis::Discretisation::mode_cutoff))
        {
          // The error bar's coarser level: the same modes up to a lower
          // cut-off, with their own residual. The estimate scales the level
          // difference by how much closer to the direct lines the finer
          // level is (E's median): the observed convergence.
          const double                   cutoff = error_bars.cutoff_ratio * patch_model.mode_cutoff;
          const synthesis::ModeSynthesis fewer  = synthesis::truncate(synthesis, cutoff, G);
          const double                   e_fewer = synthesis::compare(fewer, G).median;
          const double                   factor =
            e_fewer > errors.median ? errors.median / (e_fewer - errors.median) : 1.;
          std::cout << "  the mode cut-off's error bar: the " << fewer.n_modes() << " modes to "
                    << format_number(cutoff) << " Hz ('Error bars/Coarser mode "
                    << "cutoff'), E median " << format_printf("%.3g", 100. * e_fewer)
                    << "% against " << format_printf("%.3g", 100. * errors.median)
                    << "%: the estimate is " << format_printf("%.3g", factor)
                    << " times the level difference\n";
          *coarser = CoarserModel{synthesis::to_patch_model(fewer, E, G.df * (G.n_lines - 1)),
                                  cutoff, factor};
        }
      return synthesis::to_patch_model(synthesis, E, G.df * (G.n_lines - 1));
    }



    std::optional<TyreRoadContactScene::CoarserSection>
    TyreRoadContactScene::coarser_section(const std::filesystem::path &directory,
                                          const base::ParameterRecord &record) const
    {
      if (!error_bars.estimates_any(analysis::Discretisation::ring_section))
        return std::nullopt;
      if (patch_model.source != modal::PatchModelSource::fe_modes || !green.harmonic())
        {
          std::cout << "  the ring section's error bar needs the ring's own modes on the "
                       "section's harmonics ('Patch model/Source' = fe modes, 'Green's "
                       "functions/Method' = harmonic): not estimated\n";
          return std::nullopt;
        }
      // The section twice as coarse, at the same degree: its Green's
      // functions and modes are stages of their own, saved and reused as
      // the run's are, under coarser_section/.
      geometry::GeometryParameters coarse = geometry;
      coarse.mesh_size *= 2.;
      // Its direct lines only at 0 and f_max: the static one is its
      // compliance, which the runs start from, and the top one fits its
      // residual's relaxation (the fit weighs each line by w^2, so the top
      // line carries most of it). The lines between only check its E, which
      // the run's own section does; each costs a set of solves.
      periodic::GreenParameters lines = green;
      lines.frequency_step            = green.max_frequency;
      const std::filesystem::path sub = directory / "coarser_section";
      std::filesystem::create_directories(sub);
      const std::string key = periodic::green_stage_key(
        prm, geometry.geo_file,
        {{"Geometry/Mesh size", format_printf("%.17g", coarse.mesh_size)},
         {"Green's functions/Frequency step", format_printf("%.17g", lines.frequency_step)}});
      std::cout << "The ring section's error bar: the section at "
                << format_number(1e3 * coarse.mesh_size)
                << " mm ('Geometry/Mesh size' doubled), its direct lines at 0 and "
                << format_number(lines.max_frequency) << " Hz, its own stages in " << sub.string()
                << '\n';
      std::unique_ptr<periodic::InflatedTyre> tyre;
      const base::FrequencyResponseMatrix     G =
        green_stage(coarse, lines, sub / "green_functions.h5", key, record, tyre);
      CoarserSection section{modal_stage(coarse, G, key, sub, record, tyre.get()),
                             synthesis::static_line(G), coarse.mesh_size,
                             analysis::richardson_factor(2., analysis::ring_section_order)};
      std::cout << "  the ring section's error bar: the estimate is "
                << format_printf("%.3g", section.factor) << " times the level difference (order "
                << format_number(analysis::ring_section_order) << " in the mesh size)\n";
      return section;
    }



    TyreRoadContactScene::TreadStage
    TyreRoadContactScene::tread_stage(const double radius) const
    {
      TreadStage stage;
      if (!tread_pattern.enabled())
        {
          stage.of_road.assign(run_roads.size(), nullptr);
          return stage;
        }
      stage.pattern = std::make_unique<contact::TreadPattern>(tread_pattern, radius);
      std::cout << "Tread pattern '" << tread_pattern.pattern << "': " << stage.pattern->summary()
                << "\n";
      for (const auto &r : run_roads)
        stage.of_road.push_back(patterned(r) ? stage.pattern.get() : nullptr);
      if (!tread_pattern.finite_blocks())
        return stage;
      const auto blocks = [&](const double mesh_size, const std::string &what) {
        std::cout << "Finite tread blocks" << what << " (3D finite elements, cells of "
                  << format_number(1e3 * mesh_size) << " mm):\n";
        const auto set_up = std::chrono::steady_clock::now();
        auto       made   = std::make_unique<contact::BlockCompliance>(
          *stage.pattern, tread_pattern, tread_layer(), geometry.tread_width, mesh_size,
          dealii::MultithreadInfo::n_threads(), true);
        std::cout << "  " << made->summary() << " (set up in "
                  << format_printf("%.3g", base::seconds_since(set_up)) << " s)\n";
        return made;
      };
      stage.blocks = blocks(tread_pattern.block_mesh_size, "");
      if (error_bars.estimates_any(analysis::Discretisation::block_mesh))
        stage.coarser_blocks =
          blocks(analysis::block_mesh_ratio * tread_pattern.block_mesh_size,
                 ", the error bar's coarser level ('Error bars/Estimates' = block mesh; order " +
                   format_number(analysis::block_mesh_order) + " assumed)");
      return stage;
    }
  } // namespace scenes
} // namespace greentread
