#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/plot.h>
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
    namespace
    {

      double
      median(std::vector<double> values)
      {
        if (values.empty())
          return NAN;
        std::sort(values.begin(), values.end());
        const std::size_t n = values.size();
        return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
      }
    } // namespace



    IdentifyScene::IdentifyScene(dealii::ParameterHandler &prm_, const GlobalParameters &global_)
      : prm(prm_)
      , global(global_)
    {
      identification.parse_parameters(prm);
      const bool csv = !identification.frf_file.empty(), h5 = !identification.green_file.empty();
      if (csv == h5)
        throw InputError(std::string("scene 'identify' needs exactly one input: ") +
                         (csv ? "both 'Identification/FRF file' and 'Identification/Green's "
                                "function file' are set"
                              : "set 'Identification/FRF file' (one FRF, CSV 'f,re,im') or "
                                "'Identification/Green's function file' (HDF5)"));
    }



    void
    IdentifyScene::run()
    {
      namespace fs = std::filesystem;
      // Read the input before anything is written.
      modal::FrequencyResponse                           single;
      modal::FrequencyResponseMatrix                     green;
      std::vector<std::pair<unsigned int, unsigned int>> pairs;
      std::string                                        source;
      if (!identification.frf_file.empty())
        {
          single = modal::read_frf_csv(identification.frf_file);
          pairs  = {{0u, 0u}};
          source = identification.frf_file;
        }
      else
        {
          green  = modal::read_green_hdf5(identification.green_file);
          pairs  = modal::parse_point_pairs(identification.pairs, green.n_points(),
                                            "Identification/Pairs");
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
                << std::filesystem::path(source).filename().string()
                << "\n  lines: " << n_lines << " from 0 to " << format_number(df * (n_lines - 1))
                << " Hz (df = " << format_number(df) << " Hz); at most "
                << identification.max_modes << " modes; residue model "
                << modal::to_string(identification.residue_model) << "; bands "
                << (identification.bands == 0 ? std::string("auto") :
                                                std::to_string(identification.bands))
                << "\n";

      const auto  start  = std::chrono::steady_clock::now();
      std::size_t reused = 0;
      const auto  results =
        single.values.empty() ? modal::identify_pairs(green, pairs, identification, reused) :
                                modal::identify_all(get, 1, identification);
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

      {
        base::AtomicFile file(directory / "modal_parameters.csv");
        auto            &out = file.stream();
        out.precision(16);
        out << "i,j,lambda_re,lambda_im,R_re,R_im\n";
        for (std::size_t n = 0; n < pairs.size(); ++n)
          for (const auto &term : results[n].model.terms())
            out << pairs[n].first << ',' << pairs[n].second << ',' << term.lambda.real() << ','
                << term.lambda.imag() << ',' << term.residue.real() << ',' << term.residue.imag()
                << '\n';
        record.write_comments(out);
        file.commit();
      }
      {
        base::AtomicFile file(directory / "identification_report.csv");
        auto            &out = file.stream();
        out << "i,j,n_modes,error\n";
        for (std::size_t n = 0; n < pairs.size(); ++n)
          out << pairs[n].first << ',' << pairs[n].second << ',' << results[n].n_modes << ','
              << results[n].error << '\n';
        record.write_comments(out);
        file.commit();
      }
      if (identification.lower_residual || identification.upper_residual)
        {
          base::AtomicFile file(directory / "residual_terms.csv");
          auto            &out = file.stream();
          out << "i,j,lower,upper\n";
          for (std::size_t n = 0; n < pairs.size(); ++n)
            out << pairs[n].first << ',' << pairs[n].second << ',' << results[n].lower_residual
                << ',' << results[n].upper_residual << '\n';
          record.write_comments(out);
          file.commit();
        }

      // Statistics.
      std::vector<double> errors, modes, other;
      std::size_t         worst = 0, other_better = 0, bands_used = 0;
      modal::PoleCounts   poles;
      double              condition = 0.;
      for (std::size_t n = 0; n < pairs.size(); ++n)
        {
          const auto &r = results[n];
          errors.push_back(r.error);
          modes.push_back(r.n_modes);
          if (r.error > results[worst].error)
            worst = n;
          if (std::isfinite(r.other_model_error))
            {
              other.push_back(r.other_model_error);
              other_better += r.other_model_error < r.error;
            }
          bands_used += r.n_bands > 1;
          poles.roots += r.poles.roots;
          poles.unstable += r.poles.unstable;
          poles.out_of_band += r.poles.out_of_band;
          poles.spurious += r.poles.spurious;
          poles.physical += r.poles.physical;
          condition = std::max(condition, r.condition);
        }

      // The worst fit, as in Figure A.10.
      const modal::FrequencyResponse worst_frf = get(worst);
      const auto                    &worst_id  = results[worst];
      {
        base::AtomicFile file(directory / "worst_fit.csv");
        auto            &out = file.stream();
        out << "f,re,im,fit_re,fit_im\n";
        for (std::size_t k = 0; k < worst_frf.values.size(); ++k)
          {
            const double         omega = 2. * M_PI * k * worst_frf.df;
            std::complex<double> fit   = worst_id.model.frequency_response(omega) +
                                       worst_id.upper_residual;
            if (worst_id.lower_residual != 0. && k > 0)
              fit -= worst_id.lower_residual / (omega * omega);
            out << k * worst_frf.df << ',' << worst_frf.values[k].real() << ','
                << worst_frf.values[k].imag() << ',' << fit.real() << ',' << fit.imag() << '\n';
          }
        record.write_comments(out);
        file.commit();
      }
      const std::string data = base::gnuplot_quote(directory / "worst_fit.csv");
      const std::string title =
        "g_{" + std::to_string(pairs[worst].first) + "," + std::to_string(pairs[worst].second) +
        "}: N_m = " + std::to_string(worst_id.n_modes) + ", E = " +
        format_printf("%.3g", 100. * worst_id.error) + " %";
      const bool plotted = base::plot_png(
        directory / "identification_worst.png",
        "set datafile separator ','\nset multiplot layout 2,1 title 'GreenTread identify, worst "
        "fit: " + title + "'\nset grid\nset xlabel 'f [Hz]'\nset ylabel '|g| [m/N]'\n"
        "set logscale y\nset format y '10^{%L}'\nplot " + data +
          " skip 1 using 1:(sqrt($2**2+$3**2)) with lines lc rgb 'black' lw 2 title 'FRF', '' "
          "skip 1 using 1:(sqrt($4**2+$5**2)) with lines lc rgb '#d62728' dt 2 lw 2 title "
          "'modal fit'\nunset logscale y\nset format y '%g'\nset ylabel 'phase [deg]'\n"
          "set yrange [-180:180]\nset ytics 90\nplot " + data +
          " skip 1 using 1:(atan2($3,$2)*180/pi) with lines lc rgb 'black' lw 2 title 'FRF', '' "
          "skip 1 using 1:(atan2($5,$4)*180/pi) with lines lc rgb '#d62728' dt 2 lw 2 title "
          "'modal fit'\nunset multiplot\n",
        record, 1100, 800);

      const std::string other_name = identification.residue_model == modal::ResidueModel::eq7 ?
                                       "general" :
                                       "eq7";
      std::cout << "Error E (Eq. 50): min " << format_printf("%.4g", *std::min_element(errors.begin(), errors.end()))
                << ", median " << format_printf("%.4g", median(errors)) << ", max "
                << format_printf("%.4g", errors[worst]) << " (worst: i = " << pairs[worst].first
                << ", j = " << pairs[worst].second << ")\n"
                << "Modes N_m: min " << *std::min_element(modes.begin(), modes.end())
                << ", median " << median(modes) << ", max "
                << *std::max_element(modes.begin(), modes.end()) << "\n";
      if (!other.empty())
        std::cout << "Residue models on the same poles: median E "
                  << modal::to_string(identification.residue_model) << " "
                  << format_printf("%.4g", median(errors)) << ", " << other_name << " "
                  << format_printf("%.4g", median(other)) << "; " << other_name << " fits better on "
                  << other_better << " of " << other.size() << "\n";
      std::cout << "Roots of the LSCE polynomials: " << poles.roots << "; rejected "
                << poles.unstable << " unstable, " << poles.out_of_band << " out of band, "
                << poles.spurious << " spurious (not stable across orders); "
                << poles.physical << " physical\n"
                << "Largest condition estimate of a Hankel matrix: " << format_printf("%.3g", condition)
                << "\n";
      if (identification.bands == 0)
        std::cout << "Zoom LSCE (8 bands) used for " << bands_used << " of " << pairs.size()
                  << " FRFs (E above " << format_number(identification.zoom_above_error)
                  << " with one band)\n";
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
