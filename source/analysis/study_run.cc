#include <greentread/analysis/study_run.h>
#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/progress.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/contact/rolling.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>
#include <utility>

namespace greentread
{
  namespace analysis
  {
    namespace
    {
      /// What a run prints, sent out in whole blocks (runs go side by side).
      struct RunPrinter
      {
        std::ostringstream out;

        void
        flush()
        {
          static std::mutex                 mutex;
          const std::lock_guard<std::mutex> lock(mutex);
          std::cout << out.str() << std::flush;
          out.str("");
        }
      };

      /// The contact set-up of a run from the scene's 'Rolling' parameters.
      contact::RollingSetup
      rolling_setup(const contact::RollingParameters &rolling,
                    const BandRun                    &band_run,
                    const double                      V,
                    const unsigned int                threads)
      {
        contact::RollingSetup setup;
        setup.speed           = V;
        setup.time_step       = band_run.time_step;
        setup.n_steps         = band_run.steps;
        setup.static_load     = rolling.static_load;
        setup.indentation     = rolling.indentation;
        setup.static_start    = rolling.static_start;
        setup.convolution     = rolling.convolution;
        setup.direct_kernel   = rolling.direct_kernel;
        setup.threads         = threads;
        setup.shape_precision = rolling.shape_precision;
        return setup;
      }

      /// The record of one run, step by step, and its extension while its
      /// observed standard errors miss the target ('Spectra/Extend runs').
      struct RunRecord
      {
        const SpectraParameters &spectra;
        double                   stress_reference, dt, V;
        BandRun                  extensible;
        std::vector<double>      centre, force;
        /// The spectra of the last check, when it ended the run.
        std::optional<std::pair<BandSpectrum, BandSpectrum>> final_spectra;
        std::string                                          extended; ///< "2.5 m, 3.1 m"

        BandSpectrum
        stress_spectrum() const
        {
          return welch_band_spectrum(centre, dt, stress_reference, lowest_band, extensible.f_high,
                                     spectra.lines_per_segment);
        }

        BandSpectrum
        force_spectrum() const
        {
          return welch_band_spectrum(force, dt, 1., lowest_band, extensible.f_high,
                                     spectra.lines_per_segment);
        }

        /// The steps to roll on after @p done (0: the run ends).
        unsigned int
        more_steps(const unsigned int done, base::Progress &progress)
        {
          if (extensible.longest_steps <= done)
            return 0;
          auto               stress_so_far = stress_spectrum(), force_so_far = force_spectrum();
          const unsigned int more =
            more_steps_for_target(spectra, extensible, stress_so_far, force_so_far, done);
          if (more == 0)
            final_spectra.emplace(std::move(stress_so_far), std::move(force_so_far));
          else
            {
              extended += (extended.empty() ? "" : ", ") +
                          format_printf("%.3g", (done + more) * V * dt) + " m";
              progress.extend(done + more);
            }
          return more;
        }
      };

      /// The lines a run prints at its end.
      void
      report_run(std::ostream                  &out,
                 const std::string             &run,
                 const RunRecord               &record,
                 const contact::RollingSummary &summary,
                 const double                   static_load,
                 const unsigned int             failed_steps,
                 const double                   seconds,
                 const bool                     print_timings)
      {
        const double       dt = record.dt, V = record.V;
        const unsigned int n_steps = summary.steps;
        if (!record.extended.empty())
          out << "    " << run << ": extended to " << record.extended
              << " for the standard error target ('Spectra/Extend runs'): "
              << format_short(n_steps * V * dt) << " m, " << n_steps << " steps"
              << (n_steps >= record.extensible.longest_steps ?
                    " (its longest: 'Spectra/Longest distance', or 3 times its plan, or the road)" :
                    "")
              << '\n';
        const double top_band = record.extensible.f_high;
        if (record.extensible.name.empty() && top_band < highest_band)
          out << "    the spectrum ends at the " << format_number(top_band)
              << " Hz band: dt = " << format_printf("%.4g", 1e6 * dt) << " us resolves up to "
              << format_printf("%.0f", 0.5 / dt) << " Hz\n";
        const double mean_force = summary.impulse / (n_steps * dt);
        out << "    " << run << ": mean total force " << format_printf("%.4g", mean_force)
            << " N (static " << format_printf("%.4g", static_load) << " N), points in contact "
            << format_printf("%.0f", 100. * summary.min_contact_fraction) << "% to "
            << format_printf("%.0f", 100. * summary.max_contact_fraction)
            << "%, largest penetration at a step's end "
            << format_printf("%.2g", summary.max_penetration)
            << " m, steps the contact solve did not converge: " << failed_steps
            << ", point-steps on the fallback: " << summary.fallback_points << '\n';
        if (summary.candidate_steps > 0)
          out << "    " << run << ": candidate set: up to " << summary.max_candidates
              << " points; points joined it during the solve at " << summary.grown_steps << " of "
              << summary.candidate_steps << " steps, it started smaller than the last step's at "
              << summary.shrunk_steps << ", the whole grid solved instead at "
              << summary.whole_grid_steps << '\n';
        if (print_timings)
          out << "    " << run << ": " << format_printf("%.3g", seconds) << " s, "
              << format_printf("%.3g", 1e3 * seconds / n_steps) << " ms per step\n";
      }
    } // namespace



