#include <greentread/base/exceptions.h>
#include <greentread/contact/patch_convolution.h>
#include <greentread/contact/shape_kernels.h>
#include <greentread/convolution/exponential_integrals.h>

#include <deal.II/base/thread_management.h>

#include <cmath>
#include <utility>

namespace greentread
{
  namespace contact
  {
    namespace
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



      /**
       * The recursion for a rank-one model: one complex state per term,
       * driven by the modal force phi_k^T q, and u = sum_k Re(c_k s_k phi_k).
       * A complex shape a + j b is two rows of the shape matrix, a and b:
       * its modal force is a^T q + j b^T q, and it adds
       * Re(c s) a - Im(c s) b to u.
       * O(N_p N_m) per step, not O(N_p^2 N_m). The step is memory bound (the
       * N_m x N_p shapes do not fit in cache), so advance() makes one pass
       * over them in blocks of rows that stay in cache: the modal forces of
       * the step's loads, the new states, and at once the next step's history
       * u, v. The terms are split between two threads when asked.
       *
       * Only the load vectors that are not zero are projected, and a step's
       * start load that equals the previous step's end load (a force
       * continuous in time, as with a static residual G_r) reuses that step's
       * modal forces: one dot product per row instead of four.
       * @p Shape is the shapes' precision (ShapePrecision): double or float.
       */
      template <typename Shape>
      class ModePatchConvolution : public PatchConvolution
      {
      public:
        ModePatchConvolution(const modal::PatchModel &model, const double dt,
                             const unsigned int n_threads)
          : PatchConvolution(model.n_points(), dt)
          , threads(n_threads)
          , w(model, dt)
          , stride(model.shapes_imag.size() ? 2 : 1)
          , lambda(model.lambda)
        {
          psi = w.influence();
          shapes.resize(stride * model.shapes.rows(), n_p);
          for (Eigen::Index k = 0; k < model.shapes.rows(); ++k)
            {
              shapes.row(stride * k) = model.shapes.row(k).template cast<Shape>();
              if (stride == 2)
                shapes.row(2 * k + 1) = model.shapes_imag.row(k).template cast<Shape>();
            }
          hr = hi = end_r = end_i = Eigen::VectorXd::Zero(model.shapes.rows());
          uv                      = Eigen::MatrixXd::Zero(n_p, 2);
          loads_t.resize(4, n_p);
        }

        void
        history(Eigen::VectorXd &u, Eigen::VectorXd &v) override
        {
          velocity = true;
          if (!history_ready)
            sum_states(true, true);
          else if (!velocity_ready)
            sum_states(false, true);
          u = uv.col(0);
          v = uv.col(1);
        }

        /// From here on the steps' sums leave the velocity out, until
        /// history(u, v) asks for it again (it then sums it from the states).
        void
        history_u(Eigen::VectorXd &u) override
        {
          velocity = false;
          if (!history_ready)
            sum_states(true, true);
          u = uv.col(0);
        }

        void
        advance(const PatchLoad &load) override
        {
          if (!history_ready)
            {
              Eigen::VectorXd u(n_p), v(n_p);
              history(u, v);
            }
          // The load vectors to project; the start load may reuse the
          // previous end's modal forces (end_r, end_i).
          reuse   = have_end && load.component[1].size() == end_load.size() &&
                  load.component[1] == end_load;
          n_loads = 0;
          for (unsigned int g = 0; g < 4; ++g)
            {
              slot[g] = -1;
              if ((g == 1 && reuse) || (load.component[g].array() == 0.).all())
                continue;
              slot[g]                = n_loads;
              loads_t.row(n_loads++) = load.component[g].transpose();
            }
          end_load = load.component[2];
          have_end = true;
          const Eigen::Index m = hr.size(), half = m / 2;
          if (threads > 1 && half > 64)
            {
              Eigen::MatrixXd first(n_p, 2);
              auto task = dealii::Threads::new_task([&]() { sweep(0, half, first); });
              sweep(half, m, uv);
              task.join();
              uv += first;
            }
          else
            sweep(0, m, uv);
          history_ready  = true;
          velocity_ready = velocity;
        }

