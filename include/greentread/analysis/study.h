#pragma once

#include <greentread/analysis/band_runs.h>
#include <greentread/analysis/error_bar_parameters.h>
#include <greentread/analysis/error_bars.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/analysis/spectra_parameters.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/rolling_parameters.h>
#include <greentread/contact/tread_block.h>
#include <greentread/contact/tread_pattern.h>
#include <greentread/modal/patch_model.h>
#include <greentread/road/patch_road.h>

#include <Eigen/Core>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

/**
 * @file
 * The study of a tyre on its roads at its speeds: which runs each road and
 * speed needs (the band runs, and the error bars' other levels), what each
 * run rolls on, and the merge of their spectra into one per road and speed.
 * The scene only calls these. Implemented in source/analysis/study.cc; one
 * run in source/analysis/study_run.cc.
 */

namespace greentread
{
  namespace analysis
  {
    /// What a run rolls on: one level of the study's discretisations. The
    /// objects belong to the scene; every road has its profiles under this
    /// level's contact points.
    struct RunLevel
    {
      const modal::PatchModel    *model   = nullptr;
      const contact::ContactGrid *grid    = nullptr;
      const Eigen::MatrixXd      *G0      = nullptr; ///< static compliance [m/N]
      const Eigen::VectorXd      *tread   = nullptr; ///< the tread's own heights [m]
      const PatchLattice         *lattice = nullptr;
      /// By road, in the order of the study's roads.
      std::vector<const road::PatchRoad *> roads;
      /// By road: the tread pattern its runs roll (nullptr or none: slick).
      std::vector<const contact::TreadPattern *> patterns;
      /// The pattern's finite blocks (nullptr: the endless layer), for the
      /// roads with a pattern.
      const contact::BlockCompliance *blocks = nullptr;
    };

    /// The levels of a study: the run's own, and the other levels that roll
    /// on other inputs (a coarser grid, fewer modes, a coarser section).
    /// The time step's other level rolls on the run's own inputs.
    struct RunLevels
    {
      RunLevel                           fine;
      std::map<Discretisation, RunLevel> other;

      /// The inputs of a run that is the other level of @p d, or (nullopt)
      /// a run of the plan: the one place a run's inputs are chosen.
      const RunLevel &
      of(const std::optional<Discretisation> &d) const;
    };

    /// A road of a study, as its runs need it.
    struct StudyRoad
    {
      std::string name;
      double      spacing = 0.; ///< its samples' spacing along the road [m]
      /// The furthest its runs may roll [m]: 'Spectra/Longest distance', or
      /// less for a texture file.
      double longest_distance = 0.;
      bool   from_file        = false;
      /// Whether its runs roll a pattern's finite tread blocks (the only
      /// runs with a 'block mesh' estimate).
      bool finite_blocks = false;
    };

    /// One road at one speed: its band runs and their other levels.
    struct StudyCase
    {
      std::size_t              road = 0, speed = 0;
      double                   speed_kmh = 0.;
      std::vector<BandRun>     plan;      ///< plan_band_runs()
      std::vector<EstimateRun> estimates; ///< plan_estimate_runs(), those the scene has
    };

    /// One run of the study.
    struct StudyJob
    {
      std::size_t study_case = 0; ///< into Study::cases
      BandRun     run;
      /// -1, or the index of the case's estimate whose other level it is.
      int estimate = -1;
    };

    /**
     * @brief Every run of every road at every speed (one list, longest
     * first, so that threads taking them in order end together) and the
     * merge of their spectra.
     */
    struct Study
    {
      std::vector<StudyRoad> roads;
      std::vector<StudyCase> cases; ///< road by road, the speeds within
      std::vector<StudyJob>  jobs;
      /// The most each road's runs may roll, extensions included [m].
      std::vector<double> road_length;

      /// The discretisation job @p k is the other level of, if any.
      std::optional<Discretisation>
      level_of(std::size_t k) const;

      /// Whether some job is the other level of @p d.
      bool
      needs(Discretisation d) const;

      /**
       * @brief One spectrum per road and speed, in the order of #cases,
       * from @p job_spectra (one per job, in the order of #jobs): each band
       * from the run that gives it (a low-rate run that disagrees with the
       * run at the scene's step is left out, with a warning on standard
       * output), and the error bars added (add_error_bars()).
       */
      std::vector<RunSpectrum>
      merge(const std::vector<RunSpectrum> &job_spectra,
            double                          stress_reference,
            unsigned int                    lines_per_segment) const;

      /**
       * @brief Every job's rolling resistance (RunSpectrum::rolling_resistance),
       * in the order of #jobs, as rolling_resistance.csv lists it, @p mpd
       * giving each road's: each part of each run of the plan gets an error
       * bar from each of its other levels that was rolled
       * (rolling_resistance_level_error() on the part's work, part_work(),
       * over the level's window, scaled by rolling_resistance_factor()).
       */
      std::vector<RunRollingResistance>
      rolling_resistance(const std::vector<RunSpectrum> &job_spectra,
                         const std::vector<double>      &mpd) const;
    };

    /**
     * @brief The study of @p roads at @p rolling's speeds: each case's band
     * runs (plan_band_runs(), at the time step of @p rolling's
     * time_step_for()) and the error bars' other levels of @p error_bars
     * (plan_estimate_runs() on a grid of @p subdivisions), keeping only the
     * discretisations the scene can roll: the time step and contact grid
     * always, the mode cut-off and ring section when @p factors gives their
     * factor (which their estimates then carry). Prints a line for each
     * low-rate run that cannot meet the standard error target.
     */
    Study
    plan_study(const std::vector<StudyRoad>           &roads,
               const contact::RollingParameters       &rolling,
               const SpectraParameters                &spectra,
               const ErrorBarParameters               &error_bars,
               unsigned int                            subdivisions,
               const std::map<Discretisation, double> &factors);
  } // namespace analysis
} // namespace greentread
