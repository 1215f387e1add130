#include <greentread/convolution/mode_patch_convolution.h>
#include <greentread/convolution/pole_weights.h>
#include <greentread/convolution/shape_kernels.h>
#include <greentread/convolution/shape_sums.h>

#include <greentread/modal/patch_model.h>

#include <deal.II/base/thread_management.h>

#include <array>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace greentread
{
  namespace convolution
  {
    namespace
    {
      using internal::PoleWeights;

      /// A sum over the shapes [0, @p m) in two halves, @p first over [0, m /
      /// 2) on a task when @p threads > 1 and @p second over [m / 2, m) here:
      /// split the same way whatever the thread count, so that the sum's
      /// bytes do not depend on it.
      template <typename First, typename Second>
      void
      in_two_halves(const unsigned int threads,
                    const Eigen::Index m,
                    First            &&first,
                    Second           &&second)
      {
        const Eigen::Index half = m / 2;
        if (threads > 1)
          {
            auto task = dealii::Threads::new_task([&]() {
              first(Eigen::Index(0), half);
            });
            second(half, m);
            task.join();
          }
        else
          {
            first(Eigen::Index(0), half);
            second(half, m);
          }
      }

      /// The recursion for a rank-one model, with its time blocks: the
      /// method is in mode_patch_convolution.h.
      template <typename Shape>
      class ModePatchConvolution : public PatchConvolution
      {
      public:
        ModePatchConvolution(const modal::PatchModel &model,
                             const double             dt,
                             const unsigned int       n_threads,
                             const unsigned int       block_steps)
            : PatchConvolution(model.n_points(), dt)
            , threads(n_threads)
            , J(block_steps)
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
          end_load = Eigen::VectorXd::Zero(n_p);
          for (std::size_t k = 0; k < lambda.size(); ++k)
            gamma.push_back(w.alpha[k] * w.beta_b[k] + w.beta_a[k]);
          pole_r.resize(lambda.size(), 4);
          pole_i.resize(lambda.size(), 4);
          for (std::size_t k = 0; k < lambda.size(); ++k)
            {
              const std::complex<double> c[4] = {w.alpha[k], gamma[k], w.beta_a[k], w.cu1[k]};
              for (unsigned int g = 0; g < 4; ++g)
                {
                  pole_r(k, g) = c[g].real();
                  pole_i(k, g) = c[g].imag();
                }
            }
        }

        void
        history(Eigen::VectorXd &u, Eigen::VectorXd &v) override
        {
          velocity = true;
          end_block();
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
          if (J > 1)
            {
              if (!in_block)
                start_block();
              u = block_hist.col(n_block);
              return;
            }
          if (!history_ready)
            sum_states(true, true);
          u = uv.col(0);
        }

        void
        advance(const PatchLoad &load) override
        {
          if (in_block)
            {
              if (!velocity && continuous(load))
                return record(load.component[2]);
              end_block();
            }
          else if (!history_ready)
            {
              Eigen::VectorXd u(n_p), v(n_p);
              history(u, v);
            }
          // The load vectors to project; the start load may reuse the
          // previous end's modal forces (end_r, end_i).
          reuse   = load.component[1].size() == end_load.size() && load.component[1] == end_load;
          n_loads = 0;
          for (unsigned int g = 0; g < 4; ++g)
            {
              slot[g] = -1;
              if ((g == 1 && reuse) || (load.component[g].array() == 0.).all())
                continue;
              slot[g]                = n_loads;
              loads_t.row(n_loads++) = load.component[g].transpose().template cast<Shape>();
            }
          end_load = load.component[2];
          // Two halves summed, on two threads or one (in_two_halves).
          const Eigen::Index m = hr.size();
          if (m / 2 > 64)
            {
              Eigen::MatrixXd first(n_p, 2);
              in_two_halves(
                threads, m,
                [&](const Eigen::Index a, const Eigen::Index b) {
                  sweep(a, b, first);
                },
                [&](const Eigen::Index a, const Eigen::Index b) {
                  sweep(a, b, uv);
                });
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
          in_block                                        = false;
          const Eigen::Index                            m = hr.size();
          Eigen::VectorXd                               f(stride * m);
          const Eigen::Matrix<Shape, Eigen::Dynamic, 1> q = q0.template cast<Shape>();
          modal_forces(shapes.data(), stride * m, n_p, q.data(), 1, f.data());
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
          const Eigen::Index                                        m = hr.size();
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
                  const std::complex<double> s     = std::complex<double>(hr(k), hi(k)) +
                                                 w.alpha[k] * f(0) + w.beta_a[k] * f(1) +
                                                 w.beta_b[k] * f_end + f(3);
                  const std::complex<double> h = w.alpha[k] * s, u = w.cu1[k] * h, v = w.cv1[k] * h;
                  hr(k)                  = h.real();
                  hi(k)                  = h.imag();
                  end_r(k)               = f_end.real();
                  end_i(k)               = f_end.imag();
                  weights(stride * r, 0) = u.real();
                  weights(stride * r, 1) = v.real();
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

        /// Whether @p load is continuous: no impulses, and its start is the
        /// last step's end.
        bool
        continuous(const PatchLoad &load) const
        {
          return (load.component[0].array() == 0.).all() &&
                 (load.component[3].array() == 0.).all() &&
                 load.component[1].size() == end_load.size() && load.component[1] == end_load;
        }

        /// modal::shape_sums() of @p weights (per term: Re e, -Im e) in the
        /// shapes' precision: with double shapes that function itself, from
        /// the double shapes; with float shapes from the float ones, each
        /// chunk of 512 rows summed in float (one triangle, Eigen's
        /// triangular product: twice the rate of double) and the chunks
        /// added in double. Relative error about 1e-6, that of the single
        /// precision update's own sums; the set-up takes half the time.
        std::vector<Eigen::MatrixXd>
        lag_sums(const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> &weights) const
        {
          if constexpr (std::is_same_v<Shape, double>)
            return modal::shape_sums(w.shapes, w.shapes_imag, weights);
          else
            return single_precision_shape_sums(shapes, stride, weights);
        }

        /// The lag kernels K_1 .. K_{J-1}, stacked: rows (m - 1) N_p .. of
        /// block_kernels are K_m. Two threads, each forming half of them.
        void
        form_kernels()
        {
          const std::size_t                                        m = lambda.size();
          std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> weights;
          for (unsigned int lag = 1; lag < J; ++lag)
            {
              Eigen::VectorXd re(m), im(m);
              for (std::size_t k = 0; k < m; ++k)
                {
                  const std::complex<double> z =
                    w.cu1[k] * (lag == 1 ? w.alpha[k] * w.beta_b[k] :
                                           std::pow(w.alpha[k], int(lag - 1)) * gamma[k]);
                  re(k) = z.real();
                  im(k) = -z.imag();
                }
              weights.emplace_back(re, im);
            }
          const std::size_t                                        half = weights.size() / 2;
          std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> first(weights.begin(),
                                                                         weights.begin() + half),
            second(weights.begin() + half, weights.end());
          std::vector<Eigen::MatrixXd> a, b;
          auto                         task = dealii::Threads::new_task([&]() {
            a = lag_sums(first);
          });
          b                                 = lag_sums(second);
          task.join();
          a.insert(a.end(), b.begin(), b.end());
          block_kernels.resize(Eigen::Index(J - 1) * n_p, n_p);
          for (unsigned int lag = 1; lag < J; ++lag)
            block_kernels.middleRows(Eigen::Index(lag - 1) * n_p, n_p) = a[lag - 1];
        }

        /// Enter a time block at the current step: the free responses of its
        /// J steps from the current states.
        void
        start_block()
        {
          if (block_kernels.size() == 0)
            form_kernels();
          block_q = decltype(block_q)::Zero(n_p, J);
          n_block = 0;
          block_pass(true);
          in_block = true;
        }

        /// Record a continuous load's end value q: add its part to the
        /// block's later histories, and at the block's end step the states.
        void
        record(const Eigen::VectorXd &q)
        {
          block_q.col(n_block)     = q.template cast<Shape>();
          const Eigen::Index later = J - 1 - n_block;
          if (later > 0)
            Eigen::Map<Eigen::VectorXd>(block_hist.data() + (n_block + 1) * n_p, later * n_p)
              .noalias() += block_kernels.topRows(later * n_p) * q;
          end_load = q;
          if (++n_block == J)
            {
              block_pass(true);
              block_q.setZero();
              n_block = 0;
            }
        }

        /// Leave the time block: the states h and end forces after the loads
        /// recorded so far, for the step-by-step path.
        void
        end_block()
        {
          if (!in_block)
            return;
          if (n_block > 0)
            block_pass(false);
          in_block      = false;
          history_ready = false;
        }

        /// One pass over the shapes: the states stepped over the block's
        /// n_block loads, and with @p next the free responses of the next
        /// J steps into block_hist.
        void
        block_pass(const bool next)
        {
          // Split as history() splits its sum, whatever the thread count.
          const Eigen::Index m = hr.size();
          if (m / 2 > 64)
            {
              Eigen::MatrixXd first = Eigen::MatrixXd::Zero(n_p, J);
              block_hist.setZero(n_p, J);
              in_two_halves(
                threads, m,
                [&](const Eigen::Index a, const Eigen::Index b) {
                  block_sweep(a, b, next, first);
                },
                [&](const Eigen::Index a, const Eigen::Index b) {
                  block_sweep(a, b, next, block_hist);
                });
              block_hist += first;
            }
          else
            {
              block_hist.setZero(n_p, J);
              block_sweep(0, m, next, block_hist);
            }
        }

        /// The @p n terms from @p b: their states stepped over the block's
        /// loads (modal forces @p f), and with @p next the weights @p wt of
        /// the next block's free responses, both J per shape row, in the
        /// shapes' precision (as the products read and write them). Each
        /// loop runs over the terms, which are independent, in real
        /// arithmetic on the per-term arrays: one term at a time, its J
        /// steps were one chain of dependent complex products.
        void
        step_terms(const Eigen::Index b,
                   const Eigen::Index n,
                   const Shape       *f,
                   const bool         next,
                   Shape             *wt,
                   double            *tr,
                   double            *ti)
        {
          const double *ar = pole_r.col(0).data() + b, *ai = pole_i.col(0).data() + b,
                       *gr = pole_r.col(1).data() + b, *gi = pole_i.col(1).data() + b,
                       *br = pole_r.col(2).data() + b, *bi = pole_i.col(2).data() + b,
                       *cr = pole_r.col(3).data() + b, *ci = pole_i.col(3).data() + b;
          double *h_r = hr.data() + b, *h_i = hi.data() + b, *e_r = end_r.data() + b,
                 *e_i            = end_i.data() + b;
          const Eigen::Index row = stride * J, im = stride == 2 ? J : 0;
          // f's imaginary part: the odd rows of complex shapes, zero for real ones.
          const auto f_i = [&](const Eigen::Index k, const Eigen::Index i) {
            return stride == 2 ? double(f[k * row + im + i]) : 0.;
          };
          // t = g = h + beta_a f(last end).
          for (Eigen::Index k = 0; k < n; ++k)
            {
              tr[k] = h_r[k] + br[k] * e_r[k] - bi[k] * e_i[k];
              ti[k] = h_i[k] + br[k] * e_i[k] + bi[k] * e_r[k];
            }
          for (Eigen::Index i = 0; i < n_block; ++i)
            for (Eigen::Index k = 0; k < n; ++k)
              {
                const double fr = f[k * row + i], fi = f_i(k, i);
                const double x = ar[k] * tr[k] - ai[k] * ti[k] + gr[k] * fr - gi[k] * fi;
                ti[k]          = ar[k] * ti[k] + ai[k] * tr[k] + gr[k] * fi + gi[k] * fr;
                tr[k]          = x;
              }
          if (n_block > 0)
            for (Eigen::Index k = 0; k < n; ++k)
              {
                // h = t - beta_a f(last), and the last load's modal forces.
                e_r[k] = f[k * row + n_block - 1];
                e_i[k] = f_i(k, n_block - 1);
                h_r[k] = tr[k] - br[k] * e_r[k] + bi[k] * e_i[k];
                h_i[k] = ti[k] - br[k] * e_i[k] - bi[k] * e_r[k];
              }
          if (!next)
            return;
          // u_j = Re(c z_j phi): z_0 = h, z_j = alpha^j g (g = t); the
          // weights of a complex shape's rows: Re(c z) and -Im(c z).
          for (Eigen::Index k = 0; k < n; ++k)
            {
              wt[k * row] = Shape(cr[k] * h_r[k] - ci[k] * h_i[k]);
              if (stride == 2)
                wt[k * row + im] = Shape(-(cr[k] * h_i[k] + ci[k] * h_r[k]));
              const double x = cr[k] * tr[k] - ci[k] * ti[k];
              ti[k]          = cr[k] * ti[k] + ci[k] * tr[k];
              tr[k]          = x;
            }
          for (Eigen::Index j = 1; j < J; ++j)
            for (Eigen::Index k = 0; k < n; ++k)
              {
                const double x  = ar[k] * tr[k] - ai[k] * ti[k];
                ti[k]           = ar[k] * ti[k] + ai[k] * tr[k];
                tr[k]           = x;
                wt[k * row + j] = Shape(x);
                if (stride == 2)
                  wt[k * row + im + j] = Shape(-ti[k]);
              }
        }

        /// Terms [begin, end) of block_pass(); their free responses added to
        /// @p out (N_p x J).
        void
        block_sweep(const Eigen::Index begin,
                    const Eigen::Index end,
                    const bool         next,
                    Eigen::MatrixXd   &out)
        {
          // 256 rows per call (measured: the products' overheads fall with
          // longer calls up to about 256 rows, and the rows still fit in L2).
          const Eigen::Index  block = 256 / stride;
          std::vector<Shape>  forces(stride * block * J), weights(stride * block * J);
          std::vector<double> t_r(block), t_i(block);
          // The loads at the points where any of the block's is not zero (the
          // points in contact: on a textured road a few of the patch's), J
          // values per point.
          std::vector<unsigned int> points;
          for (unsigned int p = 0; p < n_p; ++p)
            if ((block_q.row(p).array() != Shape(0)).any())
              points.push_back(p);
          Eigen::Matrix<Shape, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> q_t(points.size(),
                                                                                    J);
          for (std::size_t a = 0; a < points.size(); ++a)
            q_t.row(a) = block_q.row(points[a]);
          // The kernels read and add J values per point.
          Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> sum =
            Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>::Zero(n_p, J);
          for (Eigen::Index b = begin; b < end; b += block)
            {
              const Eigen::Index rows = std::min(block, end - b);
              const Shape       *phi  = shapes.data() + stride * b * n_p;
              if (n_block > 0)
                block_forces(phi, stride * rows, n_p, points.data(), points.size(), q_t.data(), J,
                             forces.data());
              step_terms(b, rows, forces.data(), next, weights.data(), t_r.data(), t_i.data());
              if (next)
                add_block_weighted_shapes(phi, stride * rows, n_p, weights.data(), J, sum.data());
            }
          out += sum;
        }

        unsigned int threads;
        // The time block's length (1: step by step only).
        Eigen::Index J;
        PoleWeights  w;
        // 1 for real shapes, 2 for complex ones (rows a_k, b_k).
        Eigen::Index stride;
        // Row-major: a block of terms is one contiguous stretch of memory.
        Eigen::Matrix<Shape, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> shapes;
        std::vector<std::complex<double>>                                     lambda;
        // The states of the next history, h = e^{lambda dt} s, and its u, v.
        Eigen::VectorXd hr, hi;
        Eigen::MatrixXd uv;
        // The step's load vectors to project, one row each, in the shapes'
        // precision, as modal_forces() reads them, and where each component is among them
        // (-1: zero, or reused).
        Eigen::Matrix<Shape, 4, Eigen::Dynamic, Eigen::RowMajor> loads_t;
        unsigned int                                             n_loads = 0;
        std::array<int, 4>                                       slot{{-1, -1, -1, -1}};
        // The last end load and its modal forces.
        Eigen::VectorXd end_load, end_r, end_i;
        bool            reuse = false;
        // The time block: gamma = alpha beta_b + beta_a per term, the lag
        // kernels, the block's histories (N_p x J) and loads (N_p x J, in
        // the shapes' precision), and how many loads it has.
        std::vector<std::complex<double>> gamma;
        // Per term, real and imaginary parts: alpha, gamma, beta_a, c_u.
        Eigen::MatrixXd                                      pole_r, pole_i;
        Eigen::MatrixXd                                      block_kernels, block_hist;
        Eigen::Matrix<Shape, Eigen::Dynamic, Eigen::Dynamic> block_q;
        Eigen::Index                                         n_block       = 0;
        bool                                                 in_block      = false;
        bool                                                 history_ready = false;
        // Whether the steps sum the velocity, and whether uv's holds it.
        bool velocity = true, velocity_ready = false;
      };
    } // namespace


    std::unique_ptr<PatchConvolution>
    make_rank_one_patch_convolution(const modal::PatchModel &model,
                                    const double             dt,
                                    const unsigned int       n_threads,
                                    const ShapePrecision     precision,
                                    const unsigned int       block_steps)
    {
      if (!model.is_rank_one())
        throw std::logic_error("make_rank_one_patch_convolution: the model has full residues");
      if (block_steps != 0 && block_steps != 1 && block_steps != 4 && block_steps != 8 &&
          block_steps != 16)
        throw std::logic_error("make_rank_one_patch_convolution: " + std::to_string(block_steps) +
                               " steps per time block; allowed: 0 (chosen), 1, 4, 8 or 16");
      // Blocks of J steps cost (J - 1) N_p^2 / 2 per step in their lag
      // kernels against the 2 R N_p of a pass over the R shape rows that
      // they save J - 1 times in J: worth it with many rows per point (the
      // tyre's model: 590), not with few (a fine contact grid on few modes).
      const Eigen::Index rows = model.shapes.rows() * (model.shapes_imag.size() ? 2 : 1);
      const unsigned int J    = block_steps != 0                             ? block_steps :
                                rows >= 128 * Eigen::Index(model.n_points()) ? 16 :
                                                                               1;
      if (precision == ShapePrecision::single_precision)
        return std::make_unique<ModePatchConvolution<float>>(model, dt, n_threads, J);
      return std::make_unique<ModePatchConvolution<double>>(model, dt, n_threads, J);
    }
  } // namespace convolution
} // namespace greentread
