#include <greentread/base/exceptions.h>
#include <greentread/convolution/mode_patch_convolution.h>
#include <greentread/convolution/patch_convolution.h>
#include <greentread/convolution/pole_weights.h>

#include <deal.II/base/thread_management.h>

#include <cmath>
#include <utility>

namespace greentread
{
  namespace convolution
  {
    namespace
    {
      using internal::PoleWeights;

      class ModalPatchConvolution : public PatchConvolution
      {
      public:
        ModalPatchConvolution(const modal::PatchModel &model,
                              const double             dt,
                              const unsigned int       n_threads)
            : PatchConvolution(model.n_points(), dt)
            , n_terms(model.n_terms())
            , threads(n_threads)
        {
          const PoleWeights w(model, dt);
          psi                   = w.influence();
          const Eigen::Index nk = Eigen::Index(n_terms) * n_p;
          Au.resize(n_p, 2 * nk);
          Av.resize(n_p, 2 * nk);
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              Au.middleCols(Eigen::Index(k) * n_p, n_p)      = w.cu[k].real();
              Au.middleCols(nk + Eigen::Index(k) * n_p, n_p) = -w.cu[k].imag();
              Av.middleCols(Eigen::Index(k) * n_p, n_p)      = w.cv[k].real();
              Av.middleCols(nk + Eigen::Index(k) * n_p, n_p) = -w.cv[k].imag();
            }
          lambda.resize(n_terms);
          alpha.resize(n_terms);
          beta_a.resize(n_terms);
          beta_b.resize(n_terms);
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              lambda[k] = model.lambda[k];
              alpha[k]  = w.alpha[k];
              beta_a[k] = w.beta_a[k];
              beta_b[k] = w.beta_b[k];
            }
          state = Eigen::VectorXd::Zero(2 * nk);
          hist  = Eigen::VectorXd::Zero(2 * nk);
        }

        void
        history(Eigen::VectorXd &u, Eigen::VectorXd &v) override
        {
          const Eigen::Index nk = Eigen::Index(n_terms) * n_p;
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              const double ar = alpha[k].real(), ai = alpha[k].imag();
              auto         sr = state.segment(Eigen::Index(k) * n_p, n_p);
              auto         si = state.segment(nk + Eigen::Index(k) * n_p, n_p);
              hist.segment(Eigen::Index(k) * n_p, n_p)      = ar * sr - ai * si;
              hist.segment(nk + Eigen::Index(k) * n_p, n_p) = ar * si + ai * sr;
            }
          if (threads > 1)
            {
              auto task   = dealii::Threads::new_task([&]() {
                u.noalias() = Au * hist;
              });
              v.noalias() = Av * hist;
              task.join();
            }
          else
            {
              u.noalias() = Au * hist;
              v.noalias() = Av * hist;
            }
          history_ready = true;
        }

