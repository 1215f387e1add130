#pragma once

#include <greentread/analysis/third_octave.h>
#include <greentread/base/output.h>

#include <filesystem>
#include <string>
#include <vector>

/**
 * @file
 * The sound of each road and speed: its band levels at the microphones, its
 * radiated power and the power its forces put in, with their error bars, as
 * sound_<road>_<V>.csv and .png. Implemented in
 * source/analysis/sound_output.cc.
 */

namespace greentread
{
  namespace analysis
  {
    /// The sound of one road at one speed.
    struct SoundCase
    {
      std::string road;
      double      speed_kmh = 0.;
      /// The outputs' names: the microphones', "power", "input".
      std::vector<std::string> quantities;
      /// One per quantity, each band with its standard error, its
      /// discretisation estimates and their total.
      std::vector<BandSpectrum> spectra;
    };

    /**
     * @brief sound_<road>_<V>.csv (a row per band and quantity: level,
     * standard error, the boundary element mesh's estimate, their total)
     * and sound_<road>_<V>.png (the levels with their total error bars),
     * and a summary line per case on standard output.
     */
    void
    write_sound(const std::filesystem::path  &directory,
                const std::vector<SoundCase> &cases,
                const base::ParameterRecord  &record);

    /**
     * @brief @p b's bands appended to @p a's (a band run's spectrum after
     * another's): every per-band field, the estimates by name.
     * @throws NumericalError if their bands overlap or their estimates
     * differ.
     */
    void
    append_bands(BandSpectrum &a, const BandSpectrum &b);
  } // namespace analysis
} // namespace greentread
