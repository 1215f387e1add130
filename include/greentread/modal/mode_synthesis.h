#pragma once

#include <greentread/modal/frequency_response.h>

#include <Eigen/Dense>

#include <array>
#include <vector>

/**
 * @file
 * The patch model from the ring's own modes: with real, mass-normalised
 * modes phi_k (their values at the contact points), natural frequencies w_k
 * and modal damping ratios xi_k,
 *   g(w) = G_r + sum_k phi_k phi_k^T / (w_k^2 - w^2 + 2 j xi_k w_k w),
 * where the static residual G_r = G(0) - sum_k phi_k phi_k^T / w_k^2 carries
 * the modes above the cut-off at their static value (the mode-acceleration
 * correction). Every term is passive: -Im g(w) is a sum of positive
 * semidefinite rank-one terms for w > 0. G_r is positive semidefinite: it is
 * the part of the static flexibility that the modes left out.
 */

namespace greentread
{
  namespace modal
  {
    /// A modal synthesis at the contact points.
    struct ModeSynthesis
    {
      /// Per mode: natural frequency [Hz] and damping ratio, ascending.
      Eigen::VectorXd frequency_hz, damping_ratio;
      /// The mass-normalised mode values at the points, [mode][point] [1/sqrt(kg)].
      Eigen::MatrixXd shapes;
      /// G_r, [point][point] [m/N].
      Eigen::MatrixXd instantaneous;
      /// The points [m]: x, y, radius.
      std::vector<std::array<double, 3>> points;

      unsigned int
      n_modes() const
      {
        return static_cast<unsigned int>(frequency_hz.size());
      }

      /// g(w) at the angular frequency @p omega [rad/s].
      Eigen::MatrixXcd
      at(double omega) const;

      /// The smallest eigenvalue of G_r over its largest: >= -1e-12 for a
      /// positive semidefinite residual (round-off).
      double
      residual_definiteness() const;
    };

    /**
     * @brief The synthesis from the modes (@p omega [rad/s], @p damping_ratio,
     * @p shapes [mode][point]) and the static Green's functions
     * @p static_green (the direct solve at 0 Hz) at @p points.
     */
    ModeSynthesis
    synthesise(const Eigen::VectorXd                    &omega,
               const Eigen::VectorXd                    &damping_ratio,
               const Eigen::MatrixXd                    &shapes,
               const Eigen::MatrixXd                    &static_green,
               const std::vector<std::array<double, 3>> &points);

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
    };

    /**
     * @brief E of Eq. (50) of @p model against @p direct over all its lines
     * and pairs, and the model's passivity on the same lines.
     */
    SynthesisErrors
    compare(const ModeSynthesis &model, const FrequencyResponseMatrix &direct);
  } // namespace modal
} // namespace greentread
