#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/synthesis/mode_synthesis.h>

/**
 * @file
 * A coarser mode cut-off on saved modes: the mode_cutoff benchmark's table
 * and the error bars' coarser level (analysis/error_bars.h). Not part of the
 * modal stage, so outside its source digest (CMakeLists.txt).
 */

namespace greentread
{
  namespace synthesis
  {
    /**
     * @brief The synthesis from the modes of @p all up to @p cutoff_hz
     * only, with its own G_r and beta_r from @p direct (synthesise()):
     * without a new search.
     */
    ModeSynthesis
    truncate(const ModeSynthesis                 &all,
             double                               cutoff_hz,
             const base::FrequencyResponseMatrix &direct);
  } // namespace synthesis
} // namespace greentread
