#pragma once

#include <greentread/analysis/band_runs.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/analysis/spectra_parameters.h>
#include <greentread/analysis/study.h>
#include <greentread/base/output.h>
#include <greentread/contact/rolling_parameters.h>

#include <cstddef>
#include <filesystem>
#include <string>

/**
 * @file
 * One run of a study: the road under the points, the static start, the
 * rolling (extended while its standard errors miss the target) and its
 * outputs. Implemented in source/analysis/study_run.cc.
 */

namespace greentread
{
  namespace analysis
  {
    /// What every run of a study shares: the scene's parameters and where
    /// its outputs go.
    struct RunSettings
    {
      const contact::RollingParameters &rolling;
      const SpectraParameters          &spectra;
      const std::filesystem::path      &directory;
      const base::ParameterRecord      &record;
      bool                              print_timings = true;
      /// Keep each run's contact forces gathered on the Green's-function
      /// points (RunSpectrum::point_forces), for the sound.
      bool point_forces = false;
      /// The tread rubber's loss factor (`Materials/Tread pattern/Loss factor`), for
      /// the tread's small-scale losses (tread_losses.h).
      double tread_loss_factor = 0.;
    };

    /**
     * @brief One run: road @p road (index into @p level's roads, named
     * @p road_name) at @p speed_kmh, at the time step and over the distance
     * of @p band_run, on @p level's contact points, from the static contact
     * under @p level's static compliance; returns its spectrum. Its modal
     * convolution runs on @p threads threads. Runs may go side by side: a
     * run prints its lines in whole blocks. Without @p write_outputs (an
     * error bar's other level) it keeps its histories only.
     * @throws InputError if @p band_run is longer than the road allows.
     */
    RunSpectrum
    roll_run(const RunLevel    &level,
             std::size_t        road,
             const std::string &road_name,
             double             speed_kmh,
             const BandRun     &band_run,
             const RunSettings &settings,
             unsigned int       threads,
             bool               write_outputs);
  } // namespace analysis
} // namespace greentread
