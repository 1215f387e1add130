#pragma once

#include <greentread/base/output.h>

#include <array>
#include <complex>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

/**
 * @file
 * Frequency responses (FRFs) on a uniform grid from 0 Hz, in the convention
 * of Eq. (3): \f$\hat g(\omega) = (K + j\omega C - \omega^2 M)^{-1}\f$, i.e.
 * \f$\hat g(\omega) = \int_0^\infty g(t) e^{-j\omega t} dt\f$.
 */

namespace greentread
{
  namespace base
  {
    class Hdf5Writer;

    /**
     * @brief One FRF: values at \f$f_k = k\,\Delta f\f$, k = 0 .. n-1.
     */
    struct FrequencyResponse
    {
      /// Line spacing \f$\Delta f\f$ [Hz].
      double df = 0.;
      /// \f$\hat g(f_k)\f$ [m/N].
      std::vector<std::complex<double>> values;

      /// The last line [Hz].
      double
      f_max() const
      {
        return df * (values.size() - 1);
      }
    };

    /**
     * @brief Read an FRF from a CSV file with the header `f,re,im` (f in Hz).
     *
     * Lines starting with '#' are comments. The grid must start at 0 Hz and
     * be uniform (to a relative 1e-6 of the spacing); every value must be a
     * finite number.
     * @throws InputError naming the file, the line and what is wrong.
     */
    FrequencyResponse
    read_frf_csv(const std::string &file);

    /**
     * @brief Write an FRF as `f,re,im` (atomically, with the parameter record).
     */
    void
    write_frf_csv(const std::filesystem::path &file,
                  const FrequencyResponse     &frf,
                  const base::ParameterRecord &record);

    /**
     * @brief Many FRFs g_ij(f) between points: the contents of a Green's
     * function file (see read_green_hdf5()).
     */
    struct FrequencyResponseMatrix
    {
      double df = 0.;
      /// Point coordinates [m], one row per point.
      std::vector<std::array<double, 3>> points;
      /// g(f_k, i, j) at index (k * n + i) * n + j, n = points.size() [m/N].
      std::vector<std::complex<double>> values;
      unsigned int                      n_lines = 0;

      unsigned int
      n_points() const
      {
        return static_cast<unsigned int>(points.size());
      }

      /// The FRF g_ij.
      FrequencyResponse
      get(unsigned int i, unsigned int j) const;
    };

    /**
     * @brief The pairs (i, j) of 0-based point indices named by @p text:
     * "all", "diagonal", or a list "i:j, i:j, ...".
     * @throws InputError naming @p parameter if the text is malformed or an
     * index is not below @p n_points.
     */
    std::vector<std::pair<unsigned int, unsigned int>>
    parse_point_pairs(const std::string &text, unsigned int n_points, const std::string &parameter);

    /**
     * @brief Read a Green's function file, an HDF5 file with the layout
     * - `/frequency`: double[n_f], the lines in Hz, uniform from 0;
     * - `/points`: double[n_p][3], the contact points in m;
     * - `/green`: complex double[n_f][n_p][n_p], g(f, i, j) in m/N: the
     *   displacement at point i for a unit force at point j, complex numbers
     *   stored as the compound {r, i} that h5py and deal.II read as complex.
     * @throws InputError naming the file and the dataset.
     */
    FrequencyResponseMatrix
    read_green_hdf5(const std::string &file);

    /**
     * @brief Write a Green's function file in the layout of read_green_hdf5(),
     * under a temporary name renamed when complete. The root attributes
     * `parameters` (the record, for people) and, if not empty, `stage_key`
     * (what the result depends on, for the stage cache) are written too.
     */
    void
    write_green_hdf5(const std::filesystem::path   &file,
                     const FrequencyResponseMatrix &green,
                     const base::ParameterRecord   &record,
                     const std::string             &stage_key = {});

    /**
     * @brief The `stage_key` attribute of a Green's function file, or an
     * empty string if the file, or its key, does not exist.
     */
    std::string
    read_green_stage_key(const std::string &file);

    /**
     * @brief Write a stage's HDF5 file atomically: @p fill writes the
     * stage's datasets into a temporary file, then the contact points
     * ("points", n x 3), the attribute `parameters` and, unless empty, the
     * attribute `stage_key` are added, and the file is renamed to @p file.
     * A file left unfinished has no key, and is never under its final name.
     * No object carries a time (base::Hdf5Writer): the same stage writes the
     * same bytes.
     */
    void
    write_hdf5_stage(const std::filesystem::path              &file,
                     const std::vector<std::array<double, 3>> &points,
                     const base::ParameterRecord              &record,
                     const std::string                        &stage_key,
                     const std::function<void(Hdf5Writer &)>  &fill);

    /**
     * @brief The `stage_key` attribute of any stage's HDF5 file, or an empty
     * string if the file, its key or one of @p datasets does not exist (a
     * file that was never completed has no key).
     */
    std::string
    read_hdf5_stage_key(const std::string &file, const std::vector<std::string> &datasets);
  } // namespace base
} // namespace greentread
