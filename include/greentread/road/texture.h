#pragma once

#include <cstdint>
#include <string>
#include <vector>

/**
 * @file
 * Road textures: a height grid, its one-third-octave texture spectrum
 * (ISO/TS 13473-4 style), its mean profile depth (ISO 13473-1), and
 * synthetic textures with a prescribed spectrum.
 */

namespace greentread
{
  namespace road
  {
    /**
     * @brief Heights on a regular grid: x along the rolling direction
     * (index i), y across it (index j).
     */
    struct Texture
    {
      double              dx = 0., dy = 0.; ///< grid spacing [m]
      unsigned int        nx = 0, ny = 0;   ///< points along x and across y
      std::vector<double> z;                ///< height z(i, j) at j * nx + i [m]

      double
      operator()(const unsigned int i, const unsigned int j) const
      {
        return z[std::size_t(j) * nx + i];
      }

      /// The length along x [m] of the profiles, nx dx.
      double
      length() const
      {
        return nx * dx;
      }
    };

    /**
     * @brief One-third-octave bands of wavelength, base 10 (as IEC 61260-1
     * for frequencies): exact centres 10^(k/10) mm, edges at 10^(+-1/20)
     * times the centre, labelled with their nominal values (2, 2.5, 3.15,
     * 4, ... mm).
     */
    struct WavelengthBand
    {
      int    index;        ///< k: centre 10^(k/10) mm
      double nominal;      ///< nominal centre wavelength [m]
      double centre;       ///< exact centre wavelength [m]
      double lower, upper; ///< edges [m]
    };

    /**
     * @brief Read a texture file, recognised by its first bytes:
     * - `aISO-1.0`: SDF (ISO 25178-71), ASCII: `Key = value` header lines
     *   (NumPoints along x, NumProfiles across y, Xscale, Yscale, Zscale in
     *   m), a line `*`, NumPoints x NumProfiles values profile by profile,
     *   and `*`;
     * - `bISO-1.0`: SDF, binary little-endian: the 81-byte header (version
     *   8, ManufacID 10, CreateDate 12, ModDate 12 characters; NumPoints,
     *   NumProfiles uint16; Xscale, Yscale, Zscale, Zresolution double;
     *   Compression, DataType, CheckType uint8) and the values of DataType
     *   0 uint8, 1 uint16, 2 uint32, 3 float, 4 int8, 5 int16, 6 int32,
     *   7 double; height = value x Zscale;
     * - `PK`: X3P (ISO 25178-72), a zip archive: read_x3p();
     * - a first line `profile_name:` or `sample_spacing_mm:`: an ISO 13473-1
     *   text profile in mm: read_text_profile();
     * - anything else: the plain height grid: `#` comment lines, then a line
     *   `dx dy` (m), then one line per profile along x, each with the same
     *   number of heights (m).
     * @throws InputError naming the file (and line) and what is wrong:
     * missing, unreadable, truncated, unknown data type, compression, a
     * non-finite height, spacings not > 0, or fewer than 2 x 1 points.
     */
    Texture
    read_texture(const std::string &file);

    /**
     * @brief Write @p texture as SDF, ASCII or binary (DataType 7, Zscale
     * 1), under a temporary name renamed when complete.
     */
    void
    write_sdf(const std::string &file, const Texture &texture, bool binary);

    /// The bands whose nominal centre lies in [@p shortest, @p longest] [m].
    std::vector<WavelengthBand>
    wavelength_bands(double shortest, double longest);

    /**
     * @brief The texture spectrum: for each band, the level
     * L = 10 log10(<a^2> / a_0^2), a_0 = 1 um, of the profiles along x,
     * <a^2> their mean square in the band (each profile's linear trend
     * removed, its discrete Fourier transform summed over the band's
     * wavenumbers, averaged over the profiles).
     *
     * A band that no Fourier line of the profiles falls in gets -inf.
     */
    std::vector<double>
    texture_spectrum(const Texture &texture, const std::vector<WavelengthBand> &bands);

    /**
     * @brief The mean profile depth (ISO 13473-1) [m] of the profiles along
     * x: each 100 mm segment has its linear trend removed, its depth is the
     * mean of the peaks of its two halves, and the MPD is the mean over
     * all whole segments of all profiles.
     * @throws InputError if the profiles are shorter than one segment.
     */
    double
    mean_profile_depth(const Texture &texture, double baseline = 0.1);

    /**
     * @brief A synthetic texture: white noise filtered in Fourier space so
     * that its texture spectrum matches @p target (one level in dB re 1 um
     * per band of @p bands) within @p tolerance dB in every band.
     *
     * The filter is separable, g(k_x) h(k_y): across y, h has the target's
     * own spectral shape, so that the texture has like scales in both
     * directions; along x, g is solved band by band on the noise drawn, so
     * that the profiles along x, which the tyre rolls over, carry exactly
     * the target (up to the effect of removing each profile's trend). An
     * isotropic filter cannot do that for the presets: its profiles see
     * all |k| >= k_x, and the long-wavelength bands came out 2 dB high. The
     * grid is periodic in both directions.
     *
     * @param[in] seed Reproducible: the same seed gives the same texture.
     * @throws NumericalError if the tolerance is not reached.
     */
    Texture
    synthetic_texture(const std::vector<WavelengthBand> &bands,
                      const std::vector<double>         &target,
                      double                             spacing,
                      unsigned int                       nx,
                      unsigned int                       ny,
                      std::uint64_t                      seed,
                      double                             tolerance = 0.5);

    /**
     * @brief A documented target spectrum: the preset's bands (2 mm to
     * 100 mm) and levels [dB re 1 um]. "road-A": rough, like a surface
     * dressing; "road-B": smoother, like a dense asphalt concrete.
     * @throws InputError naming the preset if unknown.
     */
    void
    texture_preset(const std::string           &name,
                   std::vector<WavelengthBand> &bands,
                   std::vector<double>         &levels);
  } // namespace road
} // namespace greentread
