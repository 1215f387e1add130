#pragma once

#include <greentread/convolution/convolution.h>
#include <greentread/modal/modal_model.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>

#include <string>
#include <vector>

namespace greentread
{
  namespace convolution
  {
    /// The three convolution methods the paper compares.
    enum class Method
    {
      direct,         ///< Eqs. (39)-(40), cost O(N_g) per step
      modal_paper,    ///< Eqs. (12)-(15) as printed, growing exponentials
      modal_recursive ///< one decaying state per pole, exact weights
    };

    /// The names of the .prm files: "direct", "modal-paper", "modal-recursive".
    std::string
    to_string(Method method);

    /**
     * @brief The method named @p name, among @p allowed.
     * @throws InputError naming 'Convolution/Method', the value and the
     * allowed names (@p why, if given, says why others are not).
     */
    Method
    parse_method(const std::string         &name,
                 const std::vector<Method> &allowed = {Method::direct, Method::modal_paper,
                                                       Method::modal_recursive},
                 const std::string         &why     = "");

    /**
     * @brief Subsection "Convolution".
     */
    struct ConvolutionParameters
    {
      Method method = Method::modal_recursive;
      /// Relative amplitude below which the direct kernel is cut (paper: 1%).
      double truncation_threshold = 0.01;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// An impulse response known in closed form, for the direct method.
    struct ImpulseResponse
    {
      std::function<double(double)> g, dg;     ///< g(t) [m/(N s)] and dg/dt
      double                        rate = 0.; ///< its fastest rate |lambda| [1/s]
    };

    /**
     * @brief The one selection point of the one-point convolutions: the
     * method of @p parameters for a run of @p n_steps steps of @p dt.
     *
     * The modal methods convolve with @p model; the direct method with
     * @p exact if given, else with the impulse response of @p model, cut
     * by the truncation threshold.
     */
    std::unique_ptr<Convolution>
    create(const ConvolutionParameters &parameters,
           const modal::ModalModel     &model,
           double                       dt,
           unsigned int                 n_steps,
           const ImpulseResponse       *exact = nullptr);
  } // namespace convolution
} // namespace greentread
