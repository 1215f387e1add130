#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/base/progress.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <deal.II/base/multithread_info.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <complex>
#include <limits>
#include <mutex>
#include <string>

namespace greentread
{
  namespace synthesis
  {
    namespace
    {
      /// The lanes of for_each_line(): a fixed number, whatever the thread
      /// count, so that sums kept per lane and added in lane order give the
      /// same bytes with any number of threads.
      constexpr unsigned int n_lanes = 16;

      /// line(l, s) for the lines @p first to @p n_lines - 1, line l in lane
      /// s = (l - first) mod n_lanes, each lane's lines in increasing order on
      /// one thread; the lanes are shared among the threads
      /// (DEAL_II_NUM_THREADS). A failure on any thread is thrown as
      /// "@p what: message".
      template <typename Line>
      void
      for_each_line(const unsigned int first,
                    const unsigned int n_lines,
                    const std::string &what,
                    const Line        &line)
      {
        const unsigned int lanes =
          std::min(n_lanes, std::max(1u, n_lines - std::min(first, n_lines)));
        const unsigned int n_threads =
          std::max(1u, std::min<unsigned int>(dealii::MultithreadInfo::n_threads(), lanes));
        std::atomic<unsigned int> done{first}, next_lane{0};
        std::mutex                mutex;
        std::string               failure;
        const auto                work = [&]() {
          try
            {
              for (unsigned int s = next_lane++; s < lanes; s = next_lane++)
                for (unsigned int l = first + s; l < n_lines; l += n_lanes, ++done)
                  line(l, s);
            }
          catch (const std::exception &e)
            {
              const std::lock_guard<std::mutex> lock(mutex);
              if (failure.empty())
                failure = e.what();
            }
        };
        base::run_on_threads(n_threads, work, done, n_lines, nullptr, [] {
          return false;
        });
        if (!failure.empty())
          throw NumericalError(what + ": " + failure);
      }

      /**
       * The modes' part of g(w), sum_k psi_k psi_k^T d_k(w), of the modes
       * (@p frequency_hz, @p damping_ratio, @p shapes + j @p shapes_imag).
       * Per mode the factors of Re and Im of psi psi^T (modal::shape_sums()):
       * d1 = 1 / (w_k^2 - w^2 + 2 j xi w_k w), and for a complex shape
       * d2 = j (c - c'), c = 1 / (2 j w_d (j w - l)), c' = -1 / (2 j w_d (j w - conj l)).
       */
      Eigen::MatrixXcd
      modal_part(const Eigen::VectorXd &frequency_hz,
                 const Eigen::VectorXd &damping_ratio,
                 const Eigen::MatrixXd &shapes,
                 const Eigen::MatrixXd &shapes_imag,
                 const double           omega)
      {
        const Eigen::Index         m = shapes.rows();
        Eigen::VectorXd            re1(m), im1(m), re2 = Eigen::VectorXd::Zero(m), im2 = re2;
        const std::complex<double> s(0., omega);
        for (Eigen::Index k = 0; k < m; ++k)
          {
            const double               w = 2. * M_PI * frequency_hz(k), xi = damping_ratio(k);
            const std::complex<double> d1 =
              1. / std::complex<double>(w * w - omega * omega, 2. * xi * w * omega);
            re1(k) = d1.real();
            im1(k) = d1.imag();
            if (shapes_imag.size() == 0 || !(xi < 1.))
              continue;
            const double               wd = w * std::sqrt(1. - xi * xi);
            const std::complex<double> l(-xi * w, wd), twice(0., 2. * wd);
            const std::complex<double> d2 =
              std::complex<double>(0., 1.) *
              (1. / (twice * (s - l)) + 1. / (twice * (s - std::conj(l))));
            re2(k) = d2.real();
            im2(k) = d2.imag();
          }
        const auto       sums = modal::shape_sums(shapes, shapes_imag, {{re1, re2}, {im1, im2}});
        Eigen::MatrixXcd g(shapes.cols(), shapes.cols());
        g.real() = sums[0];
        g.imag() = sums[1];
        return g;
      }

      /// A mode is interpolated across the lines if its poles are at least
      /// this many times the highest line away, on the real axis (or as
      /// far in the sense of ellipse_parameter()).
      constexpr double far_ratio = 1.25;

      /// rho = |x + sqrt(x^2 - 1)| >= 1 for a point @p x of the complex plane:
      /// the Bernstein ellipse about [-1, 1] through it. A function whose
      /// poles lie outside the ellipse rho is interpolated at Q + 1
      /// Chebyshev points within a few times rho^-Q of its size.
      double
      ellipse_parameter(const std::complex<double> x)
      {
        const std::complex<double> root = std::sqrt(x - 1.) * std::sqrt(x + 1.);
        return std::max(std::abs(x + root), std::abs(x - root));
      }

