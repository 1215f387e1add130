#pragma once

#include <greentread/base/exceptions.h>
#include <greentread/convolution/exponential_integrals.h>
#include <greentread/convolution/patch_convolution.h>
#include <greentread/modal/patch_model.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <deal.II/base/thread_management.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <complex>
#include <vector>

/**
 * @file
 * The per-pole weights that the patch convolutions share
 * (source/convolution/patch_convolution.cc, source/contact/
 * mode_patch_convolution.cc): the exact recursion's weights for a load linear
 * over the step, the residues in full or rank-one form, and the one-step
 * influences. Internal to the contact stage.
 */

namespace greentread
{
  namespace convolution
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
          // The eight sums (u and v of alpha, beta_a, beta_b, 1); for a
          // rank-one model in two passes over the shapes, one per thread,
          // not eight.
          const std::array<const std::vector<std::complex<double>> *, 4> z{
            {&alpha, &beta_a, &beta_b, &ones}};
          std::array<Eigen::MatrixXd, 8> sums;
          if (rank_one())
            {
              std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> weights[2];
              for (unsigned int s = 0; s < 8; ++s)
                {
                  const auto     &c = s < 4 ? cu1 : cv1;
                  const auto     &x = *z[s % 4];
                  Eigen::VectorXd re(x.size()), im(x.size());
                  for (std::size_t k = 0; k < x.size(); ++k)
                    {
                      re(k) = std::real(c[k] * x[k]);
                      im(k) = -std::imag(c[k] * x[k]);
                    }
                  weights[s / 4].emplace_back(re, im);
                }
              std::vector<Eigen::MatrixXd> first;
              auto                         task = dealii::Threads::new_task([&]() {
                first = modal::shape_sums(shapes, shapes_imag, weights[0]);
              });
              const auto second = modal::shape_sums(shapes, shapes_imag, weights[1]);
              task.join();
              for (unsigned int s = 0; s < 4; ++s)
                {
                  sums[s]     = first[s];
                  sums[4 + s] = second[s];
                }
            }
          else
            for (unsigned int s = 0; s < 8; ++s)
              sums[s] = contract(s >= 4, *z[s % 4]);
          const Eigen::MatrixXd &g0 = sums[3];
          psi.u                     = {{sums[0], sums[1], sums[2], g0}};
          psi.v                     = {{sums[4], sums[5], sums[6] + g0, sums[7]}};
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
  }   // namespace convolution
} // namespace greentread
