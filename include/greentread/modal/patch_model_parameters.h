#pragma once

#include <deal.II/base/parameter_handler.h>

/**
 * @file
 * Subsection "Patch model": where the patch model comes from and how it is
 * fitted (modal::PatchModelParameters, modal::PatchModelSource); the model
 * itself is in greentread/modal/patch_model.h. Implemented in
 * source/modal/patch_model_parameters.cc.
 */

namespace greentread
{
  namespace modal
  {
    /// Where the patch model comes from.
    enum class PatchModelSource
    {
      /// LSCE poles and fitted residues (Appendix A): the paper's path.
      identified,
      /// The ring's own modes with a static residual (synthesis/mode_synthesis.h).
      fe_modes
    };

    /// Subsection "Patch model".
    struct PatchModelParameters
    {
      PatchModelSource source = PatchModelSource::identified;
      /// The modes kept by `fe modes`: natural frequency <= this [Hz].
      double mode_cutoff = 8000.;
      /// A constant G_r (true) or a real pole (false) carries the residual.
      bool instantaneous_residual = true;
      /// f_r / f_max of the residual pole (0: no residual pole).
      double residual_pole_factor = 3.;
      /// Weight of the 0 Hz line relative to the others.
      double static_weight = 20.;
      /// Poles closer than this, relative to |lambda|, are one pole.
      double pole_merge_tolerance = 0.005;
      /// Transfers from the centre point identified for poles.
      unsigned int reference_transfers = 8;
      /// Roll a model that is not passive (modal/passivity.h), with a warning.
      bool allow_non_passive = false;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace modal
} // namespace greentread
