#pragma once

#include <greentread/convolution/convolution_parameters.h>
#include <greentread/convolution/patch_convolution.h>

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace greentread
{
  namespace contact
  {
    /// Subsection "Rolling", with 'Time stepping/Time step', 'Convolution/Method' and
    /// 'Convolution/Shape precision'.
    struct RollingParameters
    {
      std::vector<double> speeds   = {50., 70., 90.}; // km/h
      double              distance = 2.;
      double time_step    = 0.; // Time stepping/Time step; 0: the road sampling interval / V
      double static_load  = 600.;
      double indentation  = 0.;
      bool   static_start = true;
      convolution::Method         convolution = convolution::Method::modal_recursive;
      convolution::ShapePrecision shape_precision =
        convolution::ShapePrecision::single_precision; // convolution::Convolution/Shape precision
      unsigned int direct_kernel    = 0;
      unsigned int frames           = 40;
      double       stress_reference = 100.;

      /// The time step at @p speed [m/s] on a road sampled every @p spacing
      /// [m]: 'Time stepping/Time step', or (0) one road sample per step.
      double
      time_step_for(const double spacing, const double speed) const
      {
        return time_step > 0. ? time_step : spacing / speed;
      }

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace contact
} // namespace greentread
