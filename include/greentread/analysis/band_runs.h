#pragma once

#include <greentread/analysis/spectra_parameters.h>
#include <greentread/analysis/third_octave.h>

#include <string>
#include <vector>

/**
 * @file
 * Multi-rate estimation of band levels: which runs one road and speed
 * needs so that each band's level meets the standard error target, and the
 * band spectrum that takes each band from the run that fits it.
 * Implemented in source/analysis/band_runs.cc; the manual's page
 * doc/methods/analysis.md gives the method and the study that bounds the
 * coarser step.
 */

namespace greentread
{
  namespace analysis
  {
    /// One run of a road at a speed.
    struct BandRun
    {
      /// "" for the run at the scene's time step, "low-rate" for the run of
      /// the low bands (its files carry this suffix).
      std::string  name;
      double       time_step = 0.; ///< [s]
      double       distance  = 0.; ///< rolled [m]
      unsigned int steps     = 0;  ///< contact::steps_to_cover(distance, V, time_step)
      /// The nominal centres of the bands this run gives the merged spectrum.
      double f_low = lowest_band, f_high = highest_band;
      /// The target is not met, by the prediction, within the longest
      /// distance allowed ('Spectra/Longest distance').
      bool target_out_of_reach = false;
      /// The most steps the run may extend to while its observed standard
      /// errors miss the target ('Spectra/Extend runs'); 0: no extension.
      unsigned int longest_steps = 0;
    };

    /**
     * @brief The highest band of a run's spectrum at time step @p dt [s]:
     * highest_band, or the highest band below the Nyquist frequency
     * 1 / (2 dt) of a coarser step.
     * @throws InputError naming 'Time stepping/Time step' if not even the
     * lowest band fits.
     */
    double
    top_band_for_step(double dt);

    /**
     * @brief How many more steps a run of @p steps_done steps needs so that
     * the standard errors of @p stress and @p force (their spectra so far)
     * meet 'Spectra/Standard error target' in the bands @p run gives, from
     * 'Spectra/Target from' up: 0 if they do, or if the run is at its
     * longest_steps. Otherwise the record the worst band needs (its error
     * falls as one over the square root of the record), 5% beyond it so
     * that the next check, of a scatter that is itself an estimate, is
     * likely to pass, and at most longest_steps.
     */
    unsigned int
    more_steps_for_target(const SpectraParameters &spectra,
                          const BandRun           &run,
                          const BandSpectrum      &stress,
                          const BandSpectrum      &force,
                          unsigned int             steps_done);

    /**
     * @brief The runs of one road at speed @p speed [m/s]: the run at the
     * scene's time step @p time_step [s] over @p distance [m] (the
     * 'Rolling/Distance'), which gives every band above 'Spectra/Low bands
     * up to' (all of them with one rate), and, with more than one rate, the
     * low-rate run: at 'Spectra/Low-band time step' (when coarser than
     * @p time_step), over the
     * distance whose predicted standard errors (predicted_standard_errors())
     * meet 'Spectra/Standard error target' in the bands from 'Spectra/Target
     * from' to 'Low bands up to', at least @p distance and at most 'Spectra/
     * Longest distance'. The low-rate run is left out when @p distance already
     * meets the target in its bands, or when it could not be longer than
     * @p distance (a 'Longest distance' that short, or a texture file's
     * length): the run at the scene's step then gives every band.
     *
     * @param top_band The highest band the scene's step resolves (5 kHz or
     *        lower, nominal centre).
     * @throws InputError naming 'Spectra/Low-band time step' if it does not
     *         resolve the low bands (the message gives the largest step that
     *         does).
     */
    std::vector<BandRun>
    plan_band_runs(const SpectraParameters &spectra,
                   double                   speed,
                   double                   time_step,
                   double                   distance,
                   double                   top_band);

    /// How many combined standard errors apart a band of the low-rate run
    /// and the same band of the run at the scene's step may be.
    constexpr double low_rate_tolerance = 4.;

    /**
     * @brief The check of a low-rate run against the run at the scene's
     * step, in the bands the low-rate run gives: "" when every band of
     * @p low_spectrum lies within low_rate_tolerance combined standard errors
     * of the same band of @p fine, and otherwise the band furthest apart,
     * described. The two runs roll the same road from the same start, so
     * they differ by their records' statistics and by the coarser step's
     * error: a coarser step that the contact does not tolerate (stiff,
     * sustained contact, where the coarse step rings) shows here, and the
     * scene then keeps the run at its step for every band.
     */
    std::string
    low_rate_disagreement(const BandSpectrum &fine,
                          const BandSpectrum &low_spectrum,
                          const BandRun      &low);

    /**
     * @brief The fine spectrum @p fine with the bands from @p low.f_low to
     * @p low.f_high taken from @p low_spectrum (level, rms, standard errors,
     * segments, time step and duration): each band from the run that fits
     * it. The bands are matched by nominal centre.
     * @throws InputError if @p low_spectrum lacks one of those bands.
     */
    BandSpectrum
    merge_band_spectra(const BandSpectrum &fine,
                       const BandSpectrum &low_spectrum,
                       const BandRun      &low);
  } // namespace analysis
} // namespace greentread