      /// The smallest ellipse_parameter() of the poles of mode (@p w [rad/s],
      /// @p xi) in w, about [0, @p omega_max] mapped onto [-1, 1]: w_d + j xi w
      /// and -w_d + j xi w below critical damping, j w (xi -+ sqrt(xi^2 - 1))
      /// above it.
      double
      mode_ellipse(const double w, const double xi, const double omega_max)
      {
        std::array<std::complex<double>, 2> poles;
        if (xi < 1.)
          {
            const double wd = w * std::sqrt(1. - xi * xi);
            poles           = {{{wd, xi * w}, {-wd, xi * w}}};
          }
        else
          {
            const double root = std::sqrt(xi * xi - 1.);
            poles             = {{{0., w * (xi - root)}, {0., w * (xi + root)}}};
          }
        double rho = std::numeric_limits<double>::infinity();
        for (const auto z : poles)
          rho = std::min(rho, ellipse_parameter(2. * z / omega_max - 1.));
        return rho;
      }
    } // namespace



    Eigen::MatrixXcd
    ModeSynthesis::modes_at(const double omega) const
    {
      return modal_part(frequency_hz, damping_ratio, shapes, shapes_imag, omega);
    }



    std::vector<Eigen::MatrixXcd>
    ModeSynthesis::modes_at_lines(const double df, const unsigned int n_lines) const
    {
      // Chebyshev-Lobatto nodes x_q = cos(pi q / Q) on [0, w_max], x = 2 w / w_max - 1.
      const double omega_max = 2. * M_PI * df * (n_lines > 0 ? n_lines - 1 : 0);
      const double rho       = ellipse_parameter(2. * far_ratio - 1.);
      const auto   Q         = static_cast<unsigned int>(std::ceil(std::log(1e16) / std::log(rho)));
      std::vector<Eigen::Index> near, far;
      for (Eigen::Index k = 0; k < frequency_hz.size(); ++k)
        (omega_max > 0. &&
             mode_ellipse(2. * M_PI * frequency_hz(k), damping_ratio(k), omega_max) >= rho ?
           far :
           near)
          .push_back(k);
      std::vector<Eigen::MatrixXcd> g(n_lines);
      // Interpolating pays only with fewer nodes than lines.
      if (far.empty() || n_lines <= Q + 1)
        {
          for_each_line(0, n_lines, "the modes at every line",
                        [&](const unsigned int l, const unsigned int) {
                          g[l] = modes_at(2. * M_PI * l * df);
                        });
          return g;
        }
      const auto rows = [](const Eigen::MatrixXd &A, const std::vector<Eigen::Index> &which) {
        return A.size() ? Eigen::MatrixXd(A(which, Eigen::all)) : Eigen::MatrixXd();
      };
      const auto entries = [](const Eigen::VectorXd &v, const std::vector<Eigen::Index> &which) {
        return Eigen::VectorXd(v(which));
      };
      const Eigen::VectorXd f_near  = entries(frequency_hz, near),
                            xi_near = entries(damping_ratio, near);
      const Eigen::MatrixXd A_near = rows(shapes, near), B_near = rows(shapes_imag, near);
      for_each_line(0, n_lines, "the modes at every line",
                    [&](const unsigned int l, const unsigned int) {
                      g[l] = modal_part(f_near, xi_near, A_near, B_near, 2. * M_PI * l * df);
                    });

      const Eigen::VectorXd f_far         = entries(frequency_hz, far),
                            xi_far        = entries(damping_ratio, far);
      const Eigen::MatrixXd         A_far = rows(shapes, far), B_far = rows(shapes_imag, far);
      Eigen::VectorXd               node(Q + 1);
      std::vector<Eigen::MatrixXcd> at_node(Q + 1);
      for (unsigned int q = 0; q <= Q; ++q)
        node(q) = std::cos(M_PI * q / Q);
      for_each_line(
        0, Q + 1, "the modes above the lines", [&](const unsigned int q, const unsigned int) {
          at_node[q] = modal_part(f_far, xi_far, A_far, B_far, 0.5 * omega_max * (1. + node(q)));
        });
      // The barycentric formula of the second kind (weights (-1)^q, halved at
      // the ends); a line on a node takes the node's value.
      for_each_line(
        0, n_lines, "the modes above the lines", [&](const unsigned int l, const unsigned int) {
          const double    x = 2. * (2. * M_PI * l * df) / omega_max - 1.;
          Eigen::VectorXd weight(Q + 1);
          for (unsigned int q = 0; q <= Q; ++q)
            {
              if (x == node(q))
                {
                  g[l] += at_node[q];
                  return;
                }
              weight(q) = ((q % 2) ? -1. : 1.) * ((q == 0 || q == Q) ? 0.5 : 1.) / (x - node(q));
            }
          weight /= weight.sum();
          for (unsigned int q = 0; q <= Q; ++q)
            g[l] += weight(q) * at_node[q];
        });
      return g;
    }



