#pragma once

#include <greentread/convolution/convolution.h>
#include <greentread/modal/modal_model.h>

#include <Eigen/Core>

#include <vector>

namespace greentread
{
  namespace convolution
  {
    /**
     * @brief Exact recursive modal convolution: one state per pole,
     * \f$s_k(t) = \int_0^t e^{\lambda_k (t-\tau)} q(\tau)\,d\tau\f$, advanced by
     * \f[
     *   s_{n+1} = e^{\lambda\Delta t}\,(s_n + P^{start})
     *           + \beta_1\,q^{start} + \beta_0\,q^{end} + P^{end},
     * \f]
     * with \f$\beta_0 = \Delta t\,(\psi_0 - \psi_1)(\lambda\Delta t)\f$ and
     * \f$\beta_1 = \Delta t\,\psi_1(\lambda\Delta t)\f$ the exact weights of a
     * load linear over the step (greentread/convolution/exponential_integrals.h).
     *
     * Unlike Eqs. (12)-(15) nothing grows: \f$|e^{\lambda\Delta t}| \le 1\f$
     * for a stable pole, so runs of any length and damping stay exact to
     * round-off. Cost O(N_m) per step; states are kept as separate real and
     * imaginary arrays so that Eigen vectorises the update.
     */
    class ModalRecursiveConvolution : public Convolution
    {
    public:
      /**
       * @throws NumericalError if the model has a pole with Re(lambda) > 0.
       */
      ModalRecursiveConvolution(const modal::ModalModel &model, double dt);

      Response
      history() override;

      void
      advance(const StepLoad &load) override;

      std::string
      name() const override
      {
        return "modal-recursive";
      }

      unsigned int
      size() const override
      {
        return n_modes;
      }

    private:
      unsigned int n_modes;

      // Simple poles (pairs and real ones), structure of arrays.
      Eigen::ArrayXd alpha_re, alpha_im;   // e^{lambda dt}
      Eigen::ArrayXd beta_a_re, beta_a_im; // weight of the start value
      Eigen::ArrayXd beta_b_re, beta_b_im; // weight of the end value
      Eigen::ArrayXd cu_re, cu_im;         // u = Re(sum cu s)
      Eigen::ArrayXd cv_re, cv_im;         // v = Re(sum cv s) + g0 q
      Eigen::ArrayXd s_re, s_im;           // states
      Eigen::ArrayXd h_re, h_im;           // e^{lambda dt} s, from history()

      /// A double pole: states s0 = int e^{l(t-tau)} q, s1 = int (t-tau) e^{l(t-tau)} q.
      struct DoublePole
      {
        double lambda, r0, r1;
        double alpha;    // e^{lambda dt}
        double wa0, wb0; // weights into s0
        double wa1, wb1; // weights into s1
        double s0 = 0., s1 = 0.;
        double h0 = 0., h1 = 0.;
      };
      std::vector<DoublePole> double_poles;

      bool history_ready = false;
    };
  } // namespace convolution
} // namespace greentread
