#include <greentread/base/exceptions.h>
#include <greentread/modal/patch_model.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace greentread
{
  namespace modal
  {
    modal::ModalModel
    PatchModel::pair_model(const unsigned int i, const unsigned int j) const
    {
      modal::ModalModel m;
      for (unsigned int k = 0; k < n_terms(); ++k)
        if (real[k])
          m.add_real(lambda[k].real(), residue(k, i, j).real());
        else
          m.add_pair(lambda[k], residue(k, i, j));
      return m;
    }



    std::complex<double>
    PatchModel::frequency_response(const unsigned int i,
                                   const unsigned int j,
                                   const double       omega) const
    {
      const std::complex<double> jw(0., omega);
      std::complex<double>       g = instantaneous.size() ? instantaneous(i, j) : 0.;
      for (unsigned int k = 0; k < n_terms(); ++k)
        {
          const std::complex<double> r = residue(k, i, j);
          if (real[k])
            g += r.real() / (jw - lambda[k].real());
          else
            g += r / (jw - lambda[k]) + std::conj(r) / (jw - std::conj(lambda[k]));
        }
      return g;
    }



    std::vector<Eigen::MatrixXd>
    shape_sums(const Eigen::MatrixXd                                          &A,
               const Eigen::MatrixXd                                          &B,
               const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> &weights)
    {
      // Each sum is symmetric: only its lower triangle is computed (Eigen's
      // triangular product, half the work of a full one), then mirrored.
      // With complex shapes it is A^T (W1 A + W2 B) + B^T (W2 A - W1 B), two
      // such products instead of three full ones. The shapes are taken a
      // chunk of rows at a time, every sum from the same chunk while it is
      // in cache, and the weighted shapes formed in a buffer of a chunk:
      // formed whole they were tens of megabytes per sum, allocated,
      // written and read again at every line of the synthesis.
      constexpr Eigen::Index       chunk = 512;
      const Eigen::Index           m = A.rows(), n = A.cols();
      std::vector<Eigen::MatrixXd> sums(weights.size(), Eigen::MatrixXd::Zero(n, n));
      Eigen::MatrixXd              X(std::min(chunk, m), n);
      for (Eigen::Index r = 0; r < m; r += chunk)
        {
          const Eigen::Index len = std::min(chunk, m - r);
          auto               Xc  = X.topRows(len);
          const auto         Ac  = A.middleRows(r, len);
          for (std::size_t s = 0; s < weights.size(); ++s)
            {
              auto      &sum = sums[s];
              const auto v1  = weights[s].first.segment(r, len).asDiagonal();
              if (B.size() == 0)
                {
                  Xc.noalias() = v1 * Ac;
                  sum.triangularView<Eigen::Lower>() += Ac.transpose() * Xc;
                  continue;
                }
              const auto Bc = B.middleRows(r, len);
              const auto v2 = weights[s].second.segment(r, len).asDiagonal();
              Xc.noalias()  = v1 * Ac;
              Xc.noalias() += v2 * Bc;
              sum.triangularView<Eigen::Lower>() += Ac.transpose() * Xc;
              Xc.noalias() = v2 * Ac;
              Xc.noalias() -= v1 * Bc;
              sum.triangularView<Eigen::Lower>() += Bc.transpose() * Xc;
            }
        }
      for (auto &sum : sums)
        sum = sum.selfadjointView<Eigen::Lower>();
      return sums;
    }



    Eigen::MatrixXd
    shape_sum(const Eigen::MatrixXd &A,
              const Eigen::MatrixXd &B,
              const Eigen::VectorXd &w1,
              const Eigen::VectorXd &w2)
    {
      return shape_sums(A, B, {{w1, w2}}).front();
    }



    Eigen::MatrixXd
    PatchModel::static_compliance() const
    {
      const unsigned int n = n_points();
      Eigen::MatrixXd    g = instantaneous.size() ? instantaneous : Eigen::MatrixXd::Zero(n, n);
      if (is_rank_one())
        {
          // Re(s c_k / lambda_k phi_k phi_k^T), s = 1 for a real pole, 2 for a pair.
          Eigen::VectorXd re(n_terms()), im(n_terms());
          for (unsigned int k = 0; k < n_terms(); ++k)
            {
              const std::complex<double> e = (real[k] ? 1. : 2.) * factor[k] / lambda[k];
              re(k)                        = e.real();
              im(k)                        = -e.imag();
            }
          g -= shape_sum(shapes, shapes_imag, re, im);
          return g;
        }
      for (unsigned int k = 0; k < n_terms(); ++k)
        if (real[k])
          g -= residues[k].real() / lambda[k].real();
        else
          g -= 2. * (residues[k].array() / lambda[k]).real().matrix();
      return g;
    }



    namespace
    {
      /**
       * The functions LSCE finds the poles on, which see the modes from
       * different places: the summed driving points, the total response to
       * a uniform pressure, and @p n_references transfers from the point
       * nearest the centre to points spread over the patch.
       */
      std::vector<base::FrequencyResponse>
      reference_functions(const base::FrequencyResponseMatrix &green,
                          const unsigned int                   n_references)
      {
        const unsigned int n       = green.n_points();
        const unsigned int n_lines = green.n_lines;
        const auto         summed  = [&](const auto &take) {
          base::FrequencyResponse frf;
          frf.df = green.df;
          frf.values.assign(n_lines, 0.);
          for (unsigned int k = 0; k < n_lines; ++k)
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                if (take(i, j))
                  frf.values[k] += green.values[(std::size_t(k) * n + i) * n + j];
          return frf;
        };
        std::vector<base::FrequencyResponse> sources;
        sources.push_back(summed([](unsigned int i, unsigned int j) {
          return i == j;
        }));
        sources.push_back(summed([](unsigned int, unsigned int) {
          return true;
        }));
        std::array<double, 3> centre{{0., 0., 0.}};
        for (const auto &p : green.points)
          for (unsigned int d = 0; d < 3; ++d)
            centre[d] += p[d] / n;
        unsigned int c    = 0;
        double       best = INFINITY;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double d =
              std::hypot(green.points[i][0] - centre[0], green.points[i][1] - centre[1]);
            if (d < best)
              best = d, c = i;
          }
        const unsigned int n_transfers = std::min(n_references, n - 1);
        for (unsigned int s = 1; s <= n_transfers; ++s)
          sources.push_back(green.get(c, (c + s * n / (n_transfers + 1)) % n));
        return sources;
      }



      /**
       * The poles of @p model: those LSCE finds on @p sources, merged when
       * closer than the tolerance, then the residual term's choice: with an
       * instantaneous residual, the poles above the band are dropped (G_r
       * carries what they would imitate); otherwise a real residual pole is
       * added. @return The worst E of the identifications.
       */
      double
      find_poles(PatchModel                                 &model,
                 const std::vector<base::FrequencyResponse> &sources,
                 const IdentificationParameters             &identification,
                 const PatchModelParameters                 &parameters)
      {
        IdentificationParameters poles_only = identification;
        poles_only.upper_residual           = true;
        poles_only.compare_models           = false;
        // LSCE's poles as found: refined poles of different reference
        // functions can land within a residue column of each other, and
        // the patch model's shared least squares then loses rank.
        poles_only.polish_poles = false;
        double worst_error      = 0.;
        for (const auto &frf : sources)
          {
            const Identification found = identify(frf, poles_only);
            worst_error                = std::max(worst_error, found.error);
            for (const auto &term : found.model.terms())
              {
                // A double pole (critical damping) is carried by one real pole.
                const bool                 real = term.kind != modal::ModalTerm::Kind::complex_pair;
                const std::complex<double> l =
                  real ? std::complex<double>(term.lambda.real(), 0.) : term.lambda;
                bool known = false;
                for (unsigned int t = 0; t < model.lambda.size(); ++t)
                  if (model.real[t] == real &&
                      std::abs(model.lambda[t] - l) < parameters.pole_merge_tolerance * std::abs(l))
                    known = true;
                if (!known)
                  {
                    model.lambda.push_back(l);
                    model.real.push_back(real);
                  }
              }
          }
        model.identified_modes = model.lambda.size();
        if (parameters.instantaneous_residual)
          {
            for (unsigned int t = model.lambda.size(); t-- > 0;)
              if (model.real[t] || std::abs(model.lambda[t].imag()) > 2. * M_PI * model.f_max)
                {
                  model.lambda.erase(model.lambda.begin() + t);
                  model.real.erase(model.real.begin() + t);
                }
            model.identified_modes = model.lambda.size();
          }
        else if (parameters.residual_pole_factor > 0.)
          {
            model.lambda.emplace_back(-2. * M_PI * parameters.residual_pole_factor * model.f_max,
                                      0.);
            model.real.push_back(true);
          }
        if (model.lambda.empty())
          throw NumericalError("patch model: the identification of the summed driving points "
                               "found no stable pole; raise 'Identification/Maximum number of "
                               "modes' or set 'Patch model/Residual pole factor' > 0");
        return worst_error;
      }



      /**
       * The linear least squares of the residues, all pairs as right-hand
       * sides. Rows: Re and Im of every line (the 0 Hz line weighted).
       * Columns: one per real pole, two per pair (Re and Im of R), and one
       * for the constant G_r.
       */
      struct ResidueSystem
      {
        unsigned int              n, n_lines;
        std::size_t               n_pairs;
        Eigen::VectorXd           row_weight;
        Eigen::MatrixXd           data, A;
        std::vector<unsigned int> first_column;
        unsigned int              n_modal_columns = 0;
        /// The columns used: all with a real residual pole; with an
        /// instantaneous one, only Im R of each pair (R = j b: a mode
        /// 2 Re(j b e^{lambda t}) = -2 b e^{sigma t} sin(omega_d t), which
        /// starts from rest) and the constant.
        std::vector<Eigen::Index> used;

        ResidueSystem(const base::FrequencyResponseMatrix &green,
                      const PatchModel                    &model,
                      const PatchModelParameters          &parameters)
            : n(green.n_points())
            , n_lines(green.n_lines)
            , n_pairs(std::size_t(n) * n)
            , row_weight(n_lines)
            , data(2 * n_lines, n_pairs)
        {
          for (unsigned int k = 0; k < n_lines; ++k)
            row_weight[k] = (k == 0) ? parameters.static_weight : 1.;
          for (unsigned int k = 0; k < n_lines; ++k)
            for (std::size_t p = 0; p < n_pairs; ++p)
              {
                const std::complex<double> g = green.values[std::size_t(k) * n_pairs + p];
                data(k, p)                   = g.real();
                data(k + n_lines, p)         = g.imag();
              }
          for (unsigned int t = 0; t < model.n_terms(); ++t)
            {
              first_column.push_back(n_modal_columns);
              n_modal_columns += model.real[t] ? 1 : 2;
            }
          A.resize(2 * n_lines, n_modal_columns + 1);
          for (unsigned int k = 0; k < n_lines; ++k)
            {
              const std::complex<double> jw(0., 2. * M_PI * k * green.df);
              for (unsigned int t = 0; t < model.n_terms(); ++t)
                {
                  const std::complex<double> l = model.lambda[t];
                  const unsigned int         c = first_column[t];
                  if (model.real[t])
                    {
                      const std::complex<double> a = 1. / (jw - l.real());
                      A(k, c)                      = a.real();
                      A(k + n_lines, c)            = a.imag();
                    }
                  else
                    {
                      const std::complex<double> I(0., 1.);
                      const std::complex<double> a = 1. / (jw - l) + 1. / (jw - std::conj(l));
                      const std::complex<double> b = I / (jw - l) - I / (jw - std::conj(l));
                      A(k, c)                      = a.real();
                      A(k + n_lines, c)            = a.imag();
                      A(k, c + 1)                  = b.real();
                      A(k + n_lines, c + 1)        = b.imag();
                    }
                }
              A(k, n_modal_columns)           = 1.;
              A(k + n_lines, n_modal_columns) = 0.;
            }
          for (unsigned int t = 0; t < model.n_terms(); ++t)
            {
              if (!parameters.instantaneous_residual)
                used.push_back(first_column[t]);
              if (!model.real[t])
                used.push_back(first_column[t] + 1);
            }
        }

        /// The used coefficients (and G_r if @p with_constant) fitting
        /// @p rhs, in physical units, zero where unused.
        Eigen::MatrixXd
        solve(const bool with_constant, const Eigen::MatrixXd &rhs) const
        {
          std::vector<Eigen::Index> columns = used;
          if (with_constant)
            columns.push_back(n_modal_columns);
          const Eigen::Index n_used = columns.size();
          Eigen::MatrixXd    WA(A.rows(), n_used);
          for (Eigen::Index c = 0; c < n_used; ++c)
            WA.col(c) = A.col(columns[c]);
          Eigen::MatrixXd WB = rhs;
          for (unsigned int k = 0; k < n_lines; ++k)
            {
              WA.row(k) *= row_weight[k];
              WA.row(k + n_lines) *= row_weight[k];
              WB.row(k) *= row_weight[k];
              WB.row(k + n_lines) *= row_weight[k];
            }
          Eigen::VectorXd scale(n_used);
          for (Eigen::Index c = 0; c < n_used; ++c)
            {
              scale[c] = WA.col(c).norm();
              WA.col(c) /= scale[c];
            }
          Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(WA);
          qr.setThreshold(1e-12);
          if (qr.rank() < n_used)
            throw NumericalError(
              "patch model: the residue least-squares problem is rank deficient (rank " +
              std::to_string(qr.rank()) + " of " + std::to_string(n_used) +
              " columns): two poles nearly coincide; lower 'Identification/Maximum number of "
              "modes'");
          const Eigen::MatrixXd Y = qr.solve(WB);
          Eigen::MatrixXd       X = Eigen::MatrixXd::Zero(n_modal_columns + 1, rhs.cols());
          for (Eigen::Index c = 0; c < n_used; ++c)
            X.row(columns[c]) = Y.row(c) / scale[c];
          return X;
        }
      };



      /// The nearest positive semi-definite matrix to the symmetric part of
      /// @p a, with eigenvalues at least @p floor times the largest.
      Eigen::MatrixXd
      positive_part(const Eigen::MatrixXd &a, const double floor)
      {
        const Eigen::MatrixXd                          sym = 0.5 * (a + a.transpose());
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sym);
        const double top = std::max(eig.eigenvalues().maxCoeff(), 0.);
        return Eigen::MatrixXd(eig.eigenvectors() *
                               eig.eigenvalues().cwiseMax(floor * top).asDiagonal() *
                               eig.eigenvectors().transpose());
      }



      /**
       * The coefficients with an instantaneous residual: residues purely
       * imaginary (R_k = j b_k, the phi phi^T / (2 j m omega_d) of a mode
       * with proportional damping) and G_r symmetric positive definite,
       * stored in @p model.instantaneous and in the returned coefficients.
       * Measured on the default tyre, all at 600 N on a flat road from the
       * static equilibrium:
       * - complex residues fitted freely (E 1.5% median): the contact of the
       *   patch, force = G^{-1} u, grows by 1.4 per step at dt = 27.65 us,
       *   and at every dt from 10 us to 1 ms;
       * - each b_k also projected onto the semi-definite cone: E above 100%
       *   (the free b_k are far from definite);
       * - imaginary residues: E 6% median, 0.8% at worst on the driving
       *   points, and the contact stays at equilibrium, and bounded under a
       *   2 kHz excitation, for dt from 10 us to 1 ms.
       */
      Eigen::MatrixXd
      fit_with_instantaneous(PatchModel &model, const ResidueSystem &system)
      {
        const unsigned int n   = system.n;
        Eigen::MatrixXd    X   = system.solve(true, system.data);
        const Eigen::Index row = system.n_modal_columns;
        Eigen::MatrixXd    m(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            m(i, j) = X(row, std::size_t(i) * n + j);
        model.instantaneous = positive_part(m, 1e-3);
        if (!(model.instantaneous.trace() > 0.))
          throw NumericalError("patch model: the fitted instantaneous compliance G_r has no "
                               "positive eigenvalue: the Green's functions show no local "
                               "compliance; use 'Patch model/Residual flexibility = real "
                               "pole'");
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            X(row, std::size_t(i) * n + j) = model.instantaneous(i, j);
        return X;
      }



      /// The residues of @p model from the coefficients @p X.
      void
      set_residues(PatchModel &model, const ResidueSystem &system, const Eigen::MatrixXd &X)
      {
        const unsigned int n = system.n;
        model.residues.assign(model.n_terms(), Eigen::MatrixXcd::Zero(n, n));
        for (unsigned int t = 0; t < model.n_terms(); ++t)
          {
            const unsigned int c = system.first_column[t];
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                {
                  const std::size_t p = std::size_t(i) * n + j;
                  if (model.real[t])
                    model.residues[t](i, j) = X(c, p);
                  else
                    model.residues[t](i, j) = {X(c, p), X(c + 1, p)};
                }
          }
      }



      /// E of Eq. (50) for every pair, with the trapezoidal weights of the
      /// identification (half weight on the first and last line).
      void
      set_errors(PatchModel &model, const ResidueSystem &system, const Eigen::MatrixXd &X)
      {
        const unsigned int    n = system.n, n_lines = system.n_lines;
        const Eigen::MatrixXd fitted = system.A * X;
        model.errors.resize(n, n);
        for (std::size_t p = 0; p < system.n_pairs; ++p)
          {
            double e = 0., norm = 0.;
            for (unsigned int k = 0; k < n_lines; ++k)
              {
                const double w  = (k == 0 || k + 1 == n_lines) ? 0.5 : 1.;
                const double gr = system.data(k, p), gi = system.data(k + n_lines, p);
                e += w * std::hypot(gr - fitted(k, p), gi - fitted(k + n_lines, p));
                norm += w * std::hypot(gr, gi);
              }
            model.errors(p / n, p % n) = norm > 0. ? e / norm : 0.;
            if (!std::isfinite(model.errors(p / n, p % n)))
              throw NumericalError("patch model: the fit of pair " + std::to_string(p / n) + ":" +
                                   std::to_string(p % n) + " is not finite");
          }
      }
    } // namespace



    PatchModel
    fit_patch_model(const base::FrequencyResponseMatrix &green,
                    const IdentificationParameters      &identification,
                    const PatchModelParameters          &parameters,
                    const bool                           show_progress)
    {
      const unsigned int n       = green.n_points();
      const unsigned int n_lines = green.n_lines;
      if (n == 0 || n_lines < 4)
        throw InputError("patch model: the Green's functions have " + std::to_string(n) +
                         " points and " + std::to_string(n_lines) +
                         " lines; at least 1 point and 4 lines are needed");
      // 1. The poles.
      const auto sources = reference_functions(green, parameters.reference_transfers);
      PatchModel model;
      model.points    = green.points;
      model.f_max     = green.df * (n_lines - 1);
      model.sum_error = find_poles(model, sources, identification, parameters);
      // 2. The residues (and G_r) by linear least squares.
      const ResidueSystem   system(green, model, parameters);
      const Eigen::MatrixXd X = parameters.instantaneous_residual ?
                                  fit_with_instantaneous(model, system) :
                                  system.solve(false, system.data);
      set_residues(model, system, X);
      // 3. The error of every pair.
      set_errors(model, system, X);
      if (show_progress)
        std::cout << "  patch model: " << model.n_terms() << " poles (" << model.identified_modes
                  << " identified by LSCE on " << sources.size()
                  << " reference functions, worst E there " << format_short(100. * model.sum_error)
                  << "%), residues of " << system.n_pairs << " pairs" << std::endl;
      return model;
    }
  } // namespace modal
} // namespace greentread
