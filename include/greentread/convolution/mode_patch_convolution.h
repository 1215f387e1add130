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
