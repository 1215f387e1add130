#pragma once

#include <greentread/base/exceptions.h>
#include <greentread/convolution/exponential_integrals.h>
#include <greentread/contact/patch_convolution.h>
#include <greentread/modal/mode_synthesis.h>
#include <greentread/modal/patch_model.h>

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <vector>

/**
 * @file
 * The per-pole weights that the patch convolutions share
 * (source/contact/patch_convolution.cc, source/contact/
 * mode_patch_convolution.cc): the exact recursion's weights for a load linear
 * over the step, the residues in full or rank-one form, and the one-step
 * influences. Internal to the contact stage.
 */

namespace greentread
{
  namespace contact
  {
    namespace internal
    {
      /// Per-pole quantities shared by the convolutions.
      struct PoleWeights
      {
        // Per term k: e^{lambda dt} and the weights of the start and end
        // values of a linear load (greentread/convolution/
        // modal_recursive_convolution.h).
        std::vector<std::complex<double>> alpha, beta_a, beta_b;
        // Per term k, full form: c_u = s R, c_v = s R lambda, s = 2 for
        // pairs, 1 for real poles.
        std::vector<Eigen::MatrixXcd> cu, cv;
        // Rank-one form: c_u = s c_k phi_k phi_k^T, stored as the scalars
        // s c_k and s c_k lambda_k and the shapes phi_k (rows; complex
        // shapes have their imaginary parts in shapes_imag).
        std::vector<std::complex<double>> cu1, cv1;
        Eigen::MatrixXd                   shapes, shapes_imag;
        // The instantaneous compliance (may be empty) and the step.
        Eigen::MatrixXd instantaneous;
        double          dt;
        // A relaxing residual (its poles are among the terms): the force is
        // continuous as with an instantaneous one.
        bool relaxing;

        PoleWeights(const modal::PatchModel &model, const double dt_)
          : instantaneous(model.instantaneous)
          , dt(dt_)
          , relaxing(model.residual_relaxation > 0.)
        {
          if (!(dt > 0.) || !std::isfinite(dt))
            throw InputError("patch convolution: time step " + format_short(dt) +
                             " s is not allowed; allowed: a finite number > 0");
          if (model.is_rank_one())
            {
              shapes      = model.shapes;
              shapes_imag = model.shapes_imag;
            }
          for (unsigned int k = 0; k < model.n_terms(); ++k)
            {
              const std::complex<double> l = model.lambda[k];
              if (!(l.real() < 0.))
                throw NumericalError("patch convolution: pole " + std::to_string(k) +
                                     " has Re(lambda) = " + format_short(l.real()) +
                                     " >= 0; only stable poles can be convolved");
              const auto psi = convolution::exponential_moments(l * dt);
              alpha.push_back(std::exp(l * dt));
              beta_a.push_back(dt * psi[1]);
              beta_b.push_back(dt * (psi[0] - psi[1]));
              const double scale = model.real[k] ? 1. : 2.;
              if (model.is_rank_one())
                {
                  const std::complex<double> c =
                    model.real[k] ? std::complex<double>(scale * model.factor[k].real()) :
                                    scale * model.factor[k];
                  cu1.push_back(c);
                  cv1.push_back(c * l);
                  continue;
                }
              Eigen::MatrixXcd r = scale * model.residues[k];
              if (model.real[k])
                r = r.real().cast<std::complex<double>>();
              cu.push_back(r);
              cv.push_back(r * l);
            }
        }

        bool
        rank_one() const
        {
          return shapes.rows() > 0;
        }

        /// Re sum_k c_k z_k (c_u, or c_v with @p velocity) for per-term
        /// coefficients z.
        Eigen::MatrixXd
        contract(const bool velocity, const std::vector<std::complex<double>> &z) const
        {
          if (rank_one())
            {
              const auto     &c = velocity ? cv1 : cu1;
              Eigen::VectorXd re(z.size()), im(z.size());
              for (std::size_t k = 0; k < z.size(); ++k)
                {
                  re(k) = std::real(c[k] * z[k]);
                  im(k) = -std::imag(c[k] * z[k]);
                }
              return modal::shape_sum(shapes, shapes_imag, re, im);
            }
          const auto     &c      = velocity ? cv : cu;
          Eigen::MatrixXd result = Eigen::MatrixXd::Zero(c[0].rows(), c[0].cols());
          for (std::size_t k = 0; k < c.size(); ++k)
            result += (c[k].real() * z[k].real() - c[k].imag() * z[k].imag());
          return result;
        }

        PatchInfluence
        influence() const
        {
          const std::vector<std::complex<double>> ones(alpha.size(), 1.);
          PatchInfluence                          psi;
          const Eigen::MatrixXd                   g0 = contract(false, ones);
          psi.u = {{contract(false, alpha), contract(false, beta_a), contract(false, beta_b), g0}};
          psi.v = {{contract(true, alpha), contract(true, beta_a), contract(true, beta_b) + g0,
                    contract(true, ones)}};
          if (instantaneous.size() && instantaneous.cwiseAbs().maxCoeff() > 0.)
            {
              // u = G_r q(t): the end value acts at once; the slope of the
              // linear load, (end - start) / dt, gives G_r q'.
              psi.u[2] += instantaneous;
              psi.v[1] -= instantaneous / dt;
              psi.v[2] += instantaneous / dt;
              psi.instantaneous = true;
            }
          if (relaxing)
            psi.instantaneous = true;
          return psi;
        }
      };
    } // namespace internal
  } // namespace contact
} // namespace greentread
