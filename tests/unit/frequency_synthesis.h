#pragma once

// An independent check of a rolling run: the contact forces it recorded,
// convolved with the patch model's Green's functions in the frequency domain
// (a numerical inverse Laplace transform), give the displacement of every
// point at every step. It shares nothing with the time stepping of
// greentread/contact/patch_contact.h (no recursion, no influence matrices,
// no LCP): only the model's poles, residues and G_r. The kinematic contact
// must then leave every point on or above the road, and every point that
// carries a force on the road.

#include <greentread/modal/patch_model.h>

#include <Eigen/Core>
#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

namespace test
{
  /**
   * @brief The displacements \f$u(t_n)\f$, n = 1..N, of a run that starts
   * from the force \f$q_0\f$ held since \f$t = -\infty\f$ and whose force is
   * linear over each step between the values @p q[n] at \f$t_n = n\Delta t\f$
   * (@p q[0] = \f$q_0\f$). Only for a model with an instantaneous G_r (the
   * force is then continuous).
   *
   * \f$u = G(0)q_0 + G_r\,\Delta q(t) + (g_m * \Delta q)(t)\f$ with
   * \f$\Delta q = q - q_0\f$. The last term is summed as a Fourier series
   * over a period \f$T = 8 t_N\f$ of \f$e^{-\sigma t}(g_m*\Delta q)\f$,
   * whose coefficients are \f$G_m(s)\,H(s)\,\sum_k \Delta q_k e^{-s t_k}/T\f$
   * at \f$s = \sigma + 2\pi j m/T\f$, where
   * \f$H(s) = (e^{s\Delta t} - 2 + e^{-s\Delta t})/(s^2\Delta t)\f$ is the
   * transform of one step's hat function. |m| runs to @p replicas times
   * the Nyquist index, folded onto the N-point grid of one inverse FFT;
   * the terms fall as \f$|s|^{-4}\f$ (the imaginary residues make
   * \f$g_m(0^+) = 0\f$). \f$\sigma\f$ damps the wrap-around of the period to
   * \f$e^{-\sigma(T - t_N)} = 10^{-9}\f$.
   */
  inline std::vector<Eigen::VectorXd>
  synthesise_displacements(const greentread::modal::PatchModel &model,
                           const double                         dt,
                           const std::vector<Eigen::VectorXd>  &q,
                           const unsigned int                   replicas = 8)
  {
    using C = std::complex<double>;
    if (model.instantaneous.size() == 0)
      throw std::invalid_argument("synthesise_displacements: the model has no G_r");
    const unsigned int n_p    = model.n_points();
    const unsigned int n_run  = q.size() - 1;
    const unsigned int N      = 8 * n_run;
    const double       T      = N * dt;
    const double       sigma  = std::log(1e9) / (T - n_run * dt);
    const unsigned int n_term = model.n_terms();

    // D_r = sum_k Delta q_k e^{-sigma t_k} e^{-2 pi j r k / N}, per point.
    Eigen::FFT<double>             fft;
    std::vector<Eigen::VectorXcd>  D(N, Eigen::VectorXcd::Zero(n_p));
    std::vector<double>            a(N, 0.);
    std::vector<C>                 spectrum;
    for (unsigned int p = 0; p < n_p; ++p)
      {
        for (unsigned int k = 1; k <= n_run; ++k)
          a[k] = (q[k][p] - q[0][p]) * std::exp(-sigma * k * dt);
        fft.fwd(spectrum, a);
        for (unsigned int r = 0; r < N; ++r)
          D[r][p] = spectrum[r];
      }
    // X_r = sum over m = r (mod N) of H(s_m) G_m(s_m) D_r: the scalar sums
    // alpha_rk = sum_m H / (s_m - lambda_k) (beta_rk with conj(lambda_k))
    // first, then one product with each residue matrix per class r.
    const long                   M = static_cast<long>(replicas) * N / 2;
    std::vector<Eigen::VectorXcd> alpha(N, Eigen::VectorXcd::Zero(n_term)),
      beta(N, Eigen::VectorXcd::Zero(n_term));
    for (long m = -M; m <= M; ++m)
      {
        const C s(sigma, 2. * M_PI * m / T);
        const C z = s * dt;
        const C H = std::abs(z) < 1e-3 ? dt * (1. + z * z / 12. + z * z * z * z / 360.) :
                                         (std::exp(z) - 2. + std::exp(-z)) / (z * z) * dt;
        const unsigned int r = static_cast<unsigned int>(((m % long(N)) + long(N)) % long(N));
        for (unsigned int k = 0; k < n_term; ++k)
          if (model.real[k])
            alpha[r][k] += H / (s - model.lambda[k].real());
          else
            {
              alpha[r][k] += H / (s - model.lambda[k]);
              beta[r][k] += H / (s - std::conj(model.lambda[k]));
            }
      }
    std::vector<Eigen::VectorXcd> X(N, Eigen::VectorXcd::Zero(n_p));
    for (unsigned int k = 0; k < n_term; ++k)
      {
        const Eigen::MatrixXcd R  = model.real[k] ? Eigen::MatrixXcd(model.residues[k].real().cast<C>()) :
                                                    model.residues[k];
        const Eigen::MatrixXcd Rc = R.conjugate();
        for (unsigned int r = 0; r < N; ++r)
          {
            X[r] += alpha[r][k] * (R * D[r]);
            if (!model.real[k])
              X[r] += beta[r][k] * (Rc * D[r]);
          }
      }
    // u = G(0) q0 + G_r Delta q, plus the modal part
    // w(t_n) = (1 / T) sum_r X_r e^{2 pi j r n / N} = inverse FFT / dt.
    const Eigen::VectorXd        static_u = model.static_compliance() * q[0];
    std::vector<Eigen::VectorXd> u(n_run + 1);
    for (unsigned int n = 0; n <= n_run; ++n)
      u[n] = static_u + model.instantaneous * (q[n] - q[0]);
    std::vector<C> line(N), w;
    for (unsigned int p = 0; p < n_p; ++p)
      {
        for (unsigned int r = 0; r < N; ++r)
          line[r] = X[r][p];
        fft.inv(w, line);
        for (unsigned int n = 0; n <= n_run; ++n)
          u[n][p] += std::exp(sigma * n * dt) * w[n].real() / dt;
      }
    return u;
  }
} // namespace test
