#pragma once

#include <deal.II/base/parameter_handler.h>

/**
 * @file
 * Subsection "Inflation": the tyre's inflation pressure
 * (fe::InflationParameters); the inflation itself is in
 * greentread/fe/inflation.h. Implemented in source/fe/inflation_parameters.cc.
 */

namespace greentread
{
  namespace fe
  {
    /**
     * @brief Subsection "Inflation".
     */
    struct InflationParameters
    {
      double pressure = 2e5; ///< gauge pressure on the inner surface [Pa]

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace fe
} // namespace greentread