    Eigen::MatrixXcd
    ModeSynthesis::at(const double omega) const
    {
      // G_r / (1 + j w beta_r) and the modes.
      return with_residual(omega, modes_at(omega));
    }



    Eigen::MatrixXcd
    ModeSynthesis::with_residual(const double omega, Eigen::MatrixXcd modal) const
    {
      const std::complex<double> relaxed =
        1. / std::complex<double>(1., omega * residual_relaxation);
      modal.real() += relaxed.real() * instantaneous;
      modal.imag() += relaxed.imag() * instantaneous;
      return modal;
    }



    double
    ModeSynthesis::residual_definiteness() const
    {
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(instantaneous,
                                                                 Eigen::EigenvaluesOnly);
      const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
      return largest > 0. ? eigen.eigenvalues().minCoeff() / largest : 0.;
    }



    Eigen::MatrixXd
    static_line(const base::FrequencyResponseMatrix &green)
    {
      const unsigned int P = green.n_points();
      Eigen::MatrixXd    G0(P, P);
      for (unsigned int i = 0; i < P; ++i)
        for (unsigned int j = 0; j < P; ++j)
          G0(i, j) = green.values[std::size_t(i) * P + j].real();
      return G0;
    }



    double
    fit_residual_relaxation(const ModeSynthesis                 &model,
                            const base::FrequencyResponseMatrix &direct,
                            const ModalLines                    *lines)
    {
      const bool         kept = lines != nullptr && lines->matches(direct);
      const unsigned int P    = direct.n_points();
      if (model.shapes.cols() != P || model.instantaneous.rows() != P)
        throw NumericalError("fit_residual_relaxation: the model has " +
                             std::to_string(model.shapes.cols()) +
                             " points, the Green's functions " + std::to_string(P));
      // R = g - (modes) at each line; R (1 + j w beta) = G_r in the least-squares
      // sense over every pair and line, which is linear in beta:
      // beta = -Re sum conj(j w R) (R - G_r) / sum |w R|^2.
      std::vector<double> numerator(n_lanes, 0.), denominator(n_lanes, 0.);
      for_each_line(
        1, direct.n_lines, "fit_residual_relaxation",
        [&](const unsigned int l, const unsigned int t) {
          const double               omega = 2. * M_PI * l * direct.df;
          const Eigen::MatrixXcd     modal = kept ? lines->g[l] : model.modes_at(omega);
          const std::complex<double> A(0., omega);
          for (unsigned int i = 0; i < P; ++i)
            for (unsigned int j = 0; j < P; ++j)
              {
                const std::complex<double> R =
                  direct.values[std::size_t(l) * P * P + std::size_t(i) * P + j] - modal(i, j);
                numerator[t] -= std::real(std::conj(A * R) * (R - model.instantaneous(i, j)));
                denominator[t] += std::norm(A * R);
              }
        });
      double sum_numerator = 0., sum_denominator = 0.;
      for (unsigned int t = 0; t < n_lanes; ++t)
        {
          sum_numerator += numerator[t];
          sum_denominator += denominator[t];
        }
      return sum_denominator > 0. ? std::max(sum_numerator / sum_denominator, 0.) : 0.;
    }



    ModeSynthesis
    synthesise(const Eigen::VectorXd                    &omega,
               const Eigen::VectorXd                    &damping_ratio,
               const Eigen::MatrixXd                    &shapes,
               const Eigen::MatrixXd                    &shapes_imag,
               const Eigen::MatrixXd                    &static_green,
               const std::vector<std::array<double, 3>> &points)
    {
      const Eigen::Index m = omega.size(), P = static_green.rows();
      if (damping_ratio.size() != m || shapes.rows() != m || shapes.cols() != P ||
          (shapes_imag.size() && (shapes_imag.rows() != m || shapes_imag.cols() != P)) ||
          static_green.cols() != P || static_cast<Eigen::Index>(points.size()) != P)
        throw NumericalError("synthesise: the modes, the static Green's functions and the "
                             "points do not match in size");
      ModeSynthesis model;
      model.frequency_hz  = omega / (2. * M_PI);
      model.damping_ratio = damping_ratio;
      model.shapes        = shapes;
      if (shapes_imag.size() && shapes_imag.cwiseAbs().maxCoeff() > 0.)
        model.shapes_imag = shapes_imag;
      for (Eigen::Index k = 0; k < m; ++k)
        if (model.shapes_imag.size() && !(damping_ratio(k) < 1.) &&
            model.shapes_imag.row(k).cwiseAbs().maxCoeff() > 0.)
          throw NumericalError("synthesise: mode " + std::to_string(k) +
                               " has a complex shape and a damping ratio of " +
                               format_short(damping_ratio(k)) + "; a complex shape needs < 1");
      model.points = points;
      // The modes' static part is real (for a real shape 1 / w_k^2).
      const Eigen::MatrixXd residual = static_green - model.modes_at(0.).real();
      model.instantaneous            = 0.5 * (residual + residual.transpose());
      return model;
    }



