#include <greentread/analysis/identification_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/scenes/identify_scene.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace greentread
{
  namespace scenes
  {
    IdentifyScene::IdentifyScene(dealii::ParameterHandler &prm_, const GlobalParameters &global_)
        : prm(prm_)
        , global(global_)
    {
      identification.parse_parameters(prm);
      const bool csv = !identification.frf_file.empty(), h5 = !identification.green_file.empty();
      if (csv == h5)
        throw InputError(std::string("scene 'identify' needs exactly one input: ") +
                         (csv ? "both 'Identification/FRF file' and 'Identification/Green's "
                                "function file' are set" :
                                "set 'Identification/FRF file' (one FRF, CSV 'f,re,im') or "
                                "'Identification/Green's function file' (HDF5)"));
    }



    void
    IdentifyScene::run()
    {
      namespace fs = std::filesystem;
      // Read the input before anything is written.
      base::FrequencyResponse                            single;
      base::FrequencyResponseMatrix                      green;
      std::vector<std::pair<unsigned int, unsigned int>> pairs;
      std::string                                        source;
      if (!identification.frf_file.empty())
        {
          single = base::read_frf_csv(identification.frf_file);
          pairs  = {{0u, 0u}};
          source = identification.frf_file;
        }
      else
        {
          green = base::read_green_hdf5(identification.green_file);
          pairs =
            base::parse_point_pairs(identification.pairs, green.n_points(), "Identification/Pairs");
          source = identification.green_file;
        }
      const double df      = single.values.empty() ? green.df : single.df;
      const auto   n_lines = single.values.empty() ? green.n_lines : single.values.size();
      const auto   get     = [&](std::size_t n) {
        return single.values.empty() ? green.get(pairs[n].first, pairs[n].second) : single;
      };

      const fs::path directory = base::prepare_output_directory(global.output_directory);
      const auto     record =
        base::ParameterRecord::from(prm, "identify", recorded_sections("identify"));

      std::cout << "GreenTread: scene 'identify', LSCE modal identification (Appendix A) of "
                << pairs.size() << " FRF" << (pairs.size() > 1 ? "s" : "") << " from "
                << std::filesystem::path(source).filename().string() << "\n  lines: " << n_lines
                << " from 0 to " << format_number(df * (n_lines - 1))
                << " Hz (df = " << format_number(df) << " Hz); at most " << identification.max_modes
                << " modes; residue model " << modal::to_string(identification.residue_model)
                << "; bands "
                << (identification.bands == 0 ? std::string("auto") :
                                                std::to_string(identification.bands))
                << "\n";

      const auto   start   = std::chrono::steady_clock::now();
      std::size_t  reused  = 0;
      const auto   results = single.values.empty() ?
                               modal::identify_pairs(green, pairs, identification, reused) :
                               modal::identify_all(get, 1, identification);
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

      analysis::write_identifications(
        directory, pairs, results, identification.lower_residual || identification.upper_residual,
        record);
      const analysis::IdentificationStatistics statistics(results);
      // The worst fit, as in Figure A.10.
      const bool plotted =
        analysis::write_worst_fit(directory, get(statistics.worst), results[statistics.worst],
                                  pairs[statistics.worst], record);
      std::cout << statistics.describe(pairs, identification);
      if (reused > 0)
        std::cout << "Reciprocity: " << reused << " FRFs g_ij equal to g_ji were identified once "
                  << "for both\n";
      if (global.print_timings)
        std::cout << "Run time: " << format_printf("%.3g", seconds) << " s, "
                  << format_printf("%.3g", 1e3 * seconds / (pairs.size() - reused))
                  << " ms per FRF identified\n";
      std::cout << "Wrote modal_parameters.csv, identification_report.csv, "
                << (identification.lower_residual || identification.upper_residual ?
                      "residual_terms.csv, " :
                      "")
                << "worst_fit.csv" << (plotted ? ", identification_worst.png" : "") << " in "
                << directory.string() << "\n";
    }
  } // namespace scenes
} // namespace greentread
