#include <greentread/modal/pole_polish.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/LevenbergMarquardt>

#include <cmath>

namespace greentread
{
  namespace modal
  {
    namespace
    {
      using Complex = std::complex<double>;

      /**
       * The variable-projection problem: parameters theta (two per pair,
       * log(-Re l) and log(Im l); one per real pole, log(-l)), residual
       * r = W (g - A(theta) x(theta)) over the lines, Re then Im, x the
       * linear least-squares residues and residual terms.
       */
      struct Projection : Eigen::DenseFunctor<double>
      {
        Projection(const base::FrequencyResponse &frf_,
                   const std::vector<PolishPole> &shape,
                   const bool                     lower_,
                   const bool                     upper_)
            : Eigen::DenseFunctor<double>(parameter_count(shape),
                                          2 * int(frf_.values.size() - (lower_ ? 1 : 0)))
            , frf(frf_)
            , real(shape.size())
            , lower(lower_)
            , upper(upper_)
            , first(lower_ ? 1 : 0)
        {
          for (std::size_t r = 0; r < shape.size(); ++r)
            real[r] = shape[r].real;
          const Eigen::Index n = frf.values.size() - first;
          omega.resize(n);
          weight.resize(n);
          data.resize(2 * n);
          for (Eigen::Index k = 0; k < n; ++k)
            {
              omega(k)    = 2. * M_PI * (k + first) * frf.df;
              weight(k)   = (k == 0 || k + 1 == n) ? std::sqrt(0.5) : 1.;
              data(k)     = weight(k) * frf.values[k + first].real();
              data(k + n) = weight(k) * frf.values[k + first].imag();
            }
        }

        static int
        parameter_count(const std::vector<PolishPole> &poles)
        {
          int count = 0;
          for (const auto &p : poles)
            count += p.real ? 1 : 2;
          return count;
        }

        /// The poles of parameters @p theta.
        std::vector<Complex>
        poles(const Eigen::VectorXd &theta) const
        {
          std::vector<Complex> l;
          Eigen::Index         i = 0;
          for (const bool is_real : real)
            if (is_real)
              l.emplace_back(-std::exp(theta(i++)), 0.);
            else
              {
                l.emplace_back(-std::exp(theta(i)), std::exp(theta(i + 1)));
                i += 2;
              }
          return l;
        }

        Eigen::VectorXd
        parameters(const std::vector<PolishPole> &given) const
        {
          Eigen::VectorXd theta(inputs());
          Eigen::Index    i = 0;
          for (const auto &p : given)
            if (p.real)
              theta(i++) = std::log(-p.lambda.real());
            else
              {
                theta(i++) = std::log(-p.lambda.real());
                theta(i++) = std::log(p.lambda.imag());
              }
          return theta;
        }

        /// The weighted real basis A (unscaled), per pole its columns, then
        /// the residual terms.
        Eigen::MatrixXd
        basis(const std::vector<Complex> &l) const
        {
          const Eigen::Index n    = omega.size();
          Eigen::Index       cols = (lower ? 1 : 0) + (upper ? 1 : 0);
          for (const bool is_real : real)
            cols += is_real ? 1 : 2;
          Eigen::MatrixXd A(2 * n, cols);
          const auto      put = [&](const Eigen::Index c, const Eigen::Index k, const Complex v) {
            A(k, c)     = weight(k) * v.real();
            A(k + n, c) = weight(k) * v.imag();
          };
          const Complex j(0., 1.);
          for (Eigen::Index k = 0; k < n; ++k)
            {
              const Complex jw(0., omega(k));
              Eigen::Index  c = 0;
              for (std::size_t r = 0; r < l.size(); ++r)
                if (real[r])
                  put(c++, k, 1. / (jw - l[r]));
                else
                  {
                    const Complex a = 1. / (jw - l[r]), b = 1. / (jw - std::conj(l[r]));
                    put(c++, k, a + b);
                    put(c++, k, j * a - j * b);
                  }
              if (lower)
                put(c++, k, -1. / (omega(k) * omega(k)));
              if (upper)
                put(c++, k, 1.);
            }
          return A;
        }

        /// The least-squares coefficients of A and the projector's basis Q.
        void
        solve(const Eigen::MatrixXd &A, Eigen::VectorXd &x, Eigen::MatrixXd &Q) const
        {
          Eigen::VectorXd scale = A.colwise().norm().transpose();
          for (Eigen::Index c = 0; c < scale.size(); ++c)
            if (!(scale(c) > 0.))
              scale(c) = 1.;
          const Eigen::MatrixXd S = A * scale.cwiseInverse().asDiagonal();
          const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(S);
          x = qr.solve(data).cwiseQuotient(scale);
          Q = qr.householderQ() * Eigen::MatrixXd::Identity(A.rows(), qr.rank());
        }

