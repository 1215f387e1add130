#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

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

    std::string
    to_string(Method method);

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
  } // namespace convolution
} // namespace greentread
