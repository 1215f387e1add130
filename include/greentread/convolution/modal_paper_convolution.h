#pragma once

#include <greentread/convolution/convolution.h>
#include <greentread/modal/modal_model.h>

#include <complex>
#include <vector>

namespace greentread
{
  namespace convolution
  {
    /**
     * @brief The fast modal convolution as the paper prints it, Eqs. (12)-(15)
     * and (22): for each mode the integrals
     * \f$\alpha(t) = \int_0^t e^{\xi\omega\tau}\cos(\omega_d\tau)q\,d\tau\f$ and
     * \f$\beta(t) = \int_0^t e^{\xi\omega\tau}\sin(\omega_d\tau)q\,d\tau\f$
     * are accumulated, and multiplied by \f$e^{-\xi\omega t}\f$ to give u.
     *
     * Written with complex poles, \f$\alpha - j\beta = \int_0^t
     * e^{-\lambda\tau} q\,d\tau\f$ and \f$u = \sum 2\,\mathrm{Re}(R e^{\lambda
     * t}(\alpha - j\beta))\f$, which also covers real and double poles. Each
     * step adds the two-point Gauss quadrature of the step's load (the Gauss
     * forces of Eq. 23), and impulses exactly.
     *
     * The factor \f$e^{\xi\omega t}\f$ grows without bound: the round-off of
     * u grows with it and it overflows after
     * \f$t = 709/(\xi\omega)\f$. This class watches it: past
     * warning_growth it says once how many digits are lost; past
     * limit_growth (1/epsilon, no digit left) it throws a NumericalError
     * instead of returning garbage, inf or NaN.
     */
    class ModalPaperConvolution : public Convolution
    {
    public:
      /// Growth factor past which a warning is printed once (8 digits lost).
      static constexpr double warning_growth = 1e8;
      /// Growth factor past which the run is stopped (no digit left).
      static constexpr double limit_growth = 4.5e15;

      ModalPaperConvolution(const modal::ModalModel &model, double dt);

      Response
      history() override;

      void
      advance(const StepLoad &load) override;

      std::string
      name() const override
      {
        return "modal-paper";
      }

      unsigned int
      size() const override
      {
        return static_cast<unsigned int>(modes.size());
      }

      /// The largest \f$|e^{-\lambda t}|\f$ reached so far.
      double
      largest_growth() const
      {
        return growth;
      }

    private:
      struct Mode
      {
        modal::ModalTerm::Kind kind;
        std::complex<double>   lambda, residue;
        double                 residue_t;
        double                 scale;           // 2 for a pair, 1 otherwise
        std::complex<double>   step_decay;      // e^{lambda dt}
        std::complex<double>   step_growth;     // e^{-lambda dt}
        std::complex<double>   gauss_growth[2]; // e^{-lambda theta_g dt}
        std::complex<double>   decay = 1.;      // e^{lambda t_n}
        std::complex<double>   grow  = 1.;      // e^{-lambda t_n}
        std::complex<double>   acc0  = 0.;      // int e^{-lambda tau} q
        std::complex<double>   acc1  = 0.;      // int tau e^{-lambda tau} q (double pole)
      };

      std::vector<Mode> modes;
      double            theta[2], weight[2];
      double            g0;
      double            growth = 1.;
      bool              warned = false;
    };
  } // namespace convolution
} // namespace greentread