        int
        operator()(const Eigen::VectorXd &theta, Eigen::VectorXd &r) const
        {
          const Eigen::MatrixXd A = basis(poles(theta));
          Eigen::VectorXd       x;
          Eigen::MatrixXd       Q;
          solve(A, x, Q);
          r = data - A * x;
          ++evaluations;
          return r.allFinite() ? 0 : -1;
        }

        /// Kaufman's Jacobian: -(I - Q Q^T) dA/dtheta x.
        int
        df(const Eigen::VectorXd &theta, Eigen::MatrixXd &J) const
        {
          const std::vector<Complex> l = poles(theta);
          const Eigen::MatrixXd      A = basis(l);
          Eigen::VectorXd            x;
          Eigen::MatrixXd            Q;
          solve(A, x, Q);
          const Eigen::Index n = omega.size();
          J.resize(2 * n, inputs());
          const Complex j(0., 1.);
          Eigen::Index  c = 0, i = 0;
          for (std::size_t p = 0; p < l.size(); ++p)
            {
              // d/dtheta of the pole's part of A x at every line.
              const auto column = [&](const Complex dl, const Complex dlb) {
                Eigen::VectorXd v(2 * n);
                for (Eigen::Index k = 0; k < n; ++k)
                  {
                    const Complex jw(0., omega(k));
                    Complex       d;
                    if (real[p])
                      d = x(c) * dl / ((jw - l[p]) * (jw - l[p]));
                    else
                      {
                        const Complex a = dl / ((jw - l[p]) * (jw - l[p]));
                        const Complex b = dlb / ((jw - std::conj(l[p])) * (jw - std::conj(l[p])));
                        d               = x(c) * (a + b) + x(c + 1) * (j * a - j * b);
                      }
                    v(k)     = weight(k) * d.real();
                    v(k + n) = weight(k) * d.imag();
                  }
                return v;
              };
              if (real[p])
                J.col(i++) = column(l[p], 0.);
              else
                {
                  const double sigma = -l[p].real(), wd = l[p].imag();
                  J.col(i++) = column(-sigma, -sigma);
                  J.col(i++) = column(j * wd, -j * wd);
                }
              c += real[p] ? 1 : 2;
            }
          J = -(J - Q * (Q.transpose() * J)).eval();
          return 0;
        }

        const base::FrequencyResponse &frf;
        std::vector<bool>              real;
        bool                           lower, upper;
        unsigned int                   first;
        Eigen::VectorXd                omega, weight, data;
        mutable unsigned int           evaluations = 0;
      };
    } // namespace



    std::vector<PolishPole>
    polish_poles(const base::FrequencyResponse &frf,
                 const std::vector<PolishPole> &poles,
                 const bool                     lower,
                 const bool                     upper,
                 PolishReport                  &report)
    {
      report = PolishReport();
      if (poles.empty())
        return poles;
      for (const auto &p : poles)
        if (!(p.lambda.real() < 0.) || (!p.real && !(p.lambda.imag() > 0.)))
          return poles; // only stable poles, pairs above the real axis
      Projection      problem(frf, poles, lower, upper);
      Eigen::VectorXd theta = problem.parameters(poles), r;
      if (problem(theta, r) != 0)
        return poles;
      report.misfit_before = r.squaredNorm();

      Eigen::LevenbergMarquardt<Projection> lm(problem);
      lm.setMaxfev(20 * (problem.inputs() + 1));
      lm.setXtol(1e-8);
      lm.setFtol(1e-6);
      lm.minimize(theta);
      report.iterations  = lm.iterations();
      report.evaluations = problem.evaluations;
      // A pole that left for infinity or zero (a mode of no weight, which
      // the fit does not hold in place) goes back to where it was; the
      // others are kept if the misfit is still lower.
      const std::vector<Complex> l     = problem.poles(theta);
      const double               w_max = 2. * M_PI * frf.f_max();
      std::vector<PolishPole>    out   = poles;
      for (std::size_t p = 0; p < out.size(); ++p)
        if (std::isfinite(std::abs(l[p])) && std::abs(l[p]) > 1e-6 * w_max &&
            std::abs(l[p]) < 10. * w_max && (out[p].real || l[p].imag() > 0.))
          out[p].lambda = l[p];
      if (problem(problem.parameters(out), r) != 0 || !(r.squaredNorm() < report.misfit_before))
        {
          report.misfit_after = report.misfit_before;
          return poles;
        }
      report.misfit_after = r.squaredNorm();
      return out;
    }
  } // namespace modal
} // namespace greentread
