#include <greentread/analysis/rolling_output.h>
#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/progress.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/contact/rolling.h>
#include <greentread/scenes/tyre_road_contact_scene.h>

#include <chrono>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>
#include <utility>

/**
 * @file
 * One rolling run of the tyre-road-contact scene: the road under the
 * points, the static start, the rolling and its outputs.
 */

namespace greentread
{
  namespace scenes
  {
    namespace
    {
      /// The results of one run that its report needs.
      struct RunResult
      {
        double       seconds = 0., mean_force = 0.;
        unsigned int failed_steps = 0, fallback_points = 0;
        double       max_contact_fraction = 0., min_contact_fraction = 1.;
      };
    } // namespace



    analysis::RunSpectrum
    TyreRoadContactScene::roll(const modal::PatchModel      &model,
                               const contact::ContactGrid   &grid,
                               const Eigen::MatrixXd        &G0,
                               const Eigen::VectorXd        &tread,
                               const analysis::PatchLattice &lattice,
                               const road::PatchRoad        &patch_road,
                               const std::string            &road_name,
                               const double                  speed_kmh,
                               const analysis::BandRun      &band_run,
                               const std::filesystem::path  &directory,
                               const base::ParameterRecord  &record,
                               const unsigned int            threads,
                               const bool                    write_outputs) const
    {
      const double V       = speed_kmh / 3.6;
      const double dt      = band_run.time_step;
      unsigned int n_steps = band_run.steps; // the steps rolled, once extended
      if (band_run.distance > patch_road.usable_length())
        throw InputError("parameter 'Rolling/Distance' = " + format_short(band_run.distance) +
                         " m is longer than road '" + road_name + "' allows (" +
                         format_short(patch_road.usable_length()) + " m once the patch is on it)");
      const std::string run = analysis::road_label(road_name) + "_" +
                              analysis::speed_label(speed_kmh) +
                              (band_run.name.empty() ? "" : "_" + band_run.name);
      // What the run prints goes out in whole blocks (runs go side by side).
      std::ostringstream out;
      const auto         print = [&out]() {
        static std::mutex                 mutex;
        const std::lock_guard<std::mutex> lock(mutex);
        std::cout << out.str() << std::flush;
        out.str("");
      };
      out << "  run " << run << ": V0 = " << format_number(speed_kmh)
          << " km/h, dt = " << format_printf("%.4g", 1e6 * dt) << " us, "
          << format_short(band_run.distance) << " m, " << n_steps << " steps, "
          << convolution::to_string(rolling.convolution)
          << (band_run.name.empty() ?
                "" :
                ", for the bands up to " + format_number(band_run.f_high) + " Hz")
          << '\n';
      print();
      const auto         t_run    = std::chrono::steady_clock::now();
      const double       top_band = band_run.f_high;
      const unsigned int n_p      = grid.n_points();

      // The road under the points, the static start and the run's set-up.
      const contact::PatchRoadHeights road_heights = [&](const double s, Eigen::VectorXd &z,
                                                         Eigen::VectorXd &slope) {
        patch_road.heights(s, z, slope);
      };
      contact::RollingSetup setup;
      setup.speed            = V;
      setup.time_step        = dt;
      setup.n_steps          = n_steps;
      setup.static_load      = rolling.static_load;
      setup.indentation      = rolling.indentation;
      setup.static_start     = rolling.static_start;
      setup.convolution      = rolling.convolution;
      setup.direct_kernel    = rolling.direct_kernel;
      setup.threads          = threads;
      setup.shape_precision  = rolling.shape_precision;
      const auto equilibrium = contact::start_grid_contact(grid, G0, tread, road_heights, setup);
      out << "    " << run << ": static contact: indentation "
          << format_printf("%.4g", 1e3 * equilibrium.delta) << " mm, load "
          << format_printf("%.4g", equilibrium.q.sum()) << " N, " << equilibrium.n_contact << " of "
          << n_p << " points in contact\n";
      const double          tributary = patch_road.dx_points * patch_road.dy_points;
      const Eigen::VectorXd reporting =
        grid.reporting_weights(spectra.reporting_along, spectra.reporting_across);

      RunResult result;
      // An error-bar run (the other level of a discretisation) keeps its
      // histories only.
      std::optional<analysis::RunOutput> output;
      if (write_outputs)
        output.emplace(directory, run, lattice, V, tributary, reporting, n_steps, rolling.frames,
                       record);
      std::vector<double> centre, force;
      centre.reserve(n_steps);
      force.reserve(n_steps);
      base::Progress progress("    " + run, n_steps);
      const auto     observe = [&](const contact::RollingStep &step) {
        if (!step.report.converged && result.failed_steps < 5)
          out << "    step " << step.step << " (" << run << ", t = " << format_short(step.time)
              << " s): the contact solve did not converge: " << step.report.message << '\n';
        result.failed_steps += step.report.converged ? 0 : 1;
        if (output)
          output->add(step);
        centre.push_back(reporting.dot(step.force) / tributary);
        force.push_back(step.force.sum());
        if (global.print_timings)
          progress.update(step.step + 1);
      };
      const auto convolution = contact::make_grid_convolution(
        contact::make_patch_convolution(setup.convolution, model, dt, n_steps, setup.direct_kernel,
                                        setup.threads, setup.shape_precision),
        grid);
      // On past the planned record while the observed standard errors miss
      // the target ('Spectra/Extend runs'), as far as the road allows.
      // (Not the direct convolution: its kernels have the planned length.)
      analysis::BandRun extensible = band_run;
      extensible.longest_steps     = std::min<double>(
        band_run.longest_steps, std::floor(patch_road.usable_length() / (V * dt) * (1. + 1e-9)));
      if (setup.convolution == convolution::Method::direct)
        extensible.longest_steps = 0;
      const auto stress_spectrum = [&] {
        return analysis::welch_band_spectrum(centre, dt, rolling.stress_reference, 100., top_band,
                                             spectra.lines_per_segment);
      };
      const auto force_spectrum = [&] {
        return analysis::welch_band_spectrum(force, dt, 1., 100., top_band,
                                             spectra.lines_per_segment);
      };
      // The spectra of the last check, when it ended the run: the run's own.
      std::optional<std::pair<analysis::BandSpectrum, analysis::BandSpectrum>> final_spectra;
      std::string                                                              extended;
      const auto more_steps = [&](const unsigned int done) -> unsigned int {
        if (extensible.longest_steps <= done)
          return 0;
        auto               stress_so_far = stress_spectrum(), force_so_far = force_spectrum();
        const unsigned int more =
          analysis::more_steps_for_target(spectra, extensible, stress_so_far, force_so_far, done);
        if (more == 0)
          final_spectra.emplace(std::move(stress_so_far), std::move(force_so_far));
        else
          {
            extended +=
              (extended.empty() ? "" : ", ") + format_printf("%.3g", (done + more) * V * dt) + " m";
            progress.extend(done + more);
          }
        return more;
      };
      const auto summary     = contact::roll_patch(*convolution, tread, road_heights, equilibrium,
                                                   setup, observe, more_steps);
      n_steps                = summary.steps;
      result.fallback_points = summary.fallback_points;
      result.min_contact_fraction = summary.min_contact_fraction;
      result.max_contact_fraction = summary.max_contact_fraction;
      const double impulse_total  = summary.impulse;
      progress.finish();
      result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_run).count();
      result.mean_force = impulse_total / (n_steps * dt);
      if (!extended.empty())
        out << "    " << run << ": extended to " << extended
            << " for the standard error target ('Spectra/Extend runs'): "
            << format_short(n_steps * V * dt) << " m, " << n_steps << " steps"
            << (n_steps >= extensible.longest_steps ?
                  " (its longest: 'Spectra/Longest distance', or 3 times its plan, or the road)" :
                  "")
            << '\n';
      if (band_run.name.empty() && top_band < 5000.)
        out << "    the spectrum ends at the " << format_number(top_band)
            << " Hz band: dt = " << format_printf("%.4g", 1e6 * dt) << " us resolves up to "
            << format_printf("%.0f", 0.5 / dt) << " Hz\n";
      analysis::RunSpectrum spectra_of_run{road_name, speed_kmh, {}, {}, centre, force, dt};
      if (write_outputs)
        {
          if (!final_spectra)
            final_spectra.emplace(stress_spectrum(), force_spectrum());
          spectra_of_run.spectrum       = std::move(final_spectra->first);
          spectra_of_run.force_spectrum = std::move(final_spectra->second);
        }
      out << "    " << run << ": mean total force " << format_printf("%.4g", result.mean_force)
          << " N (static " << format_printf("%.4g", equilibrium.q.sum())
          << " N), points in contact " << format_printf("%.0f", 100. * result.min_contact_fraction)
          << "% to " << format_printf("%.0f", 100. * result.max_contact_fraction)
          << "%, largest penetration at a step's end "
          << format_printf("%.2g", summary.max_penetration)
          << " m, steps the contact solve did not converge: " << result.failed_steps
          << ", point-steps on the fallback: " << result.fallback_points << '\n';
      if (global.print_timings)
        out << "    " << run << ": " << format_printf("%.3g", result.seconds) << " s, "
            << format_printf("%.3g", 1e3 * result.seconds / n_steps) << " ms per step\n";

      if (output)
        output->finish("Road " + road_name + ", " + format_number(speed_kmh) + " km/h");
      print();
      return spectra_of_run;
    }
  } // namespace scenes
} // namespace greentread
