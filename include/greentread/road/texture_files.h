#pragma once

#include <greentread/road/texture.h>

#include <string>
#include <vector>

/**
 * @file
 * The road files that texture scanners and profilometers write, beside the
 * SDF and plain grids of texture.h: X3P (ISO 25178-72) surfaces and
 * profiles, and ISO 13473-1 text profiles. read_texture() recognises them
 * by their first bytes and calls these readers.
 */

namespace greentread
{
  namespace road
  {
    /**
     * @brief Read an X3P file (ISO 25178-72, the openGPS ISO 5436-2 XML
     * format): a zip archive holding main.xml, md5checksum.hex and the
     * binary data its Record3 links to, or the heights inline as Datum
     * elements.
     *
     * - The feature is a surface (SUR) or a profile (PRF), on a regular
     *   grid: CX and CY incremental, CZ absolute, one layer.
     * - The heights are of DataType I (int16), L (int32), F (float32) or D
     *   (float64), little-endian, x fastest; each is Offset + value x
     *   Increment of CZ [m] (1 and 0 if absent).
     * - The archive's main.xml may sit in one top-level folder; elements are
     *   matched by their local names.
     * - Missing points (NaN or infinite heights, a cleared bit of the valid
     *   points file, an empty Datum) are filled as fill_missing() says.
     * - The MD5 sums of main.xml (md5checksum.hex) and of the data
     *   (MD5ChecksumPointData, MD5ChecksumValidPoints) are checked.
     *
     * @throws InputError naming the file and what is wrong: not a zip, no
     * main.xml, a wrong checksum, a point cloud or absolute x or y axes, an
     * unsupported data type, more than one layer, truncated data, too many
     * missing points.
     */
    Texture
    read_x3p(const std::string &file);

    /**
     * @brief Write @p texture as an X3P surface (FeatureType SUR) with its
     * heights of @p data_type 'I', 'L', 'F' or 'D', under a temporary name
     * renamed when complete. Integer heights are scaled to span the type's
     * range. Points where @p valid (if not empty, one flag per height) is
     * false are written missing: NaN for F and D, a cleared bit in
     * bindata/valid.bin for all types.
     */
    void
    write_x3p(const std::string       &file,
              const Texture           &texture,
              char                     data_type,
              const std::vector<bool> &valid = {});

    /**
     * @brief Read an ISO 13473-1 text profile: header lines 'key: value',
     * of which 'sample_spacing_mm' is required (the layout of the ERPUG
     * reference profiles), then one height per line in mm, 'NaN' for a
     * dropout. The profile becomes a texture of one profile along x, as a
     * plain grid of one line does (the contact grid extrudes it across the
     * tread). Dropouts are filled as fill_missing() says.
     *
     * @throws InputError naming the file and line: no spacing, a value that
     * is not a number, fewer than 2 heights, heights whose peak-to-valley
     * lies outside 0.01 mm to 100 mm (a unit other than mm), too many
     * dropouts.
     */
    Texture
    read_text_profile(const std::string &bytes, const std::string &file);

    /// Whether @p bytes begin as read_text_profile() reads.
    bool
    is_text_profile(const std::string &bytes);

    /**
     * @brief Fill the missing heights (not finite) of @p texture, profile by
     * profile along x, linearly between the nearest valid neighbours and
     * with the nearest valid height at a profile's ends, as ISO 13473-1
     * interpolates dropouts.
     * @return how many were filled.
     * @throws InputError naming @p file if more than 10% of all heights
     * are missing (ISO 13473-1's limit for a segment), or a profile has
     * none valid.
     */
    std::size_t
    fill_missing(Texture &texture, const std::string &file);
  } // namespace road
} // namespace greentread
