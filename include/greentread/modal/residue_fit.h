#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/modal/identification.h>

#include <Eigen/Dense>

#include <algorithm>
#include <complex>
#include <numeric>
#include <vector>

/**
 * @file
 * The frequency-domain least-squares fit of residues to an FRF for a given
 * set of poles, the second step of LSCE identification (Appendix A). Used by
 * source/modal/identification.cc only; a header of its own so that file
 * stays readable.
 */

namespace greentread
{
  namespace modal
  {
    namespace internal
    {
      struct Pole
      {
        std::complex<double> lambda; // Im >= 0
        bool                 real;
      };

      /// The frequency-domain least-squares problem for a set of poles.
      class ResidueFit
      {
      public:
        ResidueFit(const base::FrequencyResponse &frf,
                   const std::vector<Pole>       &poles,
                   ResidueModel                   model,
                   bool                           lower,
                   bool                           upper)
            : frf(frf)
            , poles(poles)
            , model(model)
            , first_line(lower ? 1 : 0)
        {
          const unsigned int n_lines = frf.values.size() - first_line;
          // Columns: residual terms first (always kept), then the modes.
          std::vector<Eigen::VectorXcd> columns;
          const auto                    omega = [&](unsigned int k) {
            return 2. * M_PI * (k + first_line) * frf.df;
          };
          if (lower)
            {
              Eigen::VectorXcd c(n_lines);
              for (unsigned int k = 0; k < n_lines; ++k)
                c[k] = -1. / (omega(k) * omega(k));
              columns.push_back(c);
              residual_kind.push_back(0);
            }
          if (upper)
            {
              columns.push_back(Eigen::VectorXcd::Ones(n_lines));
              residual_kind.push_back(1);
            }
          n_residual = columns.size();
          for (const auto &pole : poles)
            {
              first_column.push_back(columns.size());
              const std::complex<double> l = pole.lambda, lb = std::conj(pole.lambda);
              Eigen::VectorXcd           a(n_lines), b(n_lines);
              for (unsigned int k = 0; k < n_lines; ++k)
                {
                  const std::complex<double> jw(0., omega(k));
                  if (pole.real)
                    a[k] = 1. / (jw - l);
                  else if (model == ResidueModel::eq7)
                    a[k] = 1. / ((jw - l) * (jw - lb));
                  else
                    {
                      a[k] = 1. / (jw - l) + 1. / (jw - lb);
                      b[k] = std::complex<double>(0., 1.) / (jw - l) -
                             std::complex<double>(0., 1.) / (jw - lb);
                    }
                }
              columns.push_back(a);
              if (!pole.real && model == ResidueModel::general)
                columns.push_back(b);
            }
          first_column.push_back(columns.size());

          // Real least squares: rows Re then Im, columns scaled to unit norm.
          A.resize(2 * n_lines, columns.size());
          scale.resize(columns.size());
          for (std::size_t c = 0; c < columns.size(); ++c)
            {
              scale[c] = columns[c].norm();
              if (!(scale[c] > 0.))
                scale[c] = 1.;
              A.col(c).head(n_lines) = columns[c].real() / scale[c];
              A.col(c).tail(n_lines) = columns[c].imag() / scale[c];
            }
          data.resize(2 * n_lines);
          weights.resize(n_lines);
          for (unsigned int k = 0; k < n_lines; ++k)
            {
              data[k]           = frf.values[k + first_line].real();
              data[k + n_lines] = frf.values[k + first_line].imag();
              weights[k]        = (k == 0 || k + 1 == n_lines) ? 0.5 : 1.;
            }
          norm = 0.;
          for (unsigned int k = 0; k < n_lines; ++k)
            norm += weights[k] * std::abs(frf.values[k + first_line]);
        }

        unsigned int
        n_modes() const
        {
          return poles.size();
        }

        /// Least squares over all columns.
        Eigen::VectorXd
        solve_all() const
        {
          // Plain Householder QR: the scaled columns of distinct poles are
          // well apart; a column-pivoted (rank-revealing) QR takes over when a
          // diagonal of R says two of them nearly coincide.
          Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
          const auto                           &R   = qr.matrixQR();
          double                                top = 0., low = INFINITY;
          for (Eigen::Index i = 0; i < A.cols(); ++i)
            {
              top = std::max(top, std::abs(R(i, i)));
              low = std::min(low, std::abs(R(i, i)));
            }
          if (A.cols() == 0 || low > 1e-10 * top)
            return qr.solve(data);
          Eigen::ColPivHouseholderQR<Eigen::MatrixXd> pivoted(A);
          pivoted.setThreshold(1e-13);
          return pivoted.solve(data);
        }

        /// E of Eq. (50) of a fitted vector A x.
        double
        error(const Eigen::VectorXd &fitted) const
        {
          const unsigned int n_lines = weights.size();
          double             e       = 0.;
          for (unsigned int k = 0; k < n_lines; ++k)
            e +=
              weights[k] * std::hypot(data[k] - fitted[k], data[k + n_lines] - fitted[k + n_lines]);
          return e / norm;
        }

