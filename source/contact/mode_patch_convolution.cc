#include <greentread/contact/mode_patch_convolution.h>
#include <greentread/contact/pole_weights.h>
#include <greentread/contact/shape_kernels.h>

#include <deal.II/base/thread_management.h>

#include <array>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

namespace greentread
{
  namespace contact
  {
    namespace
    {
      using internal::PoleWeights;

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
              loads_t.row(n_loads++) = load.component[g].transpose().template cast<Shape>();
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
        // The step's load vectors to project, one row each, in the shapes'
        // precision, as modal_forces() reads them, and where each component is among them
        // (-1: zero, or reused).
        Eigen::Matrix<Shape, 4, Eigen::Dynamic, Eigen::RowMajor> loads_t;
        unsigned int                                              n_loads = 0;
        std::array<int, 4>                                        slot{{-1, -1, -1, -1}};
        // The last end load and its modal forces.
        Eigen::VectorXd end_load, end_r, end_i;
        bool            have_end = false, reuse = false;
        bool            history_ready = false;
        // Whether the steps sum the velocity, and whether uv's holds it.
        bool velocity = true, velocity_ready = false;
      };
    } // namespace



    std::unique_ptr<PatchConvolution>
    make_rank_one_patch_convolution(const modal::PatchModel &model, const double dt,
                                    const unsigned int n_threads, const ShapePrecision precision)
    {
      if (!model.is_rank_one())
        throw std::logic_error("make_rank_one_patch_convolution: the model has full residues");
      if (precision == ShapePrecision::single_precision)
        return std::make_unique<ModePatchConvolution<float>>(model, dt, n_threads);
      return std::make_unique<ModePatchConvolution<double>>(model, dt, n_threads);
    }
  } // namespace contact
} // namespace greentread
