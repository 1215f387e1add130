#include <greentread/analysis/green_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>

#include <cmath>

namespace greentread
{
  namespace analysis
  {
    void
    write_contact_points(const std::filesystem::path  &file_name,
                         const periodic::ContactPatch &patch,
                         const base::ParameterRecord  &record)
    {
      base::AtomicFile file(file_name);
      auto            &o = file.stream();
      o.precision(10);
      o << "point,i_x,i_y,x,y,radius,load_dofs\n";
      for (unsigned int p = 0; p < patch.points.size(); ++p)
        {
          const auto &c = patch.points[p];
          o << p << ',' << p / patch.points_across << ',' << p % patch.points_across << ',' << c.x
            << ',' << c.y << ',' << c.radius << ',' << c.load.size() << '\n';
        }
      record.write_comments(o);
      file.commit();
    }



    GreenPairFiles
    write_green_pairs(const std::filesystem::path                              &directory,
                      const base::FrequencyResponseMatrix                      &green,
                      const std::vector<std::pair<unsigned int, unsigned int>> &pairs,
                      const std::string                                        &title,
                      const base::ParameterRecord                              &record)
    {
      GreenPairFiles files;
      std::string    magnitude, phase;
      const char    *colours[] = {"black", "#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b"};
      for (std::size_t n = 0; n < pairs.size(); ++n)
        {
          const auto [i, j]      = pairs[n];
          const std::string name = "green_" + std::to_string(i) + "_" + std::to_string(j) + ".csv";
          base::write_frf_csv(directory / name, green.get(i, j), record);
          files.csv.push_back(name);
          const std::string data  = base::gnuplot_quote(directory / name);
          const std::string style = "with lines lw 2 lc rgb '" + std::string(colours[n % 6]) +
                                    "' title 'g_{" + std::to_string(i) + "," + std::to_string(j) +
                                    "}'";
          magnitude += (n ? ", " : "plot ") + data + " skip 1 using 1:(sqrt($2**2+$3**2)) " + style;
          phase += (n ? ", " : "plot ") + data + " skip 1 using 1:(atan2($3,$2)*180/pi) " + style;
        }
      files.plotted = base::plot_png(
        directory / "green_functions.png",
        "set datafile separator ','\nset datafile commentschars '#'\nset multiplot layout 2,1 "
        "title '" +
          title +
          "'\nset grid\nset xlabel 'f [Hz]'\nset ylabel '|g| [m/N]'\n"
          "set logscale y\nset format y '10^{%L}'\n" +
          magnitude +
          "\nunset logscale y\nset format y '%g'\nset ylabel 'phase [deg]'\nset yrange "
          "[-180:180]\nset ytics 90\n" +
          phase + "\nunset multiplot\n",
        record, 1100, 800);
      return files;
    }



    std::string
    summarise_pairs(const base::FrequencyResponseMatrix                      &green,
                    const std::vector<std::pair<unsigned int, unsigned int>> &pairs)
    {
      // The driving point: resonance and passivity at a glance.
      const auto   driving = green.get(pairs.front().first, pairs.front().second);
      unsigned int peak    = 0;
      for (unsigned int k = 1; k < driving.values.size(); ++k)
        if (std::abs(driving.values[k]) > std::abs(driving.values[peak]))
          peak = k;
      const auto transfer = green.get(pairs.back().first, pairs.back().second);
      return "Driving point " + std::to_string(pairs.front().first) + ": static receptance " +
             format_printf("%.6g", 1e6 * driving.values[0].real()) + " um/N, largest |g| " +
             format_printf("%.6g", 1e6 * std::abs(driving.values[peak])) + " um/N at " +
             format_number(peak * driving.df) + " Hz; g at f_max " +
             format_printf("%.6g", 1e6 * driving.values.back().real()) + " " +
             format_printf("%+.6g", 1e6 * driving.values.back().imag()) + "j um/N\nTransfer g_" +
             std::to_string(pairs.back().first) + "," + std::to_string(pairs.back().second) +
             ": static " + format_printf("%.6g", 1e6 * transfer.values[0].real()) +
             " um/N, at f_max " + format_printf("%.6g", 1e6 * transfer.values.back().real()) + " " +
             format_printf("%+.6g", 1e6 * transfer.values.back().imag()) + "j um/N\n";
    }
  } // namespace analysis
} // namespace greentread
