#include <greentread/base/exceptions.h>
#include <greentread/convolution/exponential_integrals.h>
#include <greentread/convolution/modal_recursive_convolution.h>

#include <cmath>

namespace greentread
{
  namespace convolution
  {
    ModalRecursiveConvolution::ModalRecursiveConvolution(const modal::ModalModel &model,
                                                         const double             dt_)
        : Convolution(dt_)
        , n_modes(model.n_modes())
    {
      if (model.max_real_part() > 0.)
        throw NumericalError("modal-recursive convolution: the modal model has an unstable pole "
                             "(Re(lambda) = " +
                             format_short(model.max_real_part()) +
                             " > 0); only stable poles can be convolved");

      std::vector<const modal::ModalTerm *> simple;
      for (const auto &term : model.terms())
        if (term.kind == modal::ModalTerm::Kind::double_pole)
          {
            const double l   = term.lambda.real();
            const auto   psi = exponential_moments(l * dt);
            DoublePole   d;
            d.lambda = l;
            d.r0     = term.residue.real();
            d.r1     = term.residue_t;
            d.alpha  = std::exp(l * dt);
            d.wa0    = dt * psi[1].real();
            d.wb0    = dt * (psi[0] - psi[1]).real();
            d.wa1    = dt * dt * psi[2].real();
            d.wb1    = dt * dt * (psi[1] - psi[2]).real();
            double_poles.push_back(d);
          }
        else
          simple.push_back(&term);

      const auto m = static_cast<Eigen::Index>(simple.size());
      for (auto *a : {&alpha_re, &alpha_im, &beta_a_re, &beta_a_im, &beta_b_re, &beta_b_im, &cu_re,
                      &cu_im, &cv_re, &cv_im, &s_re, &s_im, &h_re, &h_im})
        a->setZero(m);

      double g0 = 0.;
      for (Eigen::Index k = 0; k < m; ++k)
        {
          const modal::ModalTerm    &term  = *simple[k];
          const std::complex<double> z     = term.lambda * dt;
          const auto                 psi   = exponential_moments(z);
          const std::complex<double> alpha = std::exp(z);
          const std::complex<double> ba    = dt * psi[1];
          const std::complex<double> bb    = dt * (psi[0] - psi[1]);
          const double scale = term.kind == modal::ModalTerm::Kind::complex_pair ? 2. : 1.;
          const std::complex<double> cu = scale * term.residue;
          const std::complex<double> cv = scale * term.residue * term.lambda;
          alpha_re[k]                   = alpha.real();
          alpha_im[k]                   = alpha.imag();
          beta_a_re[k]                  = ba.real();
          beta_a_im[k]                  = ba.imag();
          beta_b_re[k]                  = bb.real();
          beta_b_im[k]                  = bb.imag();
          cu_re[k]                      = cu.real();
          cu_im[k]                      = cu.imag();
          cv_re[k]                      = cv.real();
          cv_im[k]                      = cv.imag();
          g0 += cu.real();
        }
      for (const auto &d : double_poles)
        g0 += d.r0;

      // The influence of the current step's loads (Psi of Eq. 20).
      const auto re = [](const Eigen::ArrayXd &xr, const Eigen::ArrayXd &xi,
                         const Eigen::ArrayXd &cr, const Eigen::ArrayXd &ci) {
        return (cr * xr - ci * xi).sum();
      };
      psi.u = {{re(alpha_re, alpha_im, cu_re, cu_im), re(beta_a_re, beta_a_im, cu_re, cu_im),
                re(beta_b_re, beta_b_im, cu_re, cu_im), g0}};
      psi.v = {{re(alpha_re, alpha_im, cv_re, cv_im), re(beta_a_re, beta_a_im, cv_re, cv_im),
                re(beta_b_re, beta_b_im, cv_re, cv_im) + g0, cv_re.sum()}};
      for (const auto &d : double_poles)
        {
          // u = r0 s0 + r1 s1;  v = (r0 l + r1) s0 + r1 l s1 + r0 q.
          const double cv0 = d.r0 * d.lambda + d.r1, cv1 = d.r1 * d.lambda;
          psi.u[0] += d.r0 * d.alpha + d.r1 * dt * d.alpha;
          psi.u[1] += d.r0 * d.wa0 + d.r1 * d.wa1;
          psi.u[2] += d.r0 * d.wb0 + d.r1 * d.wb1;
          psi.v[0] += cv0 * d.alpha + cv1 * dt * d.alpha;
          psi.v[1] += cv0 * d.wa0 + cv1 * d.wa1;
          psi.v[2] += cv0 * d.wb0 + cv1 * d.wb1;
          psi.v[3] += cv0;
        }
    }



    Response
    ModalRecursiveConvolution::history()
    {
      // One fused pass; the pragma lets the compiler vectorise the sums
      // (reassociating them), without -ffast-math elsewhere.
      const Eigen::Index m = s_re.size();
      double             u = 0., v = 0.;
      const double      *ar = alpha_re.data(), *ai = alpha_im.data(), *sr = s_re.data(),
                   *si = s_im.data(), *ur = cu_re.data(), *ui = cu_im.data(), *vr = cv_re.data(),
                   *vi = cv_im.data();
      double *hr = h_re.data(), *hi = h_im.data();
#pragma omp simd reduction(+ : u, v)
      for (Eigen::Index k = 0; k < m; ++k)
        {
          const double x = ar[k] * sr[k] - ai[k] * si[k];
          const double y = ar[k] * si[k] + ai[k] * sr[k];
          hr[k]          = x;
          hi[k]          = y;
          u += ur[k] * x - ui[k] * y;
          v += vr[k] * x - vi[k] * y;
        }
      Response r;
      r.u = u;
      r.v = v;
      for (auto &d : double_poles)
        {
          d.h0 = d.alpha * d.s0;
          d.h1 = d.alpha * (d.s1 + dt * d.s0);
          r.u += d.r0 * d.h0 + d.r1 * d.h1;
          r.v += (d.r0 * d.lambda + d.r1) * d.h0 + d.r1 * d.lambda * d.h1;
        }
      history_ready = true;
      return r;
    }



    void
    ModalRecursiveConvolution::advance(const StepLoad &load)
    {
      if (!history_ready)
        history();
      const Eigen::Index m = s_re.size();
      const double       a = load.start, b = load.end, p = load.impulse_start;
      const double      *hr = h_re.data(), *hi = h_im.data(), *bar = beta_a_re.data(),
                   *bai = beta_a_im.data(), *bbr = beta_b_re.data(), *bbi = beta_b_im.data(),
                   *ar = alpha_re.data(), *ai = alpha_im.data();
      double *sr = s_re.data(), *si = s_im.data();
#pragma omp simd
      for (Eigen::Index k = 0; k < m; ++k)
        {
          sr[k] = hr[k] + bar[k] * a + bbr[k] * b + ar[k] * p + load.impulse_end;
          si[k] = hi[k] + bai[k] * a + bbi[k] * b + ai[k] * p;
        }
      for (auto &d : double_poles)
        {
          d.s0 = d.h0 + d.wa0 * load.start + d.wb0 * load.end + d.alpha * load.impulse_start +
                 load.impulse_end;
          d.s1 = d.h1 + d.wa1 * load.start + d.wb1 * load.end + dt * d.alpha * load.impulse_start;
        }
      history_ready = false;
      ++n;
    }
  } // namespace convolution
} // namespace greentread