        void
        preload(const Eigen::VectorXd &q0) override
        {
          // s_k = int_{-inf}^0 e^{-lambda tau} phi_k^T q0 dtau = -phi_k^T q0 / lambda_k,
          // and the history's states h = e^{lambda dt} s. The first step's
          // start load is q0: its modal forces are kept.
          const Eigen::Index m = hr.size();
          Eigen::VectorXd    f(stride * m);
          modal_forces(shapes.data(), stride * m, n_p, q0.data(), 1, f.data());
          for (Eigen::Index k = 0; k < m; ++k)
            {
              const std::complex<double> fk(f(stride * k), stride == 2 ? f(2 * k + 1) : 0.);
              const std::complex<double> h = -w.alpha[k] * fk / lambda[k];
              hr(k)                        = h.real();
              hi(k)                        = h.imag();
              end_r(k)                     = fk.real();
              end_i(k)                     = fk.imag();
            }
          end_load      = q0;
          have_end      = true;
          history_ready = false;
        }

        std::string
        name() const override
        {
          return "modal-recursive";
        }

      private:
        /// The history's u (@p want_u) and v (@p want_v), columns of uv,
        /// from the states h = e^{lambda dt} s, as after a preload.
        void
        sum_states(const bool want_u, const bool want_v)
        {
          const Eigen::Index m = hr.size();
          Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> weights(stride * m, 2);
          for (Eigen::Index k = 0; k < m; ++k)
            {
              const std::complex<double> h(hr(k), hi(k)), v = w.cv1[k] * h,
                                                          u = want_u ? w.cu1[k] * h : v;
              weights.row(stride * k) << u.real(), v.real();
              if (stride == 2)
                weights.row(2 * k + 1) << -u.imag(), -v.imag();
            }
          Eigen::Matrix<double, 2, Eigen::Dynamic, Eigen::RowMajor> sum =
            Eigen::Matrix<double, 2, Eigen::Dynamic, Eigen::RowMajor>::Zero(2, n_p);
          const unsigned int n_out = want_u && want_v ? 2 : 1;
          add_weighted_shapes(shapes.data(), stride * m, n_p, weights.data(), n_out, sum.data());
          if (want_u)
            uv.col(0) = sum.row(0).transpose();
          if (want_v)
            uv.col(1) = sum.row(n_out - 1).transpose();
          history_ready  = true;
          velocity_ready = want_v || velocity_ready;
        }

        /// Terms [begin, end): the new states from the step's loads, and
        /// their part of the next history in @p out.
        void
        sweep(const Eigen::Index begin, const Eigen::Index end, Eigen::MatrixXd &out)
        {
          const Eigen::Index  block = 128 / stride;
          std::vector<double> forces(stride * block * 4, 0.);
          // Row-major, as the kernel reads them: weights [row][c].
          Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> weights(stride * block, 2);
          // [c][p]: u then v.
          Eigen::Matrix<double, 2, Eigen::Dynamic, Eigen::RowMajor> sum =
            Eigen::Matrix<double, 2, Eigen::Dynamic, Eigen::RowMajor>::Zero(2, n_p);
          for (Eigen::Index b = begin; b < end; b += block)
            {
              const Eigen::Index rows = std::min(block, end - b);
              const Shape       *phi  = shapes.data() + stride * b * n_p;
              if (n_loads > 0)
                modal_forces(phi, stride * rows, n_p, loads_t.data(), n_loads, forces.data());
              for (Eigen::Index r = 0; r < rows; ++r)
                {
                  const Eigen::Index k = b + r;
                  const auto         f = [&](const unsigned int g) {
                    if (slot[g] < 0)
                      return g == 1 && reuse ? std::complex<double>(end_r(k), end_i(k)) :
                                               std::complex<double>();
                    const double *row = forces.data() + n_loads * stride * r + slot[g];
                    return std::complex<double>(row[0], stride == 2 ? row[n_loads] : 0.);
                  };
                  const std::complex<double> f_end = f(2);
                  const std::complex<double> s = std::complex<double>(hr(k), hi(k)) +
                                                 w.alpha[k] * f(0) + w.beta_a[k] * f(1) +
                                                 w.beta_b[k] * f_end + f(3);
                  const std::complex<double> h = w.alpha[k] * s, u = w.cu1[k] * h,
                                             v = w.cv1[k] * h;
                  hr(k)                        = h.real();
                  hi(k)                        = h.imag();
                  end_r(k)                     = f_end.real();
                  end_i(k)                     = f_end.imag();
                  weights(stride * r, 0)       = u.real();
                  weights(stride * r, 1)       = v.real();
                  if (stride == 2)
                    {
                      weights(2 * r + 1, 0) = -u.imag();
                      weights(2 * r + 1, 1) = -v.imag();
                    }
                }
              add_weighted_shapes(phi, stride * rows, n_p, weights.data(), velocity ? 2 : 1,
                                  sum.data());
            }
          out = sum.transpose();
        }

