#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/base/output.h>
#include <greentread/modal/identification.h>
#include <greentread/modal/patch_model.h>

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <string>

/**
 * @file
 * The modal stage as a saved stage: the patch model of the Green's functions,
 * read from patch_model.h5 when its key matches and the file reads in full,
 * fitted and saved otherwise. Implemented in source/modal/patch_model_stage.cc.
 */

namespace greentread
{
  namespace modal
  {
    /**
     * @brief The key saved with patch_model.h5: the Green's stage's key, a
     * digest of the modal sources, and the parameters of "Identification"
     * and "Patch model". Not the git revision: a commit elsewhere keeps the
     * fit.
     */
    std::string
    patch_model_stage_key(const dealii::ParameterHandler &prm, const std::string &green_key);

    /**
     * @brief The patch model of @p green: reused from @p file if @p reuse and
     * its key is @p key, fitted (fit_patch_model()) and written otherwise.
     * Prints what it did and the fit's E (Eq. 50), and writes
     * modal_errors.csv beside @p file.
     */
    PatchModel
    patch_model_stage(const base::FrequencyResponseMatrix &green,
                      const IdentificationParameters      &identification,
                      const PatchModelParameters          &parameters,
                      const std::filesystem::path         &file,
                      const std::string                   &key,
                      const base::ParameterRecord         &record,
                      bool                                 reuse,
                      bool                                 print_timings);
  } // namespace modal
} // namespace greentread
