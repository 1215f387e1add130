#include <greentread/analysis/error_bars.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/analysis/study.h>
#include <greentread/analysis/study_run.h>
#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/contact/contact_parameters.h>
#include <greentread/contact/rolling.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/scenes/tyre_road_contact_scene.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <tuple>

namespace greentread
{
  namespace scenes
  {
    namespace
    {
      /// The error bars' coarser contact grid ('Contact grid/Subdivisions'
      /// halved), when the study rolls on it: its points' lattice and tread
      /// heights too.
      struct CoarserGrid
      {
        std::unique_ptr<contact::ContactGrid>   grid;
        std::unique_ptr<analysis::PatchLattice> lattice;
        Eigen::VectorXd                         tread;

        CoarserGrid(const std::vector<std::array<double, 3>> &coarse_points,
                    const contact::ContactGrid               &fine,
                    const contact::ElasticLayer              &layer,
                    const bool                                wanted)
        {
          if (!wanted)
            return;
          grid = std::make_unique<contact::ContactGrid>(coarse_points, fine.subdivisions / 2, layer,
                                                        fine.matrix_free, fine.candidate_set);
          lattice =
            std::make_unique<analysis::PatchLattice>(grid->points, "the coarser contact grid");
          tread = contact::tread_heights(grid->points);
        }
      };

      /// @p level with another patch model (and static compliance).
      analysis::RunLevel
      with_model(const analysis::RunLevel &level,
                 const modal::PatchModel  &model,
                 const Eigen::MatrixXd    *G0 = nullptr)
      {
        analysis::RunLevel other = level;
        other.model              = &model;
        if (G0 != nullptr)
          other.G0 = G0;
        return other;
      }

      /// Pointers to @p roads, for a RunLevel.
      std::vector<const road::PatchRoad *>
      pointers(const std::vector<std::unique_ptr<road::PatchRoad>> &roads)
      {
        std::vector<const road::PatchRoad *> p;
        for (const auto &r : roads)
          p.push_back(r.get());
        return p;
      }



      /// The error bars' Richardson factors of the levels the scene makes
      /// itself (the contact grid's and the time step's are the study's).
      std::map<analysis::Discretisation, double>
      richardson_factors(const TyreRoadContactScene::TreadStage                    &tread,
                         const std::optional<TyreRoadContactScene::CoarserModel>   &coarser_model,
                         const std::optional<TyreRoadContactScene::CoarserSection> &section)
      {
        std::map<analysis::Discretisation, double> factors;
        if (tread.coarser_blocks)
          factors[analysis::Discretisation::block_mesh] =
            analysis::richardson_factor(analysis::block_mesh_ratio, analysis::block_mesh_order);
        if (coarser_model)
          factors[analysis::Discretisation::mode_cutoff] = coarser_model->factor;
        if (section)
          factors[analysis::Discretisation::ring_section] = section->factor;
        return factors;
      }



      /// The error bars' other levels: @p fine with one discretisation
      /// changed, for each that the scene has.
      std::map<analysis::Discretisation, analysis::RunLevel>
      other_levels(const analysis::RunLevel                                  &fine,
                   const CoarserGrid                                         &coarser,
                   const std::vector<std::unique_ptr<road::PatchRoad>>       &coarser_roads,
                   const std::optional<TyreRoadContactScene::CoarserModel>   &coarser_model,
                   const std::optional<TyreRoadContactScene::CoarserSection> &section,
                   const TyreRoadContactScene::TreadStage                    &tread)
      {
        std::map<analysis::Discretisation, analysis::RunLevel> other;
        if (coarser.grid)
          other[analysis::Discretisation::contact_grid] = {
            fine.model,     coarser.grid.get(),    fine.G0,
            &coarser.tread, coarser.lattice.get(), pointers(coarser_roads),
            tread.of_road,  tread.blocks.get()};
        if (coarser_model)
          other[analysis::Discretisation::mode_cutoff] = with_model(fine, coarser_model->model);
        if (section)
          other[analysis::Discretisation::ring_section] =
            with_model(fine, section->model, &section->G0);
        if (tread.coarser_blocks)
          {
            other[analysis::Discretisation::block_mesh]        = fine;
            other[analysis::Discretisation::block_mesh].blocks = tread.coarser_blocks.get();
          }
        return other;
      }
    } // namespace



