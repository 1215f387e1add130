#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/base/output.h>
#include <greentread/modal/patch_model.h>

#include <Eigen/Dense>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

/**
 * @file
 * The patch model from the ring's own modes: with real, mass-normalised
 * modes phi_k (their values at the contact points), natural frequencies w_k
 * and modal damping ratios xi_k,
 *   g(w) = G_r + sum_k phi_k phi_k^T / (w_k^2 - w^2 + 2 j xi_k w_k w),
 * where the static residual G_r = G(0) - sum_k phi_k phi_k^T / w_k^2 carries
 * the modes above the cut-off (the mode-acceleration correction). Every term
 * is passive: -Im g(w) is a sum of positive semidefinite rank-one terms for
 * w > 0. G_r is positive semidefinite: it is the part of the static
 * flexibility that the modes left out.
 *
 * **The residual's damping.** With C = alpha M + beta K per material, a mode
 * far above the band responds below it as phi phi^T / (w_k^2 (1 + j w
 * beta_k)), beta_k its share of beta by modal strain energy: the residual is
 * a Kelvin-Voigt solid, G_r / (1 + j w beta_r), not a spring. beta_r is
 * fitted to the residual of the direct Green's functions, line by line
 * (fit_residual_relaxation()): one number, no pole moves. It matters most
 * when the contact nodes carry no mass ('Surface mass = moved inward'):
 * their motion is all in G_r, and it relaxes in beta (7 us for the tread's
 * default loss factor), the scale of a contact time step.
 *
 * **Complex shapes.** With a damping that is not proportional the modes
 * are coupled (synthesis/ring_modes.h); the synthesis then holds complex
 * shapes psi_k = shapes + j shapes_imag, and mode k contributes
 *   psi psi^T / (2 j w_d (j w - l)) - conj(psi) conj(psi)^T / (2 j w_d (j w - conj(l))),
 * l = w_k (-xi_k + j sqrt(1 - xi_k^2)), w_d = Im l, which for a real psi is
 * the term above. A mode with a complex shape has xi_k < 1.
 * Implemented in source/synthesis/mode_synthesis.cc (the synthesis and its
 * errors) and source/synthesis/mode_synthesis_io.cc (the rank-one patch model
 * and modal_model.h5).
 */

namespace greentread
{
  namespace synthesis
  {
    /// The ring's Bloch frequencies per circumferential wavenumber.
    struct Dispersion
    {
      /// Per wavenumber k = 0 .. N/2: the branches' frequencies [Hz],
      /// ascending, and their damping ratios.
      std::vector<Eigen::VectorXd> frequency_hz, damping_ratio;
    };

    /// A modal synthesis at the contact points.
    struct ModeSynthesis
    {
      /// Per mode: natural frequency [Hz] and damping ratio, ascending.
      Eigen::VectorXd frequency_hz, damping_ratio;
      /// The mass-normalised mode values at the points, [mode][point]
      /// [1/sqrt(kg)], and their imaginary parts (empty: real shapes).
      Eigen::MatrixXd shapes, shapes_imag;
      /// G_r, [point][point] [m/N].
      Eigen::MatrixXd instantaneous;
      /// beta_r [s]: the residual is G_r / (1 + j w beta_r) (0: a spring).
      double residual_relaxation = 0.;
      /// The points [m]: x, y, radius.
      std::vector<std::array<double, 3>> points;
      /// Per mode: the circumferential wavenumber it comes from (may be empty).
      std::vector<unsigned int> wavenumber;
      /// The dispersion curves the modes came from (may be empty).
      Dispersion dispersion;

      unsigned int
      n_modes() const
      {
        return static_cast<unsigned int>(frequency_hz.size());
      }

      /// g(w) at the angular frequency @p omega [rad/s].
      Eigen::MatrixXcd
      at(double omega) const;

      /// The modes' part of g(w), without the residual.
      Eigen::MatrixXcd
      modes_at(double omega) const;

