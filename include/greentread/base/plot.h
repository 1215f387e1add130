#pragma once

#include <greentread/base/output.h>

#include <filesystem>
#include <string>

/**
 * @file
 * PNG figures drawn by gnuplot (Debian package gnuplot-nox).
 */

namespace greentread
{
  namespace base
  {
    /**
     * @brief Whether a working gnuplot is on this machine.
     */
    bool
    gnuplot_available();

    /**
     * @brief Draw a PNG with gnuplot and embed the parameter record in it.
     *
     * @param[in] png      Final path of the figure.
     * @param[in] commands gnuplot commands that plot; terminal and output are
     *                     set here (pngcairo, @p width x @p height pixels).
     * @param[in] record   Stored in the PNG as a tEXt chunk "parameters".
     * @return false, with a warning on @p std::cerr, when gnuplot is missing or
     * fails: a figure is a convenience, the CSV beside it is the result.
     */
    bool
    plot_png(const std::filesystem::path &png,
             const std::string           &commands,
             const ParameterRecord       &record,
             unsigned int                 width  = 1000,
             unsigned int                 height = 700);

    /**
     * @brief Quote a path for a gnuplot string literal.
     */
    std::string
    gnuplot_quote(const std::filesystem::path &path);
  } // namespace base
} // namespace greentread