    TyreRoadContactScene::TyreRoadContactScene(dealii::ParameterHandler &prm_,
                                               const GlobalParameters   &global_)
        : prm(prm_)
        , global(global_)
    {
      geometry.parse_parameters(prm);
      materials.parse_parameters(prm);
      inflation.parse_parameters(prm);
      green.parse_parameters(prm);
      identification.parse_parameters(prm);
      patch_model.parse_parameters(prm);
      roads.parse_parameters(prm);
      rolling.parse_parameters(prm);
      spectra.parse_parameters(prm);
      error_bars.parse_parameters(prm);
      contact_grid.parse_parameters(prm);
      sound.parse_parameters(prm);
      // Microphones above the road and outside the tyre, checked on the
      // parameters' tyre now; the surface checks them again.
      sound.check_microphones(geometry.outer_radius(), geometry.section_width);
      // The solver against the patch model, refused now rather than after
      // the Green's functions.
      contact_grid.matrix_free(patch_model.source == modal::PatchModelSource::fe_modes,
                               green.patch.points_along * green.patch.points_across);
      // The tread pattern against the tread and the contact grid, on the
      // parameters' tyre now; the run builds it on the contact points' radius.
      tread_pattern.parse_parameters(prm);
      if (tread_pattern.enabled())
        {
          const unsigned int s = contact_grid.subdivisions;
          contact::check_pattern(tread_pattern,
                                 contact::TreadPattern(tread_pattern, geometry.outer_radius()),
                                 geometry.tread_width, geometry.tread_thickness,
                                 green.patch.length / (double(green.patch.points_along) * s),
                                 green.patch.width / (double(green.patch.points_across) * s), s);
          if (tread_pattern.finite_blocks() &&
              !contact_grid.matrix_free(patch_model.source == modal::PatchModelSource::fe_modes,
                                        green.patch.points_along * green.patch.points_across))
            throw InputError(
              "parameter 'Tread pattern/Block compliance' = " + tread_pattern.block_compliance +
              " takes the finite blocks, which need 'Contact grid/Solver' = "
              "projected CG; allowed with 'pivoting': endless layer");
        }

      // A run's files are named by its road's and speed's labels: two roads
      // or two speeds with one label would overwrite each other's.
      const auto once = [](const std::vector<std::string> &labels,
                           const std::vector<std::string> &given, const std::string &parameter) {
        for (std::size_t i = 0; i < labels.size(); ++i)
          for (std::size_t j = 0; j < i; ++j)
            if (labels[i] == labels[j])
              throw InputError("parameter '" + parameter + "' gives '" + given[j] + "' and '" +
                               given[i] + "', whose runs would write the same files (both '" +
                               labels[i] + "'); allowed: each once");
      };
      run_roads.clear();
      for (const auto &r : roads.roads)
        {
          // The slick tyre's runs are named by a suffix; a road of that name
          // would be taken for them.
          if (tread_pattern.enabled() && tread_pattern.compare_with_slick &&
              analysis::texture_of_road(r) != r)
            throw InputError("parameter 'Road texture/Roads' gives '" + r +
                             "', which ends as the slick tyre's runs are named ('" +
                             analysis::slick_road("<road>") +
                             "') with 'Tread pattern/Compare with slick' = true; allowed: "
                             "another name, or 'Compare with slick' = false");
          run_roads.push_back(r);
          if (tread_pattern.enabled() && tread_pattern.compare_with_slick)
            run_roads.push_back(analysis::slick_road(r));
        }
      std::vector<std::string> road_labels, speed_labels, speeds_given;
      for (const auto &r : run_roads)
        road_labels.push_back(analysis::road_label(r));
      for (const double v : rolling.speeds)
        {
          speed_labels.push_back(analysis::speed_label(v));
          speeds_given.push_back(format_number(v));
        }
      once(road_labels, run_roads, "Road texture/Roads");
      once(speed_labels, speeds_given, "Rolling/Speeds (kph)");

      // The reporting cell must lie in the patch; checked now, not after the
      // Green's functions.
      for (const auto &[name, size, patch_size] :
           {std::tuple<const char *, double, double>{"along", spectra.reporting_along,
                                                     green.patch.length},
            {"across", spectra.reporting_across, green.patch.width}})
        if (size > patch_size * (1. + 1e-9))
          throw InputError("parameter 'Spectra/Reporting cell " + std::string(name) +
                           "' = " + format_number(1e3 * size) +
                           " mm; allowed: 0 (the Green's-function "
                           "rectangle) or up to the contact patch's " +
                           format_number(1e3 * patch_size) + " mm ('Green's functions/Patch " +
                           (std::string(name) == "along" ? "length" : "width") + "')");

      // A texture file is read now, not after the Green's functions (five
      // minutes): a malformed file, or one too narrow or too short for the
      // patch and the distance, is refused at once. PatchRoad checks the
      // points' extent again.
      for (const auto &name : roads.roads)
        if (!road::RoadTextureParameters::is_built_in(name) && texture_files.count(name) == 0)
          {
            road::Texture t            = road::read_texture(name);
            const double  needed_width = green.patch.width + 2. * t.dy;
            if (t.ny > 1 && t.ny * t.dy < needed_width)
              throw InputError("texture file '" + name + "' is " + format_short(t.ny * t.dy) +
                               " m wide; the patch ('Green's functions/Patch width' = " +
                               format_short(green.patch.width) + " m) needs " +
                               format_short(needed_width) + " m");
            const double usable = t.length() - green.patch.length - 2. * t.dx;
            if (rolling.distance > usable)
              throw InputError("parameter 'Rolling/Distance' = " + format_short(rolling.distance) +
                               " m is longer than texture file '" + name + "' allows (" +
                               format_short(std::max(0., usable)) + " m: the file is " +
                               format_short(t.length()) + " m long, the patch " +
                               format_short(green.patch.length) + " m)");
            check_road_spacing("texture file '" + name + "'", t.dx, t.ny > 1 ? t.dy : 0.);
            texture_files.emplace(name, std::move(t));
          }

      // The built-in roads' samples ('flat' has no facets to refine; a
      // sinusoid is the same across).
      for (const auto &name : roads.roads)
        if (road::RoadTextureParameters::is_built_in(name) && name != "flat")
          check_road_spacing("parameter 'Road texture/Spacing' = " + format_number(roads.spacing) +
                               " m (road '" + name + "')",
                             roads.spacing, name == "sinusoid" ? 0. : roads.spacing);

      // The spectra of each run, checked now rather than after the run: the
      // time step must resolve the 100 Hz band, and the record must be long
      // enough for its Fourier lines to fall in that band.
      const auto lowest =
        analysis::third_octave_bands(analysis::lowest_band, analysis::lowest_band)[0];
      const double needed = 1. / (lowest.upper - lowest.lower);
      for (const auto &name : roads.roads)
        {
          for (const double speed_kmh : rolling.speeds)
            {
              const double V = speed_kmh / 3.6;
              const double top =
                analysis::top_band_for_step(rolling.time_step_for(road_spacing(name), V));
              if (sound.enabled() && sound.top_band > top * (1. + 1e-9))
                throw InputError(
                  "parameter 'Sound/Top band' = " + format_number(sound.top_band) +
                  " Hz is above the highest band of the runs of road '" + name + "' at " +
                  format_number(speed_kmh) + " km/h (" + format_number(top) +
                  " Hz, from their time step); allowed: up to " + format_number(top) + " Hz");
              if (rolling.distance / V < needed)
                throw InputError(
                  "parameter 'Rolling/Distance' = " + format_short(rolling.distance) + " m lasts " +
                  format_short(rolling.distance / V) + " s at " + format_number(speed_kmh) +
                  " km/h; the 100 Hz band of the spectra needs a record of at "
                  "least " +
                  format_short(needed) + " s; allowed: a distance >= " + format_short(needed * V) +
                  " m");
            }
        }
    }



