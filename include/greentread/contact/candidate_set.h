#pragma once

#include <greentread/contact/projected_cg.h>

#include <Eigen/Core>

#include <functional>
#include <vector>

/**
 * @file
 * The contact's complementarity problem (projected_cg.h) solved where the
 * contact can be: a step whose cost follows the points that can touch the
 * road, not the whole grid. Implemented in source/contact/candidate_set.cc.
 *
 * On a rolling tyre's contact grid only a few points touch the road at a
 * time: 3% to 10% of the main job's 7680. A point whose gap without the
 * step's new forces is open (\f$q_i \ge 0\f$) stays open unless the forces at
 * the others pull it down, which a compliance's off-diagonal entries only do
 * where they are negative (a nearly incompressible tread bulges beside a
 * load). So:
 * 1. The candidates: \f$N = \{i : q_i < 0\}\f$, the points the road would
 *    be inside without the step's new forces, warm-started from
 *    \f$z^{start}\f$. A point in contact at the last step whose gap is now
 *    open is left out: it joins in step 3 if the others pull it down. (With
 *    those points in N, the low-rate runs' sets, 5 road samples a step,
 *    doubled to 760 to 890 points and went to the whole grid at almost every
 *    step.)
 * 2. The LCP on N alone, by MPRGP on the dense block \f$W_{NN}\f$, which
 *    @p block forms (the contact grid: from the layer's kernel and the
 *    patch model's compliance, entry by entry): each product costs
 *    \f$|N|^2\f$, not the whole grid's FFT.
 * 3. The check on the whole grid: one product \f$w = W z + q\f$ with the
 *    matrix-free W. A point outside N with \f$w_i < -\tau s\f$ (pulled into
 *    the road by the others) joins N, and the solve goes back to 2, warm-
 *    started, with the block grown by the new rows and columns only. At
 *    most 50 rounds.
 *
 * The answer is that of solve_lcp_projected_cg() on the whole grid: the same
 * convergence test, \f$\|\nu\|_\infty \le \tau s\f$ with \f$s =
 * \|q\|_\infty\f$ of the whole grid, met on N by the reduced solve and off
 * N by step 3 (z = 0 there, so \f$\nu_i = \min(w_i, 0)\f$).
 *
 * **When.** A dense product costs \f$|N|^2\f$, the whole grid's FFT product
 * about \f$n \log n\f$. While \f$|N|^2 \le 34\,n\f$ (and N is at most
 * half the grid) the candidate set is solved on, otherwise the whole grid,
 * decided at each step and round. The constant is the crossover measured on
 * the main job's 7680-point grid (|N| about 510): road-A's 300 to 450
 * candidates solve in 9.0 ms per step against 15.1 on the whole grid,
 * road-B's 820 would take 36 ms against 17 (doc/methods/contact.md).
 */

namespace greentread
{
  namespace contact
  {
    /// out = W(rows, columns): a block of W.
    using OperatorBlock = std::function<void(const std::vector<unsigned int> &rows,
                                             const std::vector<unsigned int> &columns,
                                             Eigen::MatrixXd                 &out)>;

    /// What a candidate-set solve did with its set.
    struct CandidateSetReport
    {
      /// |N| from q (step 1), and at the end.
      unsigned int start = 0, end = 0;
      /// Whether N grew past the dense limit and the whole grid was solved.
      bool whole_grid = false;
    };

    /**
     * @brief The LCP of projected_cg.h on the candidate set of the file
     * documentation.
     * @param[in] W The whole grid's operator (one product per round).
     * @param[in] block Its dense blocks.
     * @param[in] q, start, options As solve_lcp_projected_cg();
     *            options.operator_norm (\f$\|W\|_2\f$, which bounds every
     *            block's) is computed if 0.
     * @param[out] report If not null: the set at the start and at the end.
     * @return As solve_lcp_projected_cg(); LcpResult::iterations counts the
     *         products with the blocks and with W.
     */
    LcpResult
    solve_lcp_candidate_set(const SymmetricOperator &W,
                            const OperatorBlock     &block,
                            const Eigen::VectorXd   &q,
                            const Eigen::VectorXd   &start,
                            ProjectedCgOptions       options,
                            CandidateSetReport      *report = nullptr);
  } // namespace contact
} // namespace greentread
