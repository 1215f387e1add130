#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/convolution/convolution_parameters.h>

namespace greentread
{
  namespace convolution
  {
    std::string
    to_string(const Method method)
    {
      switch (method)
        {
          case Method::direct:
            return "direct";
          case Method::modal_paper:
            return "modal-paper";
          case Method::modal_recursive:
            return "modal-recursive";
        }
      return "unknown";
    }



    void
    ConvolutionParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Convolution");
      {
        prm.declare_entry(
          "Method", "modal-recursive",
          dealii::Patterns::Selection("direct|modal-paper|modal-recursive"),
          "How u = g * q is evaluated. 'direct': Eqs. (39)-(40), a sum over the last N_g "
          "steps. 'modal-paper': Eqs. (12)-(15) as printed, with exp(+xi w t) factors that "
          "grow and overflow on long or heavily damped runs (detected and reported). "
          "'modal-recursive': one decaying state per pole with exact weights for a load "
          "linear over the step; exact for any run length.");
        prm.declare_entry(
          "Truncation threshold", "0.01", base::RangePattern::closed(0., 1., ""),
          "Direct method only: the Green's function is cut after N_g steps, where its "
          "amplitude stays below this fraction of its maximum (the paper's rule: 0.01). "
          "0 keeps the whole run. Unit: 1.");
      }
      prm.leave_subsection();
    }



    void
    ConvolutionParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Convolution");
      {
        const std::string name = prm.get("Method");
        method = name == "direct"      ? Method::direct :
                 name == "modal-paper" ? Method::modal_paper :
                                         Method::modal_recursive;
        truncation_threshold = prm.get_double("Truncation threshold");
      }
      prm.leave_subsection();
    }
  } // namespace convolution
} // namespace greentread