    void
    TyreRoadContactScene::run()
    {
      namespace fs             = std::filesystem;
      const auto     start     = std::chrono::steady_clock::now();
      const fs::path directory = base::prepare_output_directory(global.output_directory);
      const auto     record =
        base::ParameterRecord::from(prm, global.scene, recorded_sections(global.scene));
      std::cout << "GreenTread: scene 'tyre-road-contact', dynamic contact of the rolling tyre "
                   "on road textures (Meftah et al. 2013, Section 5)\n";

      // Stages 1-3: geometry, fe, periodic: the Green's functions (saved).
      const std::string green_key = periodic::green_stage_key(prm, geometry.geo_file);
      const fs::path    h5        = directory / "green_functions.h5";
      std::unique_ptr<periodic::InflatedTyre> tyre;
      const base::FrequencyResponseMatrix     G =
        green_stage(geometry, green, h5, green_key, record, tyre);

      // Stage 4: modal, the patch model (saved too), and the error bars'
      // coarser levels of the modes and of the ring's section.
      std::optional<CoarserModel> coarser_model;
      const modal::PatchModel     model =
        modal_stage(geometry, G, green_key, directory, record, tyre.get(), &coarser_model);
      tyre.reset();
      const std::optional<CoarserSection> section = coarser_section(directory, record);

      // The contact grid, its lattice, the tread's own heights and the
      // structure's static compliance, which the static start uses.
      const contact::ContactGrid grid(
        model.points, contact_grid.subdivisions, tread_layer(),
        contact_grid.matrix_free(patch_model.source == modal::PatchModelSource::fe_modes,
                                 unsigned(model.points.size())),
        contact_grid.candidate_set(), contact_grid.tolerance);
      const analysis::PatchLattice lattice(grid.points, h5.string());
      const Eigen::VectorXd        heights = contact::tread_heights(grid.points);
      const Eigen::MatrixXd        G0      = synthesis::static_line(G);
      report_contact_setup(grid, model, G0);

      // The tread pattern and its finite blocks, for every level.
      const TreadStage tread = tread_stage(grid.points[0][2]);

      // The study: every road at every speed, and the error bars' levels.
      const analysis::Study study =
        analysis::plan_study(study_roads(grid), rolling, spectra, error_bars, grid.subdivisions,
                             richardson_factors(tread, coarser_model, section));

      // Stage road, and what each level's runs roll on.
      const CoarserGrid                             coarser(model.points, grid, tread_layer(),
                                                            study.needs(analysis::Discretisation::contact_grid));
      std::vector<std::unique_ptr<road::PatchRoad>> fine_roads, coarser_roads;
      std::vector<double>                           mpd;
      make_roads(study, grid, coarser.grid.get(), directory, record, fine_roads, coarser_roads,
                 mpd);
      const analysis::RunLevel  fine{&model,        &grid,
                                    &G0,           &heights,
                                    &lattice,      pointers(fine_roads),
                                    tread.of_road, tread.blocks.get()};
      const analysis::RunLevels levels{
        fine, other_levels(fine, coarser, coarser_roads, coarser_model, section, tread)};

      // Stage contact: the runs, side by side (base::for_each_index()).
      const std::vector<analysis::RunSpectrum> job_spectra =
        roll_study(study, levels, directory, record);

      // Stage analysis: each band from the run that gives it, with its error
      // bars; the spectra per road (speeds) and per speed (roads).
      analysis::write_spectra(
        directory, study.merge(job_spectra, rolling.stress_reference, spectra.lines_per_segment),
        run_roads, rolling.speeds, rolling.stress_reference, model.f_max, spectra, record);
      // The rolling resistance the texture adds, from every run, with the
      // time step's error bar.
      const std::vector<analysis::RunRollingResistance> resistance =
        study.rolling_resistance(job_spectra, mpd);
      analysis::print_rolling_resistance_errors(std::cout, resistance);
      analysis::write_rolling_resistance(directory, resistance, record);
      if (sound.enabled())
        sound_stage(study, job_spectra, model, directory, record);
      if (global.print_timings)
        std::cout << "Total run time " << format_printf("%.3g", base::seconds_since(start))
                  << " s\n";
    }