    RunSpectrum
    roll_run(const RunLevel    &level,
             const std::size_t  road,
             const std::string &road_name,
             const double       speed_kmh,
             const BandRun     &band_run,
             const RunSettings &settings,
             const unsigned int threads,
             const bool         write_outputs)
    {
      const contact::RollingParameters &rolling    = settings.rolling;
      const road::PatchRoad            &patch_road = *level.roads.at(road);
      const contact::ContactGrid       &grid       = *level.grid;
      const contact::TreadPattern      *pattern =
        road < level.patterns.size() ? level.patterns[road] : nullptr;
      const double V  = speed_kmh / 3.6;
      const double dt = band_run.time_step;
      if (band_run.distance > patch_road.usable_length())
        throw InputError("parameter 'Rolling/Distance' = " + format_short(band_run.distance) +
                         " m is longer than road '" + road_name + "' allows (" +
                         format_short(patch_road.usable_length()) + " m once the patch is on it)");
      const std::string run = road_label(road_name) + "_" + speed_label(speed_kmh) +
                              (band_run.name.empty() ? "" : "_" + band_run.name);
      RunPrinter printer;
      printer.out << "  run " << run << ": V0 = " << format_number(speed_kmh)
                  << " km/h, dt = " << format_printf("%.4g", 1e6 * dt) << " us, "
                  << format_short(band_run.distance) << " m, " << band_run.steps << " steps, "
                  << convolution::to_string(rolling.convolution)
                  << (band_run.name.empty() ?
                        "" :
                        ", for the bands up to " + format_number(band_run.f_high) + " Hz")
                  << '\n';
      printer.flush();
      const auto t_run = std::chrono::steady_clock::now();

      // The road under the points, the pattern's grooves and blocks at the
      // same position, the static start and the run's set-up.
      std::optional<contact::BlockState> blocks;
      if (pattern != nullptr && level.blocks != nullptr)
        blocks.emplace(*level.blocks, grid.points);
      const contact::PatchRoadHeights road_heights = [&](const double s, Eigen::VectorXd &z,
                                                         Eigen::VectorXd &slope) {
        patch_road.heights(s, z, slope);
        if (pattern != nullptr)
          pattern->recess(grid.points, s, z);
        if (blocks)
          blocks->set_position(s);
      };
      const contact::BlockState  *block_state = blocks ? &*blocks : nullptr;
      const contact::RollingSetup setup       = rolling_setup(rolling, band_run, V, threads);
      const auto equilibrium = contact::start_grid_contact(grid, *level.G0, *level.tread,
                                                           road_heights, setup, block_state);
      printer.out << "    " << run << ": static contact: indentation "
                  << format_printf("%.4g", 1e3 * equilibrium.delta) << " mm, load "
                  << format_printf("%.4g", equilibrium.q.sum()) << " N, " << equilibrium.n_contact
                  << " of " << grid.n_points() << " points in contact\n";
      const double          tributary = patch_road.dx_points * patch_road.dy_points;
      const Eigen::VectorXd reporting =
        grid.reporting_weights(settings.spectra.reporting_along, settings.spectra.reporting_across);

      // An error bar's other level keeps its histories only.
      std::optional<RunOutput> output;
      if (write_outputs)
        output.emplace(settings.directory, run, *level.lattice, V, tributary, reporting,
                       band_run.steps, rolling.frames, settings.record);
      RunRecord record{settings.spectra, rolling.stress_reference, dt, V, band_run, {}, {}, {}, {}};
      // On past the planned record as far as the road allows; not the direct
      // convolution, whose kernels have the planned length.
      record.extensible.longest_steps = std::min<double>(
        band_run.longest_steps, std::floor(patch_road.usable_length() / (V * dt) * (1. + 1e-9)));
      if (setup.convolution == convolution::Method::direct)
        record.extensible.longest_steps = 0;
      record.centre.reserve(band_run.steps);
      std::vector<std::vector<double>> point_forces;
      Eigen::VectorXd                  gathered;
      if (settings.point_forces && write_outputs)
        point_forces.resize(level.model->n_points());
      for (auto &history : point_forces)
        history.reserve(band_run.steps);
      record.force.reserve(band_run.steps);
      unsigned int      failed_steps = 0;
      RollingPowerMeter power(equilibrium.u, dt);
      // The tread's losses: the local term's displacement under each step's
      // end force, the finite blocks' at the step's position with it.
      power.track_tread_losses(
        settings.tread_loss_factor, V, TreadLossGrid{grid.nx, grid.ny, grid.dx},
        [&](const Eigen::VectorXd &f, Eigen::VectorXd &w) {
          w.setZero(f.size());
          grid.add_local(f, w);
          if (block_state != nullptr)
            block_state->add_product(f, w);
        },
        equilibrium.q);
      base::Progress progress("    " + run, band_run.steps);
      const auto     observe = [&](const contact::RollingStep &step) {
        if (!step.report.converged && failed_steps < 5)
          printer.out << "    step " << step.step << " (" << run
                      << ", t = " << format_short(step.time)
                      << " s): the contact solve did not converge: " << step.report.message << '\n';
        failed_steps += step.report.converged ? 0 : 1;
        if (output)
          output->add(step);
        record.centre.push_back(reporting.dot(step.force) / tributary);
        record.force.push_back(step.force.sum());
        power.add(step);
        if (!point_forces.empty())
          {
            grid.gather(step.force, gathered);
            for (std::size_t p = 0; p < point_forces.size(); ++p)
              point_forces[p].push_back(gathered[static_cast<Eigen::Index>(p)]);
          }
        if (settings.print_timings)
          progress.update(step.step + 1);
      };
      const auto convolution = contact::make_grid_convolution(
        contact::make_patch_convolution(setup.convolution, *level.model, dt, band_run.steps,
                                        setup.direct_kernel, setup.threads, setup.shape_precision),
        grid, block_state);
      const auto summary =
        contact::roll_patch(*convolution, *level.tread, road_heights, equilibrium, setup, observe,
                            [&](const unsigned int done) {
                              return record.more_steps(done, progress);
                            });
      progress.finish();
      report_run(printer.out, run, record, summary, equilibrium.q.sum(), failed_steps,
                 base::seconds_since(t_run), settings.print_timings);
      std::array<RollingResistance, 3> resistance;
      for (const PowerPart part : all_power_parts)
        resistance[static_cast<std::size_t>(part)] = power.result(V, 0.2, 10, part);
      const RollingResistance &sum = resistance[static_cast<std::size_t>(PowerPart::sum)];
      printer.out << "    " << run
                  << ": rolling resistance the texture adds: " << format_printf("%.4g", sum.force)
                  << " +- " << format_printf("%.2g", sum.force_error) << " N, C_RR "
                  << format_printf("%.3g", 1e3 * sum.coefficient) << " +- "
                  << format_printf("%.2g", 1e3 * sum.coefficient_error) << " x 1e-3, of which "
                  << format_printf("%.3g", 1e3 * resistance[0].coefficient)
                  << " into the structure and "
                  << format_printf("%.3g", 1e3 * resistance[1].coefficient)
                  << " the tread's losses (after the first "
                  << format_printf("%.3g", sum.skipped * V) << " m)\n";

      RunSpectrum spectra_of_run{road_name,
                                 speed_kmh,
                                 {},
                                 {},
                                 record.centre,
                                 record.force,
                                 dt,
                                 std::move(point_forces),
                                 run,
                                 resistance,
                                 power.step_work(),
                                 power.tread_step_work()};
      if (write_outputs)
        {
          if (!record.final_spectra)
            record.final_spectra.emplace(record.stress_spectrum(), record.force_spectrum());
          spectra_of_run.spectrum       = std::move(record.final_spectra->first);
          spectra_of_run.force_spectrum = std::move(record.final_spectra->second);
        }
      if (output)
        output->finish("Road " + road_name + ", " + format_number(speed_kmh) + " km/h");
      printer.flush();
      return spectra_of_run;
    }
  } // namespace analysis
} // namespace greentread
