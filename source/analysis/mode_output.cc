#include <greentread/analysis/mode_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>

#include <algorithm>
#include <iostream>

namespace greentread
{
  namespace analysis
  {
    void
    write_dispersion(const std::filesystem::path &directory,
                     const synthesis::Dispersion &dispersion,
                     const double                 cutoff_hz,
                     const base::ParameterRecord &record)
    {
      const auto csv = directory / "dispersion.csv";
      {
        base::AtomicFile f(csv);
        f.stream() << "wavenumber,branch,frequency_Hz,damping_ratio\n";
        for (std::size_t k = 0; k < dispersion.frequency_hz.size(); ++k)
          for (Eigen::Index b = 0; b < dispersion.frequency_hz[k].size(); ++b)
            f.stream() << k << ',' << b << ','
                       << format_printf("%.10g", dispersion.frequency_hz[k](b)) << ','
                       << format_printf("%.6g", dispersion.damping_ratio[k](b)) << '\n';
        record.write_comments(f.stream());
        f.commit();
      }
      base::plot_png(
        directory / "dispersion.png",
        "set datafile separator ','\nset datafile commentschars '#'\n"
        "set title 'Dispersion curves of the ring (Bloch modes per circumferential "
        "wavenumber)'\nset xlabel 'circumferential wavenumber n'\n"
        "set ylabel 'natural frequency [Hz]'\nset grid\n"
        "set key outside bottom center horizontal\nset xrange [0:" +
          std::to_string(dispersion.frequency_hz.size() > 1 ? dispersion.frequency_hz.size() - 1 :
                                                              1) +
          "]\nset yrange [0:" + format_printf("%.10g", 1.05 * cutoff_hz) +
          "]\n"
          "plot " +
          base::gnuplot_quote(csv) +
          " skip 1 using 1:3 with points pt 7 ps 0.3 lc rgb '#5e3c99' title 'Bloch modes', " +
          format_printf("%.10g", cutoff_hz) + " with lines dt 2 lc rgb 'black' title 'cut-off'\n",
        record);
    }



    void
    report_synthesis(const std::filesystem::path      &directory,
                     const synthesis::ModeSynthesis   &synthesis,
                     const synthesis::SynthesisErrors &errors,
                     const base::ParameterRecord      &record)
    {
      const unsigned int n_p      = synthesis.shapes.cols();
      double             diagonal = 0.;
      for (unsigned int i = 0; i < n_p; ++i)
        diagonal = std::max(diagonal, errors.pair_error[i * n_p + i]);
      std::cout << "  modal synthesis against the direct Green's functions, E of Eq. (50) "
                   "over the "
                << errors.pair_error.size() << " pairs: median "
                << format_printf("%.3f", 100. * errors.median) << "%, 90th percentile "
                << format_printf("%.3f", 100. * errors.p90) << "%, largest "
                << format_printf("%.3f", 100. * errors.worst) << "% (pair " << errors.worst_i
                << ", " << errors.worst_j << "; driving points at most "
                << format_printf("%.3f", 100. * diagonal) << "%), " << synthesis.n_modes()
                << " modes\n"
                << "  passivity: smallest eigenvalue of -Im g over its largest, over the lines "
                << format_printf("%.2g", errors.passivity)
                << "; static residual G_r: smallest eigenvalue over its largest "
                << format_printf("%.2g", synthesis.residual_definiteness()) << '\n';
      base::AtomicFile f(directory / "modal_errors.csv");
      f.stream() << "i,j,E\n";
      for (unsigned int i = 0; i < n_p; ++i)
        for (unsigned int j = 0; j < n_p; ++j)
          f.stream() << i << ',' << j << ',' << errors.pair_error[i * n_p + j] << '\n';
      record.write_comments(f.stream());
      f.commit();
    }
  } // namespace analysis
} // namespace greentread