    std::vector<analysis::RunSpectrum>
    TyreRoadContactScene::roll_study(const analysis::Study       &study,
                                     const analysis::RunLevels   &levels,
                                     const std::filesystem::path &directory,
                                     const base::ParameterRecord &record) const
    {
      // The runs are independent, so they go side by side, one per thread,
      // each run's modal convolution on the threads left over (a run on one
      // thread is memory- and FFT-bound: a second thread on its modal sums
      // gained 10%). Each run's spectrum goes in its place in the list.
      const std::size_t  n_runs  = study.jobs.size();
      const unsigned int threads = dealii::MultithreadInfo::n_threads();
      const unsigned int side_by_side =
        static_cast<unsigned int>(std::max<std::size_t>(1, std::min<std::size_t>(threads, n_runs)));
      if (side_by_side > 1)
        std::cout << "  " << n_runs << " runs, " << side_by_side << " at a time\n";
      const analysis::RunSettings        settings{rolling,
                                           spectra,
                                           directory,
                                           record,
                                           global.print_timings,
                                           sound.enabled(),
                                           materials.tread_loss};
      std::vector<analysis::RunSpectrum> job_spectra(n_runs);
      base::for_each_index(n_runs, side_by_side, [&](const std::size_t k, unsigned int) {
        const analysis::StudyJob  &job = study.jobs[k];
        const analysis::StudyCase &c   = study.cases[job.study_case];
        job_spectra[k]                 = analysis::roll_run(
                          levels.of(study.level_of(k)), c.road, study.roads[c.road].name, c.speed_kmh, job.run,
                          settings, std::max(1u, threads / side_by_side), job.estimate < 0);
      });
      return job_spectra;
    }



