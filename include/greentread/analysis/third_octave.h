#pragma once

#include <Eigen/Dense>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * One-third-octave band spectra of uniformly sampled time signals (IEC
 * 61260-1 base-10 bands), e.g. of a contact force or a sound pressure, and
 * their CSV output. Implemented in source/analysis/third_octave.cc, the
 * spectra of several signals' outputs in source/analysis/welch_channels.cc
 * (both on source/analysis/welch_segments.h) and the CSV output in
 * source/analysis/band_spectrum_csv.cc.
 */

namespace greentread
{
  namespace analysis
  {
    /**
     * @brief One one-third-octave band of frequency, base 10 (IEC 61260-1):
     * exact centre 1000 x 10^(k/10) Hz, edges at 10^(+-1/20) times the
     * centre, labelled with its nominal centre (..., 100, 125, 160, 200,
     * 250, 315, 400, 500, 630, 800, 1000, ... Hz).
     *
     * The edges are computed as 1000 x 10^((2k +- 1)/20) Hz, so that the
     * upper edge of one band is bit for bit the lower edge of the next.
     */
    struct FrequencyBand
    {
      double nominal; ///< nominal centre [Hz], the band's label
      double centre;  ///< exact centre 1000 x 10^(k/10) [Hz]
      double lower;   ///< lower edge centre x 10^(-1/20) [Hz], in the band
      double upper;   ///< upper edge centre x 10^(+1/20) [Hz], not in it
    };

    /// The range of every spectrum of a rolling run: the bands of tyre/road
    /// noise, from 100 Hz to 5 kHz (nominal centres) [Hz].
    constexpr double lowest_band  = 100.;
    constexpr double highest_band = 5000.;

    /**
     * @brief The base-10 one-third-octave bands whose nominal centres lie in
     * [@p f_low, @p f_high] [Hz] (both inclusive, to a relative 1e-9), in
     * increasing order. The default 100 Hz to 5 kHz gives the 18 bands of
     * tyre/road noise.
     * @throws InputError naming the values unless 0 < f_low <= f_high are
     * finite and at least one nominal centre lies between them.
     */
    std::vector<FrequencyBand>
    third_octave_bands(double f_low = lowest_band, double f_high = highest_band);

    /**
     * @brief The level given to a band whose rms is at most 1e-10 times the
     * reference (in particular a zero rms): -200 dB, instead of -inf.
     */
    constexpr double level_floor = -200.;

    /**
     * @brief A one-third-octave band spectrum: per band, the rms of the
     * signal's content in the band and its level.
     */
    struct BandSpectrum
    {
      std::vector<FrequencyBand> bands; ///< the bands, increasing
      std::vector<double>        rms;   ///< rms in each band [signal unit]
      /// 20 log10(rms / reference) [dB], at least level_floor.
      std::vector<double> level;
      double              reference; ///< reference rms of the levels [signal unit]
      /**
       * Number of discrete Fourier lines with a share in the lowest
       * (narrowest) band, at least 1: the spectrum's resolution. With the
       * Hann window a pure tone's power lies on the two to four lines
       * nearest its frequency, so
       * a tone within about one line spacing 1 / (N dt) of a band edge
       * shares its power with the neighbouring band (in a band of few lines
       * that is most of the band).
       */
      unsigned int lines_in_lowest_band;
      /**
       * The standard error of each level [dB], from welch_band_spectrum();
       * empty from third_octave_spectrum(). It is the scatter of the band's
       * power over the Welch segments when there are at least
       * min_observed_segments of them (and at least predicted_error below
       * floor_segments), and predicted_error otherwise.
       */
      std::vector<double> standard_error;
      /// The standard error a Gaussian signal would give [dB], from the
      /// band's lines and the segments' windows (welch_band_spectrum()).
      std::vector<double> predicted_error;
      /// The Welch segments of each band (1: the whole record).
      std::vector<unsigned int> segments;
      /// The sample interval [s] and the record's duration [s] each band
      /// came from (a multi-rate estimate takes bands from two records:
      /// merge_band_spectra()).
      std::vector<double> time_step, duration;
      /// The discretisation error estimates of each level [dB], by what was
      /// coarsened ("time_step", "contact_grid", "mode_cutoff";
      /// analysis/error_bars.h), NaN in a band not estimated. Empty: none.
      std::vector<std::pair<std::string, std::vector<double>>> discretisation_error;
      /// The standard error and the estimates combined in quadrature [dB]
      /// (combine_errors()); empty without estimates.
      std::vector<double> total_error;
    };

