#pragma once

#include <greentread/contact/patch_convolution.h>
#include <greentread/modal/patch_model.h>

#include <memory>

/**
 * @file
 * The rolling update of a rank-one model (the ring's own modes, Patch
 * model/Source = fe modes): one complex state per mode, driven by the modal
 * force phi_k^T q, O(N_p N_m) per step. make_modal_patch_convolution() chooses
 * it for a rank-one model. Implemented in
 * source/contact/mode_patch_convolution.cc.
 */

namespace greentread
{
  namespace contact
  {
    /**
     * @brief The rank-one recursion of @p model at @p dt, its terms split over
     * @p n_threads threads, its shapes kept in @p precision.
     * @throws std::logic_error if @p model is not rank-one.
     */
    std::unique_ptr<PatchConvolution>
    make_rank_one_patch_convolution(const modal::PatchModel &model, double dt,
                                    unsigned int n_threads, ShapePrecision precision);
  } // namespace contact
} // namespace greentread
