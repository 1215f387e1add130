#include <greentread/base/exceptions.h>
#include <greentread/contact/candidate_set.h>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace contact
  {
    namespace
    {
      /// The candidate set is solved on while |N|^2 <= dense_limit n: its
      /// products cost |N|^2, the whole grid's FFT products about n log n.
      /// On the main job's 7680-point grid: |N| up to 700. A tread
      /// pattern's finite blocks, softer, bring up to 620 points into
      /// contact on road-A, and on the whole grid their step cost 10.4 ms
      /// against 7.8 on the set (benchmarks/tread_pattern); the runs of
      /// benchmarks/contact_solvers/contact_solvers.sh show both sides.
      constexpr double dense_limit = 64.;
    } // namespace



    LcpResult
    solve_lcp_candidate_set(const SymmetricOperator &W,
                            const OperatorBlock     &block,
                            const Eigen::VectorXd   &q,
                            const Eigen::VectorXd   &start,
                            ProjectedCgOptions       options,
                            CandidateSetReport      *report)
    {
      const Eigen::Index n = q.size();
      check_lcp_input(q, start, "candidate-set contact");
      if (options.operator_norm <= 0.)
        options.operator_norm = operator_norm(W, n);
      const double scale = options.scale > 0. ? options.scale : q.lpNorm<Eigen::Infinity>();
      const double tol   = options.tolerance * scale;
      options.scale      = scale;

      // The candidates, in the order they joined; M = W(set, set).
      std::vector<char>         in_set(n, 0);
      std::vector<unsigned int> set, joined;
      for (Eigen::Index i = 0; i < n; ++i)
        if (q[i] < 0.)
          {
            in_set[i] = 1;
            joined.push_back(i);
          }
      if (report != nullptr)
        *report = {unsigned(joined.size()), unsigned(joined.size()), false};
      Eigen::VectorXd z =
        start.size() == n ? Eigen::VectorXd(start.cwiseMax(0.)) : Eigen::VectorXd::Zero(n);
      LcpResult       result;
      unsigned int    products = 0;
      Eigen::MatrixXd M, back, corner;
      Eigen::VectorXd q_set, z_set, w(n);
      // |M|'s row sums: their largest bounds ||M||_2 (M is symmetric), and
      // on a few hundred candidates it is far below the whole grid's norm,
      // so the reduced solve takes longer projected steps.
      Eigen::VectorXd        row_sums;
      ProjectedCgOptions     reduced_options = options;
      constexpr unsigned int max_rounds      = 50;
      for (unsigned int round = 0; round < max_rounds; ++round)
        {
          const double size = set.size() + joined.size();
          if (2. * size > n || size * size > dense_limit * n)
            {
              // Too many candidates: the whole-grid solve is cheaper.
              if (report != nullptr)
                {
                  report->end        = set.size() + joined.size();
                  report->whole_grid = true;
                }
              result = solve_lcp_projected_cg(W, q, z, options);
              result.iterations += products;
              return result;
            }
          // The block grows by the new rows alone: M is symmetric, and only
          // its lower triangle is formed and read.
          const Eigen::Index old = set.size(), m = old + joined.size();
          if (!joined.empty())
            {
              block(joined, set, back);
              block(joined, joined, corner);
              M.conservativeResize(m, m);
              M.bottomLeftCorner(m - old, old)      = back;
              M.bottomRightCorner(m - old, m - old) = corner;
              row_sums.conservativeResize(m);
              row_sums.head(old) += back.cwiseAbs().colwise().sum().transpose();
              row_sums.tail(m - old) =
                back.cwiseAbs().rowwise().sum() + corner.cwiseAbs().rowwise().sum();
              reduced_options.operator_norm = std::min(options.operator_norm, row_sums.maxCoeff());
              set.insert(set.end(), joined.begin(), joined.end());
              joined.clear();
            }
          if (report != nullptr)
            report->end = m;
          if (m > 0)
            {
              q_set.resize(m);
              z_set.resize(m);
              for (Eigen::Index k = 0; k < m; ++k)
                {
                  q_set[k] = q[set[k]];
                  z_set[k] = z[set[k]];
                }
              const LcpResult reduced = solve_lcp_projected_cg(
                [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
                  y.noalias() = M.selfadjointView<Eigen::Lower>() * x;
                },
                q_set, z_set, reduced_options);
              products += reduced.iterations;
              z.setZero();
              for (Eigen::Index k = 0; k < m; ++k)
                z[set[k]] = reduced.z[k];
              if (!reduced.converged)
                {
                  W(z, w);
                  result.z          = z;
                  result.w          = w + q;
                  result.iterations = products + 1;
                  result.message =
                    "on " + std::to_string(m) + " candidate points: " + reduced.message;
                  return result;
                }
            }
          else
            z.setZero();
          // The whole grid's gaps.
          W(z, w);
          w += q;
          ++products;
          if (!w.allFinite())
            throw NumericalError("candidate-set contact: the product with the operator is "
                                 "not finite");
          for (Eigen::Index i = 0; i < n; ++i)
            if (!in_set[i] && w[i] < -tol)
              {
                in_set[i] = 1;
                joined.push_back(i);
              }
          if (!joined.empty())
            continue;
          result.z          = z;
          result.w          = w;
          result.iterations = products;
          result.converged  = true;
          // The natural-map residual of lcp.h, m = ||W||_2.
          const double norm = options.operator_norm;
          result.residual =
            natural_residual(z, w, norm, std::max(scale, norm * z.lpNorm<Eigen::Infinity>()));
          return result;
        }
      W(z, w);
      result.w          = w + q;
      result.iterations = products + 1;
      result.z          = z;
      result.message    = "the candidate set still grew after " + std::to_string(max_rounds) +
                       " rounds (" + std::to_string(set.size()) + " points)";
      return result;
    }
  } // namespace contact
} // namespace greentread