    /// The segments a band needs before its standard error is their scatter.
    constexpr unsigned int min_observed_segments = 3;
    /// Below this many segments the scatter's error is at least the
    /// Gaussian prediction (a few segments' scatter can come out low by
    /// chance).
    constexpr unsigned int floor_segments = 10;

    /**
     * @brief The one-third-octave band spectrum of the real signal
     * x_n = x(n dt), n = 0, ..., N - 1.
     *
     * The record's mean is removed and the periodic Hann window
     * w_n = (1 - cos(2 pi n / N)) / 2 applied; the windowed record is
     * zero-padded to the smallest length M >= N of the form 2^a 3^b 5^c
     * and Fourier transformed (Eigen's FFT), Y_k. The mean square in a band
     * is the one-sided power of the lines k > 0, each weighted by the share
     * a_k of its cell [k - 1/2, k + 1/2) / (M dt) that lies in
     * [lower, upper),
     * @f[
     *   \langle x^2 \rangle_b = \frac{2}{M \sum_n w_n^2}
     *                           \sum_{k} a_k |Y_k|^2 ,
     * @f]
     * so that a flat spectrum gives exactly the band's width, however few
     * lines the band holds (a line at an edge is shared by the two bands),
     * normalised by the window's energy (sum_n w_n^2 = 3N/8): by Parseval,
     * summed over all lines this is the windowed record's mean square
     * divided by that of the window, so a stationary signal keeps its rms
     * (the "energy correction", 8/3 in power). A sine of amplitude A whose
     * frequency lies well inside one band gives A / sqrt(2) there; the
     * sum over the bands of a broadband signal is its mean square between
     * the lowest band's lower and the highest band's upper edge.
     *
     * The levels are 20 log10(rms / @p reference), and level_floor (-200 dB)
     * for an rms of at most 1e-10 @p reference.
     *
     * @param[in] x         The signal, N samples [any unit].
     * @param[in] dt        Sample interval [s].
     * @param[in] reference The rms of 0 dB, in the unit of @p x (e.g. 2e-5
     *                      for a sound pressure in Pa).
     * @param[in] f_low, f_high The nominal centres of the lowest and highest
     *                      bands [Hz], as third_octave_bands().
     *
     * @throws InputError naming the value: dt or the reference not finite and
     * > 0; bad band limits; the highest band's upper edge above the Nyquist
     * frequency 1 / (2 dt) (the message gives the largest dt allowed); a
     * record shorter than 1 / (upper - lower) of the lowest band, the
     * duration that guarantees a Fourier line in every band (the message
     * names the record, the band and the duration needed).
     * @throws NumericalError naming the index of the first sample that is
     * not a finite number, or if a band's rms overflows.
     */
    BandSpectrum
    third_octave_spectrum(const std::vector<double> &x,
                          double                     dt,
                          double                     reference,
                          double                     f_low  = lowest_band,
                          double                     f_high = highest_band);

    /**
     * @brief The one-third-octave band spectrum of x_n = x(n dt) averaged
     * over segments (Welch's method), with the standard error of each level.
     *
     * Each band b gets its own segment length, the shorter of the record
     * and the N_b samples that put @p lines_per_segment Fourier lines in the
     * band, N_b = ceil(lines_per_segment / ((upper - lower) dt)); a record of
     * at most N_b samples is one segment, as in third_octave_spectrum(). The
     * segments overlap by half and end with the record (the samples left
     * over are dropped from its start, where the run starts). Each segment
     * has its mean removed, the periodic Hann window and the band's mean
     * square as third_octave_spectrum(); the level is that of the mean over
     * the K_b segments.
     *
     * The standard error of a level is 10 log10(e) times the relative
     * standard error of the mean power (first order in it):
     *  - with K_b >= min_observed_segments, from the segments' own scatter,
     *    s_P^2 / K_b, times the overlap's factor
     *    1 + 2 sum_j (1 - j / K_b) rho_j^2 with rho_j the window's overlap
     *    correlation at j hops (Welch 1967): no assumption on the signal's
     *    distribution; with fewer than floor_segments, at least the Gaussian
     *    prediction below (a few segments' scatter can come out low by
     *    chance; a pure tone's is zero);
     *  - otherwise the prediction for a Gaussian signal with a flat spectrum
     *    across the band: the band sums n lines whose Hann-windowed Fourier
     *    coefficients correlate as the window's squared transform, so the
     *    relative variance of a segment's band power is
     *    sum_{k,k'} |r(k - k')|^2 / n^2 (1.94 / n for many lines), divided
     *    among the segments by the same overlap factor.
     *
     * @param[in] lines_per_segment The lines a band's segment holds, >= 1.
     * @throws the errors of third_octave_spectrum(), and InputError if
     * @p lines_per_segment is 0.
     */
    BandSpectrum
    welch_band_spectrum(const std::vector<double> &x,
                        double                     dt,
                        double                     reference,
                        double                     f_low             = lowest_band,
                        double                     f_high            = highest_band,
                        unsigned int               lines_per_segment = 8);