        void
        advance(const PatchLoad &load) override
        {
          if (!history_ready)
            {
              Eigen::VectorXd u(n_p), v(n_p);
              history(u, v);
            }
          const Eigen::Index nk = Eigen::Index(n_terms) * n_p;
          const auto        &p = load.component[0], &a = load.component[1], &b = load.component[2],
                     &e = load.component[3];
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              state.segment(Eigen::Index(k) * n_p, n_p) =
                hist.segment(Eigen::Index(k) * n_p, n_p) + beta_a[k].real() * a +
                beta_b[k].real() * b + alpha[k].real() * p + e;
              state.segment(nk + Eigen::Index(k) * n_p, n_p) =
                hist.segment(nk + Eigen::Index(k) * n_p, n_p) + beta_a[k].imag() * a +
                beta_b[k].imag() * b + alpha[k].imag() * p;
            }
          history_ready = false;
        }

        void
        preload(const Eigen::VectorXd &q0) override
        {
          // s_k = int_{-inf}^0 e^{-lambda tau} q0 dtau = -q0 / lambda_k.
          const Eigen::Index nk = Eigen::Index(n_terms) * n_p;
          for (unsigned int k = 0; k < n_terms; ++k)
            {
              const std::complex<double> f                   = -1. / lambda[k];
              state.segment(Eigen::Index(k) * n_p, n_p)      = f.real() * q0;
              state.segment(nk + Eigen::Index(k) * n_p, n_p) = f.imag() * q0;
            }
          history_ready = false;
        }

        std::string
        name() const override
        {
          return "modal-recursive";
        }

      private:
        unsigned int                      n_terms;
        unsigned int                      threads;
        Eigen::MatrixXd                   Au, Av;
        std::vector<std::complex<double>> lambda, alpha, beta_a, beta_b;
        Eigen::VectorXd                   state, hist;
        bool                              history_ready = false;
      };



      class DirectPatchConvolution : public PatchConvolution
      {
      public:
        DirectPatchConvolution(const modal::PatchModel &model,
                               const double             dt,
                               const unsigned int       n_kernel_)
            : PatchConvolution(model.n_points(), dt)
            , n_kernel(std::max(2u, n_kernel_))
            , preload_model(make_modal_patch_convolution(model, dt, 1))
        {
          const PoleWeights w(model, dt);
          psi = w.influence();
          // Lag m >= 1: the loads of step n - m seen at t_{n+1} are those of
          // the current step's influence, decayed over m steps:
          // W_m = Re sum_k c_k e^{lambda_k m dt} w_k, w = (alpha, beta_a, beta_b, 1).
          // Stored per lag as one n_p x 4 n_p block [W_g0 W_g1 W_g2 W_g3].
          const unsigned int n_terms = model.n_terms();
          const Eigen::Index n_lags  = n_kernel - 1;
          Wu.assign(n_lags, Eigen::MatrixXd(n_p, 4 * n_p));
          Wv.assign(n_lags, Eigen::MatrixXd(n_p, 4 * n_p));
          if (w.rank_one())
            {
              std::vector<std::complex<double>> z(n_terms);
              for (Eigen::Index m = 0; m < n_lags; ++m)
                for (unsigned int g = 0; g < 4; ++g)
                  {
                    for (unsigned int k = 0; k < n_terms; ++k)
                      {
                        const std::complex<double> gen[4] = {w.alpha[k], w.beta_a[k], w.beta_b[k],
                                                             1.};
                        z[k] = std::exp(model.lambda[k] * double(m + 1) * dt) * gen[g];
                      }
                    Wu[m].middleCols(g * n_p, n_p) = w.contract(false, z);
                    Wv[m].middleCols(g * n_p, n_p) = w.contract(true, z);
                  }
              past.assign(n_lags, Eigen::VectorXd::Zero(4 * n_p));
              return;
            }
          // Full form: all lags at once as one product: rows (lag, generator),
          // columns (i, j), inner dimension the real and imaginary part of
          // each pole.
          Eigen::MatrixXd Z(n_lags * 4, 2 * n_terms);
          for (Eigen::Index m = 0; m < n_lags; ++m)
            for (unsigned int k = 0; k < n_terms; ++k)
              {
                const std::complex<double> decay  = std::exp(model.lambda[k] * double(m + 1) * dt);
                const std::complex<double> gen[4] = {w.alpha[k], w.beta_a[k], w.beta_b[k], 1.};
                for (unsigned int g = 0; g < 4; ++g)
                  {
                    const std::complex<double> z = decay * gen[g];
                    Z(4 * m + g, k)              = z.real();
                    Z(4 * m + g, n_terms + k)    = -z.imag();
                  }
              }
          for (const auto *c : {&w.cu, &w.cv})
            {
              Eigen::MatrixXd C(2 * n_terms, Eigen::Index(n_p) * n_p);
              for (unsigned int k = 0; k < n_terms; ++k)
                {
                  // Column index i + n_p * j: a column-major n_p x n_p block.
                  C.row(k) = Eigen::Map<const Eigen::MatrixXd>(
                    Eigen::MatrixXd((*c)[k].real()).data(), 1, Eigen::Index(n_p) * n_p);
                  C.row(n_terms + k) = Eigen::Map<const Eigen::MatrixXd>(
                    Eigen::MatrixXd((*c)[k].imag()).data(), 1, Eigen::Index(n_p) * n_p);
                }
              const Eigen::MatrixXd W      = Z * C;
              auto                 &target = (c == &w.cu) ? Wu : Wv;
              for (Eigen::Index m = 0; m < n_lags; ++m)
                for (unsigned int g = 0; g < 4; ++g)
                  target[m].middleCols(g * n_p, n_p) =
                    Eigen::Map<const Eigen::MatrixXd>(W.row(4 * m + g).eval().data(), n_p, n_p);
            }
          past.assign(n_lags, Eigen::VectorXd::Zero(4 * n_p));
        }

        void
        history(Eigen::VectorXd &u, Eigen::VectorXd &v) override
        {
          preload_model->history(u, v);
          const std::size_t n_lags = std::min<std::size_t>(n_recorded, past.size());
          for (std::size_t m = 0; m < n_lags; ++m)
            {
              // past[(head - 1 - m) mod size] is the step m + 1 steps back.
              const std::size_t slot = (head + past.size() - 1 - m) % past.size();
              u.noalias() += Wu[m] * past[slot];
              v.noalias() += Wv[m] * past[slot];
            }
        }

        void
        advance(const PatchLoad &load) override
        {
          Eigen::VectorXd &slot = past[head];
          for (unsigned int g = 0; g < 4; ++g)
            slot.segment(g * n_p, n_p) = load.component[g];
          head = (head + 1) % past.size();
          ++n_recorded;
          // The preload decays freely.
          preload_model->advance(PatchLoad(n_p));
        }

        void
        preload(const Eigen::VectorXd &q0) override
        {
          preload_model->preload(q0);
        }

        std::string
        name() const override
        {
          return "direct";
        }

      private:
        unsigned int                      n_kernel;
        std::unique_ptr<PatchConvolution> preload_model;
        std::vector<Eigen::MatrixXd>      Wu, Wv;
        std::vector<Eigen::VectorXd>      past;
        std::size_t                       head = 0, n_recorded = 0;
      };
    } // namespace



    std::unique_ptr<PatchConvolution>
    make_modal_patch_convolution(const modal::PatchModel &model,
                                 const double             dt,
                                 const unsigned int       n_threads,
                                 const ShapePrecision     precision)
    {
      if (model.is_rank_one())
        return make_rank_one_patch_convolution(model, dt, n_threads, precision);
      return std::make_unique<ModalPatchConvolution>(model, dt, n_threads);
    }



    std::unique_ptr<PatchConvolution>
    make_direct_patch_convolution(const modal::PatchModel &model,
                                  const double             dt,
                                  const unsigned int       n_kernel)
    {
      return std::make_unique<DirectPatchConvolution>(model, dt, n_kernel);
    }



    void
    add_influence(const PatchInfluence  &psi,
                  const unsigned int     g,
                  const Eigen::VectorXd &x,
                  Eigen::VectorXd       &y)
    {
      if (psi.add_u)
        psi.add_u(g, x, y);
      else
        {
          // y += M x from the columns where x is not zero (the loads of the
          // points in contact: a few percent of a fine grid's).
          const Eigen::MatrixXd &M = psi.u[g];
          for (Eigen::Index j = 0; j < x.size(); ++j)
            if (x[j] != 0.)
              y += x[j] * M.col(j);
        }
    }
  } // namespace convolution
} // namespace greentread
