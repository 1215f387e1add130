#include <greentread/analysis/error_bars.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/progress.h>
#include <greentread/radiation/helmholtz_bem.h>
#include <greentread/radiation/sound_model.h>

#include <deal.II/base/numbers.h>
#include <deal.II/fe/mapping_q1.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

namespace greentread
{
  namespace radiation
  {
    namespace
    {
      /// The convergence order of the constant-per-cell collocation in the
      /// cell size: the far field's power moved as h^2 at 800 Hz
      /// (unit/sound_field), so the coarser level's cells sqrt(2) larger
      /// give Richardson's factor 1.
      constexpr double bem_order = 2.;
    } // namespace



    SoundModel::SoundModel(const fe::HarmonicSection      &section,
                           const dealii::Triangulation<2> &section_mesh,
                           const periodic::ContactPatch   &patch,
                           const SoundParameters          &parameters,
                           const double                    mode_cutoff,
                           const double                    lowest_speed,
                           const bool                      print)
        : bands(analysis::third_octave_bands(parameters.lowest_band, parameters.top_band))
    {
      const SectionLine contour = outer_contour(section_mesh);
      double            radius  = 0.;
      for (const auto &p : contour)
        radius = std::max(radius, p[0]);
      const double length = patch.points_along * patch.dx;
      deflection          = length * length / (8. * radius);
      const double two_pi = 2. * dealii::numbers::PI;
      const auto   forced =
        static_cast<unsigned int>(std::ceil(two_pi * radius * bands.back().upper / lowest_speed) +
                                  std::ceil(two_pi * radius / length));
      Air air;
      air.ground = true;

      for (unsigned int l = 0; l < 2; ++l)
        {
          SoundLevel &level = levels[l];
          level.cell_size   = parameters.cell_size * (l == 0 ? 1. : SoundParameters::coarser_ratio);
          level.surface     = std::make_unique<TyreSurface>(contour, level.cell_size, deflection);
          const TyreSurface &surface = *level.surface;
          if (l == 0)
            {
              if (parameters.microphones.empty())
                microphones = cpx_microphones(surface);
              else
                for (const auto &[name, position] : parameters.microphones)
                  microphones.push_back({name, position});
              for (const auto &m : microphones)
                if (surface.inside(m.position))
                  throw InputError("parameter 'Sound/Microphones': microphone '" + m.name +
                                   "' lies inside the tyre's surface or under the road; "
                                   "allowed: a point in the air");
            }
          const dealii::MappingQ1<2, 3> mapping;
          HelmholtzBem                  bem(surface.mesh, mapping, surface.outward);
          if (bands.back().centre > bem.highest_frequency(air) * (1. + 1e-12))
            throw InputError("parameter 'Sound/Top band' = " + format_number(bands.back().nominal) +
                             " Hz is beyond what the " +
                             (l == 0 ? std::string("surface mesh") : "error bar's coarser mesh") +
                             " of 'Sound/Cell size' " + (l == 0 ? "" : "x sqrt(2) ") + "= " +
                             format_short(1e3 * level.cell_size) + " mm resolves; allowed: up to " +
                             format_short(bem.highest_frequency(air)) +
                             " Hz (six cells to a wavelength)");
          level.cells = bem.n_cells();
          if (l == 0)
            level.harmonics =
              std::max(forced, static_cast<unsigned int>(std::lround(two_pi / surface.arc)));
          else
            level.harmonics = levels[0].harmonics;

          auto start     = std::chrono::steady_clock::now();
          level.mobility = std::make_unique<SurfaceMobility>(
            section, patch, surface, 2. * dealii::numbers::PI * mode_cutoff, level.harmonics);
          level.mobility_seconds = base::seconds_since(start);
          if (print)
            std::cout << "  " << (l == 0 ? "the mesh" : "the error bar's coarser mesh") << ": "
                      << format_printf("%.3g", 1e3 * level.cell_size) << " mm cells, "
                      << level.cells << " of them, " << level.harmonics
                      << " harmonics round the tyre, " << level.mobility->n_modes() << " modes to "
                      << format_number(mode_cutoff) << " Hz ("
                      << format_printf("%.3g", level.mobility_seconds) << " s)\n"
                      << std::flush;
          if (l == 0)
            {
              fewer_harmonics = static_cast<unsigned int>(std::ceil(0.75 * level.harmonics));
              fewer = std::make_unique<SurfaceMobility>(level.mobility->truncated(fewer_harmonics));
            }

          start = std::chrono::steady_clock::now();
          std::vector<dealii::Point<3>> positions;
          for (const auto &m : microphones)
            positions.push_back(m.position);
          base::Progress progress("    boundary elements, band by band", bands.size());
          for (std::size_t b = 0; b < bands.size(); ++b)
            {
              level.transfers.push_back(
                band_transfer(bem, surface, air, bands[b].centre, positions));
              if (print)
                progress.update(b + 1);
            }
          progress.finish();
          level.bem_seconds = base::seconds_since(start);
          if (print)
            std::cout << "    its boundary elements: " << bands.size() << " bands, "
                      << format_printf("%.3g", level.bem_seconds) << " s\n";
        }
    }