    std::string
    TyreRoadContactScene::texture_of(const std::string &run_road) const
    {
      return tread_pattern.enabled() && tread_pattern.compare_with_slick ?
               analysis::texture_of_road(run_road) :
               run_road;
    }



    bool
    TyreRoadContactScene::patterned(const std::string &run_road) const
    {
      return tread_pattern.enabled() && texture_of(run_road) == run_road;
    }



    contact::ElasticLayer
    TyreRoadContactScene::tread_layer() const
    {
      return {materials.tread_E, materials.tread_nu, geometry.tread_thickness};
    }



    double
    TyreRoadContactScene::road_spacing(const std::string &road_name) const
    {
      const auto file = texture_files.find(texture_of(road_name));
      return file != texture_files.end() ? file->second.dx : roads.spacing;
    }



    void
    TyreRoadContactScene::check_road_spacing(const std::string &what,
                                             const double       dx,
                                             const double       dy) const
    {
      // The contact rectangle at the scene's subdivisions, from the
      // parameters (the grid is made after the Green's functions).
      constexpr double rectangles = 4.;
      const double     along =
        green.patch.length / (double(green.patch.points_along) * contact_grid.subdivisions);
      const double across =
        green.patch.width / (double(green.patch.points_across) * contact_grid.subdivisions);
      for (const auto &[name, spacing, rectangle] :
           {std::tuple<const char *, double, double>{"along", dx, along}, {"across", dy, across}})
        if (spacing > rectangles * rectangle * (1. + 1e-9))
          throw InputError(
            what + ": samples " + format_number(1e3 * spacing) + " mm apart " + name +
            " the road, too coarse for the contact grid's rectangles of " +
            format_printf("%.3g", 1e3 * rectangle) +
            " mm ('Contact grid/Subdivisions' = " + std::to_string(contact_grid.subdivisions) +
            "); allowed: at most " + format_printf("%.3g", 1e3 * rectangles * rectangle) +
            " mm (4 rectangles): the grid would refine straight facets "
            "between samples, which no error bar covers");
    }



