#include <greentread/base/exceptions.h>
#include <greentread/modal/mode_synthesis.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace greentread
{
  namespace modal
  {
    Eigen::MatrixXcd
    ModeSynthesis::at(const double omega) const
    {
      // Two real products, Phi^T diag(Re f) Phi and Phi^T diag(Im f) Phi:
      // a quarter of the work of one complex product.
      const Eigen::Index m = shapes.rows();
      Eigen::VectorXd    re(m), im(m);
      for (Eigen::Index k = 0; k < m; ++k)
        {
          const double               w = 2. * M_PI * frequency_hz(k);
          const std::complex<double> factor =
            1. / std::complex<double>(w * w - omega * omega, 2. * damping_ratio(k) * w * omega);
          re(k) = factor.real();
          im(k) = factor.imag();
        }
      // G_r / (1 + j w beta_r).
      const std::complex<double> relaxed =
        1. / std::complex<double>(1., omega * residual_relaxation);
      Eigen::MatrixXd real = relaxed.real() * instantaneous;
      real.noalias() += shapes.transpose() * (re.asDiagonal() * shapes);
      Eigen::MatrixXd imag = relaxed.imag() * instantaneous;
      imag.noalias() += shapes.transpose() * (im.asDiagonal() * shapes);
      Eigen::MatrixXcd      g(real.rows(), real.cols());
      g.real() = real;
      g.imag() = imag;
      return g;
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
    static_line(const FrequencyResponseMatrix &green)
    {
      const unsigned int P = green.n_points();
      Eigen::MatrixXd    G0(P, P);
      for (unsigned int i = 0; i < P; ++i)
        for (unsigned int j = 0; j < P; ++j)
          G0(i, j) = green.values[std::size_t(i) * P + j].real();
      return G0;
    }



    double
    fit_residual_relaxation(const ModeSynthesis &model, const FrequencyResponseMatrix &direct)
    {
      const unsigned int P = direct.n_points();
      if (model.shapes.cols() != P || model.instantaneous.rows() != P)
        throw NumericalError("fit_residual_relaxation: the model has " +
                             std::to_string(model.shapes.cols()) +
                             " points, the Green's functions " + std::to_string(P));
      // R = g - (modes) at each line; R (1 + j w beta) = G_r in the least-squares
      // sense over every pair and line, which is linear in beta:
      // beta = -Re sum conj(j w R) (R - G_r) / sum |w R|^2.
      double numerator = 0., denominator = 0.;
      for (unsigned int l = 1; l < direct.n_lines; ++l)
        {
          const double           omega = 2. * M_PI * l * direct.df;
          // The modes' part: the model less its own (relaxed) residual, no copy
          // of the shapes.
          const std::complex<double> own =
            1. / std::complex<double>(1., omega * model.residual_relaxation);
          const Eigen::MatrixXcd modal = model.at(omega) - own * model.instantaneous;
          for (unsigned int i = 0; i < P; ++i)
            for (unsigned int j = 0; j < P; ++j)
              {
                const std::complex<double> R =
                  direct.values[std::size_t(l) * P * P + std::size_t(i) * P + j] - modal(i, j);
                const std::complex<double> A(0., omega);
                numerator -= std::real(std::conj(A * R) * (R - model.instantaneous(i, j)));
                denominator += std::norm(A * R);
              }
        }
      return denominator > 0. ? std::max(numerator / denominator, 0.) : 0.;
    }



    ModeSynthesis
    synthesise(const Eigen::VectorXd                    &omega,
               const Eigen::VectorXd                    &damping_ratio,
               const Eigen::MatrixXd                    &shapes,
               const Eigen::MatrixXd                    &static_green,
               const std::vector<std::array<double, 3>> &points)
    {
      const Eigen::Index m = omega.size(), P = static_green.rows();
      if (damping_ratio.size() != m || shapes.rows() != m || shapes.cols() != P ||
          static_green.cols() != P || static_cast<Eigen::Index>(points.size()) != P)
        throw NumericalError("synthesise: the modes, the static Green's functions and the "
                             "points do not match in size");
      ModeSynthesis model;
      model.frequency_hz  = omega / (2. * M_PI);
      model.damping_ratio = damping_ratio;
      model.shapes        = shapes;
      model.points        = points;
      const Eigen::MatrixXd scaled = omega.cwiseInverse().asDiagonal() * shapes;
      Eigen::MatrixXd       residual = static_green - scaled.transpose() * scaled;
      model.instantaneous            = 0.5 * (residual + residual.transpose());
      return model;
    }



    ModeSynthesis
    synthesise(const Eigen::VectorXd         &omega,
               const Eigen::VectorXd         &damping_ratio,
               const Eigen::MatrixXd         &shapes,
               const FrequencyResponseMatrix &direct)
    {
      ModeSynthesis model =
        synthesise(omega, damping_ratio, shapes, static_line(direct), direct.points);
      model.residual_relaxation = fit_residual_relaxation(model, direct);
      return model;
    }



    SynthesisErrors
    compare(const ModeSynthesis &model, const FrequencyResponseMatrix &direct)
    {
      const unsigned int P = direct.n_points(), L = direct.n_lines;
      if (model.shapes.cols() != P)
        throw NumericalError("compare: the model has " + std::to_string(model.shapes.cols()) +
                             " points, the Green's functions " + std::to_string(P));
      // Trapezoidal sums of |g - g_model| and |g| over the lines.
      Eigen::MatrixXd difference = Eigen::MatrixXd::Zero(P, P), size = difference;
      SynthesisErrors errors;
      errors.passivity = 1.;
      for (unsigned int l = 0; l < L; ++l)
        {
          const double           weight = (l == 0 || l + 1 == L) ? 0.5 : 1.;
          const Eigen::MatrixXcd g_model = model.at(2. * M_PI * l * direct.df);
          const Eigen::Map<const Eigen::Matrix<std::complex<double>, Eigen::Dynamic,
                                               Eigen::Dynamic, Eigen::RowMajor>>
            g(direct.values.data() + std::size_t(l) * P * P, P, P);
          difference += weight * (g - g_model).cwiseAbs();
          size += weight * g.cwiseAbs();
          if (l > 0)
            {
              const Eigen::MatrixXd loss = -0.5 * (g_model.imag() + g_model.imag().transpose());
              const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(loss,
                                                                         Eigen::EigenvaluesOnly);
              const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
              if (largest > 0.)
                errors.passivity =
                  std::min(errors.passivity, eigen.eigenvalues().minCoeff() / largest);
            }
        }
      errors.pair_error.resize(std::size_t(P) * P);
      for (unsigned int i = 0; i < P; ++i)
        for (unsigned int j = 0; j < P; ++j)
          {
            // A pair that is zero at every line: no error if the model is zero too.
            const double e = size(i, j) > 0. ? difference(i, j) / size(i, j) :
                             difference(i, j) > 0. ? std::numeric_limits<double>::infinity() : 0.;
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
  } // namespace modal
} // namespace greentread
