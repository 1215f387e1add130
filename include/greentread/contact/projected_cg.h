#pragma once

#include <greentread/contact/lcp.h>

#include <Eigen/Core>

#include <functional>
#include <string>

/**
 * @file
 * The contact's complementarity problem without its matrix: the LCP
 * \f$w = W z + q,\ z \ge 0,\ w \ge 0,\ z^T w = 0\f$ for a symmetric
 * positive definite W known only through its products, as the bound-
 * constrained quadratic programme \f$\min_{z \ge 0} \tfrac12 z^T W z + q^T z\f$
 * (its gradient is w). Implemented in source/contact/projected_cg.cc.
 *
 * **Algorithm: MPRGP** (modified proportioning with reduced gradient
 * projections; Dostál & Schöberl 2005, Dostál's "Optimal quadratic
 * programming algorithms", 2009, ch. 8). Conjugate gradients on the free
 * set (z_i > 0) while its gradient \f$\varphi\f$ dominates the chopped
 * gradient \f$\beta\f$ of the bound set (\f$\beta_i = \min(w_i, 0)\f$ at
 * z_i = 0): \f$\|\beta\|^2 \le \Gamma^2 \tilde\varphi^T\varphi\f$, Γ = 1,
 * \f$\tilde\varphi\f$ the free gradient reduced so that a step
 * \f$\bar\alpha\f$ stays feasible. A CG step that would leave the feasible
 * set becomes an expansion step: to the bound, then a projected gradient
 * step of fixed length \f$\bar\alpha = 1.9 / \|W\|_2\f$ (\f$\|W\|_2\f$ by
 * power iteration, once per matrix). Otherwise a proportioning step along
 * \f$\beta\f$ releases points from the bound. It converges for every SPD W
 * (R-linearly, at a rate set by W's spectral condition number), and is warm-
 * started from the last step's forces: a rolling tyre's contact changes
 * little from one step to the next. Each iteration costs one product with
 * W (two for an expansion step).
 *
 * **Convergence test.** With \f$s = \|q\|_\infty\f$ and the projected gradient
 * \f$\nu = \varphi + \beta\f$ (the part of w that violates the optimality
 * conditions: \f$w_i\f$ where z_i > 0, \f$\min(w_i, 0)\f$ where z_i = 0),
 * \f$\|\nu\|_\infty \le \tau s\f$, τ = ProjectedCgOptions::tolerance. So the
 * points in contact meet the road to τ s, the others are not inside it by
 * more than τ s, and no force is negative. The gradient is recomputed from
 * W z + q before it is accepted. LcpResult::residual is the natural-map
 * residual of lcp.h with m = \f$\|W\|_2\f$.
 */

namespace greentread
{
  namespace contact
  {
    /// y = W x for a symmetric positive definite W.
    using SymmetricOperator = std::function<void(const Eigen::VectorXd &x, Eigen::VectorXd &y)>;

    /// Settings of solve_lcp_projected_cg().
    struct ProjectedCgOptions
    {
      /// τ of the convergence test.
      double       tolerance      = 1e-10;
      unsigned int max_iterations = 20000;
      /// \f$\|W\|_2\f$ from operator_norm(); 0 computes it at every call.
      double operator_norm = 0.;
      /// s of the convergence test; 0: \f$\|q\|_\infty\f$ (a solve on part
      /// of a grid passes the whole grid's).
      double scale = 0.;
    };

    /**
     * @brief The checks every solve of an LCP by products makes on its input.
     * @throws NumericalError if @p q is not finite; InputError if @p start
     * is neither empty nor of q's size. @p who names the solver.
     */
    void
    check_lcp_input(const Eigen::VectorXd &q, const Eigen::VectorXd &start, const std::string &who);

    /**
     * @brief \f$\|W\|_2\f$ (W's largest eigenvalue) of an SPD operator on
     * vectors of size @p n, by power iteration to 1e-3, times 1.01.
     * @throws NumericalError if a product is not finite or not positive.
     */
    double
    operator_norm(const SymmetricOperator &W, unsigned int n);

    /**
     * @brief The LCP of the file documentation by MPRGP.
     * @param[in] W The operator; symmetric positive definite.
     * @param[in] q The vector q.
     * @param[in] start The warm start (negative entries are projected to 0);
     *            empty: from z = 0.
     * @return z, w = W z + q, the number of iterations (products with W), whether
     *         the convergence test was met, the residual; a failure (the
     *         iteration limit, or a curvature \f$p^T W p \le 0\f$: W is not
     *         positive definite) does not throw: the message says why.
     * @throws NumericalError if q is not finite or a product is not.
     */
    LcpResult
    solve_lcp_projected_cg(const SymmetricOperator  &W,
                           const Eigen::VectorXd    &q,
                           const Eigen::VectorXd    &start,
                           const ProjectedCgOptions &options = {});
  } // namespace contact
} // namespace greentread