    std::vector<std::string>
    SoundModel::quantities() const
    {
      std::vector<std::string> names;
      for (const auto &m : microphones)
        names.push_back(m.name);
      names.emplace_back("power");
      names.emplace_back("input");
      return names;
    }



    std::vector<analysis::BandSpectrum>
    SoundModel::spectra(const std::vector<std::vector<double>> &forces,
                        const double                            dt,
                        const double                            f_low,
                        const double                            f_high,
                        const unsigned int                      lines_per_segment) const
    {
      const auto wanted = analysis::third_octave_bands(f_low, f_high);
      const auto first  = std::find_if(bands.begin(), bands.end(), [&](const auto &b) {
        return std::abs(b.nominal - wanted.front().nominal) < 1e-9 * b.nominal;
      });
      const auto offset = static_cast<std::size_t>(first - bands.begin());
      if (first == bands.end() || offset + wanted.size() > bands.size())
        throw NumericalError("sound spectra from " + format_number(f_low) + " to " +
                             format_number(f_high) + " Hz: outside the model's bands");
      // The scene's mesh, the coarser one, the scene's with fewer harmonics.
      std::array<std::vector<analysis::BandSpectrum>, 3> of_level;
      for (unsigned int l = 0; l < 3; ++l)
        {
          const auto                     &all = levels[l == 1 ? 1 : 0].transfers;
          const std::vector<BandTransfer> transfers(
            all.begin() + static_cast<std::ptrdiff_t>(offset),
            all.begin() + static_cast<std::ptrdiff_t>(offset + wanted.size()));
          of_level[l] = sound_spectra(forces, dt, l == 2 ? *fewer : *levels[l].mobility, transfers,
                                      f_low, f_high, lines_per_segment);
        }
      const double factor = analysis::richardson_factor(SoundParameters::coarser_ratio, bem_order);
      std::vector<analysis::BandSpectrum> result = std::move(of_level[0]);
      for (std::size_t q = 0; q < result.size(); ++q)
        {
          std::vector<double> mesh(result[q].level.size()), harmonics(mesh.size());
          for (std::size_t b = 0; b < mesh.size(); ++b)
            {
              mesh[b]      = factor * std::abs(result[q].level[b] - of_level[1][q].level[b]);
              harmonics[b] = std::abs(result[q].level[b] - of_level[2][q].level[b]);
            }
          result[q].discretisation_error.emplace_back("bem_mesh", std::move(mesh));
          result[q].discretisation_error.emplace_back("harmonics", std::move(harmonics));
          analysis::combine_errors(result[q]);
        }
      return result;
    }
  } // namespace radiation
} // namespace greentread
