#pragma once

#include <greentread/fe/harmonic_section.h>
#include <greentread/periodic/contact_patch.h>
#include <greentread/periodic/green_solvers.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

/**
 * @file
 * The Green's functions of an axisymmetric ring as sums over its
 * circumferential harmonics (the `harmonic` method).
 *
 * A unit force spread over point q's rectangle, the arc theta_q +- a / 2 and
 * the strip y_q +- dy / 2 of the tread, is the traction 1 / (a W_q) (W_q the
 * strip's int r ds). Along the ring its box has the Fourier coefficients
 * a / (2 pi) (n = 0) and 2 sin(n a / 2) / (n pi), and across the tread its
 * strip loads the section with w_q (fe::HarmonicSection::tread_strip). The
 * harmonic-n amplitude of the response is D_n^{-1} w_q times the box's
 * coefficient, and its mean over point p's rectangle gives
 *
 *   g_pq(w) = sum_n  e_n / (2 pi)  sinc^2(n a / 2)  cos(n (theta_p - theta_q))
 *                    (w_p / W_p)^T D_n(w)^{-1} (w_q / W_q),
 *
 * e_0 = 1, e_n = 2, sinc x = sin x / x, D_n = K_n + Kp_n + j w C_n - w^2 M.
 * The points of one strip share w, so each harmonic costs one factorisation
 * and one solve per strip across the tread.
 *
 * **The number of harmonics** is set by a bound on the neglected tail. For
 * n >= N the box's coefficient is at most 4 / (n a)^2, and the section's
 * static compliance h_n = max_q (w_q / W_q)^T K_n^{-1} (w_q / W_q) falls at
 * least as n^-p, p the decay seen between N / 2 and N (clamped to [0, 1]; a
 * half-space falls as 1 / n). The static tail is then at most
 *   4 h_{N-1} / (pi a^2 (N - 1) (1 + p)),
 * and N is the first for which this, relative to the smallest static driving
 * point, is below the tolerance. Dynamic lines up to w_max keep the bound
 * within a factor 2 when the lowest eigenvalue of every harmonic from N on is
 * above 2 w_max^2: N grows until K_N - 2 w_max^2 M is positive definite.
 *
 * **A line w > 0** is the static sum, computed once, plus the dynamic
 * differences d_n = H_n(w) - H_n(0) of the harmonics 0 .. N_w - 1. These fall
 * far faster than the static terms (the mass matters less and less as n
 * grows), so N_w is much smaller than N: it is the first n past the
 * dispersion range (K_n - 2 w^2 M positive definite) at which the same kind
 * of tail bound, from max |d_n| and its observed decay (clamped to [0, 3]),
 * is below the tolerance.
 */

namespace greentread
{
  namespace periodic
  {
    /// What the `harmonic` method needs besides the tyre.
    struct HarmonicOptions
    {
      /// 'Green's functions/Harmonic tolerance'.
      double tolerance = 1e-3;
      /// The highest line [rad/s].
      double max_omega = 0.;
      /// 'Patch model/Mode cutoff' [rad/s] when the ring's modes will be
      /// searched, 0 otherwise: checked by check_mode_cutoff() as soon as
      /// the harmonics are chosen, before anything is written.
      double mode_cutoff = 0.;
    };

    /**
     * @brief The ring of a HarmonicSection seen by the points of a patch:
     * each point's strip load and angle, and the harmonics that carry the
     * Green's functions to a tolerance.
     */
    class HarmonicRing
    {
    public:
      /**
       * @param[in] section    Assembled and inflated; it must outlive this.
       * @param[in] patch      Points with tributary areas.
       * @param[in] tolerance  The tail's bound relative to the smallest
       *                       static driving point ('Green's
       *                       functions/Harmonic tolerance').
       * @param[in] max_omega  The highest line [rad/s].
       * @throws InputError if the patch's points are nodes (a point force's
       *         series does not converge), naming 'Green's functions/Point
       *         load'.
       * @throws NumericalError if no number of harmonics up to 20,000 meets
       *         the tolerance.
       */
      HarmonicRing(const fe::HarmonicSection &section,
                   const ContactPatch        &patch,
                   double                     tolerance,
                   double                     max_omega);

      const fe::HarmonicSection &section;
      /// Per strip across the tread, w / W (one column each).
      Eigen::MatrixXd loads;
      /// Each point's strip and angle [rad].
      std::vector<unsigned int> strip;
      std::vector<double>       angle;
      /// The rectangles' angle a [rad].
      double arc = 0.;
      /// The harmonics used, 0 .. n_harmonics - 1.
      unsigned int n_harmonics = 0;
      /// The static tail's bound relative to the smallest static driving
      /// point, and the decay exponent p it used.
      double tail_bound = 0., decay = 0.;
      /// The tolerance it was chosen for.
      double tolerance = 0.;
      /// Per harmonic n, the static (w_i / W_i)^T K_n^{-1} (w_j / W_j) over
      /// the strips, and their sum, g at 0 Hz (P x P).
      std::vector<Eigen::MatrixXd> static_terms;
      Eigen::MatrixXd              static_green;

      /// e_n / (2 pi) sinc^2(n a / 2).
      double
      weight(unsigned int n) const;

      /// For the report: harmonics, the tail's bound, the section's size.
      std::string
      describe() const;
    };

    /**
     * @brief Refuses a mode cut-off @p cutoff [rad/s] that the harmonics
     * @p ring sums cannot carry: the ring's modes are searched harmonic by
     * harmonic up to 8 in a row without one below the cut-off, and the
     * static residual G_r of their synthesis comes from the static sum, so
     * harmonics N to N + 7 (N = ring.n_harmonics) must have no mode below
     * it (each checked by the inertia of K_n - cutoff^2 M).
     * @throws InputError naming 'Patch model/Mode cutoff' otherwise.
     */
    void
    check_mode_cutoff(const HarmonicRing &ring, double cutoff);

    /**
     * @brief GreenSolver of the `harmonic` method: g(w) by the sum over the
     * ring's harmonics (one object per thread).
     */
    class HarmonicGreenSolver : public GreenSolver
    {
    public:
      explicit HarmonicGreenSolver(const HarmonicRing &ring);

      Eigen::MatrixXcd
      solve(double omega, SolveDiagnostics &diagnostics) override;

      /// The harmonics solved dynamically at the last line, N_w.
      unsigned int
      dynamic_harmonics() const
      {
        return n_dynamic;
      }

    private:
      const HarmonicRing &ring;
      unsigned int        n_dynamic = 0;
    };
  } // namespace periodic
} // namespace greentread
