#pragma once

#include <greentread/analysis/third_octave.h>
#include <greentread/base/output.h>
#include <greentread/fe/harmonic_section.h>
#include <greentread/periodic/contact_patch.h>
#include <greentread/radiation/sound_field.h>
#include <greentread/radiation/sound_parameters.h>
#include <greentread/radiation/surface_mobility.h>
#include <greentread/radiation/tyre_surface.h>

#include <deal.II/grid/tria.h>

#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

/**
 * @file
 * The sound of a tyre at its scene's bands, on two boundary element meshes:
 * the scene's and the error bar's coarser one. What depends on the tyre and
 * the bands only (the surface, its mobility from the ring's modes, the
 * transfers to the microphones and the far field) is built once; each run's
 * contact forces then give its band levels (sound_spectra()) with the
 * mesh's error bar beside their standard errors.
 */
namespace greentread
{
  namespace radiation
  {
    /// One boundary element mesh and what it carries.
    struct SoundLevel
    {
      double                           cell_size = 0.; ///< [m]
      std::unique_ptr<TyreSurface>     surface;
      std::unique_ptr<SurfaceMobility> mobility;
      /// One per band of the model, at its centre.
      std::vector<BandTransfer> transfers;
      unsigned int              cells = 0, harmonics = 0;
      double                    mobility_seconds = 0., bem_seconds = 0.;
    };

    class SoundModel
    {
    public:
      /**
       * @brief The surfaces, mobilities and transfers of both levels.
       *
       * The surface is the section's outer contour revolved, flattened by the
       * deflection whose flat is the patch's length L (d = L^2 / (8 R) on
       * the tread's radius R), so that the forces act where the road wets
       * the tyre. The harmonics round the tyre cover the forces' content:
       * a texture of wavelength V / f moving through the patch at speed V
       * loads harmonic n = 2 pi R f / V, spread by the patch's length L
       * over 2 pi R / L more; so N = 2 pi R f_top / V_low + 2 pi R / L at the
       * top band's upper edge and the lowest speed, and at least as many
       * as the cells round the tyre (where a cell's box factor vanishes).
       * Both meshes take the same N; the harmonics' error bar sums the
       * scene's mesh over the first 3/4 of them.
       * @param[in] section      The inflated section of the ring.
       * @param[in] section_mesh Its mesh, whose outer contour radiates.
       * @param[in] patch        The contact points (tributary areas).
       * @param[in] parameters   Subsection "Sound".
       * @param[in] mode_cutoff  The ring's modes kept [Hz].
       * @param[in] lowest_speed The lowest rolling speed [m/s].
       * @param[in] print        Progress and timings on standard output.
       * @throws InputError if a microphone lies inside the surface or a
       *         band is beyond what a mesh resolves.
       */
      SoundModel(const fe::HarmonicSection      &section,
                 const dealii::Triangulation<2> &section_mesh,
                 const periodic::ContactPatch   &patch,
                 const SoundParameters          &parameters,
                 double                          mode_cutoff,
                 double                          lowest_speed,
                 bool                            print);

      /**
       * @brief The spectra of a run's contact forces @p forces (one signal
       * per point [N], @p dt [s] apart) in the bands from @p f_low to
       * @p f_high (nominal centres, within the model's): per microphone, the
       * radiated power and the power put in (sound_spectra()), each level
       * from the scene's mesh with its standard error and two estimates in
       * its discretisation_error: "bem_mesh", |L - L_coarser| times
       * Richardson's factor for order 2, and "harmonics", |L - L_fewer|
       * (3/4 of the harmonics), combined in total_error.
       */
      std::vector<analysis::BandSpectrum>
      spectra(const std::vector<std::vector<double>> &forces,
              double                                  dt,
              double                                  f_low,
              double                                  f_high,
              unsigned int                            lines_per_segment) const;

      /**
       * @brief The model as a saved stage: written atomically to @p file
       * with the contact points, the record and @p key
       * (base::write_hdf5_stage()); the surfaces themselves are not kept.
       */
      void
      save(const std::filesystem::path              &file,
           const std::vector<std::array<double, 3>> &points,
           const base::ParameterRecord              &record,
           const std::string                        &key) const;

      /// The model save() wrote. @throws InputError naming the file if it
      /// is incomplete or its arrays do not fit together.
      static SoundModel
      read(const std::filesystem::path &file);

      /// The key of a saved model, or "" if there is none.
      static std::string
      read_key(const std::filesystem::path &file);

      /// The names of spectra()'s outputs: the microphones', "power", "input".
      std::vector<std::string>
      quantities() const;

      std::vector<analysis::FrequencyBand> bands;
      std::vector<Microphone>              microphones;
      double                               deflection = 0.; ///< [m]
      /// The scene's mesh, then the error bar's coarser one.
      std::array<SoundLevel, 2> levels;
      /// The scene's mesh's mobility over the first 3/4 of its harmonics.
      std::unique_ptr<SurfaceMobility> fewer;
      unsigned int                     fewer_harmonics = 0;

    private:
      SoundModel() = default;
    };

    /**
     * @brief The saved stage radiation: the model read from @p file if
     * @p reuse and its key is @p key, else built by @p build and saved
     * there. Says which on standard output.
     */
    SoundModel
    sound_model_stage(const std::function<SoundModel()>        &build,
                      const std::filesystem::path              &file,
                      const std::string                        &key,
                      const std::vector<std::array<double, 3>> &points,
                      const base::ParameterRecord              &record,
                      bool                                      reuse);
  } // namespace radiation
} // namespace greentread
