#include <greentread/base/exceptions.h>
#include <greentread/convolution/modal_paper_convolution.h>

#include <deal.II/base/quadrature_lib.h>

#include <cmath>
#include <iostream>

namespace greentread
{
  namespace convolution
  {
    ModalPaperConvolution::ModalPaperConvolution(const modal::ModalModel &model, const double dt_)
        : Convolution(dt_)
        , g0(model.impulse_response(0.))
    {
      const dealii::QGauss<1> gauss(2);
      for (unsigned int g = 0; g < 2; ++g)
        {
          theta[g]  = gauss.point(g)[0];
          weight[g] = gauss.weight(g);
        }
      for (const auto &term : model.terms())
        {
          Mode m;
          m.kind        = term.kind;
          m.lambda      = term.lambda;
          m.residue     = term.residue;
          m.residue_t   = term.residue_t;
          m.scale       = term.kind == modal::ModalTerm::Kind::complex_pair ? 2. : 1.;
          m.step_decay  = std::exp(term.lambda * dt);
          m.step_growth = std::exp(-term.lambda * dt);
          for (unsigned int g = 0; g < 2; ++g)
            m.gauss_growth[g] = std::exp(-term.lambda * theta[g] * dt);
          modes.push_back(m);
        }

      // Psi of Eqs. (24)-(27): the current step by the same Gauss rule.
      const auto g = [&](double t) {
        return model.impulse_response(t);
      };
      const auto dg = [&](double t) {
        return model.impulse_response_derivative(t);
      };
      psi.u = {{g(dt), 0., 0., g0}};
      psi.v = {{dg(dt), 0., g0, dg(0.)}};
      for (unsigned int q = 0; q < 2; ++q)
        {
          const double r = (1. - theta[q]) * dt; // t_{n+1} - t_g
          psi.u[1] += weight[q] * dt * (1. - theta[q]) * g(r);
          psi.u[2] += weight[q] * dt * theta[q] * g(r);
          psi.v[1] += weight[q] * dt * (1. - theta[q]) * dg(r);
          psi.v[2] += weight[q] * dt * theta[q] * dg(r);
        }
    }



    Response
    ModalPaperConvolution::history()
    {
      const double t = (n + 1) * dt;
      Response     r;
      for (const auto &m : modes)
        {
          const std::complex<double> decay = m.decay * m.step_decay; // e^{lambda t}
          if (m.kind == modal::ModalTerm::Kind::double_pole)
            {
              const std::complex<double> core =
                (m.residue + m.residue_t * t) * m.acc0 - m.residue_t * m.acc1;
              r.u += std::real(decay * core);
              r.v += std::real(decay * (m.lambda * core + m.residue_t * m.acc0));
            }
          else
            {
              r.u += m.scale * std::real(m.residue * decay * m.acc0);
              r.v += m.scale * std::real(m.residue * m.lambda * decay * m.acc0);
            }
        }
      return r;
    }



    void
    ModalPaperConvolution::advance(const StepLoad &load)
    {
      const double t_n = n * dt;
      for (auto &m : modes)
        {
          // Eq. (15), with the two Gauss forces of the step.
          std::complex<double> add0 = m.grow * load.impulse_start;
          std::complex<double> add1 = t_n * m.grow * load.impulse_start;
          for (unsigned int g = 0; g < 2; ++g)
            {
              const double               q  = load.start * (1. - theta[g]) + load.end * theta[g];
              const std::complex<double> eg = m.grow * m.gauss_growth[g];
              add0 += weight[g] * dt * eg * q;
              add1 += weight[g] * dt * (t_n + theta[g] * dt) * eg * q;
            }
          m.grow *= m.step_growth;
          m.decay *= m.step_decay;
          add0 += m.grow * load.impulse_end;
          add1 += (t_n + dt) * m.grow * load.impulse_end;
          m.acc0 += add0;
          m.acc1 += add1;
          growth = std::max(growth, std::abs(m.grow));
        }
      ++n;

      if (!(growth < limit_growth))
        throw NumericalError(
          "modal-paper convolution (Eqs. 12-15) overflowed at t = " + format_short(n * dt) +
          " s (step " + std::to_string(n) + "): its growing factor exp(xi*omega*t) reached " +
          format_short(growth) +
          ", past 1/epsilon, so no significant digit of u is left, and it "
          "becomes inf at exp(709). Use 'set Method = modal-recursive' in subsection Convolution, "
          "which is exact for any run length and damping.");
      if (growth > warning_growth && !warned)
        {
          warned = true;
          std::cerr << "warning: modal-paper convolution: exp(xi*omega*t) = "
                    << format_short(growth) << " at t = " << format_short(n * dt) << " s; about "
                    << int(std::log10(growth))
                    << " of 16 significant digits of u are lost to round-off\n";
        }
    }
  } // namespace convolution
} // namespace greentread
