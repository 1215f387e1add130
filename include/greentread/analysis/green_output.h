#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/base/output.h>
#include <greentread/periodic/contact_patch.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * The outputs of the Green's-function stage (scene tyre-green): the contact
 * points, the chosen pairs as CSV and plotted, and a summary on screen.
 */

namespace greentread
{
  namespace analysis
  {
    /// contact_points.csv: `point,i_x,i_y,x,y,radius,load_dofs`: each point's
    /// centre [m] and the number of radial DoFs its tributary load spreads over.
    void
    write_contact_points(const std::filesystem::path  &file,
                         const periodic::ContactPatch &patch,
                         const base::ParameterRecord  &record);

    /// The files write_green_pairs() wrote.
    struct GreenPairFiles
    {
      std::vector<std::string> csv;
      bool                     plotted = false;
    };

    /**
     * @brief green_<i>_<j>.csv for each of @p pairs (the format 'identify'
     * reads), and green_functions.png: |g| and phase, as in Figure A.9,
     * under the title @p title.
     */
    GreenPairFiles
    write_green_pairs(const std::filesystem::path                              &directory,
                      const base::FrequencyResponseMatrix                      &green,
                      const std::vector<std::pair<unsigned int, unsigned int>> &pairs,
                      const std::string                                        &title,
                      const base::ParameterRecord                              &record);

    /**
     * @brief The first pair (the driving point) and the last (a transfer):
     * static receptance, largest |g| and its line, g at f_max, in um/N so
     * that the regression tests' absolute tolerance sees them.
     */
    std::string
    summarise_pairs(const base::FrequencyResponseMatrix                      &green,
                    const std::vector<std::pair<unsigned int, unsigned int>> &pairs);
  } // namespace analysis
} // namespace greentread
