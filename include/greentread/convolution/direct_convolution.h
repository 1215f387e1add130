#pragma once

#include <greentread/convolution/convolution.h>

#include <functional>
#include <vector>

namespace greentread
{
  namespace convolution
  {
    /**
     * @brief The number N_g of kernel steps kept by the paper's rule
     * (Section 3.2): the tail where every sample \f$|g(m\,\Delta t)|\f$ is
     * below @p threshold times the largest one is cut.
     *
     * @param[in] g         The Green's function.
     * @param[in] dt        Time step [s].
     * @param[in] threshold Relative amplitude, 0.01 in the paper; 0 keeps all.
     * @param[in] n_max     The longest kernel that can matter (the number of
     *                      steps of the run).
     * @return N_g in [1, n_max + 1]: lags 0 .. N_g - 1 are kept.
     */
    unsigned int
    truncation_length(const std::function<double(double)> &g,
                      double                               dt,
                      double                               threshold,
                      unsigned int                         n_max);

    /**
     * @brief Direct convolution, Eqs. (39)-(40): the displacement at
     * \f$t_{n+1}\f$ is a sum over the last N_g steps of kernel weights times
     * the recorded loads. Cost O(N_g) per step.
     *
     * The kernel weights are the integrals of g (and g') against the
     * piecewise-linear load of each step,
     * \f$W^b_m = \int_0^{\Delta t} g(m\Delta t + r)(1 - r/\Delta t)\,dr\f$ and
     * \f$W^a_m = \int_0^{\Delta t} g(m\Delta t + r)\,r/\Delta t\,dr\f$, plus
     * the samples \f$g(m\Delta t)\f$ for impulses. They are computed from the
     * callables by Gauss-Legendre quadrature, independently of any modal form,
     * so that this class is a reference for the modal methods: without
     * truncation the two agree to round-off on the same load history.
     */
    class DirectConvolution : public Convolution
    {
    public:
      /**
       * @param[in] g        Green's function g(t), t >= 0.
       * @param[in] dg       Its derivative, with dg(0) the right limit.
       * @param[in] dt       Time step [s].
       * @param[in] n_kernel N_g, from truncation_length().
       * @param[in] n_steps  The number of steps that will be run.
       * @param[in] rate     The fastest rate in g [1/s] (largest |lambda|),
       *                     which sets the quadrature resolution.
       */
      DirectConvolution(const std::function<double(double)> &g,
                        const std::function<double(double)> &dg,
                        double                               dt,
                        unsigned int                         n_kernel,
                        unsigned int                         n_steps,
                        double                               rate);

      Response
      history() override;

      void
      advance(const StepLoad &load) override;

      std::string
      name() const override
      {
        return "direct";
      }

      unsigned int
      size() const override
      {
        return n_kernel;
      }

    private:
      unsigned int n_kernel;
      unsigned int n_steps;

      /// Kernels stored by decreasing lag, lag n_kernel - 1 first, so that a
      /// history sum is one contiguous dot product.
      std::vector<double> rev_wa, rev_wb, rev_va, rev_vb, rev_gu, rev_gv;

      /// Linear-load values per step and impulses per node.
      std::vector<double> start_values, end_values, impulses;
    };
  } // namespace convolution
} // namespace greentread
