#include <greentread/scenes/global_parameters.h>
#include <greentread/scenes/scene_input.h>

#include <iostream>

namespace greentread
{
  namespace scenes
  {
    void
    GlobalParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Scene", "tyre-road-contact",
                        dealii::Patterns::Selection(
                          "sdof|identify|geometry-study|tyre-cell|tyre-green|tyre-road-contact|"
                          "tire-cell|tire-green|tire-road-contact"),
                        "What to compute. 'sdof': the 1-DoF oscillator rolling over a "
                        "sinusoidal road (paper, Section 3), with its exact solution. "
                        "'identify': modal identification (LSCE, Appendix A) of FRFs. "
                        "'geometry-study': the tyre section and cell, masses and inflation. "
                        "'tyre-cell': the same and the cell matrices K, M, C, Kp. "
                        "'tyre-green': the Green's functions of the inflated ring at the "
                        "contact points (Section 4.2), over the MPI ranks. "
                        "'tyre-road-contact': the whole pipeline, geometry to the contact "
                        "stresses and their spectra on road textures (Section 5). The "
                        "spellings 'tire-cell', 'tire-green' and 'tire-road-contact' are "
                        "deprecated: still read, with a warning, in this release.");
      prm.declare_entry("Output directory", "output", dealii::Patterns::DirectoryName(),
                        "Directory for every output file; created if missing. Relative "
                        "paths are relative to the working directory (input files, by "
                        "contrast, are looked for first beside the scene file).");
      prm.declare_entry("Reuse saved results", "true", dealii::Patterns::Bool(),
                        "Reuse a stage's saved output (green_functions.h5, patch_model.h5) "
                        "when it was computed from the same parameters, input files and "
                        "sources of that stage; 'false' always recomputes.");
      prm.declare_entry("Print timings", "true", dealii::Patterns::Bool(),
                        "Print run times, and the progress of long loops, on screen. "
                        "Regression tests switch this off so that their output is "
                        "reproducible.");
    }



    void
    GlobalParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      scene            = current_scene_name(prm.get("Scene"), std::cerr);
      output_directory = prm.get("Output directory");
      print_timings    = prm.get_bool("Print timings");
      reuse            = prm.get_bool("Reuse saved results");
    }
  } // namespace scenes
} // namespace greentread
