#include <greentread/analysis/sound_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/fe/harmonic_section.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/radiation/sound_model.h>
#include <greentread/radiation_sources_digest.h>
#include <greentread/scenes/tyre_road_contact_scene.h>
#include <greentread/synthesis/mode_stage.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

/**
 * @file
 * Stage radiation of the tyre-road-contact scene: the sound of each road and
 * speed from its runs' contact forces.
 */

namespace greentread
{
  namespace scenes
  {
    void
    TyreRoadContactScene::sound_stage(const analysis::Study                    &study,
                                      const std::vector<analysis::RunSpectrum> &job_spectra,
                                      const modal::PatchModel                  &model,
                                      const std::filesystem::path              &directory,
                                      const base::ParameterRecord              &record) const
    {
      std::cout << "Stage radiation: the sound from " << format_number(sound.lowest_band) << " to "
                << format_number(sound.top_band)
                << " Hz at the microphones and the radiated power, on "
                << format_number(1e3 * sound.cell_size)
                << " mm boundary elements and, for their error bar, on cells sqrt(2) larger\n";
      // The saved stage: what depends on the tyre, its modes, the bands,
      // the meshes and the microphones only, reused across roads and speeds.
      std::ostringstream key;
      key << synthesis::mode_stage_key(prm, periodic::green_stage_key(prm, geometry.geo_file))
          << "--- radiation ---\nsources digest " << GREENTREAD_RADIATION_SOURCES_DIGEST << '\n';
      for (const auto &[path, value] : base::ParameterRecord::from(prm, "", {"Sound"}).entries)
        key << path << " = " << value << '\n';
      // The harmonics follow the lowest speed (radiation/sound_model.h).
      const double lowest_speed =
        *std::min_element(rolling.speeds.begin(), rolling.speeds.end()) / 3.6;
      key << "lowest speed = " << format_printf("%.17g", lowest_speed) << " m/s\n";
      const auto build = [&] {
        // The section and its points as the Green's functions had them.
        const periodic::InflatedTyre tyre(geometry, materials, inflation, green.patch);
        fe::HarmonicSection          section(tyre.cell->section(), materials.materials(),
                                             geometry.section_degree());
        section.inflate(inflation.pressure);
        if (tyre.patch.points.size() != model.points.size())
          throw NumericalError("the sound: " + std::to_string(tyre.patch.points.size()) +
                               " contact points, the patch model has " +
                               std::to_string(model.points.size()));
        for (std::size_t p = 0; p < model.points.size(); ++p)
          if (std::abs(tyre.patch.points[p].x - model.points[p][0]) > 1e-9 ||
              std::abs(tyre.patch.points[p].y - model.points[p][1]) > 1e-9)
            throw NumericalError("the sound: contact point " + std::to_string(p) +
                                 " is not the patch model's");
        return radiation::SoundModel(section, tyre.cell->section(), tyre.patch, sound,
                                     patch_model.mode_cutoff, lowest_speed, global.print_timings);
      };
      const radiation::SoundModel sound_model = radiation::sound_model_stage(
        build, directory / "sound_model.h5", key.str(), model.points, record, global.reuse);
      std::cout << "  the surface flattened by "
                << format_printf("%.3g", 1e3 * sound_model.deflection)
                << " mm, so that its flat is the patch's "
                << format_number(1e3 * green.patch.length) << " mm; microphones:";
      for (const auto &m : sound_model.microphones)
        std::cout << " " << m.name << " (" << format_number(m.position[0]) << ", "
                  << format_number(m.position[1]) << ", " << format_number(m.position[2]) << ") m";
      std::cout << '\n';

      // Each band from the run of the plan that gives it, as the spectra of
      // the stress and force take it.
      std::vector<std::map<double, analysis::BandSpectrum>> pieces;
      std::vector<analysis::SoundCase>                      cases(study.cases.size());
      for (std::size_t k = 0; k < study.jobs.size(); ++k)
        {
          const analysis::StudyJob &job = study.jobs[k];
          if (job.estimate >= 0)
            continue;
          const double f_low  = std::max(job.run.f_low, sound.lowest_band);
          const double f_high = std::min(job.run.f_high, sound.top_band);
          if (f_low > f_high * (1. + 1e-9))
            continue;
          const analysis::RunSpectrum &run = job_spectra[k];
          analysis::SoundCase         &c   = cases[job.study_case];
          c.road                           = run.road;
          c.speed_kmh                      = run.speed_kmh;
          c.quantities                     = sound_model.quantities();
          const auto spectra = sound_model.spectra(run.point_forces, run.time_step, f_low, f_high,
                                                   this->spectra.lines_per_segment);
          if (c.spectra.empty())
            c.spectra.resize(spectra.size());
          // The runs come longest first: put the bands in order.
          std::vector<analysis::BandSpectrum> merged(spectra.size());
          for (std::size_t q = 0; q < spectra.size(); ++q)
            {
              analysis::BandSpectrum &have = c.spectra[q];
              if (!have.bands.empty() && have.bands.front().nominal > f_high)
                {
                  merged[q] = spectra[q];
                  analysis::append_bands(merged[q], have);
                  have = std::move(merged[q]);
                }
              else
                analysis::append_bands(have, spectra[q]);
            }
        }
      analysis::write_sound(directory, cases, record);
    }
  } // namespace scenes
} // namespace greentread