      /**
       * modes_at() at the lines w_l = 2 pi l @p df, l = 0 .. @p n_lines - 1,
       * to round-off. The modes whose poles lie well beyond the highest
       * line (at least 1.25 times it, for a lightly damped mode) are smooth
       * over the band: their part is computed at Q + 1 Chebyshev points of
       * [0, w_max] only and interpolated between them (barycentric formula),
       * with Q such that the interpolation error is about 1e-16 of their
       * size (Q = 39); the others are summed at every line. With the default
       * tyre's modes to twice the highest line, about three fifths of them
       * are interpolated, and the sum over modes and lines, most of the
       * synthesis' work, halves. The lines on the worker threads.
       */
      std::vector<Eigen::MatrixXcd>
      modes_at_lines(double df, unsigned int n_lines) const;

      /// @p modal, the modes' part at @p omega, with the residual
      /// G_r / (1 + j w beta_r) added: at() = with_residual(w, modes_at(w)).
      Eigen::MatrixXcd
      with_residual(double omega, Eigen::MatrixXcd modal) const;

      /// The smallest eigenvalue of G_r over its largest: >= -1e-12 for a
      /// positive semidefinite residual (round-off).
      double
      residual_definiteness() const;
    };

    /// The 0 Hz line of @p green as a real n_p x n_p matrix: the structure's
    /// static compliance G(0) [m/N].
    Eigen::MatrixXd
    static_line(const base::FrequencyResponseMatrix &green);

    /**
     * @brief The synthesis from the modes (@p omega [rad/s], @p damping_ratio,
     * @p shapes [mode][point] and their imaginary parts @p shapes_imag, empty
     * for real shapes) and the static Green's functions @p static_green (the
     * direct solve at 0 Hz) at @p points: G_r = G(0) less the modes' part at
     * 0 Hz.
     */
    ModeSynthesis
    synthesise(const Eigen::VectorXd                    &omega,
               const Eigen::VectorXd                    &damping_ratio,
               const Eigen::MatrixXd                    &shapes,
               const Eigen::MatrixXd                    &shapes_imag,
               const Eigen::MatrixXd                    &static_green,
               const std::vector<std::array<double, 3>> &points);

    /**
     * The modes' part of the synthesis, ModeSynthesis::modes_at(), at every
     * line of a set of Green's functions: the β_r fit and compare() both
     * need it, and it is most of their work (the sum over every mode at
     * every line), so the modal stage computes it once for both.
     */
    struct ModalLines
    {
      /// g[l] at l df, l = 0 .. n_lines - 1; empty when not kept.
      std::vector<Eigen::MatrixXcd> g;
      double                        df = 0.;

      bool
      matches(const base::FrequencyResponseMatrix &direct) const
      {
        return g.size() == direct.n_lines && df == direct.df;
      }
    };

    /**
     * @brief The synthesis with G_r from the 0 Hz line of @p direct and its
     * relaxation fitted to every line (fit_residual_relaxation()): what the
     * modal stage and the contact use. If @p lines is given, the modes' part
     * at every line is left there for compare() (unless it would take more
     * than 1 GB: about 490 points and more at the default 257 lines).
     */
    ModeSynthesis
    synthesise(const Eigen::VectorXd               &omega,
               const Eigen::VectorXd               &damping_ratio,
               const Eigen::MatrixXd               &shapes,
               const Eigen::MatrixXd               &shapes_imag,
               const base::FrequencyResponseMatrix &direct,
               ModalLines                          *lines = nullptr);

    /**
     * @brief The residual's relaxation time beta_r [s] that makes
     * G_r / (1 + j w beta_r) closest to the residual of the direct Green's
     * functions @p direct, R(w) = g(w) - sum_k phi_k phi_k^T / (...), in the
     * least squares over every pair and line above 0 Hz: it minimises
     * sum |R (1 + j w beta) - G_r|^2, linear in beta. At least 0; the
     * relaxation of @p model itself is ignored. @p lines, if it matches
     * @p direct, holds the modes' part at every line already.
     * @throws NumericalError if the model and @p direct differ in points.
     */
    double
    fit_residual_relaxation(const ModeSynthesis                 &model,
                            const base::FrequencyResponseMatrix &direct,
                            const ModalLines                    *lines = nullptr);