    void
    TyreRoadContactScene::report_contact_setup(const contact::ContactGrid &grid,
                                               const modal::PatchModel    &model,
                                               const Eigen::MatrixXd      &G0) const
    {
      if (grid.subdivisions > 1)
        std::cout << "Contact grid: " << grid.nx << " x " << grid.ny << " = " << grid.n_points()
                  << " points, rectangles " << format_printf("%.3f", 1e3 * grid.dx) << " x "
                  << format_printf("%.3f", 1e3 * grid.dy) << " mm (" << grid.subdivisions << " x "
                  << grid.subdivisions << " per Green's-function rectangle, the tread as a "
                  << format_number(1e3 * geometry.tread_thickness) << " mm layer below it)\n";
      std::cout << "  the contact solved by "
                << (!grid.matrix_free  ? "block principal pivoting" :
                    grid.candidate_set ? "projected CG on the candidate points (matrix-free)" :
                                         "projected CG on the whole grid (matrix-free)")
                << " ('Contact grid/Solver' = " << contact_grid.solver << ")\n";
      const double along = spectra.reporting_along > 0. ? spectra.reporting_along : grid.coarse_dx;
      const double across =
        spectra.reporting_across > 0. ? spectra.reporting_across : grid.coarse_dy;
      std::cout << "  the stress at the patch centre: the mean over a "
                << format_printf("%.3g", 1e3 * along) << " x "
                << format_printf("%.3g", 1e3 * across)
                << " mm cell ('Spectra/Reporting cell along', 'across'), nulls at V / "
                << format_printf("%.3g", 1e3 * along) << " mm\n";
      std::cout << "  the model's static compliance differs from the structure's by "
                << format_printf("%.2g", (model.static_compliance() - G0).cwiseAbs().maxCoeff() /
                                           G0.cwiseAbs().maxCoeff())
                << " (largest, relative)\n";
    }



    std::vector<analysis::StudyRoad>
    TyreRoadContactScene::study_roads(const contact::ContactGrid &grid) const
    {
      std::vector<analysis::StudyRoad> study_roads;
      for (const auto &name : run_roads)
        {
          const auto file = texture_files.find(texture_of(name));
          // A texture file bounds the runs by the length its points can roll.
          const double longest =
            file == texture_files.end() ?
              spectra.longest_distance :
              std::min(
                spectra.longest_distance,
                road::PatchRoad(file->second, grid.points, roads.sampling, name).usable_length());
          study_roads.push_back({name, road_spacing(name), longest, file != texture_files.end(),
                                 patterned(name) && tread_pattern.finite_blocks()});
        }
      return study_roads;
    }



    void
    TyreRoadContactScene::make_roads(const analysis::Study                         &study,
                                     const contact::ContactGrid                    &grid,
                                     const contact::ContactGrid                    *coarser,
                                     const std::filesystem::path                   &directory,
                                     const base::ParameterRecord                   &record,
                                     std::vector<std::unique_ptr<road::PatchRoad>> &fine_roads,
                                     std::vector<std::unique_ptr<road::PatchRoad>> &coarser_roads,
                                     std::vector<double>                           &mpd) const
    {
      // The slick tyre's runs on a road (run_roads) share its texture, made once.
      std::map<std::string, double> mpd_of;
      for (std::size_t r = 0; r < run_roads.size(); ++r)
        {
          const std::string road_name = texture_of(run_roads[r]);
          const bool        made      = mpd_of.count(road_name) > 0;
          double            length    = 0.;
          for (std::size_t o = 0; o < run_roads.size(); ++o)
            if (texture_of(run_roads[o]) == road_name)
              length = std::max(length, study.road_length[o]);
          if (made && r > 0 && texture_of(run_roads[r - 1]) == road_name)
            {
              // The same profiles under the same points as the road before.
              fine_roads.push_back(std::make_unique<road::PatchRoad>(*fine_roads.back()));
              mpd.push_back(mpd_of[road_name]);
              if (coarser != nullptr)
                coarser_roads.push_back(std::make_unique<road::PatchRoad>(*coarser_roads.back()));
              continue;
            }
          // The texture's width from the patch's, not the grid's: every
          // contact grid rolls on the same realisation; its length what the
          // longest run needs (the patch and a margin of 0.1 m beyond it).
          const double width = green.patch.width + 0.03;
          std::cout << "Road '" << road_name << "'\n";
          const auto          file = texture_files.find(road_name);
          const road::Texture texture =
            file != texture_files.end() ?
              file->second :
              roads.make(road_name, width, length + green.patch.length + 0.1);
          // A road's runs need its profiles under the points only, not the
          // texture (6 MB per metre).
          fine_roads.push_back(
            std::make_unique<road::PatchRoad>(texture, grid.points, roads.sampling, road_name));
          mpd.push_back(analysis::write_road_report(directory, road_name, texture, record));
          mpd_of[road_name] = mpd.back();
          if (coarser != nullptr)
            coarser_roads.push_back(std::make_unique<road::PatchRoad>(texture, coarser->points,
                                                                      roads.sampling, road_name));
        }
    }
  } // namespace scenes
} // namespace greentread
