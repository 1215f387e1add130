#include <greentread/base/parameters.h>
#include <greentread/modal/patch_model_parameters.h>

namespace greentread
{
  namespace modal
  {
    void
    PatchModelParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using base::RangePattern;
      prm.enter_subsection("Patch model");
      {
        prm.declare_entry(
          "Source", "fe modes", dealii::Patterns::Selection("identified|fe modes"),
          "Where the patch model comes from. 'identified': the paper's path, LSCE poles "
          "found on reference functions and the residues of every pair fitted to the Green's "
          "functions (Appendix A; the entries below). 'fe modes': the ring's own modes, "
          "computed per circumferential wavenumber from the cell (Bloch eigenproblem of "
          "K + Kp and M), g(w) = G_r + sum_k phi_k phi_k^T / (w_k^2 - w^2 + 2 j xi_k w_k w) "
          "with the static residual G_r = G(0) - sum_k phi_k phi_k^T / w_k^2; exact up to "
          "the cut-off, passive, and rank one per mode (saved as modal_model.h5; the "
          "default).");
        prm.declare_entry("Mode cutoff", "8000", base::RangePattern::positive("Hz"),
                          "'fe modes': the ring's modes with a natural frequency up to this "
                          "are kept; those above it enter through the static residual G_r "
                          "only. Unit: Hz.");
        prm.declare_entry(
          "Residual flexibility", "instantaneous",
          dealii::Patterns::Selection("instantaneous|real pole"),
          "How the local compliance of a point force that the modes below f_max do not "
          "explain enters the model. 'instantaneous': a constant term G_r (reciprocal, "
          "positive definite), u = G_r q(t) + the modal convolution, with imaginary residues "
          "so the modal part starts from rest (g(0+) = 0); the multi-point contact needs it. "
          "'real pole': a real pole at -2 pi f_r (see 'Residual pole factor'), which the "
          "one-point convolutions can carry but which makes the one-step influence of a "
          "patch indefinite (measured on the default tyre).");
        prm.declare_entry("Residual pole factor", "3", base::RangePattern::closed(0., 100., ""),
                          "The local compliance of a point force that the modes below f_max do "
                          "not explain is carried by a real pole at -2 pi f_r, f_r = this factor "
                          "times the highest line f_max; its residue is fitted with the others. "
                          "0: no residual pole (the fit of a driving point then misses most of "
                          "its compliance).");
        prm.declare_entry("Static weight", "20", base::RangePattern::closed(1., 1e6, ""),
                          "Weight of the 0 Hz line in the least-squares fit of the residues, "
                          "relative to the other lines: a large weight makes the model's "
                          "static compliance that of the structure, which the static contact "
                          "solve uses.");
        prm.declare_entry("Pole merge tolerance", "0.005",
                          base::RangePattern::closed(1e-6, 0.1, ""),
                          "The poles are identified on a few reference functions and merged: "
                          "two poles closer than this, relative to |lambda|, are one.");
        prm.declare_entry("Reference transfers", "8", dealii::Patterns::Integer(0, 64),
                          "How many transfer functions from the point nearest the patch centre, "
                          "to points spread over the patch, are identified for poles, besides "
                          "the summed driving points and the summed response to a uniform "
                          "pressure.");
        prm.declare_entry(
          "Allow non-passive", "false", dealii::Patterns::Bool(),
          "Whether the rolling scene may use a patch model that is not passive: the smallest "
          "eigenvalue of -Im g over its largest, measured at every line of the Green's "
          "functions, below -1e-9. Such a model (the identified one can be) may put energy "
          "into the contact. 'false': refused, with the figure; 'true': rolled, with a "
          "warning that names the figure. Not part of the modal stage's key.");
      }
      prm.leave_subsection();
    }



    void
    PatchModelParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Patch model");
      {
        source                 = prm.get("Source") == "fe modes" ? PatchModelSource::fe_modes :
                                                                   PatchModelSource::identified;
        mode_cutoff            = prm.get_double("Mode cutoff");
        instantaneous_residual = prm.get("Residual flexibility") == "instantaneous";
        residual_pole_factor   = prm.get_double("Residual pole factor");
        static_weight          = prm.get_double("Static weight");
        pole_merge_tolerance   = prm.get_double("Pole merge tolerance");
        reference_transfers    = prm.get_integer("Reference transfers");
        allow_non_passive      = prm.get_bool("Allow non-passive");
      }
      prm.leave_subsection();
    }
  } // namespace modal
} // namespace greentread
