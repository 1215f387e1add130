#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/convolution/convolution_parameters.h>
#include <greentread/convolution/direct_convolution.h>
#include <greentread/convolution/modal_paper_convolution.h>
#include <greentread/convolution/modal_recursive_convolution.h>

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



    Method
    parse_method(const std::string         &name,
                 const std::vector<Method> &allowed,
                 const std::string         &why)
    {
      std::string list;
      for (const auto m : allowed)
        {
          if (name == to_string(m))
            return m;
          list += (list.empty() ? "" : ", ") + to_string(m);
        }
      throw InputError("parameter 'Convolution/Method' = " + name + " is not allowed" +
                       (why.empty() ? "" : " " + why) + "; allowed: " + list);
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
          "linear over the step; exact for any run length. Scene tyre-road-contact: "
          "'direct' (the sum over every past step with the patch model's kernels, the "
          "reference) or 'modal-recursive'.");
        prm.declare_entry(
          "Shape precision", "single", dealii::Patterns::Selection("double|single"),
          "Scene tyre-road-contact with 'Patch model/Source' = fe modes and 'Method' = "
          "modal-recursive: the precision in which the rolling update keeps the mode shapes at "
          "the points. The update reads every shape once per step and is limited by memory "
          "bandwidth; 'single' halves the bytes (each value rounded to 6e-8 of itself, the "
          "products formed in float). The states and the history stay in double precision. "
          "'double' keeps the shapes as the modal stage computed them.");
        prm.declare_entry(
          "Truncation threshold", "0.01", base::RangePattern::closed(0., 1., ""),
          "Scene sdof, direct method only: the Green's function is cut after N_g steps, where its "
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
        method               = parse_method(prm.get("Method"));
        truncation_threshold = prm.get_double("Truncation threshold");
      }
      prm.leave_subsection();
    }



    std::unique_ptr<Convolution>
    create(const ConvolutionParameters &parameters,
           const modal::ModalModel     &model,
           const double                 dt,
           const unsigned int           n_steps,
           const ImpulseResponse       *exact)
    {
      switch (parameters.method)
        {
          case Method::direct:
            {
              ImpulseResponse response;
              if (exact)
                response = *exact;
              else
                response = {[&model](double t) {
                              return model.impulse_response(t);
                            },
                            [&model](double t) {
                              return model.impulse_response_derivative(t);
                            },
                            model.max_modulus()};
              const unsigned int n_g =
                truncation_length(response.g, dt, parameters.truncation_threshold, n_steps);
              return std::make_unique<DirectConvolution>(response.g, response.dg, dt, n_g, n_steps,
                                                         response.rate);
            }
          case Method::modal_paper:
            return std::make_unique<ModalPaperConvolution>(model, dt);
          case Method::modal_recursive:
            return std::make_unique<ModalRecursiveConvolution>(model, dt);
        }
      throw std::logic_error("convolution::create: unknown method");
    }
  } // namespace convolution
} // namespace greentread
