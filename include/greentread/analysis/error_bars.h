#pragma once

#include <greentread/analysis/band_runs.h>
#include <greentread/analysis/error_bar_parameters.h>
#include <greentread/analysis/third_octave.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

/**
 * @file
 * Discretisation error bars of band levels: each discretisation's error in
 * each band, estimated from one other level on the same road, from the
 * same start, over a short window of the run, and scaled by the order
 * (Richardson). Implemented in source/analysis/error_bars.cc; the method,
 * its orders and its check against refined runs are in
 * doc/methods/analysis.md.
 *
 * The other level's run and the run roll the same texture from the same
 * static start, so their band levels over the same window differ by the
 * discretisation and little else: the difference's statistical scatter is
 * far below each level's, and a window of a few Fourier lines in the lowest
 * band it estimates is enough (ErrorBarParameters::window_lines).
 */

namespace greentread
{
  namespace analysis
  {
    /// The orders the estimates assume (doc/methods/analysis.md): second in
    /// the time step (the theory, and 1.7 to 2 in contact_studies.sh); 1.5
    /// in the contact rectangle's size, the order observed on the main job
    /// (error_bars.sh over 4, 8 and 16 subdivisions: 1.49 for the stress,
    /// 1.58 for the force, rms over the bands), below the midpoint rule's 2.
    constexpr double time_step_order    = 2.;
    constexpr double contact_grid_order = 1.5;
    /// The order in the section's mesh size at its element degree: the
    /// section's coarser level is 'Geometry/Mesh size' doubled. Observed over
    /// the 16, 8 and 4 mm quartic sections on error_bars.sh's three cases,
    /// rms over the bands from 250 Hz: 0.86 to 1.62 (the force's the lower).
    /// 1.5 puts the estimate at 0.99 to 1.68 times the difference from the 4 mm
    /// section in all six (doc/methods/analysis.md); on a fourth case that
    /// did not choose it, another tyre section, 1.18 and 1.14 (observed order
    /// 1.11 and 1.06).
    constexpr double ring_section_order = 1.5;
    /// The finite tread blocks' coarser level: 'Tread pattern/Block mesh
    /// size' times this, and the order assumed in it: 1, below the
    /// elements' own, for the blocks' edges and corners are singular
    /// (benchmarks/tread_pattern gives the order the band levels show over
    /// three levels).
    constexpr double block_mesh_ratio = 1.5;
    constexpr double block_mesh_order = 1.;

    /// Richardson's factor: the finer level's error is
    /// |L_coarse - L_fine| / (ratio^order - 1) for a coarsening by @p ratio.
    double
    richardson_factor(double ratio, double order);

    /// One other level of one of a road's band runs: coarser in the grid and
    /// the mode cutoff, finer in the time step.
    struct EstimateRun
    {
      Discretisation what;
      /// The index, in the road and speed's plan (plan_band_runs()), of the
      /// run this coarsens.
      std::size_t of = 0;
      /// The other level's run (its name: the run's, "coarser_" or "finer_",
      /// and the discretisation's).
      /// Without steps (0), there is no run of its own: the low-rate run's
      /// time step is estimated against the run at the scene's step (index
      /// 0), over that run's record.
      BandRun run;
      /// The record both levels are compared over [s], from the start.
      double window = 0.;
      /// The bands estimated (nominal centres) [Hz].
      double f_low = 0., f_high = 0.;
      /// The run's error over |L_other - L_run|: richardson_factor() for the
      /// grid and the ring section, 1 + richardson_factor() for the time step
      /// (the other level is finer, or for the low-rate run the run at the
      /// scene's step); for the mode cutoff set by the scene, from the two
      /// levels' errors against the direct lines.
      double factor = 0.;
      /// The ratio of the two levels' step, rectangle or element size (the
      /// run's over the finer level's for the time step, the coarser
      /// level's over the run's otherwise); 0 for the mode cut-off.
      double ratio = 0.;
    };