    ModeSynthesis
    synthesise(const Eigen::VectorXd               &omega,
               const Eigen::VectorXd               &damping_ratio,
               const Eigen::MatrixXd               &shapes,
               const Eigen::MatrixXd               &shapes_imag,
               const base::FrequencyResponseMatrix &direct,
               ModalLines                          *lines)
    {
      ModeSynthesis model =
        synthesise(omega, damping_ratio, shapes, shapes_imag, static_line(direct), direct.points);
      const double bytes = 16. * direct.n_lines * double(direct.n_points()) * direct.n_points();
      if (lines == nullptr || bytes > 1e9)
        {
          model.residual_relaxation = fit_residual_relaxation(model, direct);
          return model;
        }
      lines->df                 = direct.df;
      lines->g                  = model.modes_at_lines(direct.df, direct.n_lines);
      model.residual_relaxation = fit_residual_relaxation(model, direct, lines);
      return model;
    }



    SynthesisErrors
    compare(const ModeSynthesis                 &model,
            const base::FrequencyResponseMatrix &direct,
            const ModalLines                    *lines)
    {
      const bool         kept = lines != nullptr && lines->matches(direct);
      const unsigned int P = direct.n_points(), L = direct.n_lines;
      if (model.shapes.cols() != P)
        throw NumericalError("compare: the model has " + std::to_string(model.shapes.cols()) +
                             " points, the Green's functions " + std::to_string(P));
      // Trapezoidal sums of |g - g_model| and |g| over the lines, each
      // lane's added in lane order (for_each_line). One line costs a few
      // GFLOP with tens of thousands of modes.
      std::vector<Eigen::MatrixXd> difference(n_lanes, Eigen::MatrixXd::Zero(P, P)),
        size = difference;
      std::vector<double> passivity(n_lanes, 1.), passivity_omega(n_lanes, 0.);
      for_each_line(0, L, "compare", [&](const unsigned int l, const unsigned int t) {
        const double           weight = (l == 0 || l + 1 == L) ? 0.5 : 1.;
        const double           omega  = 2. * M_PI * l * direct.df;
        const Eigen::MatrixXcd g_model =
          kept ? model.with_residual(omega, lines->g[l]) : model.at(omega);
        const Eigen::Map<const Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic,
                                             Eigen::RowMajor>>
          g(direct.values.data() + std::size_t(l) * P * P, P, P);
        difference[t] += weight * (g - g_model).cwiseAbs();
        size[t] += weight * g.cwiseAbs();
        if (l == 0)
          return;
        const Eigen::MatrixXd loss = -0.5 * (g_model.imag() + g_model.imag().transpose());
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(loss, Eigen::EigenvaluesOnly);
        const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
        if (largest > 0. && eigen.eigenvalues().minCoeff() / largest < passivity[t])
          {
            passivity[t]       = eigen.eigenvalues().minCoeff() / largest;
            passivity_omega[t] = omega;
          }
      });
      for (unsigned int t = 1; t < n_lanes; ++t)
        {
          difference[0] += difference[t];
          size[0] += size[t];
          if (passivity[t] < passivity[0])
            {
              passivity[0]       = passivity[t];
              passivity_omega[0] = passivity_omega[t];
            }
        }
      SynthesisErrors errors;
      errors.passivity           = passivity[0];
      errors.passivity_frequency = passivity_omega[0] / (2. * M_PI);
      errors.pair_error.resize(std::size_t(P) * P);
      for (unsigned int i = 0; i < P; ++i)
        for (unsigned int j = 0; j < P; ++j)
          {
            // A pair that is zero at every line: no error if the model is zero too.
            const double e = size[0](i, j) > 0.       ? difference[0](i, j) / size[0](i, j) :
                             difference[0](i, j) > 0. ? std::numeric_limits<double>::infinity() :
                                                        0.;
            errors.pair_error[i * P + j] = e;
            if (e > errors.worst)
              {
                errors.worst   = e;
                errors.worst_i = i;
                errors.worst_j = j;
              }
          }
      std::vector<double> sorted = errors.pair_error;
      std::sort(sorted.begin(), sorted.end());
      errors.median = sorted[sorted.size() / 2];
      errors.p90    = sorted[std::min(sorted.size() - 1, sorted.size() * 9 / 10)];
      return errors;
    }
  } // namespace synthesis
} // namespace greentread
