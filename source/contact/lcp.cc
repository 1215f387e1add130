#include <greentread/base/exceptions.h>
#include <greentread/contact/lcp.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace greentread
{
  namespace contact
  {
    namespace
    {
      /// Full exchanges allowed without a new lowest infeasible count
      /// before Murty's single exchanges take over (Judice & Pires: p = 3).
      constexpr unsigned int full_exchange_tries = 3;
    } // namespace



    double
    natural_residual(const Eigen::VectorXd &z,
                     const Eigen::VectorXd &w,
                     const double           m,
                     const double           s)
    {
      if (!(s > 0.))
        return 0.;
      double r = 0.;
      for (Eigen::Index i = 0; i < z.size(); ++i)
        r = std::max(r, std::abs(std::min(m * z[i], w[i])));
      return r / s;
    }



    double
    lcp_matrix_norm(const Eigen::MatrixXd &M)
    {
      if (!M.allFinite())
        throw NumericalError("solve_lcp: the matrix M contains NaN or inf");
      return M.rows() > 0 ? M.cwiseAbs().rowwise().sum().maxCoeff() : 0.;
    }



    LcpResult
    solve_lcp(const Eigen::MatrixXd &M,
              const Eigen::VectorXd &q,
              std::vector<bool>     &active,
              const LcpOptions      &options)
    {
      const Eigen::Index n = q.size();
      if (M.rows() != M.cols() || M.rows() != n)
        throw InputError("solve_lcp: M is " + std::to_string(M.rows()) + " x " +
                         std::to_string(M.cols()) + " and q has " + std::to_string(n) +
                         " entries; M must be square and match q");
      if (!active.empty() && active.size() != static_cast<std::size_t>(n))
        throw InputError("solve_lcp: the warm-start active set has " +
                         std::to_string(active.size()) + " entries, the problem " +
                         std::to_string(n) + "; it must be empty or match q");
      if (!(options.tolerance >= 0.) || !std::isfinite(options.tolerance))
        throw InputError("solve_lcp: tolerance = " + format_number(options.tolerance) +
                         "; allowed: a finite value >= 0");
      if (!(options.matrix_norm >= 0.) || !std::isfinite(options.matrix_norm))
        throw InputError("solve_lcp: matrix norm = " + format_number(options.matrix_norm) +
                         "; allowed: 0 (computed here) or the value of lcp_matrix_norm(M)");
      if (!q.allFinite())
        throw NumericalError("solve_lcp: the vector q contains NaN or inf");

      active.resize(n, false);

      LcpResult result;
      result.z = Eigen::VectorXd::Zero(n);
      result.w = q;
      if (n == 0)
        {
          result.converged = true;
          return result;
        }

      const double m       = options.matrix_norm > 0. ? options.matrix_norm : lcp_matrix_norm(M);
      const double q_norm  = q.lpNorm<Eigen::Infinity>();
      const double tau     = options.tolerance;
      const double epsilon = std::numeric_limits<double>::epsilon();

      Eigen::VectorXd           z(n), w(n);
      std::vector<Eigen::Index> set, infeasible;
      Eigen::MatrixXd           M_AA;
      Eigen::VectorXd           q_A, z_A;
      // w = M z + q from the columns where z is not zero.
      const auto product = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
        y = q;
        for (Eigen::Index j = 0; j < n; ++j)
          if (x[j] != 0.)
            y += x[j] * M.col(j);
      };

      unsigned int lowest_count = n + 1;
      unsigned int tries_left   = full_exchange_tries;
      double       scale        = q_norm;
      for (unsigned int iteration = 0;; ++iteration)
        {
          // Solve M_AA z_A = -q_A with z_F = 0.
          set.clear();
          for (Eigen::Index i = 0; i < n; ++i)
            if (active[i])
              set.push_back(i);
          const Eigen::Index k = set.size();
          z.setZero();
          if (k > 0)
            {
              M_AA.resize(k, k);
              q_A.resize(k);
              for (Eigen::Index b = 0; b < k; ++b)
                {
                  q_A[b] = q[set[b]];
                  for (Eigen::Index a = 0; a < k; ++a)
                    M_AA(a, b) = M(set[a], set[b]);
                }
              const Eigen::PartialPivLU<Eigen::MatrixXd> lu(M_AA);
              const double                               rcond = lu.rcond();
              z_A                                              = lu.solve(-q_A);
              if (!(rcond > epsilon) || !z_A.allFinite())
                {
                  result.iterations = iteration;
                  result.residual   = natural_residual(result.z, result.w, m, scale);
                  result.message    = "solve_lcp: the principal block M_AA of the " +
                                   std::to_string(k) + " active indices is singular " +
                                   "(reciprocal condition number " + format_short(rcond) +
                                   ") at iteration " + std::to_string(iteration) +
                                   ": M is not a P-matrix";
                  return result;
                }
              for (Eigen::Index b = 0; b < k; ++b)
                z[set[b]] = z_A[b];
            }
          product(z, w);
          scale    = std::max(q_norm, m * z.lpNorm<Eigen::Infinity>());
          result.z = z;
          result.w = w;

          // The convergence test of the file documentation.
          const double threshold = tau * scale;
          infeasible.clear();
          for (Eigen::Index i = 0; i < n; ++i)
            if (active[i] ? m * z[i] < -threshold : w[i] < -threshold)
              infeasible.push_back(i);

          if (infeasible.empty())
            {
              result.iterations = iteration;
              result.converged  = true;
              for (Eigen::Index i = 0; i < n; ++i)
                result.projected = std::max(result.projected, -m * z[i] / scale);
              result.z = z.cwiseMax(0.);
              product(result.z, result.w);
              scale           = std::max(q_norm, m * result.z.lpNorm<Eigen::Infinity>());
              result.residual = natural_residual(result.z, result.w, m, scale);
              return result;
            }

          if (iteration == options.max_iterations)
            {
              result.iterations = iteration;
              result.residual   = natural_residual(z, w, m, scale);
              result.message    = "solve_lcp: no solution after " + std::to_string(iteration) +
                               " principal pivoting iterations: residual " +
                               format_short(result.residual) + " (tolerance " + format_short(tau) +
                               "), " + std::to_string(infeasible.size()) +
                               " infeasible indices; M may not be a P-matrix, or raise the "
                               "iteration limit";
              return result;
            }

          // Exchange: all infeasible indices while their number keeps
          // reaching new lows (with a few tries of grace), else only the
          // largest one (Murty).
          if (infeasible.size() < lowest_count)
            {
              lowest_count = infeasible.size();
              tries_left   = full_exchange_tries;
              for (const Eigen::Index i : infeasible)
                active[i] = !active[i];
            }
          else if (tries_left > 0)
            {
              --tries_left;
              for (const Eigen::Index i : infeasible)
                active[i] = !active[i];
            }
          else
            active[infeasible.back()] = !active[infeasible.back()];
        }
    }
  } // namespace contact
} // namespace greentread
