#include <greentread/analysis/identification_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace analysis
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



    void
    write_identifications(const std::filesystem::path              &directory,
                          const PointPairs                         &pairs,
                          const std::vector<modal::Identification> &results,
                          const bool                                residuals,
                          const base::ParameterRecord              &record)
    {
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
      if (residuals)
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
    }



    IdentificationStatistics::IdentificationStatistics(
      const std::vector<modal::Identification> &results)
    {
      for (std::size_t n = 0; n < results.size(); ++n)
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
    }



    std::string
    IdentificationStatistics::describe(const PointPairs                      &pairs,
                                       const modal::IdentificationParameters &parameters) const
    {
      const std::string chosen = modal::to_string(parameters.residue_model);
      const std::string other_name =
        parameters.residue_model == modal::ResidueModel::eq7 ? "general" : "eq7";
      std::string text = "Error E (Eq. 50): min " +
                         format_printf("%.4g", *std::min_element(errors.begin(), errors.end())) +
                         ", median " + format_printf("%.4g", median(errors)) + ", max " +
                         format_printf("%.4g", errors[worst]) +
                         " (worst: i = " + std::to_string(pairs[worst].first) +
                         ", j = " + std::to_string(pairs[worst].second) + ")\nModes N_m: min " +
                         format_number(*std::min_element(modes.begin(), modes.end())) +
                         ", median " + format_number(median(modes)) + ", max " +
                         format_number(*std::max_element(modes.begin(), modes.end())) + "\n";
      if (!other.empty())
        text += "Residue models on the same poles: median E " + chosen + " " +
                format_printf("%.4g", median(errors)) + ", " + other_name + " " +
                format_printf("%.4g", median(other)) + "; " + other_name + " fits better on " +
                std::to_string(other_better) + " of " + std::to_string(other.size()) + "\n";
      // The split of the rest into spurious and physical is not printed:
      // with a Hankel matrix as ill-conditioned as the examples' (3e11), a
      // root at the edge of the stability test moves across it with the
      // round-off of another CPU's vector instructions (45 or 46 physical of
      // the example's 54), while the kept modes and E do not change.
      text +=
        "Roots of the LSCE polynomials: " + std::to_string(poles.roots) + "; rejected " +
        std::to_string(poles.unstable) + " unstable, " + std::to_string(poles.out_of_band) +
        " out of band; of the other " + std::to_string(poles.spurious + poles.physical) +
        ", those not stable across orders as spurious" +
        "\nLargest condition estimate of a Hankel matrix: " + format_printf("%.3g", condition) +
        "\n";
      if (parameters.bands == 0)
        text += "Zoom LSCE (8 bands) used for " + std::to_string(bands_used) + " of " +
                std::to_string(pairs.size()) + " FRFs (E above " +
                format_number(parameters.zoom_above_error) + " with one band)\n";
      return text;
    }



    bool
    write_worst_fit(const std::filesystem::path          &directory,
                    const base::FrequencyResponse        &frf,
                    const modal::Identification          &fit,
                    std::pair<unsigned int, unsigned int> pair,
                    const base::ParameterRecord          &record)
    {
      {
        base::AtomicFile file(directory / "worst_fit.csv");
        auto            &out = file.stream();
        out << "f,re,im,fit_re,fit_im\n";
        for (std::size_t k = 0; k < frf.values.size(); ++k)
          {
            const double         omega = 2. * M_PI * k * frf.df;
            std::complex<double> value = fit.model.frequency_response(omega) + fit.upper_residual;
            if (fit.lower_residual != 0. && k > 0)
              value -= fit.lower_residual / (omega * omega);
            out << k * frf.df << ',' << frf.values[k].real() << ',' << frf.values[k].imag() << ','
                << value.real() << ',' << value.imag() << '\n';
          }
        record.write_comments(out);
        file.commit();
      }
      const std::string data  = base::gnuplot_quote(directory / "worst_fit.csv");
      const std::string title = "g_{" + std::to_string(pair.first) + "," +
                                std::to_string(pair.second) +
                                "}: N_m = " + std::to_string(fit.n_modes) +
                                ", E = " + format_printf("%.3g", 100. * fit.error) + " %";
      return base::plot_png(
        directory / "identification_worst.png",
        "set datafile separator ','\nset multiplot layout 2,1 title 'GreenTread identify, worst "
        "fit: " +
          title +
          "'\nset grid\nset xlabel 'f [Hz]'\nset ylabel '|g| [m/N]'\n"
          "set logscale y\nset format y '10^{%L}'\nplot " +
          data +
          " skip 1 using 1:(sqrt($2**2+$3**2)) with lines lc rgb 'black' lw 2 title 'FRF', '' "
          "skip 1 using 1:(sqrt($4**2+$5**2)) with lines lc rgb '#d62728' dt 2 lw 2 title "
          "'modal fit'\nunset logscale y\nset format y '%g'\nset ylabel 'phase [deg]'\n"
          "set yrange [-180:180]\nset ytics 90\nplot " +
          data +
          " skip 1 using 1:(atan2($3,$2)*180/pi) with lines lc rgb 'black' lw 2 title 'FRF', '' "
          "skip 1 using 1:(atan2($5,$4)*180/pi) with lines lc rgb '#d62728' dt 2 lw 2 title "
          "'modal fit'\nunset multiplot\n",
        record, 1100, 800);
    }
  } // namespace analysis
} // namespace greentread
