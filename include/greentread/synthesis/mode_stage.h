#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/base/output.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <optional>
#include <string>

/**
 * @file
 * The modal stage of `Patch model/Source = fe modes` as a saved stage: the
 * ring's modes up to the cut-off (synthesis/ring_modes.h) at the contact
 * points, with the static residual from the Green's functions' 0 Hz line
 * (synthesis/mode_synthesis.h), read from modal_model.h5 when its key matches
 * and the file reads in full, computed and written otherwise.
 * Implemented in source/synthesis/mode_stage.cc.
 */

namespace greentread
{
  namespace synthesis
  {
    /**
     * @brief The key saved with modal_model.h5: the Green's stage's key
     * (which covers the geometry, materials, inflation, the patch and the
     * periodic sources that compute the modes), a digest of the modal
     * sources, and the 'Patch model/Mode cutoff'.
     */
    std::string
    mode_stage_key(const dealii::ParameterHandler &prm, const std::string &green_key);

    /// Everything the modal stage needs to build the tyre when it computes.
    struct ModeStageInputs
    {
      const geometry::GeometryParameters &geometry;
      const fe::MaterialParameters       &materials;
      const fe::InflationParameters      &inflation;
      const periodic::PatchRequest       &patch;
      /// Keep the modes up to this [Hz].
      double cutoff_hz = 0.;
      /// With the `harmonic` method: the modes come from the section's
      /// harmonics (synthesis/harmonic_modes.h), not from Bloch cells.
      std::optional<periodic::HarmonicOptions> harmonic = std::nullopt;
      /// The tyre built with these inputs, if one is at hand (the Green's
      /// stage's, in the same run); built here otherwise.
      const periodic::InflatedTyre *tyre = nullptr;
    };

    /**
     * @brief The modal synthesis at the points of @p green: reused from
     * @p file if @p reuse and its key is @p key, computed (the inflated tyre,
     * its ring modes over the ranks of @p comm, G_r from the 0 Hz line of
     * @p green) and written by rank 0 otherwise. Prints what it did. When
     * it computes, the modes' part at every line of @p green is left in
     * @p lines (if given) for compare().
     * @throws NumericalError if the points of the tyre built here are not
     * those of @p green (a Green's file from other parameters).
     */
    synthesis::ModeSynthesis
    run_mode_stage(const ModeStageInputs               &inputs,
                   const base::FrequencyResponseMatrix &green,
                   const std::filesystem::path         &file,
                   const std::string                   &key,
                   const base::ParameterRecord         &record,
                   bool                                 reuse,
                   bool                                 print_timings,
                   MPI_Comm                             comm,
                   synthesis::ModalLines               *lines = nullptr);
  } // namespace synthesis
} // namespace greentread