    /**
     * @brief What welch_band_spectra() asks at each Fourier line of its
     * outputs: their powers from the signals' coefficients there.
     *
     * @p coefficients holds the signals' windowed Fourier coefficients at
     * the line of frequency @p frequency [Hz] in the band of index @p band
     * (a line on a band's edge is asked for each band), one row per signal and one
     * column per segment; @p powers (sized by the caller: one row per
     * output, one column per segment) receives each output's power in the
     * same scale: an output linear in the signals, y = a^T x, gives
     * |a(f)^T coefficients|^2 (a(f) its transfer at the line), and a
     * quadratic one, x^H Q x, gives coefficients^H Q(f) coefficients.
     */
    using LinePowers = std::function<void(double                  frequency,
                                          std::size_t             band,
                                          const Eigen::MatrixXcd &coefficients,
                                          Eigen::MatrixXd        &powers)>;

    /**
     * @brief The one-third-octave band spectra of outputs that depend on
     * several signals through their spectra, by Welch's method with the
     * segments and statistics of welch_band_spectrum(): every signal is
     * cut, its mean removed and windowed as there, and each band's power
     * in a segment is the weighted sum over its lines of @p powers, so that
     * one signal with the power |coefficient|^2 gives welch_band_spectrum()
     * itself. The outputs' levels are against @p references, one per
     * output (so that @p powers' row count is their number), and each band
     * gets the standard error of its segments' scatter.
     * @param[in] signals The signals, each sampled @p dt apart, all of one
     *                    length.
     * @throws the errors of welch_band_spectrum(), and InputError if there
     * are no signals or references or the signals differ in length.
     */
    std::vector<BandSpectrum>
    welch_band_spectra(const std::vector<std::vector<double>> &signals,
                       double                                  dt,
                       const std::vector<double>              &references,
                       double                                  f_low,
                       double                                  f_high,
                       unsigned int                            lines_per_segment,
                       const LinePowers                       &powers);

    /**
     * @brief The standard error of each level that welch_band_spectrum()
     * predicts for a Gaussian signal (BandSpectrum::predicted_error) from a
     * record of @p n_samples samples @p dt apart, without the record: what
     * a run must last to meet a target is known before it runs. A band
     * with no Fourier line gets infinity.
     * @throws InputError if @p n_samples < 2, @p dt <= 0 or
     * @p lines_per_segment = 0.
     */
    std::vector<double>
    predicted_standard_errors(std::size_t                       n_samples,
                              double                            dt,
                              const std::vector<FrequencyBand> &bands,
                              unsigned int                      lines_per_segment);

    /**
     * @brief The fewest samples, at least @p at_least, whose predicted
     * standard errors (predicted_standard_errors()) are at most @p target
     * [dB] in every one of @p bands; @p at_most + 1 if @p at_most samples
     * do not meet it.
     */
    std::size_t
    samples_for_error(double                            dt,
                      const std::vector<FrequencyBand> &bands,
                      unsigned int                      lines_per_segment,
                      double                            target,
                      std::size_t                       at_least,
                      std::size_t                       at_most);

    /**
     * @brief Write @p spectrum as CSV, under a temporary name renamed when
     * complete (base::AtomicFile): a comment line `# ...` naming
     * @p quantity_and_unit (e.g. "sound pressure [Pa]"), the reference and
     * the level floor, the header
     * `nominal_Hz,centre_Hz,lower_Hz,upper_Hz,rms,level_dB`, followed by
     * `standard_error_dB,predicted_error_dB,segments,time_step_s,record_s`
     * when the spectrum has standard errors (welch_band_spectrum(): the
     * time step and the record's duration each band came from), then
     * `total_error_dB` and one `<label>_dB` per discretisation estimate when
     * it has error bars (BandSpectrum::total_error; empty where a
     * discretisation is not estimated), and one
     * row per band, 12 significant digits.
     * @throws InputError if the file cannot be written.
     */
    void
    write_band_spectrum_csv(const std::filesystem::path &file,
                            const BandSpectrum          &spectrum,
                            const std::string           &quantity_and_unit);
  } // namespace analysis
} // namespace greentread
