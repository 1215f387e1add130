#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

/**
 * @file
 * A dense linear complementarity problem (LCP) solver: find z with
 * \f[
 *   w = M z + q, \qquad z \ge 0, \qquad w \ge 0, \qquad z^T w = 0
 * \f]
 * for a square M. In GreenTread M is a P-matrix (every principal minor
 * positive: here diagonally dominant with a positive diagonal, not
 * necessarily symmetric), for which the solution exists and is unique for
 * every q.
 *
 * **Algorithm: block principal pivoting** (Judice & Pires 1994, after
 * Kostreva 1978). The unknowns are split into an active set A, where
 * \f$w_A = 0\f$ and \f$z_A\f$ is solved for, and its complement F, where
 * \f$z_F = 0\f$:
 * \f[
 *   M_{AA} z_A = -q_A, \qquad w_F = q_F + M_{FA} z_A,
 * \f]
 * with an LU factorisation (Eigen::PartialPivLU) of the block. The indices
 * of A with \f$z_i < 0\f$ and of F with \f$w_i < 0\f$ (to within the
 * tolerance below) are infeasible. While their number decreases, all of
 * them switch set at once. After three exchanges in a row that do not bring
 * it below its lowest value so far, only the largest infeasible index
 * switches (Murty's least-index rule with the order reversed), until the
 * number drops below that lowest value again. Murty's rule terminates for
 * every P-matrix, so the whole method does; the block exchanges make it fast
 * on the diagonally dominant and the symmetric positive definite matrices of
 * contact (at most 4 iterations from a cold start up to n = 60 in the unit
 * tests, none from the right active set). On strongly nonsymmetric
 * P-matrices the block exchanges stall and Murty's rule, finite but
 * exponential in the worst case, takes over: hundreds of iterations at
 * n = 60 (positive definite, skew part as large as the symmetric one), more
 * than the default limit.
 *
 * **Convergence test.** With \f$m = \|M\|_\infty\f$ (largest absolute row
 * sum) and the scale
 * \f[
 *   s = \max\left(\|q\|_\infty,\; m \|z\|_\infty\right)
 * \f]
 * of the current iterate, the iterate is accepted when
 * \f[
 *   m z_i \ge -\tau s \quad (i \in A), \qquad w_i \ge -\tau s \quad (i \in F),
 * \f]
 * where \f$\tau\f$ is LcpOptions::tolerance: z is measured in units of w
 * through m, so the test does not depend on the units of z and w, nor on a
 * common scaling of M or of q. Then the small negative \f$z_i\f$ are set to
 * 0 and \f$w = M z + q\f$ is recomputed.
 *
 * **Residual.** LcpResult::residual is the natural-map residual of the
 * returned pair, in the same units:
 * \f[
 *   r = \max_i \left|\min(m z_i,\; w_i)\right| / s ,
 * \f]
 * which bounds \f$\max(m z_i^-, w_i^-)\f$ (the sign violations) and
 * measures complementarity (\f$\min(m z_i, w_i)\f$ is zero exactly when
 * \f$z_i, w_i \ge 0\f$ and \f$z_i w_i = 0\f$); r = 0 if s = 0. After
 * convergence \f$r \le 2\tau\f$ plus the round-off of the block solve,
 * about \f$\mathrm{cond}(M_{AA})\,\varepsilon\f$.
 *
 * **Cost.** One LU factorisation of the active block per iteration, and
 * \f$w = q + M_{\cdot A} z_A\f$ from the active columns only: a warm-started
 * solve on n points of which k are in contact costs \f$O(k^3 + nk)\f$
 * besides one pass over M for its norm, which LcpOptions::matrix_norm saves
 * when M does not change between solves.
 */

namespace greentread
{
  namespace contact
  {
    /// Settings of solve_lcp().
    struct LcpOptions
    {
      /// Maximum number of principal pivoting iterations (set exchanges).
      unsigned int max_iterations = 200;
      /// Relative tolerance \f$\tau\f$ of the sign conditions, see the file
      /// documentation.
      double tolerance = 1e-10;
      /// \f$m = \|M\|_\infty\f$ from lcp_matrix_norm(), for a matrix solved
      /// many times (the contact of a rolling run): 0 computes it, and checks
      /// M for NaN and inf, at every call, a full pass over M.
      double matrix_norm = 0.;
    };

    /**
     * @brief \f$\|M\|_\infty\f$, the largest absolute row sum.
     * @throws NumericalError if M contains NaN or inf.
     */
    double
    lcp_matrix_norm(const Eigen::MatrixXd &M);

    /// The outcome of solve_lcp().
    struct LcpResult
    {
      /// The solution (on failure: the last iterate whose block could be
      /// solved, 0 if none).
      Eigen::VectorXd z;
      /// w = M z + q for the returned z.
      Eigen::VectorXd w;
      /// Number of set exchanges: 0 if the warm start was already right.
      unsigned int iterations = 0;
      /// Whether the convergence test was met.
      bool converged = false;
      /// Natural-map residual \f$\max_i|\min(m z_i, w_i)|/s\f$ of (z, w),
      /// see the file documentation.
      double residual = 0.;
      /// What the projection of a converged iterate removed:
      /// \f$\max_i m z_i^- / s\f$ before its small negative entries were set
      /// to 0 (at most the tolerance \f$\tau\f$ by the convergence test; 0
      /// for projected CG, whose iterates never leave z >= 0).
      double projected = 0.;
      /// Why the solve failed; empty on success.
      std::string message;
    };

    /// The natural-map residual \f$\max_i|\min(m z_i, w_i)|/s\f$ of the file
    /// documentation, for the given m and scale s (0 if s is not positive).
    double
    natural_residual(const Eigen::VectorXd &z, const Eigen::VectorXd &w, double m, double s);

    /**
     * @brief Solve the LCP \f$w = M z + q,\ z \ge 0,\ w \ge 0,\ z^T w = 0\f$
     * by block principal pivoting with Murty's rule as a fallback.
     *
     * @param[in] M       Dense square matrix, n x n; a P-matrix for the
     *                    solution to exist, be unique and be found.
     * @param[in] q       Vector of size n.
     * @param[in,out] active Warm start: the indices expected to have
     *                    z > 0. Either empty (no index active) or of size n.
     *                    On return, of size n: the final active set A (the
     *                    indices whose z was solved for; z may be 0 there in
     *                    a degenerate problem). Pass it to the next solve of
     *                    a similar problem.
     * @param[in] options Iteration limit and tolerance.
     * @return z, w, the iteration count and residual. A failure does not
     * throw: LcpResult::converged is false and LcpResult::message says why
     * (the iteration limit, with the residual reached, or a singular block
     * \f$M_{AA}\f$: estimated reciprocal condition number at most the
     * machine epsilon, which means M is not a P-matrix).
     * @throws InputError if M is not square, q or @p active do not match it,
     * or the tolerance is negative or not finite.
     * @throws NumericalError if M or q contain NaN or inf.
     */
    LcpResult
    solve_lcp(const Eigen::MatrixXd &M,
              const Eigen::VectorXd &q,
              std::vector<bool>     &active,
              const LcpOptions      &options = {});
  } // namespace contact
} // namespace greentread
