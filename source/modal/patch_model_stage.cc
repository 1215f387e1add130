#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/modal/patch_model_stage.h>
#include <greentread/modal_sources_digest.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <sstream>
#include <vector>

namespace greentread
{
  namespace modal
  {
    std::string
    patch_model_stage_key(const dealii::ParameterHandler &prm, const std::string &green_key)
    {
      // The record's entries only: its header names the git revision, which
      // must not throw the fit away (the sources' digest stands for it).
      std::ostringstream key;
      key << green_key << "\n--- modal ---\nsources digest " << GREENTREAD_MODAL_SOURCES_DIGEST
          << '\n';
      for (const auto &[path, value] :
           base::ParameterRecord::from(prm, "", {"Identification", "Patch model"}).entries)
        if (path != "Patch model/Allow non-passive") // what the scene does with the model
          key << path << " = " << value << '\n';
      return key.str();
    }



    PatchModel
    patch_model_stage(const base::FrequencyResponseMatrix &green,
                      const IdentificationParameters      &identification,
                      const PatchModelParameters          &parameters,
                      const std::filesystem::path         &file,
                      const std::string                   &key,
                      const base::ParameterRecord         &record,
                      const bool                           reuse,
                      const bool                           print_timings)
    {
      const unsigned int n_p = green.n_points();
      PatchModel         model;
      if (reuse && read_patch_model_key(file.string()) == key && base::read_saved_stage(file, [&] {
            model = read_patch_model(file.string());
          }))
        {
          std::cout << "Reusing " << file.string()
                    << ": same Green's functions and identification parameters\n";
        }
      else
        {
          const auto t0 = std::chrono::steady_clock::now();
          std::cout << "Stage modal: LSCE poles and the residues of all " << n_p * n_p
                    << " pairs\n";
          model = fit_patch_model(green, identification, parameters, true);
          write_patch_model(file, model, record, key);
          const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - t0;
          if (print_timings)
            std::cout << "  modal stage: " << format_printf("%.3g", seconds.count()) << " s\n";
        }
      // The fit's E (Eq. 50): on screen in summary, every pair in modal_errors.csv.
      {
        std::vector<double> e(model.errors.data(), model.errors.data() + model.errors.size());
        std::sort(e.begin(), e.end());
        double diagonal = 0.;
        for (unsigned int i = 0; i < n_p; ++i)
          diagonal = std::max(diagonal, model.errors(i, i));
        std::cout << "  modal fit, E of Eq. (50) over the " << e.size() << " pairs: median "
                  << format_printf("%.2f", 100. * e[e.size() / 2]) << "%, 90th percentile "
                  << format_printf("%.2f", 100. * e[e.size() * 9 / 10]) << "%, largest "
                  << format_printf("%.2f", 100. * e.back()) << "% (driving points at most "
                  << format_printf("%.2f", 100. * diagonal) << "%), " << model.n_terms()
                  << " poles\n";
        base::AtomicFile f(file.parent_path() / "modal_errors.csv");
        f.stream() << "i,j,E\n";
        for (unsigned int i = 0; i < n_p; ++i)
          for (unsigned int j = 0; j < n_p; ++j)
            f.stream() << i << ',' << j << ',' << model.errors(i, j) << '\n';
        record.write_comments(f.stream());
        f.commit();
      }
      return model;
    }
  } // namespace modal
} // namespace greentread
