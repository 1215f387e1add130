#pragma once

#include <Eigen/Core>

#include <vector>

/**
 * @file
 * The tread's small-scale losses: the power the rubber dissipates in the
 * deformation the contact grid's local term carries (the tread below the
 * Green's functions' rectangles, greentread/contact/contact_grid.h, and the
 * finite blocks of a tread pattern, greentread/contact/tread_block.h), which
 * the contact solve treats as elastic. Implemented in
 * source/analysis/tread_losses.cc.
 *
 * **The model.** The rubber has a loss factor eta independent of frequency
 * (`Materials/Tread pattern/Loss factor`, the one the finite-element tread turns into
 * Rayleigh damping at the Green's functions' scale). A constant loss factor
 * is not causal; a chain of J Kelvin creep elements in series with the
 * elastic layer is, and its loss factor
 * \f[
 *   \eta(\omega) = c \sum_j \frac{\omega\tau_j}{1 + \omega^2\tau_j^2}
 * \f]
 * is flat between its shortest and its longest relaxation times when they
 * are log-spaced (the sum of Debye peaks; its ripple falls as
 * \f$e^{-\pi^2/h}\f$ with h the spacing in ln tau). Here two per decade, from
 * 0.1 Hz to 1 MHz, c set so that eta(omega) = eta at their centre (316 Hz):
 * within 1% of eta from 10 Hz to 20 kHz (0.8% at 20 kHz, 3.4% at 1 Hz and
 * 100 kHz; unit/tread_losses checks it).
 *
 * **To first order in eta.** The elastic run's local displacement w at the
 * contact points (w = L f, L the local compliance and f the end force of each
 * step) drives each element's lagged displacement, \f$\tau_j \dot y_j + y_j =
 * w\f$ (element j's own displacement is c y_j), and the force its lag,
 * \f$\tau_j \dot g_j + g_j = f\f$, so that y_j = L g_j. What element j
 * dissipates is the work into it less the change of what it stores,
 * \f$c\,(f \cdot \dot y_j - \tfrac{d}{dt}\tfrac12 g_j \cdot y_j)\f$, and
 * its mean over the harmonics of amplitudes F is
 * \f[
 *   P = \sum_\omega \tfrac12 \omega\,\eta(\omega)\,\mathrm{Re}(F^H L F),
 * \f]
 * a hysteretic layer's. Taking the dissipation rather than the work keeps a
 * slow element's drift from the static start (the mean force differs from
 * it) out of a record shorter than its relaxation time: that drift moves
 * stored energy, to first order in the difference, and dissipates only to
 * second. With a pattern's finite blocks L moves with them, and g_j . y_j / 2
 * is the stored energy only approximately. The loss is not fed back into the
 * contact: the run stays elastic below the Green's functions' scale, and the
 * power is the first term of an expansion in eta.
 *
 * **In time.** w and f are linear over a step, so y_j and g_j follow exactly:
 * \f$y_{n+1} = e\,y_n + w_{n+1} - e\,w_n - (w_{n+1} - w_n)(1 - e)\tau_j /
 * \Delta t\f$ with \f$e = e^{-\Delta t/\tau_j}\f$ (g_j alike), bounded at
 * any step (no exponential grows), and the work into them, \f$\int f \cdot
 * \dot y_j\,dt\f$, is integrated exactly over the step: what the chain
 * dissipates under the run's piecewise linear force, at any step.
 */

namespace greentread
{
  namespace analysis
  {
    /**
     * @brief The work the tread's rubber dissipates, step by step (file
     * documentation): one per run, fed each step's mean contact force and
     * the local displacement at its end.
     */
    class TreadLossMeter
    {
    public:
      /**
       * @param[in] loss_factor eta, at least 0.
       * @param[in] time_step dt [s], above 0.
       * @param[in] f_start, w_start The end force and the local displacement
       *            at the static start, where every element is relaxed.
       * @throws InputError naming 'Materials/Tread pattern/Loss factor' if eta is
       *         negative or not finite; std::invalid_argument if dt is not
       *         above 0.
       */
      TreadLossMeter(double                 loss_factor,
                     double                 time_step,
                     const Eigen::VectorXd &f_start,
                     const Eigen::VectorXd &w_start);

      /**
       * @brief The energy [J] dissipated over one step, from the force
       * @p f_end and the local displacement @p w_end at its end (both linear
       * over the step from the last step's).
       */
      double
      add(const Eigen::VectorXd &f_end, const Eigen::VectorXd &w_end);

      /// eta(omega) of the chain at @p frequency [Hz] (file documentation).
      double
      loss_factor(double frequency) const;

      /// The chain's relaxation frequencies 1 / (2 pi tau_j) [Hz].
      static std::vector<double>
      relaxation_frequencies();

    private:
      double              dt;
      std::vector<double> tau, decay, lag; ///< tau_j, e_j, (1 - e_j) tau_j / dt
      double              c = 0.;
      Eigen::MatrixXd     y, g; ///< one column per element
      Eigen::VectorXd     f_last, w_last;
    };
  } // namespace analysis
} // namespace greentread
