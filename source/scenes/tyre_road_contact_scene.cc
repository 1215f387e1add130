#include <greentread/analysis/error_bars.h>
#include <greentread/analysis/mode_output.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/base/progress.h>
#include <greentread/contact/contact_parameters.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/contact/rolling.h>
#include <greentread/modal/passivity.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/scenes/tyre_road_contact_scene.h>
#include <greentread/synthesis/mode_stage.h>
#include <greentread/synthesis/mode_synthesis.h>
#include <greentread/synthesis/mode_truncation.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <tuple>

namespace greentread
{
  namespace scenes
  {
    namespace
    {
      /**
       * The highest band of a run's spectrum: 5 kHz, or the highest band
       * below the Nyquist frequency 1 / (2 dt) of a coarser time step.
       * @throws InputError naming 'Time stepping/Time step' if not even the 100 Hz
       * band fits.
       */
      double
      spectrum_top_band(const double dt)
      {
        double top = 0.;
        for (const auto &band : analysis::third_octave_bands(100., 5000.))
          if (band.upper <= 0.5 / dt)
            top = band.nominal;
        if (top == 0.)
          throw InputError("parameter 'Time stepping/Time step' = " + format_short(dt) +
                           " s: the spectra need frequencies up to at least 112 Hz (the 100 Hz "
                           "band); allowed: a time step <= " +
                           format_short(0.5 / analysis::third_octave_bands(100., 100.)[0].upper) +
                           " s");
        return top;
      }

      /// The error bars' coarser contact grid ('Contact grid/Subdivisions'
      /// halved), when some road and speed estimates the grid: its points'
      /// lattice and tread heights too.
      struct CoarserGrid
      {
        std::unique_ptr<contact::ContactGrid>   grid;
        std::unique_ptr<analysis::PatchLattice> lattice;
        Eigen::VectorXd                         tread;

        CoarserGrid(const std::vector<std::array<double, 3>>              &coarse_points,
                    const contact::ContactGrid                            &fine,
                    const contact::ElasticLayer                           &layer,
                    const std::vector<std::vector<analysis::EstimateRun>> &estimates)
        {
          bool wanted = false;
          for (const auto &of_run : estimates)
            for (const auto &e : of_run)
              wanted = wanted || e.what == analysis::Discretisation::contact_grid;
          if (!wanted)
            return;
          grid = std::make_unique<contact::ContactGrid>(coarse_points, fine.subdivisions / 2, layer,
                                                        fine.matrix_free, fine.candidate_set);
          lattice =
            std::make_unique<analysis::PatchLattice>(grid->points, "the coarser contact grid");
          tread = contact::tread_heights(grid->points);
        }
      };
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
      // The solver against the patch model, refused now rather than after
      // the Green's functions.
      contact_grid.matrix_free(patch_model.source == modal::PatchModelSource::fe_modes,
                               green.patch.points_along * green.patch.points_across);

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
            texture_files.emplace(name, std::move(t));
          }