    /**
     * @brief The other levels' runs of one road and speed's band runs @p plan at
     * speed @p speed [m/s]: for each run, each estimate of @p parameters,
     * over the window that gives its lowest band from 'Spectra/Target from'
     * (@p target_from) ErrorBarParameters::window_lines lines (at most the
     * run). The time step: the run at the scene's step with the step
     * halved (a doubled step would skip road samples at one sample per
     * step), the low-rate run against the run at the scene's step (no run).
     * The contact grid: @p subdivisions halved (none at 1). The mode cut-off:
     * the same step and grid (factor left 0 for the scene). The ring
     * section: the same step and grid, on the section twice as coarse.
     */
    std::vector<EstimateRun>
    plan_estimate_runs(const std::vector<BandRun> &plan,
                       const ErrorBarParameters   &parameters,
                       double                      target_from,
                       double                      speed,
                       unsigned int                subdivisions);

    /**
     * @brief The band spectrum of the first @p samples samples of @p x
     * (welch_band_spectrum(), bands @p f_low to @p f_high).
     */
    BandSpectrum
    window_spectrum(const std::vector<double> &x,
                    double                     dt,
                    std::size_t                samples,
                    double                     reference,
                    double                     f_low,
                    double                     f_high,
                    unsigned int               lines_per_segment);

    /**
     * @brief Add one estimate to @p target: in each band of @p target from
     * @p estimate.f_low to @p estimate.f_high that both @p run and @p other
     * (the run's levels and its other level's) hold (by nominal centre),
     * estimate.factor times |L_other - L_run| [dB], under the discretisation's label in
     * BandSpectrum::discretisation_error (NaN in the bands it does not
     * estimate; values already there from another run's bands are kept).
     */
    void
    add_estimate(BandSpectrum       &target,
                 const EstimateRun  &estimate,
                 const BandSpectrum &run,
                 const BandSpectrum &other);

    struct RunSpectrum;

    /**
     * @brief Every estimate of @p estimates (plan_estimate_runs() of
     * @p plan) added to @p merged's stress and force spectra, and their
     * combination (combine_errors()). @p run_of gives a run's results by
     * its name (BandRun::name, EstimateRun::run's name); the estimates of a
     * run of @p plan whose bands are not used (@p used false: a low-rate run
     * that disagreed) are left out. Each level pair is compared over the
     * estimate's window from the start (window_spectrum(), Welch's
     * @p lines_per_segment).
     */
    void
    add_error_bars(RunSpectrum                                                   &merged,
                   const std::vector<EstimateRun>                                &estimates,
                   const std::vector<BandRun>                                    &plan,
                   const std::vector<bool>                                       &used,
                   const std::function<const RunSpectrum &(const std::string &)> &run_of,
                   double                                                         stress_reference,
                   unsigned int lines_per_segment);

    /**
     * @brief BandSpectrum::total_error: per band, the standard error and
     * every discretisation's estimate combined in quadrature (the estimates
     * not made in a band left out).
     */
    void
    combine_errors(BandSpectrum &s);

    /// The largest error of a spectrum's leading bands, and what lowers it.
    struct Contributor
    {
      std::string what;       ///< "statistics" or a discretisation's describe()
      std::string parameter;  ///< the parameter to change, quoted
      double      error = 0.; ///< [dB]
      double      band  = 0.; ///< nominal centre [Hz]
    };

    /**
     * @brief Among the bands from @p target_from up within @p within_db of
     * the highest level of @p s, the largest of the standard error and the
     * discretisation estimates, with the parameter that lowers it
     * ('Spectra/Standard error target', 'Time stepping/Time step' or, in a
     * band of a coarser step, 'Spectra/Low-band time step', 'Contact
     * grid/Subdivisions', 'Patch model/Mode cutoff', 'Geometry/Mesh size').
     */
    Contributor
    largest_contributor(const BandSpectrum &s, double target_from, double within_db);
  } // namespace analysis
} // namespace greentread
