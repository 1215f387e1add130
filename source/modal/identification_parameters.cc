// The parameters of the identification (subsection "Identification");
// the identification itself is in identification.cc.
#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/modal/identification_parameters.h>

#include <cstdlib>
#include <string>

namespace greentread
{
  namespace modal
  {
    std::string
    to_string(const ResidueModel model)
    {
      return model == ResidueModel::eq7 ? "eq7" : "general";
    }



    void
    IdentificationParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using base::RangePattern;
      prm.enter_subsection("Identification");
      {
        prm.declare_entry("FRF file", "", dealii::Patterns::Anything(),
                          "One FRF to identify: a CSV file with the header 'f,re,im', f in Hz "
                          "on a uniform grid from 0, g in m/N with g = (K + jwC - w^2 M)^-1. "
                          "Scene 'identify' needs this or 'Green's function file'.");
        prm.declare_entry("Green's function file", "", dealii::Patterns::Anything(),
                          "Many FRFs: an HDF5 file with /frequency [n_f] (Hz), /points "
                          "[n_p][3] (m) and /green complex [n_f][n_p][n_p] (m/N), as written "
                          "by the periodic stage (doc/getting-started.md, 'File formats').");
        prm.declare_entry("Pairs", "all", dealii::Patterns::Anything(),
                          "Which g_ij of the Green's function file to identify: 'all', "
                          "'diagonal', or a list 'i:j, i:j, ...' of 0-based point indices.");
        prm.declare_entry("Bands", "auto", dealii::Patterns::Anything(),
                          "'auto', or a number B from 1 to 64. 1: LSCE on the whole band at "
                          "once, as in Appendix A. B > 1: 'zoom' LSCE in B sub-bands, each "
                          "inverse-transformed on its own (complex) and at its own lower rate, "
                          "so that the roots of each polynomial spread around the unit circle "
                          "instead of crowding near z = 1; needed when many modes lie far below "
                          "f_max. Each pole is taken from the band whose core holds its "
                          "frequency. 'auto': 1 band, and 8 bands as well where E exceeds "
                          "'Zoom above error', keeping the better fit.");
        prm.declare_entry("Zoom above error", "0.05", base::RangePattern::closed(0., 1., ""),
                          "With Bands = auto, an FRF whose error E with one band exceeds this "
                          "is identified again in 8 bands. Unit: 1 (0.05 = 5%, the paper's "
                          "typical error).");
        prm.declare_entry("Maximum number of modes", "60", dealii::Patterns::Integer(1, 500),
                          "N_max: the LSCE order is 2 N_max poles, and the chosen model has at "
                          "most N_max modes. The paper uses about 50 per Green's function.");
        prm.declare_entry("Order tolerance", "0.001", base::RangePattern::closed(0., 1., ""),
                          "The chosen N_m is the smallest whose error E (Eq. 50) is within "
                          "this of the smallest E over all orders tried. Unit: 1 (a fraction "
                          "of E, 0.001 = 0.1 percentage point).");
        prm.declare_entry("Residue model", "eq7", dealii::Patterns::Selection("eq7|general"),
                          "'eq7': one real A per mode, A/(w_k^2 - w^2 + 2j xi_k w_k w), Eq. (7), "
                          "so g(t = 0) = 0 is built in; real poles keep one real residue each. "
                          "'general': a complex residue per pair, Eq. (A.2).");
        prm.declare_entry("Compare residue models", "true", dealii::Patterns::Bool(),
                          "Also fit the other residue model with the same poles and report "
                          "its error.");
        prm.declare_entry("Lower residual", "false", dealii::Patterns::Bool(),
                          "Add a term -L/w^2 for modes below the band (free structures). The "
                          "0 Hz line is then left out of the fit and of E. The time-domain "
                          "convolution does not use residual terms.");
        prm.declare_entry("Upper residual", "false", dealii::Patterns::Bool(),
                          "Add a constant real term U for modes above f_max. The time-domain "
                          "convolution does not use residual terms.");
        prm.declare_entry("Pole refinement", "none",
                          dealii::Patterns::Selection("none|least squares"),
                          "'none': LSCE's poles as they are (Appendix A). 'least squares': the "
                          "chosen poles refined against every FRF line (Levenberg-Marquardt, "
                          "the residues solved linearly for each trial), kept if E of Eq. (50) "
                          "falls. For measured, noisy FRFs: it recovers modes closer than their "
                          "bandwidth that LSCE merges at 40 dB SNR. On clean data it trades "
                          "exact poles for a lower E (it lets in-band poles take up modes above "
                          "the band), and it costs about a hundred times LSCE's time. Scene "
                          "identify only: the contact scene's patch model keeps LSCE's poles.");
        prm.declare_entry("Stabilisation frequency tolerance", "0.01",
                          base::RangePattern::closed(0., 1., ""),
                          "A pole is kept only if the LSCE polynomial of order p - 2 has a "
                          "root within this relative distance |d lambda| / |lambda|. Unit: 1.");
        prm.declare_entry("Stabilisation damping tolerance", "0.05",
                          base::RangePattern::closed(0., 10., ""),
                          "... and with a damping ratio within this fraction of its own. "
                          "Unit: 1.");
        prm.declare_entry("Band edge", "0.98", base::RangePattern::closed(0.1, 1., ""),
                          "Poles whose damped frequency exceeds this fraction of f_max are "
                          "rejected: the cut of the FRF at f_max rings at the Nyquist "
                          "frequency and LSCE fits that ringing with poles there. Unit: 1.");
      }
      prm.leave_subsection();
    }



    void
    IdentificationParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Identification");
      {
        frf_file            = prm.get("FRF file");
        green_file          = prm.get("Green's function file");
        pairs               = prm.get("Pairs");
        const std::string b = prm.get("Bands");
        if (b == "auto")
          bands = 0;
        else
          {
            char      *end   = nullptr;
            const long value = std::strtol(b.c_str(), &end, 10);
            require_parameter(end != b.c_str() && *end == '\0' && value >= 1 && value <= 64,
                              "Identification/Bands", b, "'auto' or a whole number from 1 to 64");
            bands = static_cast<unsigned int>(value);
          }
        zoom_above_error = prm.get_double("Zoom above error");
        max_modes        = prm.get_integer("Maximum number of modes");
        order_tolerance  = prm.get_double("Order tolerance");
        residue_model =
          prm.get("Residue model") == "eq7" ? ResidueModel::eq7 : ResidueModel::general;
        compare_models      = prm.get_bool("Compare residue models");
        lower_residual      = prm.get_bool("Lower residual");
        upper_residual      = prm.get_bool("Upper residual");
        polish_poles        = prm.get("Pole refinement") == "least squares";
        stability_frequency = prm.get_double("Stabilisation frequency tolerance");
        stability_damping   = prm.get_double("Stabilisation damping tolerance");
        band_edge           = prm.get_double("Band edge");
      }
      prm.leave_subsection();
    }
  } // namespace modal
} // namespace greentread
