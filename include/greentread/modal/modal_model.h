#pragma once

#include <greentread/base/frequency_response.h>

#include <complex>
#include <string>
#include <vector>

/**
 * @file
 * A Green's function as a sum of modes: the pole-residue form of the paper's
 * Appendix A (Eq. A.1-A.3).
 */

namespace greentread
{
  namespace modal
  {
    /**
     * @brief One term of a pole-residue model.
     *
     * - complex_pair: \f$g(t) = 2\,\mathrm{Re}(R\,e^{\lambda t})\f$, with
     *   \f$\mathrm{Im}\,\lambda > 0\f$ standing for the conjugate pair;
     *   \f$\hat g(\omega) = R/(j\omega-\lambda) + \bar R/(j\omega-\bar\lambda)\f$.
     * - real_pole: \f$g(t) = R\,e^{\lambda t}\f$, \f$\lambda, R\f$ real
     *   (an over-damped mode contributes two of them).
     * - double_pole: \f$g(t) = (R + R_t\,t)\,e^{\lambda t}\f$, \f$\lambda\f$
     *   real: the critically damped mode (\f$\xi = 1\f$), where the two real
     *   poles meet and their residues would be infinite.
     */
    struct ModalTerm
    {
      enum class Kind
      {
        complex_pair,
        real_pole,
        double_pole
      };

      Kind                 kind;
      std::complex<double> lambda;
      std::complex<double> residue;
      /// Coefficient of \f$t e^{\lambda t}\f$ (double_pole only).
      double residue_t = 0.;
    };

    /**
     * @brief A Green's function \f$g(t) = \sum_k g_k(t)\f$ for \f$t \ge 0\f$
     * (zero before), stored as ModalTerm objects.
     *
     * With the time convention \f$e^{j\omega t}\f$, its frequency response is
     * \f$\hat g(\omega) = \int_0^\infty g(t) e^{-j\omega t} dt\f$, which for a
     * mass-spring-damper is \f$(K + j\omega C - \omega^2 M)^{-1}\f$ (Eq. 3).
     */
    class ModalModel
    {
    public:
      /// Add a complex-conjugate pair; @p lambda must have Im > 0.
      void
      add_pair(std::complex<double> lambda, std::complex<double> residue);

      /// Add a real pole with a real residue.
      void
      add_real(double lambda, double residue);

      /// Add a double real pole, \f$(R + R_t t) e^{\lambda t}\f$.
      void
      add_double(double lambda, double residue, double residue_t);

      const std::vector<ModalTerm> &
      terms() const
      {
        return term_list;
      }

      /// The number of modes N_m: one per pair, one per real or double pole.
      unsigned int
      n_modes() const
      {
        return static_cast<unsigned int>(term_list.size());
      }

      /// \f$g(t)\f$, zero for t < 0.
      double
      impulse_response(double t) const;

      /// \f$g'(t)\f$ for t > 0; at t = 0 the right limit \f$g'(0^+)\f$.
      double
      impulse_response_derivative(double t) const;

      /// \f$\hat g(\omega)\f$, omega in rad/s.
      std::complex<double>
      frequency_response(double omega) const;

      /// The largest \f$\mathrm{Re}\,\lambda\f$ (negative for a stable model).
      double
      max_real_part() const;

      /// The largest \f$|\lambda|\f$, the fastest time scale of the model.
      double
      max_modulus() const;

    private:
      std::vector<ModalTerm> term_list;
    };
    /**
     * @brief The FRF of a modal model on the grid \f$k\,\Delta f\f$,
     * k = 0 .. n_lines-1.
     */
    base::FrequencyResponse
    sample(const modal::ModalModel &model, double df, unsigned int n_lines);

  } // namespace modal
} // namespace greentread
