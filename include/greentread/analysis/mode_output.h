#pragma once

#include <greentread/base/output.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <filesystem>

/**
 * @file
 * The outputs of the modal stage from the ring's own modes: the dispersion
 * curves (CSV and PNG), the synthesis' E per pair (modal_errors.csv) and
 * its summary on screen. Implemented in source/analysis/mode_output.cc.
 */

namespace greentread
{
  namespace analysis
  {
    /**
     * @brief dispersion.csv, header `wavenumber,branch,frequency_Hz,damping_ratio`,
     * one row per Bloch mode (branch 0 the lowest of its wavenumber), and
     * dispersion.png: frequency against wavenumber, as wave-FE tyre papers
     * plot them, with @p cutoff_hz marked.
     */
    void
    write_dispersion(const std::filesystem::path &directory,
                     const synthesis::Dispersion &dispersion,
                     double                       cutoff_hz,
                     const base::ParameterRecord &record);

    /**
     * @brief The synthesis against the direct Green's functions: E of
     * Eq. (50) per pair in modal_errors.csv (`i,j,E`, as the identified
     * model writes it), and on screen the median, 90th percentile, worst
     * pair, worst driving point, the passivity and the definiteness of G_r.
     */
    void
    report_synthesis(const std::filesystem::path      &directory,
                     const synthesis::ModeSynthesis   &synthesis,
                     const synthesis::SynthesisErrors &errors,
                     const base::ParameterRecord      &record);
  } // namespace analysis
} // namespace greentread