        unsigned int threads;
        PoleWeights  w;
        // 1 for real shapes, 2 for complex ones (rows a_k, b_k).
        Eigen::Index stride;
        // Row-major: a block of terms is one contiguous stretch of memory.
        Eigen::Matrix<Shape, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> shapes;
        std::vector<std::complex<double>>                                    lambda;
        // The states of the next history, h = e^{lambda dt} s, and its u, v.
        Eigen::VectorXd hr, hi;
        Eigen::MatrixXd uv;
        // The step's load vectors to project, one row each, as
        // modal_forces() reads them, and where each component is among them
        // (-1: zero, or reused).
        Eigen::Matrix<double, 4, Eigen::Dynamic, Eigen::RowMajor> loads_t;
        unsigned int                                              n_loads = 0;
        std::array<int, 4>                                        slot{{-1, -1, -1, -1}};
        // The last end load and its modal forces.
        Eigen::VectorXd end_load, end_r, end_i;
        bool            have_end = false, reuse = false;
        bool            history_ready = false;
        // Whether the steps sum the velocity, and whether uv's holds it.
        bool velocity = true, velocity_ready = false;
      };



      class ModalPatchConvolution : public PatchConvolution
      {
      public:
        ModalPatchConvolution(const modal::PatchModel &model, const double dt,
                              const unsigned int n_threads)
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
              auto task = dealii::Threads::new_task([&]() { u.noalias() = Au * hist; });
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
          const auto &p = load.component[0], &a = load.component[1], &b = load.component[2],
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
              const std::complex<double> f = -1. / lambda[k];
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
        DirectPatchConvolution(const modal::PatchModel &model, const double dt,
                               const unsigned int n_kernel_)
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
                        const std::complex<double> gen[4] = {w.alpha[k], w.beta_a[k],
                                                             w.beta_b[k], 1.};
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
                const std::complex<double> decay = std::exp(model.lambda[k] * double(m + 1) * dt);
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
                  C.row(k)           = Eigen::Map<const Eigen::MatrixXd>(
                                         Eigen::MatrixXd((*c)[k].real()).data(), 1,
                                         Eigen::Index(n_p) * n_p);
                  C.row(n_terms + k) = Eigen::Map<const Eigen::MatrixXd>(
                                         Eigen::MatrixXd((*c)[k].imag()).data(), 1,
                                         Eigen::Index(n_p) * n_p);
                }
              const Eigen::MatrixXd W = Z * C;
              auto &target = (c == &w.cu) ? Wu : Wv;
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
        unsigned int                 n_kernel;
        std::unique_ptr<PatchConvolution> preload_model;
        std::vector<Eigen::MatrixXd> Wu, Wv;
        std::vector<Eigen::VectorXd> past;
        std::size_t                  head = 0, n_recorded = 0;
      };
    } // namespace



    std::unique_ptr<PatchConvolution>
    make_modal_patch_convolution(const modal::PatchModel &model, const double dt,
                                 const unsigned int n_threads, const ShapePrecision precision)
    {
      if (model.is_rank_one() && precision == ShapePrecision::single_precision)
        return std::make_unique<ModePatchConvolution<float>>(model, dt, n_threads);
      if (model.is_rank_one())
        return std::make_unique<ModePatchConvolution<double>>(model, dt, n_threads);
      return std::make_unique<ModalPatchConvolution>(model, dt, n_threads);
    }



    std::unique_ptr<PatchConvolution>
    make_direct_patch_convolution(const modal::PatchModel &model, const double dt,
                                  const unsigned int n_kernel)
    {
      return std::make_unique<DirectPatchConvolution>(model, dt, n_kernel);
    }
  } // namespace contact
} // namespace greentread