      // The spectra of each run, checked now rather than after the run: the
      // time step must resolve the 100 Hz band, and the record must be long
      // enough for its Fourier lines to fall in that band.
      const auto   lowest = analysis::third_octave_bands(100., 100.)[0];
      const double needed = 1. / (lowest.upper - lowest.lower);
      for (const auto &name : roads.roads)
        {
          const auto   file    = texture_files.find(name);
          const double spacing = file != texture_files.end() ? file->second.dx : roads.spacing;
          for (const double speed_kmh : rolling.speeds)
            {
              const double V  = speed_kmh / 3.6;
              const double dt = rolling.time_step > 0. ? rolling.time_step : spacing / V;
              spectrum_top_band(dt);
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

      // Stage 4: modal, the patch model (saved too).
      std::optional<CoarserModel> coarser_model;
      const modal::PatchModel     model =
        modal_stage(geometry, G, green_key, directory, record, tyre.get(), &coarser_model);
      tyre.reset();
      // The error bars' coarser section: its own two stages.
      const std::optional<CoarserSection> section = coarser_section(directory, record);

      // The contact grid (the Green's functions' points, or finer with the
      // tread's layer below them), its lattice, the tread's own height (its
      // curvature along x) and the structure's static compliance, which the
      // static start uses.
      const contact::ContactGrid grid(
        model.points, contact_grid.subdivisions,
        {materials.tread_E, materials.tread_nu, geometry.tread_thickness},
        contact_grid.matrix_free(patch_model.source == modal::PatchModelSource::fe_modes,
                                 unsigned(model.points.size())),
        contact_grid.candidate_set(), contact_grid.tolerance);
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
      {
        const double along =
          spectra.reporting_along > 0. ? spectra.reporting_along : grid.coarse_dx;
        const double across =
          spectra.reporting_across > 0. ? spectra.reporting_across : grid.coarse_dy;
        std::cout << "  the stress at the patch centre: the mean over a "
                  << format_printf("%.3g", 1e3 * along) << " x "
                  << format_printf("%.3g", 1e3 * across)
                  << " mm cell ('Spectra/Reporting cell along', 'across'), nulls at V / "
                  << format_printf("%.3g", 1e3 * along) << " mm\n";
      }
      const analysis::PatchLattice lattice(grid.points, h5.string());
      const Eigen::VectorXd        tread = contact::tread_heights(grid.points);
      const Eigen::MatrixXd        G0    = synthesis::static_line(G);
      const double                 static_mismatch =
        (model.static_compliance() - G0).cwiseAbs().maxCoeff() / G0.cwiseAbs().maxCoeff();
      std::cout << "  the model's static compliance differs from the structure's by "
                << format_printf("%.2g", static_mismatch) << " (largest, relative)\n";

      // Stages road and contact: every road at every speed. The roads are
      // made first; the runs are independent, so they go side by side, one
      // per thread (each run's modal convolution then on the threads left
      // over), and their spectra are kept in the order of the roads and
      // speeds. A run on one thread is memory- and FFT-bound, and a second
      // thread on its modal sums gained 10% (1.1 cores used): two runs at
      // once use both cores.
      // A road's runs need its profiles under the points only, not the
      // texture (6 MB per metre).
      struct RoadOfRuns
      {
        std::string                      name;
        road::PatchRoad                  patch_road;
        std::unique_ptr<road::PatchRoad> coarser; ///< under the coarser grid's points
      };
      // Each road at each speed: the run at the scene's step and, for the
      // low bands, a longer one at a coarser step (analysis::plan_band_runs()).
      struct Job
      {
        std::size_t       road, speed;
        analysis::BandRun run;
        /// -1, or the index of the error bars' other level it is.
        int estimate = -1;
      };
      std::vector<Job>                            jobs;
      std::vector<std::vector<analysis::BandRun>> plans;
      // The error bars' coarser levels of each road and speed's runs.
      std::vector<std::vector<analysis::EstimateRun>> estimates;
      std::vector<double>                             road_length(roads.roads.size(), 0.);
      for (std::size_t r = 0; r < roads.roads.size(); ++r)
        {
          const auto   file    = texture_files.find(roads.roads[r]);
          const double spacing = file != texture_files.end() ? file->second.dx : roads.spacing;
          // A texture file bounds the low-rate run by the length its points
          // can roll over.
          analysis::SpectraParameters limits = spectra;
          if (file != texture_files.end())
            limits.longest_distance =
              std::min(spectra.longest_distance,
                       road::PatchRoad(file->second, grid.points, roads.sampling, roads.roads[r])
                         .usable_length());
          for (std::size_t v = 0; v < rolling.speeds.size(); ++v)
            {
              const double V  = rolling.speeds[v] / 3.6;
              const double dt = rolling.time_step > 0. ? rolling.time_step : spacing / V;
              plans.push_back(
                analysis::plan_band_runs(limits, V, dt, rolling.distance, spectrum_top_band(dt)));
              for (const auto &run : plans.back())
                {
                  if (run.target_out_of_reach)
                    std::cout << "  " << roads.roads[r] << " at "
                              << format_number(rolling.speeds[v])
                              << " km/h: the low-rate run stops at " << format_short(run.distance)
                              << " m ('Spectra/Longest distance'"
                              << (file != texture_files.end() ? ", or the texture file's length" :
                                                                "")
                              << "), short of the standard error target\n";
                  jobs.push_back({r, v, run});
                  // As long as the run may extend to ('Spectra/Extend runs').
                  road_length[r] =
                    std::max({road_length[r], run.distance, run.longest_steps * V * run.time_step});
                }
              estimates.push_back(analysis::plan_estimate_runs(
                plans.back(), error_bars, spectra.target_from, V, grid.subdivisions));
              auto &e = estimates.back();
              e.erase(std::remove_if(e.begin(), e.end(),
                                     [&](const analysis::EstimateRun &x) {
                                       return (x.what == analysis::Discretisation::mode_cutoff &&
                                               !coarser_model) ||
                                              (x.what == analysis::Discretisation::ring_section &&
                                               !section);
                                     }),
                      e.end());
              for (std::size_t k = 0; k < e.size(); ++k)
                {
                  if (e[k].what == analysis::Discretisation::mode_cutoff)
                    e[k].factor = coarser_model->factor;
                  if (e[k].what == analysis::Discretisation::ring_section)
                    e[k].factor = section->factor;
                  if (e[k].run.steps > 0)
                    jobs.push_back({r, v, e[k].run, int(k)});
                }
            }
        }
      // The error bars' coarser grid (its road under its own points).
      const CoarserGrid coarser(model.points, grid,
                                {materials.tread_E, materials.tread_nu, geometry.tread_thickness},
                                estimates);
      // The longest runs first, so that two threads end together.
      std::stable_sort(jobs.begin(), jobs.end(), [](const Job &a, const Job &b) {
        return a.run.steps > b.run.steps;
      });

      std::vector<std::unique_ptr<RoadOfRuns>> road_list;
      for (std::size_t r = 0; r < roads.roads.size(); ++r)
        {
          const std::string &road_name = roads.roads[r];
          // The texture's width from the patch's, not the grid's: every
          // contact grid rolls on the same realisation; its length what the
          // longest run needs (the patch and a margin of 0.1 m beyond it).
          const double width = green.patch.width + 0.03;
          std::cout << "Road '" << road_name << "'\n";
          const auto    file = texture_files.find(road_name);
          road::Texture texture =
            file != texture_files.end() ?
              file->second :
              roads.make(road_name, width, road_length[r] + green.patch.length + 0.1);
          road::PatchRoad patch_road(texture, grid.points, roads.sampling, road_name);
          analysis::write_road_report(directory, road_name, texture, record);
          road_list.push_back(std::make_unique<RoadOfRuns>(
            RoadOfRuns{road_name, std::move(patch_road),
                       coarser.grid ? std::make_unique<road::PatchRoad>(
                                        texture, coarser.grid->points, roads.sampling, road_name) :
                                      nullptr}));
        }
      const std::size_t  n_runs  = jobs.size();
      const unsigned int threads = dealii::MultithreadInfo::n_threads();
      const unsigned int side_by_side =
        static_cast<unsigned int>(std::max<std::size_t>(1, std::min<std::size_t>(threads, n_runs)));
      std::vector<analysis::RunSpectrum> job_spectra(n_runs);
      std::vector<std::exception_ptr>    failures(n_runs);
      std::atomic<std::size_t>           next{0};
      std::atomic<unsigned int>          done{0};
      std::atomic<bool>                  failed{false};
      if (side_by_side > 1)
        std::cout << "  " << n_runs << " runs, " << side_by_side << " at a time\n";
      base::run_on_threads(
        side_by_side,
        [&]() {
          for (std::size_t k; !failed && (k = next++) < n_runs;)
            {
              const RoadOfRuns &r = *road_list[jobs[k].road];
              try
                {
                  const Job &job = jobs[k];
                  // The discretisation this run is the other level of, if any.
                  const auto is = [&](const analysis::Discretisation d) {
                    return job.estimate >= 0 &&
                           estimates[job.road * rolling.speeds.size() + job.speed][job.estimate]
                               .what == d;
                  };
                  const bool on_coarser_grid    = is(analysis::Discretisation::contact_grid);
                  const bool on_coarser_section = is(analysis::Discretisation::ring_section);
                  job_spectra[k]                = roll(
                                   is(analysis::Discretisation::mode_cutoff) ? coarser_model->model :
                                   on_coarser_section                        ? section->model :
                                                                               model,
                    on_coarser_grid ? *coarser.grid : grid, on_coarser_section ? section->G0 : G0,
                    on_coarser_grid ? coarser.tread : tread,
                    on_coarser_grid ? *coarser.lattice : lattice,
                    on_coarser_grid ? *r.coarser : r.patch_road, r.name, rolling.speeds[job.speed],
                    job.run, directory, record, std::max(1u, threads / side_by_side),
                    job.estimate < 0);
                }
              catch (...)
                {
                  failures[k] = std::current_exception();
                  failed      = true;
                }
              ++done;
            }
        },
        done, n_runs, nullptr,
        [&]() {
          return failed.load();
        });
      for (const auto &f : failures)
        if (f)
          std::rethrow_exception(f);

      // Each band from the run that fits it, in the order of the roads and speeds.
      std::vector<analysis::RunSpectrum> run_spectra;
      for (std::size_t r = 0; r < roads.roads.size(); ++r)
        for (std::size_t v = 0; v < rolling.speeds.size(); ++v)
          {
            const auto job_of = [&](const std::string &name) {
              return std::find_if(jobs.begin(), jobs.end(),
                                  [&](const Job &j) {
                                    return j.road == r && j.speed == v && j.run.name == name;
                                  }) -
                     jobs.begin();
            };
            analysis::RunSpectrum merged = job_spectra[job_of("")];
            const auto           &plan   = plans[r * rolling.speeds.size() + v];
            std::vector<bool>     used(plan.size(), true);
            for (std::size_t i = 1; i < plan.size(); ++i)
              {
                const auto &low = job_spectra[job_of(plan[i].name)];
                std::string disagreement =
                  analysis::low_rate_disagreement(merged.spectrum, low.spectrum, plan[i]);
                if (disagreement.empty())
                  disagreement = analysis::low_rate_disagreement(merged.force_spectrum,
                                                                 low.force_spectrum, plan[i]);
                if (!disagreement.empty())
                  {
                    std::cout << "Warning: " << roads.roads[r] << " at "
                              << format_number(rolling.speeds[v]) << " km/h: the low-rate run ("
                              << format_short(1e6 * plan[i].time_step)
                              << " us, 'Spectra/Low-band time step') disagrees with the run at "
                                 "the scene's step in "
                              << disagreement
                              << "; its bands are not used (a smaller 'Spectra/Low-band time "
                                 "step' may suit this contact)\n";
                    used[i] = false;
                    continue;
                  }
                merged.spectrum =
                  analysis::merge_band_spectra(merged.spectrum, low.spectrum, plan[i]);
                merged.force_spectrum =
                  analysis::merge_band_spectra(merged.force_spectrum, low.force_spectrum, plan[i]);
              }
            analysis::add_error_bars(
              merged, estimates[r * rolling.speeds.size() + v], plan, used,
              [&](const std::string &name) -> const analysis::RunSpectrum & {
                return job_spectra[job_of(name)];
              },
              rolling.stress_reference, spectra.lines_per_segment);
            run_spectra.push_back(std::move(merged));
          }

      // Stage analysis: the spectra per road (speeds) and per speed (roads).
      analysis::write_spectra(directory, run_spectra, roads.roads, rolling.speeds,
                              rolling.stress_reference, model.f_max, spectra, record);
      if (global.print_timings)
        std::cout
          << "Total run time "
          << format_printf(
               "%.3g",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count())
          << " s\n";
    }



  } // namespace scenes
} // namespace greentread
