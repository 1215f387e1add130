#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

/**
 * @file
 * Subsection "Identification": the FRFs to identify and the settings of
 * LSCE, of the residues' fit and of the order's choice
 * (modal::IdentificationParameters, modal::ResidueModel); the identification
 * itself is in greentread/modal/identification.h. Implemented in
 * source/modal/identification_parameters.cc.
 */

namespace greentread
{
  namespace modal
  {
    /// How the residues of the complex modes are parametrised.
    enum class ResidueModel
    {
      /// Eq. (7): one real A per mode, \f$A/(\omega_k^2-\omega^2+2j\xi_k\omega_k\omega)\f$,
      /// so that g(t = 0) = 0 is built in.
      eq7,
      /// Eq. (A.2): a complex residue R per pair, \f$R/(j\omega-\lambda) + \bar
      /// R/(j\omega-\bar\lambda)\f$.
      general
    };

    std::string
    to_string(ResidueModel model);

    /**
     * @brief Subsection "Identification".
     */
    struct IdentificationParameters
    {
      std::string frf_file;
      std::string green_file;
      std::string pairs = "all";
      /// Sub-bands of zoom LSCE; 0 = auto.
      unsigned int bands            = 0;
      double       zoom_above_error = 0.05;
      unsigned int max_modes        = 60;
      double       order_tolerance  = 1e-3;
      ResidueModel residue_model    = ResidueModel::eq7;
      bool         compare_models   = true;
      bool         lower_residual   = false;
      bool         upper_residual   = false;
      /// Refine the chosen poles against every line (modal/pole_polish.h),
      /// kept if E falls ('Identification/Pole refinement'): for noisy
      /// (measured) FRFs; it costs about a hundred times LSCE's time.
      bool   polish_poles        = false;
      double stability_frequency = 0.01;
      double stability_damping   = 0.05;
      double band_edge           = 0.98;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace modal
} // namespace greentread
