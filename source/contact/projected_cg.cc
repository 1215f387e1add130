#include <greentread/base/exceptions.h>
#include <greentread/contact/projected_cg.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace greentread
{
  namespace contact
  {
    double
    operator_norm(const SymmetricOperator &W, const unsigned int n)
    {
      // A start with every component: no eigenvector is missed but by accident.
      Eigen::VectorXd x(n), y(n);
      for (unsigned int i = 0; i < n; ++i)
        x[i] = 1. + 0.5 * std::sin(1.7 * i + 0.3);
      x.normalize();
      double lambda = 0.;
      for (unsigned int k = 0; k < 500; ++k)
        {
          W(x, y);
          const double next = x.dot(y);
          if (!y.allFinite() || !(next > 0.))
            throw NumericalError("projected CG: the operator's product is not finite or not "
                                 "positive (x^T W x = " +
                                 format_short(next) + "): it is not symmetric positive definite");
          const bool done = k > 5 && std::abs(next - lambda) <= 1e-3 * next;
          lambda          = next;
          if (done)
            break;
          x = y / y.norm();
        }
      return 1.01 * lambda;
    }



    void
    check_lcp_input(const Eigen::VectorXd &q, const Eigen::VectorXd &start, const std::string &who)
    {
      if (!q.allFinite())
        throw NumericalError(who + ": q is not finite");
      if (start.size() != 0 && start.size() != q.size())
        throw InputError(who + ": a warm start of " + std::to_string(start.size()) +
                         " values for " + std::to_string(q.size()) + " unknowns");
    }



    LcpResult
    solve_lcp_projected_cg(const SymmetricOperator  &W,
                           const Eigen::VectorXd    &q,
                           const Eigen::VectorXd    &start,
                           const ProjectedCgOptions &options)
    {
      const Eigen::Index n = q.size();
      check_lcp_input(q, start, "projected CG");
      const double norm  = options.operator_norm > 0. ? options.operator_norm : operator_norm(W, n);
      const double alpha = 1.9 / norm;
      const double scale = options.scale > 0. ? options.scale : q.lpNorm<Eigen::Infinity>();
      const double tol   = options.tolerance * scale;

      LcpResult        result;
      Eigen::VectorXd &z = result.z, &g = result.w;
      z = start.size() == n ? Eigen::VectorXd(start.cwiseMax(0.)) : Eigen::VectorXd::Zero(n);
      Eigen::VectorXd Ap(n), p(n), phi(n), beta(n);
      const auto      gradient = [&] {
        W(z, g);
        g += q;
        if (!g.allFinite())
          throw NumericalError("projected CG: the product with the operator is not finite");
      };
      // phi: the free gradient; beta: the chopped one; the return: the
      // projected gradient's largest absolute entry (for the test).
      const auto split = [&] {
        double largest = 0.;
        for (Eigen::Index i = 0; i < n; ++i)
          {
            const bool free = z[i] > 0.;
            phi[i]          = free ? g[i] : 0.;
            beta[i]         = free ? 0. : std::min(g[i], 0.);
            largest         = std::max(largest, std::abs(phi[i] + beta[i]));
          }
        return largest;
      };
      const auto reduced_dot = [&] {
        double s = 0.;
        for (Eigen::Index i = 0; i < n; ++i)
          if (z[i] > 0.)
            s += std::min(z[i] / alpha, phi[i]) * phi[i];
        return s;
      };
      gradient();
      double residual = split();
      p               = phi;
      unsigned int k  = 0;
      for (; k < options.max_iterations; ++k)
        {
          if (residual <= tol)
            {
              // Accept on the gradient recomputed from z, not the updated one.
              gradient();
              residual = split();
              if (residual <= tol)
                break;
              p = phi;
            }
          if (beta.squaredNorm() <= reduced_dot())
            {
              W(p, Ap);
              const double curvature = p.dot(Ap);
              if (!(curvature > 0.))
                {
                  result.message = "the curvature p^T W p = " + format_short(curvature) +
                                   " is not positive: the operator is not positive definite";
                  break;
                }
              const double step     = g.dot(p) / curvature;
              double       feasible = std::numeric_limits<double>::infinity();
              for (Eigen::Index i = 0; i < n; ++i)
                if (p[i] > 0.)
                  feasible = std::min(feasible, z[i] / p[i]);
              if (step <= feasible)
                {
                  // Conjugate gradient step.
                  z -= step * p;
                  g -= step * Ap;
                  residual = split();
                  p        = phi - (phi.dot(Ap) / curvature) * p;
                }
              else
                {
                  // Expansion step: to the bound, then a projected gradient step.
                  z -= feasible * p;
                  g -= feasible * Ap;
                  split();
                  z = (z - alpha * phi).cwiseMax(0.);
                  gradient();
                  residual = split();
                  p        = phi;
                }
            }
          else
            {
              // Proportioning step: release points from the bound.
              W(beta, Ap);
              const double curvature = beta.dot(Ap);
              if (!(curvature > 0.))
                {
                  result.message = "the curvature b^T W b = " + format_short(curvature) +
                                   " is not positive: the operator is not positive definite";
                  break;
                }
              const double step = g.dot(beta) / curvature;
              z -= step * beta;
              g -= step * Ap;
              residual = split();
              p        = phi;
            }
        }
      result.iterations = k;
      result.converged  = residual <= tol && result.message.empty();
      if (!result.converged && result.message.empty())
        result.message = "projected CG: " + std::to_string(options.max_iterations) +
                         " iterations reached, projected gradient " + format_short(residual) +
                         " against " + format_short(tol) + " asked";
      // The natural-map residual of lcp.h, m = ||W||_2.
      result.residual =
        natural_residual(z, g, norm, std::max(scale, norm * z.lpNorm<Eigen::Infinity>()));
      return result;
    }
  } // namespace contact
} // namespace greentread
