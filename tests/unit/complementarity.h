#pragma once

// The complementarity of an LCP's solution measured by a test from the
// problem's data, not taken from the solver's own residual.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace test
{
  /// The complementarity of a returned z, measured here and not by the solver:
  /// w = M z + q is formed again from M, q and z.
  struct Complementarity
  {
    /// min_i w_i / s: how far the gap goes below zero (0 or more: none).
    double gap = 0.;
    /// max_i |min(m z_i, w_i)| / s, the natural-map residual of lcp.h.
    double natural = 0.;
    /// |z^T w| / (|z|_1 s): the complementarity product, a mean of |w_i| / s
    /// weighted by z_i.
    double product = 0.;
  };

  /// The measures of Complementarity with m = ||M||_inf and
  /// s = max(||q||_inf, m ||z||_inf), the units of lcp.h's tolerance.
  inline Complementarity
  complementarity(const Eigen::MatrixXd &M, const Eigen::VectorXd &q, const Eigen::VectorXd &z)
  {
    const Eigen::VectorXd w = M * z + q;
    const double          m = M.cwiseAbs().rowwise().sum().maxCoeff();
    const double          s =
      std::max({q.lpNorm<Eigen::Infinity>(), m * z.lpNorm<Eigen::Infinity>(), 1e-300});
    Complementarity c;
    c.gap = w.minCoeff() / s;
    for (Eigen::Index i = 0; i < z.size(); ++i)
      c.natural = std::max(c.natural, std::abs(std::min(m * z[i], w[i])) / s);
    const double z_1 = z.lpNorm<1>();
    c.product        = z_1 > 0. ? std::abs(z.dot(w)) / (z_1 * s) : 0.;
    return c;
  }
} // namespace test
