#include <greentread/analysis/error_bar_parameters.h>
#include <greentread/analysis/spectra_parameters.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/contact_parameters.h>
#include <greentread/contact/rolling_parameters.h>
#include <greentread/contact/tread_pattern_parameters.h>
#include <greentread/convolution/convolution_parameters.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/modal/identification.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/radiation/sound_parameters.h>
#include <greentread/road/road_profile.h>
#include <greentread/scenes/green_scene.h>
#include <greentread/scenes/identify_scene.h>
#include <greentread/scenes/scene.h>
#include <greentread/scenes/scene_input.h>
#include <greentread/scenes/sdof_scene.h>
#include <greentread/scenes/tyre_cell_scene.h>
#include <greentread/scenes/tyre_road_contact_scene.h>
#include <greentread/sdof/oscillator.h>

#include <algorithm>

namespace greentread
{
  namespace scenes
  {
    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      GlobalParameters::declare_parameters(prm);
      sdof::OscillatorParameters::declare_parameters(prm);
      road::RoadParameters::declare_parameters(prm);
      contact::ContactParameters::declare_parameters(prm);
      convolution::ConvolutionParameters::declare_parameters(prm);
      modal::IdentificationParameters::declare_parameters(prm);
      geometry::GeometryParameters::declare_parameters(prm);
      fe::MaterialParameters::declare_parameters(prm);
      fe::InflationParameters::declare_parameters(prm);
      periodic::GreenParameters::declare_parameters(prm);
      modal::PatchModelParameters::declare_parameters(prm);
      road::RoadTextureParameters::declare_parameters(prm);
      contact::RollingParameters::declare_parameters(prm);
      analysis::SpectraParameters::declare_parameters(prm);
      analysis::ErrorBarParameters::declare_parameters(prm);
      contact::ContactGridParameters::declare_parameters(prm);
      contact::TreadPatternParameters::declare_parameters(prm);
      radiation::SoundParameters::declare_parameters(prm);
      declare_renamed_parameters(prm);
    }



    namespace
    {
      template <class SceneClass>
      std::unique_ptr<Scene>
      make(dealii::ParameterHandler &prm, const GlobalParameters &global)
      {
        return std::make_unique<SceneClass>(prm, global);
      }
    } // namespace



    const std::vector<SceneEntry> &
    scene_registry()
    {
      static const std::vector<std::string> tyre_cell = {"Geometry", "Materials", "Inflation"};
      static const std::vector<SceneEntry>  registry  = {
          {"sdof",
           "the 1-DoF oscillator rolling over a sinusoidal road (paper, Section 3), with its "
             "exact solution",
           {"Oscillator", "Road", "Contact", "Time stepping", "Convolution/Method",
            "Convolution/Truncation threshold", "Identification"},
           false,
           make<SdofScene>},
          {"identify",
           "modal identification (LSCE, Appendix A) of FRFs",
           {"Identification"},
           false,
           make<IdentifyScene>},
          {"geometry-study", "the tyre section and cell, masses and inflation", tyre_cell, false,
           make<TyreCellScene>},
          {"tyre-cell", "the same and the cell matrices K, M, C, Kp", tyre_cell, false,
           make<TyreCellScene>},
          {"tyre-green",
           "the Green's functions of the inflated ring at the contact points (Section 4.2), "
             "over the MPI ranks",
           {"Geometry", "Materials", "Inflation", "Green's functions"},
           true,
           make<GreenScene>},
          {"tyre-road-contact",
           "the whole pipeline, geometry to the contact stresses and their spectra on road "
             "textures (Section 5)",
           {"Geometry", "Materials", "Inflation", "Green's functions", "Identification",
            "Patch model", "Road texture", "Road/Sinusoid", "Rolling", "Contact grid",
            "Time stepping/Time step", "Convolution/Method", "Convolution/Shape precision", "Spectra",
            "Error bars", "Tread pattern", "Sound"},
           false,
           make<TyreRoadContactScene>}};
      return registry;
    }



    namespace
    {
      const SceneEntry &
      entry_of(const std::string &scene)
      {
        for (const auto &entry : scene_registry())
          if (entry.name == scene)
            return entry;
        // The 'Scene' parameter's pattern, made from the registry, has
        // refused any other name already.
        throw InputError("parameter 'Scene' = " + scene +
                         "; allowed: " + GlobalParameters::scene_names());
      }
    } // namespace



    std::vector<std::string>
    subsections_read(const std::string &scene)
    {
      return entry_of(scene).reads;
    }



    std::vector<std::string>
    recorded_sections(const std::string &scene)
    {
      std::vector<std::string> sections = {"Scene", "Output directory"};
      for (const auto &s : subsections_read(scene))
        sections.push_back(s);
      return sections;
    }



    void
    check_subsections(const dealii::ParameterHandler &prm, const std::string &scene)
    {
      const auto read = subsections_read(scene);
      for (const auto &entry : base::list_parameters(prm))
        {
          const auto slash = entry.path.find('/');
          if (slash == std::string::npos || entry.value == entry.default_value)
            continue;
          const std::string section = entry.path.substr(0, slash);
          if (std::find(read.begin(), read.end(), section) != read.end() ||
              std::any_of(read.begin(), read.end(), [&](const std::string &r) {
                return entry.path == r || entry.path.rfind(r + "/", 0) == 0;
              }))
            continue;
          std::string list;
          bool        reads_part = false;
          for (const auto &r : read)
            {
              list += (list.empty() ? "" : ", ") + r;
              reads_part = reads_part || r.rfind(section + "/", 0) == 0;
            }
          throw InputError(
            "parameter '" + entry.path + "' = " + entry.value + " is set, but scene '" + scene +
            "' does not read " + (reads_part ? "it" : "subsection '" + section + "'") +
            "; allowed: the subsections and entries scene '" + scene + "' reads: " + list);
        }
    }



    std::unique_ptr<Scene>
    create_scene(dealii::ParameterHandler &prm, const std::string &scene_file)
    {
      GlobalParameters global;
      global.parse_parameters(prm);
      check_subsections(prm, global.scene);
      resolve_input_files(prm, scene_file, subsections_read(global.scene));
      const SceneEntry  &entry   = entry_of(global.scene);
      const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      if (n_ranks > 1 && !entry.mpi)
        {
          std::string mpi_scenes;
          for (const auto &e : scene_registry())
            if (e.mpi)
              mpi_scenes += (mpi_scenes.empty() ? "'" : ", '") + e.name + "'";
          throw InputError("scene '" + global.scene + "' runs on one process, and this run has " +
                           std::to_string(n_ranks) + " MPI ranks: run it without mpirun (only " +
                           mpi_scenes + " uses MPI)");
        }
      return entry.create(prm, global);
    }
  } // namespace scenes
} // namespace greentread
