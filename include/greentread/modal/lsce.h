#pragma once

#include <greentread/base/frequency_response.h>

#include <Eigen/Core>

#include <complex>
#include <vector>

/**
 * @file
 * The Least Squares Complex Exponential method of the paper's Appendix A:
 * impulse response, Hankel least squares (Eq. A.10), roots of the Prony
 * polynomial (Eq. A.7) and poles \f$\lambda = \ln z / \Delta t\f$; for the
 * whole band at once (Appendix A) or for one sub-band ("zoom" LSCE).
 */

namespace greentread
{
  namespace modal
  {
    /**
     * @brief A sampled impulse response \f$h_n\f$, real for the whole band,
     * complex for a sub-band.
     */
    template <typename Number>
    struct ImpulseResponse
    {
      double              dt = 0.;
      std::vector<Number> values;
    };

    /**
     * @brief The impulse response of an FRF by inverse FFT (Eigen's FFT),
     * over the lines 0 .. @p last_line (all of them by default).
     *
     * The one-sided FRF \f$\hat g(f_k)\f$, k = 0..K, is extended to a full
     * period of 2K lines by Hermitian symmetry, \f$\hat g(-f) =
     * \overline{\hat g(f)}\f$, so that g is real; the line K keeps only its
     * real part, the only part a real sequence of even length can carry.
     * Then \f$g_n = \Delta f \sum_k \hat g(f_k) e^{2\pi j k n / 2K}\f$ with
     * \f$\Delta t = 1/(2 f_K)\f$.
     *
     * Two effects are not exponentials and LSCE must live with them: the
     * frequency sampling wraps g around the period \f$1/\Delta f\f$, which
     * keeps every pole and only rescales residues, and the cut at \f$f_K\f$
     * adds Gibbs ringing near t = 0 at the Nyquist frequency, which an
     * over-specified order absorbs into poles near the band edge (rejected).
     */
    ImpulseResponse<double>
    impulse_response(const base::FrequencyResponse &frf, unsigned int last_line = 0);

    /**
     * @brief The complex impulse response of the sub-band of lines
     * @p first_line .. @p last_line, shifted to 0 Hz: \f$h_n = \Delta f
     * \sum_m \hat g(f_{a} + m\Delta f) e^{2\pi j m n / n_b}\f$,
     * \f$\Delta t = 1/(n_b \Delta f)\f$, n_b lines. A pole \f$\lambda\f$
     * appears in it as \f$z = e^{(\lambda - j\omega_a)\Delta t}\f$.
     */
    ImpulseResponse<std::complex<double>>
    band_impulse_response(const base::FrequencyResponse &frf,
                          unsigned int                   first_line,
                          unsigned int                   last_line);

    /**
     * @brief The Hankel least squares of Eq. (A.10) for every order up to a
     * maximum, from one QR factorisation.
     *
     * Rows m = 0..L-1 hold \f$h_{m_0+m+i}\f$, i = 0..p_max; the first sample
     * \f$h_0\f$ is skipped (\f$m_0 = 1\f$), because a jump of g at t = 0 makes
     * it the mean of two values. With the QR factorisation
     * \f$[H\;h] = Q R\f$, the least squares for order p (the first p columns
     * against column p) reduces to the p x p triangle \f$R_{11}\f$, which has
     * the same singular values as the Hankel matrix of order p. It is solved
     * by a complete orthogonal decomposition (rank-revealing, minimum-norm):
     * never the normal equations of Eq. (A.11), which square the condition
     * number. The minimum-norm solution keeps the roots that do not belong to
     * the signal inside the unit circle (Kumaresan & Tufts).
     */
    template <typename Number>
    class HankelSystem
    {
    public:
      using Vector = Eigen::Matrix<Number, Eigen::Dynamic, 1>;
      using Matrix = Eigen::Matrix<Number, Eigen::Dynamic, Eigen::Dynamic>;

      /**
       * @param[in] h         The impulse response.
       * @param[in] max_order The largest polynomial degree p.
       * @throws InputError if h has fewer than 2 p_max + 2 samples.
       */
      HankelSystem(const ImpulseResponse<Number> &h, unsigned int max_order);

      /**
       * @brief The coefficients \f$\beta_0..\beta_{p-1}\f$ of the monic
       * polynomial \f$z^p + \beta_{p-1} z^{p-1} + \dots + \beta_0\f$.
       * @param[out] rank      Numerical rank of the Hankel matrix.
       * @param[out] condition Condition number estimate of the Hankel matrix:
       *   ratio of the largest to the smallest (kept) diagonal of the
       *   column-pivoted triangle, a lower bound of the 2-norm condition
       *   number that is seldom off by more than a small factor.
       */
      Vector
      coefficients(unsigned int order, unsigned int &rank, double &condition) const;

      /**
       * @brief The coefficients for order p by a column-pivoted QR (rank-
       * revealing, not minimum-norm): the cheaper solve used for the
       * persistence check of the roots.
       */
      Vector
      coefficients_pivoted(unsigned int order) const;

      /**
       * @brief An estimate of the numerical rank at the largest order, read
       * off the diagonal of the QR factor: the number of |R_ii| above 1e-13
       * of the largest. Exact for exponentials in general position, and a
       * cheap guide to how many roots a band needs.
       */
      unsigned int
      rank_estimate() const;

    private:
      Matrix triangle; // R of the QR of [H h]
    };

    /**
     * @brief The roots of the monic polynomial with @p coefficients: the
     * eigenvalues of its companion matrix.
     */
    template <typename Number>
    std::vector<std::complex<double>>
    companion_roots(const Eigen::Matrix<Number, Eigen::Dynamic, 1> &coefficients);

    /**
     * @brief Newton's method on the monic polynomial from @p z.
     * @return true if it converged (relative step below 1e-12) within 30
     * iterations; z then holds the root.
     */
    template <typename Number>
    bool
    newton_root(const Eigen::Matrix<Number, Eigen::Dynamic, 1> &coefficients,
                std::complex<double>                           &z);
  } // namespace modal
} // namespace greentread
