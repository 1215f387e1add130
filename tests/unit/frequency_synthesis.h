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
   * (@p q[0] = \f$q_0\f$). For a model whose force is continuous: an
   * instantaneous G_r, or its relaxation as real poles (then G_r = 0 below
   * and the poles are in the modal part). Residues in either form of PatchModel: the
   * full matrices, or rank one per mode (the ring's modes).
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
   * \f$g_m(0^+) = 0\f$; the real poles of a relaxed G_r fall as
   * \f$|s|^{-3}\f$). \f$\sigma\f$ damps the wrap-around of the period to
   * \f$e^{-\sigma(T - t_N)} = 10^{-9}\f$.
   */
  inline std::vector<Eigen::VectorXd>
  synthesise_displacements(const greentread::modal::PatchModel &model,
                           const double                         dt,
                           const std::vector<Eigen::VectorXd>  &q,
                           const unsigned int                   replicas = 8)
  {
    using C                   = std::complex<double>;
    const unsigned int n_p    = model.n_points();
    const unsigned int n_run  = q.size() - 1;
    const unsigned int N      = 8 * n_run;
    const double       T      = N * dt;
    const double       sigma  = std::log(1e9) / (T - n_run * dt);
    const unsigned int n_term = model.n_terms();

    // D_r = sum_k Delta q_k e^{-sigma t_k} e^{-2 pi j r k / N}, per point.
    Eigen::FFT<double>  fft;
    Eigen::MatrixXcd    D = Eigen::MatrixXcd::Zero(n_p, N);
    std::vector<double> a(N, 0.);
    std::vector<C>      spectrum;
    for (unsigned int p = 0; p < n_p; ++p)
      {
        for (unsigned int k = 1; k <= n_run; ++k)
          a[k] = (q[k][p] - q[0][p]) * std::exp(-sigma * k * dt);
        fft.fwd(spectrum, a);
        for (unsigned int r = 0; r < N; ++r)
          D(p, r) = spectrum[r];
      }
    // X_r = sum over m = r (mod N) of H(s_m) G_m(s_m) D_r: the scalar sums
    // alpha_rk = sum_m H / (s_m - lambda_k) (beta_rk with conj(lambda_k))
    // first, then the residues' products per class r.
    const long                M = static_cast<long>(replicas) * N / 2;
    std::vector<C>            s_m, H_m;
    std::vector<unsigned int> r_m;
    for (long m = -M; m <= M; ++m)
      {
        const C s(sigma, 2. * M_PI * m / T);
        const C z = s * dt;
        s_m.push_back(s);
        H_m.push_back(std::abs(z) < 1e-3 ? dt * (1. + z * z / 12. + z * z * z * z / 360.) :
                                           (std::exp(z) - 2. + std::exp(-z)) / (z * z) * dt);
        r_m.push_back(static_cast<unsigned int>(((m % long(N)) + long(N)) % long(N)));
      }
    // The class sums of one pole, into column @p column of @p sums (N rows).
    const auto class_sums = [&](const C lambda, Eigen::MatrixXcd &sums, const Eigen::Index column) {
      for (std::size_t i = 0; i < s_m.size(); ++i)
        sums(r_m[i], column) += H_m[i] / (s_m[i] - lambda);
    };
    Eigen::MatrixXcd X = Eigen::MatrixXcd::Zero(n_p, N);
    if (model.is_rank_one())
      {
        // R_k = c_k psi_k psi_k^T (the ring's modes): R D = c psi (psi^T D),
        // by blocks of terms, two matrix products per block instead of
        // N_p^2 operations per term and class.
        const unsigned int block = 256;
        for (unsigned int k0 = 0; k0 < n_term; k0 += block)
          {
            const unsigned int b = std::min(block, n_term - k0);
            Eigen::MatrixXcd   psi(n_p, b), alpha = Eigen::MatrixXcd::Zero(N, b), beta = alpha;
            for (unsigned int t = 0; t < b; ++t)
              {
                const unsigned int k = k0 + t;
                psi.col(t)           = model.shapes.row(k).transpose().cast<C>();
                if (model.shapes_imag.size() != 0)
                  psi.col(t) += C(0., 1.) * model.shapes_imag.row(k).transpose().cast<C>();
                if (model.real[k] && model.shapes_imag.size() != 0 &&
                    model.shapes_imag.row(k).cwiseAbs().maxCoeff() > 0.)
                  throw std::invalid_argument(
                    "synthesise_displacements: a real pole with a complex shape");
                class_sums(model.real[k] ? C(model.lambda[k].real()) : model.lambda[k], alpha, t);
                if (!model.real[k])
                  class_sums(std::conj(model.lambda[k]), beta, t);
                const C c = model.real[k] ? C(model.factor[k].real()) : model.factor[k];
                alpha.col(t) *= c;
                beta.col(t) *= std::conj(c);
              }
            // (psi^T D) weighted by alpha, and (psi^H D) by beta, per class.
            const Eigen::MatrixXcd P = psi.transpose() * D;
            const Eigen::MatrixXcd Q = psi.adjoint() * D;
            X += psi * P.cwiseProduct(alpha.transpose()) +
                 psi.conjugate() * Q.cwiseProduct(beta.transpose());
          }
      }
    else
      {
        Eigen::MatrixXcd alpha = Eigen::MatrixXcd::Zero(N, n_term), beta = alpha;
        for (unsigned int k = 0; k < n_term; ++k)
          {
            class_sums(model.real[k] ? C(model.lambda[k].real()) : model.lambda[k], alpha, k);
            if (!model.real[k])
              class_sums(std::conj(model.lambda[k]), beta, k);
          }
        for (unsigned int k = 0; k < n_term; ++k)
          {
            const Eigen::MatrixXcd R  = model.real[k] ?
                                          Eigen::MatrixXcd(model.residues[k].real().cast<C>()) :
                                          model.residues[k];
            const Eigen::MatrixXcd RD = R * D;
            for (unsigned int r = 0; r < N; ++r)
              {
                X.col(r) += alpha(r, k) * RD.col(r);
                if (!model.real[k])
                  X.col(r) += beta(r, k) * R.conjugate() * D.col(r);
              }
          }
      }
    // u = G(0) q0 + G_r Delta q, plus the modal part
    // w(t_n) = (1 / T) sum_r X_r e^{2 pi j r n / N} = inverse FFT / dt.
    const Eigen::VectorXd        static_u = model.static_compliance() * q[0];
    std::vector<Eigen::VectorXd> u(n_run + 1);
    for (unsigned int n = 0; n <= n_run; ++n)
      u[n] = model.instantaneous.size() != 0 ?
               Eigen::VectorXd(static_u + model.instantaneous * (q[n] - q[0])) :
               static_u;
    std::vector<C> line(N), w;
    for (unsigned int p = 0; p < n_p; ++p)
      {
        for (unsigned int r = 0; r < N; ++r)
          line[r] = X(p, r);
        fft.inv(w, line);
        for (unsigned int n = 0; n <= n_run; ++n)
          u[n][p] += std::exp(sigma * n * dt) * w[n].real() / dt;
      }
    return u;
  }
} // namespace test
