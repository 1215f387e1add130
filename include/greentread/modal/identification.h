#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/modal/identification_parameters.h>
#include <greentread/modal/modal_model.h>
#include <greentread/modal/pole_polish.h>

#include <functional>
#include <string>
#include <vector>

/**
 * @file
 * Identification of a modal model from one FRF: LSCE poles, physical poles
 * only, residues by frequency-domain least squares (Eq. A.14), and the
 * order chosen by the error of Eq. (50).
 */

namespace greentread
{
  namespace modal
  {
    /**
     * @brief What became of the roots of the Prony polynomial.
     */
    struct PoleCounts
    {
      unsigned int roots       = 0; ///< roots of the polynomial
      unsigned int unstable    = 0; ///< Re(lambda) >= 0 (or z <= 0: no pole)
      unsigned int out_of_band = 0; ///< above band_edge * f_max
      unsigned int spurious    = 0; ///< not found again at order p - 2
      unsigned int physical    = 0; ///< kept: modes offered to the fit
    };

    /**
     * @brief The LSCE solve of one band.
     */
    struct BandReport
    {
      /// The core of the band: poles are taken from it [Hz].
      double f_low = 0., f_high = 0.;
      /// Polynomial degree, numerical rank, condition estimate of the Hankel matrix.
      unsigned int order = 0, rank = 0;
      double       condition = 0.;
    };

    /**
     * @brief The identified model of one FRF and how well it fits.
     */
    struct Identification
    {
      modal::ModalModel model;
      /// N_m, modes in the chosen model (pairs and real poles).
      unsigned int n_modes = 0;
      /// E of Eq. (50) of the chosen model, a fraction.
      double error = 1.;
      /// The smallest E over all orders tried.
      double best_error = 1.;
      /// E of the other residue model with the same poles (NaN if not compared).
      double other_model_error = NAN;
      /// LSCE per band; and their total degree and rank, and the worst condition.
      std::vector<BandReport> bands;
      unsigned int            n_bands = 1;
      unsigned int            order = 0, rank = 0;
      double                  condition = 0.;
      PoleCounts              poles;
      /// Residual terms (zero when not asked for): lower -L/w^2, upper U [m/N].
      double lower_residual = 0., upper_residual = 0.;
      /// The poles' refinement, when asked (the misfits are equal when it
      /// did not lower E and LSCE's poles were kept).
      PolishReport polish;
    };

    /**
     * @brief Identify a modal model of @p frf.
     *
     * 1. LSCE at order p = 2 N_max on the whole band (Bands = 1, Appendix A),
     *    or in B sub-bands at about 4 N_max / B roots each (HankelSystem,
     *    companion_roots()); \f$\lambda = \ln z / \Delta t\f$,
     *    \f$\omega = |\lambda|\f$, \f$\xi = -\mathrm{Re}\lambda/|\lambda|\f$
     *    (Eqs. A.12-A.13).
     * 2. Physical poles: stable (Re lambda < 0); in the band's core (damped
     *    frequency below band_edge f_max overall); persistent: Newton's method
     *    from each root on the polynomial of order p - 2 must find a root
     *    within the stabilisation tolerances in frequency and damping.
     * 3. Residues of all physical modes by least squares on the FRF lines
     *    (rank-revealing), in the chosen ResidueModel, with the optional
     *    residual terms.
     * 4. Order: the modes ranked by their contribution (L1 norm of their FRF);
     *    for n = 1, 2, ... the first n modes are refitted (one QR, leading
     *    blocks) and E(n) computed; N_m is the smallest n with
     *    E(n) <= min E + order_tolerance.
     *
     * @throws InputError if the FRF is too short for the order asked.
     */
    Identification
    identify(const base::FrequencyResponse &frf, const IdentificationParameters &parameters);

    /**
     * @brief E of Eq. (50): \f$\int|\hat g - \tilde g|\,d\omega / \int|\hat
     * g|\,d\omega\f$ over the lines (trapezoidal rule), for a model plus
     * residual terms. The line at 0 Hz is skipped when lower != 0.
     */
    double
    modal_error(const base::FrequencyResponse &frf,
                const modal::ModalModel       &model,
                double                         lower = 0.,
                double                         upper = 0.);
  } // namespace modal
} // namespace greentread

namespace greentread
{
  namespace modal
  {
    /**
     * @brief Identify many FRFs on all threads (deal.II's thread count,
     * DEAL_II_NUM_THREADS), with progress on standard error.
     *
     * @param[in] get   get(n) returns FRF number n (called from the threads).
     * @param[in] count How many FRFs.
     * @throws The first exception any identification threw, after all
     * threads have stopped.
     */
    std::vector<Identification>
    identify_all(const std::function<base::FrequencyResponse(std::size_t)> &get,
                 std::size_t                                                count,
                 const IdentificationParameters                            &parameters,
                 bool                                                       show_progress = true);


    /**
     * @brief Identify the FRFs g_ij of a Green's function file for @p pairs.
     *
     * Reciprocity: where both g_ij and g_ji are asked for and hold the same
     * data (to 1e-12 relative, as a tyre's Green's matrix does), the FRF is
     * identified once and the result used for both; @p reused counts them.
     */
    std::vector<Identification>
    identify_pairs(const base::FrequencyResponseMatrix                      &green,
                   const std::vector<std::pair<unsigned int, unsigned int>> &pairs,
                   const IdentificationParameters                           &parameters,
                   std::size_t                                              &reused,
                   bool                                                      show_progress = true);
  } // namespace modal
} // namespace greentread
