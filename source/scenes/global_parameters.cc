#include <greentread/scenes/global_parameters.h>
#include <greentread/scenes/scene.h>
#include <greentread/scenes/scene_input.h>

#include <iostream>

namespace greentread
{
  namespace scenes
  {
    void
    GlobalParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      // The scenes from the registry, and the deprecated spellings
      // 'tire-...' of the 'tyre-...' ones.
      std::string pattern, documentation = "What to compute.", deprecated;
      for (const auto &entry : scene_registry())
        {
          pattern += (pattern.empty() ? "" : "|") + entry.name;
          documentation += " '" + entry.name + "': " + entry.description + ".";
          if (entry.name.rfind("tyre-", 0) == 0)
            deprecated += "|tire-" + entry.name.substr(5);
        }
      prm.declare_entry(
        "Scene", "tyre-road-contact", dealii::Patterns::Selection(pattern + deprecated),
        documentation + " The spellings 'tire-cell', 'tire-green' and 'tire-road-contact' are "
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



    std::string
    GlobalParameters::scene_names()
    {
      std::string names;
      for (const auto &entry : scene_registry())
        names += (names.empty() ? "" : ", ") + entry.name;
      return names;
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
