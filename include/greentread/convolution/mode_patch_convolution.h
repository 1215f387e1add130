#pragma once

#include <greentread/convolution/patch_convolution.h>
#include <greentread/modal/patch_model.h>

#include <memory>

/**
 * @file
 * The rolling update of a rank-one model (the ring's own modes, Patch
 * model/Source = fe modes): one complex state per mode, driven by the modal
 * force phi_k^T q, O(N_p N_m) per step. The displacement of a continuous
 * force is updated in time blocks: one pass over the shapes per block of J
 * steps, with J - 1 lag kernels (N_p x N_p) for the loads inside the block.
 * make_modal_patch_convolution() chooses it for a rank-one model. Implemented
 * in source/convolution/mode_patch_convolution.cc.
 *
 * <b>The method.</b>
 * The recursion for a rank-one model: one complex state per term,
 * driven by the modal force phi_k^T q, and u = sum_k Re(c_k s_k phi_k).
 * A complex shape a + j b is two rows of the shape matrix, a and b:
 * its modal force is a^T q + j b^T q, and it adds
 * Re(c s) a - Im(c s) b to u.
 * O(N_p N_m) per step, not O(N_p^2 N_m). The step is memory bound (the
 * N_m x N_p shapes do not fit in cache), so advance() makes one pass
 * over them in blocks of rows that stay in cache: the modal forces of
 * the step's loads, the new states, and at once the next step's history
 * u, v. The terms are split between two threads when asked.
 *
 * Only the load vectors that are not zero are projected, and a step's
 * start load that equals the previous step's end load (a force
 * continuous in time, as with a static residual G_r) reuses that step's
 * modal forces: one dot product per row instead of four.
 *
 * Time blocks. A contact with a continuous force asks for the
 * displacement alone (history_u()), and its loads are the end values
 * q_i of the steps (each start equals the last end). The update then
 * reads the shapes once per J steps instead of once per step. With
 * the states g = h + beta_a f(q_{n-1}) at the block's start n, and
 * gamma = alpha beta_b + beta_a,
 *   u_{n+j} = Re sum_k c_k alpha_k^j g_k phi_k + sum_{i<j} K_{j-i} q_{n+i}
 * (for j = 0 the first term is Re sum_k c_k h_k phi_k), with the lag
 * kernels K_1 = Re sum_k c_k alpha_k beta_b,k phi_k phi_k^T and
 * K_m = Re sum_k c_k alpha_k^{m-1} gamma_k phi_k phi_k^T: J - 1
 * symmetric N_p x N_p matrices, formed once on the first block, in the
 * shapes' precision (lag_sums()). One pass at the block's end
 * forms the modal forces of its J loads (a product with J columns),
 * steps the states over the block,
 *   g_{n+J} = alpha^J g_n + sum_i alpha^{J-1-i} gamma f(q_{n+i}),
 * and sums the next block's free responses (J columns) while the rows
 * are in cache. The flops per step are at most those of the per-step
 * pass (the modal forces are formed from the points loaded in the
 * block alone), in products of J columns, which keep their operands in
 * registers: the pass is no longer bound by memory bandwidth. Any other
 * use (the velocity asked for, a load that is not continuous, a
 * preload) first completes the states of the loads so far, exactly,
 * and goes on step by step.
 * @p Shape is the shapes' precision (ShapePrecision): double or float.
 */

namespace greentread
{
  namespace convolution
  {
    /**
     * @brief The rank-one recursion of @p model at @p dt, its terms split over
     * @p n_threads threads, its shapes kept in @p precision, the displacement
     * of a continuous force (PatchConvolution::history_u()) updated in time
     * blocks of @p block_steps steps (1: step by step; 4, 8 or 16; 0: 16 where
     * the model has at least 128 shape rows per point, else 1).
     * @throws std::logic_error if @p model is not rank-one, or for another
     * block length.
     */
    std::unique_ptr<PatchConvolution>
    make_rank_one_patch_convolution(const modal::PatchModel &model,
                                    double                   dt,
                                    unsigned int             n_threads,
                                    ShapePrecision           precision,
                                    unsigned int             block_steps = 0);
  } // namespace convolution
} // namespace greentread
