#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/base/output.h>
#include <greentread/modal/identification.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * The outputs of the identification (scene identify): the modal parameters
 * and the fit of every pair, the worst fit plotted as in Figure A.10, and
 * the statistics on screen.
 */

namespace greentread
{
  namespace analysis
  {
    using PointPairs = std::vector<std::pair<unsigned int, unsigned int>>;

    /**
     * @brief modal_parameters.csv (`i,j,lambda_re,lambda_im,R_re,R_im`),
     * identification_report.csv (`i,j,n_modes,error`) and, with
     * @p residuals, residual_terms.csv (`i,j,lower,upper`).
     */
    void
    write_identifications(const std::filesystem::path              &directory,
                          const PointPairs                         &pairs,
                          const std::vector<modal::Identification> &results,
                          bool                                      residuals,
                          const base::ParameterRecord              &record);

    /// The statistics of the identifications of many pairs.
    struct IdentificationStatistics
    {
      std::vector<double> errors, modes;
      /// E of the other residue model, where it was compared.
      std::vector<double> other;
      std::size_t         worst = 0, other_better = 0, bands_used = 0;
      modal::PoleCounts   poles;
      double              condition = 0.;

      explicit IdentificationStatistics(const std::vector<modal::Identification> &results);

      /**
       * @brief On screen: E and N_m (min, median, max), the other residue
       * model, the poles, the conditioning and the zoom bands.
       */
      std::string
      describe(const PointPairs &pairs, const modal::IdentificationParameters &parameters) const;
    };

    /**
     * @brief worst_fit.csv (`f,re,im,fit_re,fit_im`): @p frf of pair @p pair
     * and its model @p fit, residual terms included, and
     * identification_worst.png (magnitude and phase).
     * @return Whether it was plotted.
     */
    bool
    write_worst_fit(const std::filesystem::path          &directory,
                    const base::FrequencyResponse        &frf,
                    const modal::Identification          &fit,
                    std::pair<unsigned int, unsigned int> pair,
                    const base::ParameterRecord          &record);
  } // namespace analysis
} // namespace greentread
