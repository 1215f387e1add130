#pragma once

#include <greentread/modal/modal_model.h>
#include <greentread/sdof/oscillator_parameters.h>

/**
 * @file
 * The single-degree-of-freedom oscillator of the paper's Section 3,
 * \f$M\ddot u + C\dot u + K u = -M g + F\f$ (Eq. 30).
 */

namespace greentread
{
  namespace sdof
  {
    /**
     * @brief The oscillator's closed-form responses.
     *
     * Every function here is valid for any damping ratio: under-damped,
     * critically damped (\f$\xi = 1\f$, where \f$\omega_d = 0\f$ and the
     * textbook formulas divide by zero) and over-damped, and never overflows:
     * the products \f$e^{-\sigma t}\cos(\omega_d t)\f$ and
     * \f$e^{-\sigma t}\sin(\omega_d t)/\omega_d\f$ are evaluated as one
     * function of \f$\delta = \omega_0^2 - \sigma^2\f$ (a power series in
     * \f$\delta t^2\f$ near \f$\delta = 0\f$, hyperbolic functions folded
     * into the exponential for \f$\delta < 0\f$).
     */
    class Oscillator
    {
    public:
      explicit Oscillator(const OscillatorParameters &parameters);

      double
      mass() const
      {
        return M;
      }
      double
      stiffness() const
      {
        return K;
      }
      double
      damping() const
      {
        return C;
      }
      double
      damping_ratio() const
      {
        return xi;
      }
      double
      gravity() const
      {
        return g;
      }
      /// \f$\omega_0 = \sqrt{K/M}\f$ [rad/s].
      double
      natural_frequency() const
      {
        return omega0;
      }
      /// \f$-g/\omega_0^2\f$: where gravity alone would hold the mass [m].
      double
      static_deflection() const
      {
        return -g / (omega0 * omega0);
      }

      /// Both damped functions below in one evaluation.
      void
      damped_functions(double t, double &damped_cos_value, double &damped_sin_value) const;

      /// \f$e^{-\sigma t}\cos(\omega_d t)\f$ and its analytic continuations.
      double
      damped_cos(double t) const;

      /// \f$e^{-\sigma t}\sin(\omega_d t)/\omega_d\f$ and its continuations.
      double
      damped_sin(double t) const;

      /// Green's function \f$g(t)\f$ (Eq. 8 with one mode, A = 1/M).
      double
      green(double t) const;

      /// \f$g'(t)\f$, with \f$g'(0) = 1/M\f$.
      double
      green_derivative(double t) const;

      /// \f$\hat g(\omega) = (K + j\omega C - \omega^2 M)^{-1}\f$ (Eq. 3).
      std::complex<double>
      frequency_response(double omega) const;

      /**
       * @brief The pole-residue form of g: one pair for \f$\xi < 1\f$, two
       * real poles for \f$\xi > 1\f$, a double pole for
       * \f$|\xi - 1| \le 10^{-8}\f$ (there the split residues would lose
       * more digits to cancellation than the merge costs).
       */
      modal::ModalModel
      modal_model() const;

      /**
       * @brief Free motion under gravity alone from (u0, v0): displacement
       * and velocity after time @p t.
       */
      void
      free_motion(double u0, double v0, double t, double &u, double &v) const;

    private:
      double M, K, xi, g;
      double C, omega0, sigma, delta;
    };
  } // namespace sdof
} // namespace greentread