    /**
     * @brief The synthesis as a PatchModel in rank-one form, for the
     * contact's convolutions: per mode the pole pair
     * \f$\lambda = \omega_k(-\xi_k + j\sqrt{1-\xi_k^2})\f$ with
     * \f$R = \phi\phi^T / (2 j \omega_d)\f$, so that
     * \f$R/(j\omega-\lambda) + \bar R/(j\omega-\bar\lambda)\f$ equals
     * \f$\phi\phi^T/(\omega_k^2-\omega^2+2j\xi_k\omega_k\omega)\f$ exactly. An
     * over-critical mode (\f$\xi_k \ge 1\f$) is two real poles
     * \f$\omega_k(-\xi_k \pm \sqrt{\xi_k^2-1})\f$ (\f$\xi_k\f$ within 1e-6
     * of 1 is taken as 1 + 1e-6). G_r is the model's instantaneous
     * compliance; with a relaxation beta_r > 0 it is instead n_p more real
     * poles at -1/beta_r, one per eigenvector v of G_r = sum d v v^T (shape
     * sqrt(d) v, factor 1/beta_r), `instantaneous` is left empty and
     * `residual_relaxation` says so. @p errors (E per pair, may be empty)
     * and @p f_max are copied.
     * @throws NumericalError for a mode with w_k <= 0 or a negative damping ratio.
     */
    modal::PatchModel
    to_patch_model(const ModeSynthesis &synthesis, const Eigen::MatrixXd &errors, double f_max);

    /**
     * @brief The same model with every residue a dense n_p x n_p matrix
     * (\f$R_k = c_k\phi_k\phi_k^T\f$): the identified model's form, for checks
     * of the rank-one path against the full one. A full model is returned as is.
     */
    modal::PatchModel
    full_form(const modal::PatchModel &model);

    /**
     * @brief Write @p synthesis as modal_model.h5 (temporary name, renamed when
     * complete): `/frequency_hz` [m], `/damping_ratio` [m], `/wavenumber` [m],
     * `/shapes` [m][n_p], `/shapes_imag` [m][n_p] (zeros for real shapes),
     * `/instantaneous` [n_p][n_p] (G_r),
     * `/residual_relaxation` [1] (beta_r [s]), `/points`
     * [n_p][3], `/dispersion` [rows][4] (wavenumber, branch, frequency [Hz],
     * damping ratio), and the attributes `parameters` and `stage_key`.
     */
    void
    write_modal_model(const std::filesystem::path &file,
                      const ModeSynthesis         &synthesis,
                      const base::ParameterRecord &record,
                      const std::string           &stage_key);

    /// Read a file written by write_modal_model().
    /// @throws InputError naming the file if it is incomplete or inconsistent.
    ModeSynthesis
    read_modal_model(const std::string &file);

    /// The `stage_key` of a modal model file, empty if there is none.
    std::string
    read_modal_model_key(const std::string &file);

    /// How far a synthesis is from the direct Green's functions.
    struct SynthesisErrors
    {
      /// E of Eq. (50) of every pair (i, j), at index i * n_p + j.
      std::vector<double> pair_error;
      double              median = 0., p90 = 0., worst = 0.;
      /// The worst pair.
      unsigned int worst_i = 0, worst_j = 0;
      /// The smallest eigenvalue of -Im g_model over its largest, over all
      /// lines above 0 Hz: >= 0 (to round-off) for a passive model.
      double passivity = 0.;
      /// The line of that smallest value [Hz].
      double passivity_frequency = 0.;
    };

    /**
     * @brief E of Eq. (50) of @p model against @p direct over all its lines
     * and pairs, and the model's passivity on the same lines. @p lines, if it
     * matches @p direct, holds the modes' part at every line already (the
     * modal stage's, left by synthesise()).
     */
    SynthesisErrors
    compare(const ModeSynthesis                 &model,
            const base::FrequencyResponseMatrix &direct,
            const ModalLines                    *lines = nullptr);
  } // namespace synthesis
} // namespace greentread