        /// L1 norm over the lines of the FRF of mode m with coefficients x.
        double
        contribution(const Eigen::VectorXd &x, unsigned int m) const
        {
          const unsigned int n_lines = weights.size();
          Eigen::VectorXd    part    = Eigen::VectorXd::Zero(2 * n_lines);
          for (unsigned int c = first_column[m]; c < first_column[m + 1]; ++c)
            part += A.col(c) * x[c];
          double sum = 0.;
          for (unsigned int k = 0; k < n_lines; ++k)
            sum += weights[k] * std::hypot(part[k], part[k + n_lines]);
          return sum;
        }

        /**
         * Fit the modes in @p order, prefix by prefix, from one QR: E for
         * each number of modes 0..M (coefficients_of() gives the fit).
         */
        std::vector<double>
        prefix_errors(const std::vector<unsigned int> &order) const
        {
          std::vector<unsigned int> columns;
          for (unsigned int c = 0; c < n_residual; ++c)
            columns.push_back(c);
          std::vector<unsigned int> boundary = {static_cast<unsigned int>(columns.size())};
          for (const unsigned int m : order)
            {
              for (unsigned int c = first_column[m]; c < first_column[m + 1]; ++c)
                columns.push_back(c);
              boundary.push_back(columns.size());
            }
          Eigen::MatrixXd P(A.rows(), columns.size());
          for (std::size_t c = 0; c < columns.size(); ++c)
            P.col(c) = A.col(columns[c]);
          Eigen::HouseholderQR<Eigen::MatrixXd> qr(P);
          triangle_        = qr.matrixQR().topRows(P.cols()).triangularView<Eigen::Upper>();
          qtb_             = (qr.householderQ().transpose() * data).head(P.cols());
          columns_         = columns;
          boundary_        = boundary;
          const double top = columns.empty() ? 1. : std::abs(triangle_(0, 0));

          // E of each prefix: its coefficients by back-substitution, its fit
          // from the prefix's columns alone.
          std::vector<double> errors(boundary.size(), INFINITY);
          for (std::size_t n = 0; n < boundary.size(); ++n)
            {
              const unsigned int m = boundary[n];
              if (m > 0 && !(std::abs(triangle_(m - 1, m - 1)) > 1e-12 * top))
                break; // a prefix with a dependent column, and all longer ones
              const Eigen::VectorXd y =
                triangle_.topLeftCorner(m, m).triangularView<Eigen::Upper>().solve(qtb_.head(m));
              errors[n] = error(P.leftCols(m) * y);
            }
          return errors;
        }

        /// The coefficients of prefix @p n of the last prefix_errors() call.
        Eigen::VectorXd
        coefficients_of(const std::size_t n) const
        {
          const unsigned int    m = boundary_[n];
          const Eigen::VectorXd y =
            triangle_.topLeftCorner(m, m).triangularView<Eigen::Upper>().solve(qtb_.head(m));
          Eigen::VectorXd x = Eigen::VectorXd::Zero(A.cols());
          for (unsigned int i = 0; i < m; ++i)
            x[columns_[i]] = y[i];
          return x;
        }

        /// The modal model of coefficients x for the modes in @p modes.
        modal::ModalModel
        model_of(const Eigen::VectorXd           &x,
                 const std::vector<unsigned int> &modes,
                 double                          &lower,
                 double                          &upper) const
        {
          lower = upper = 0.;
          for (unsigned int c = 0; c < n_residual; ++c)
            (residual_kind[c] == 0 ? lower : upper) = x[c] / scale[c];
          modal::ModalModel result;
          for (const unsigned int m : modes)
            {
              const Pole        &pole = poles[m];
              const unsigned int c    = first_column[m];
              if (pole.real)
                result.add_real(pole.lambda.real(), x[c] / scale[c]);
              else if (model == ResidueModel::eq7)
                // A / ((jw - l)(jw - conj l)): R = A / (l - conj l).
                result.add_pair(pole.lambda, x[c] / scale[c] /
                                               std::complex<double>(0., 2. * pole.lambda.imag()));
              else
                result.add_pair(pole.lambda, {x[c] / scale[c], x[c + 1] / scale[c + 1]});
            }
          return result;
        }

        double
        data_norm() const
        {
          return norm;
        }

      private:
        const base::FrequencyResponse &frf;
        std::vector<Pole>              poles;
        ResidueModel                   model;
        unsigned int                   first_line;
        std::size_t                    n_residual = 0;
        std::vector<int>               residual_kind;
        std::vector<unsigned int>      first_column;
        Eigen::MatrixXd                A;
        std::vector<double>            scale;
        Eigen::VectorXd                data;
        std::vector<double>            weights;
        double                         norm = 0.;
        // State of the last prefix_errors() call.
        mutable Eigen::MatrixXd           triangle_;
        mutable Eigen::VectorXd           qtb_;
        mutable std::vector<unsigned int> columns_, boundary_;
      };
    } // namespace internal
  }   // namespace modal
} // namespace greentread
