#include <greentread/analysis/sdof_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>
#include <greentread/contact/kinematic_contact.h>

#include <algorithm>

namespace greentread
{
  namespace analysis
  {
    void
    write_modal_parameters(const std::filesystem::path &file_name,
                           const modal::ModalModel     &model,
                           const base::ParameterRecord &record)
    {
      base::AtomicFile file(file_name);
      file.stream().precision(16);
      file.stream() << "i,j,lambda_re,lambda_im,R_re,R_im\n";
      for (const auto &term : model.terms())
        file.stream() << "0,0," << term.lambda.real() << ',' << term.lambda.imag() << ','
                      << term.residue.real() << ',' << term.residue.imag() << '\n';
      record.write_comments(file.stream());
      file.commit();
    }



    void
    write_time_history(const std::filesystem::path &file_name,
                       const sdof::SdofRun         &run,
                       const base::ParameterRecord &record)
    {
      base::AtomicFile file(file_name);
      auto            &out = file.stream();
      out << "t,u,v,F\n";
      for (std::size_t n = 0; n < run.t.size(); ++n)
        out << run.t[n] << ',' << run.u[n] << ',' << run.v[n] << ',' << run.F[n] << '\n';
      record.write_comments(out);
      file.commit();
    }



    void
    write_reference(const std::filesystem::path &file_name,
                    const sdof::SdofRun         &run,
                    const sdof::ExactSolution   &exact,
                    const road::RoadTrack       &track,
                    const base::ParameterRecord &record)
    {
      base::AtomicFile file(file_name);
      auto            &out = file.stream();
      out << "t,u_road,u_exact,v_exact,F_exact\n";
      for (std::size_t n = 0; n < run.t.size(); ++n)
        {
          const double t = run.t[n];
          out << t << ',' << track.height(t) << ',' << exact.displacement(t) << ','
              << exact.velocity(t) << ','
              << (n == 0 ? 0. : exact.impulse(run.t[n - 1], t) / run.time_step) << '\n';
        }
      record.write_comments(out);
      file.commit();
    }



    void
    write_summary(const std::filesystem::path &file_name,
                  const sdof::SdofRun         &run,
                  const sdof::SdofErrors      &e,
                  const sdof::ExactSolution   &exact,
                  const double                 a0,
                  const std::string           &size_name,
                  const base::ParameterRecord &record)
    {
      base::AtomicFile file(file_name);
      auto            &out = file.stream();
      out << "quantity,value,unit\n"
          << "max_u_error," << e.max_u_error << ",m\n"
          << "max_u_error_relative_to_A0," << (a0 > 0 ? e.max_u_error / a0 : 0.) << ",1\n"
          << "max_v_error," << e.max_v_error << ",m/s\n"
          << "max_force_error," << e.max_force_error << ",N\n"
          << "peak_contact_force," << e.peak_contact_force << ",N\n"
          << "total_impulse_error," << e.impulse_error << ",1\n"
          << "max_penetration_at_steps," << e.max_penetration_grid << ",m\n"
          << "max_penetration_inside_steps," << e.max_penetration_step << ",m\n"
          << "contact_fraction," << e.contact_fraction << ",1\n"
          << "exact_contact_fraction," << e.exact_contact_fraction << ",1\n"
          << "impacts_exact," << exact.n_impacts() << ",1\n"
          << "time_step," << run.time_step << ",s\n"
          << "steps," << run.t.size() - 1 << ",1\n"
          << size_name << ',' << run.size << ",1\n"
          << "run_time," << run.run_time << ",s\n";
      for (unsigned int b = 0; b < run.branch_count.size(); ++b)
        out << "steps_" << contact::to_string(static_cast<contact::KinematicBranch>(b)) << ','
            << run.branch_count[b] << ",1\n";
      record.write_comments(out);
      file.commit();
    }



    bool
    plot_time_history(const std::filesystem::path &directory,
                      const std::string           &label,
                      const double                 peak_force,
                      const base::ParameterRecord &record)
    {
      const double      force_top = std::max(1.0, 1.3 * peak_force);
      const std::string commands =
        "set datafile separator ','\n"
        "set multiplot layout 2,1 title 'GreenTread sdof: " +
        label +
        "'\n"
        "set grid\nset key top right\n"
        "set xlabel 't [s]'\nset ylabel 'u [mm]'\n"
        "plot " +
        base::gnuplot_quote(directory / "reference.csv") +
        " skip 1 using 1:($2*1e3) with lines lc rgb '#999999' lw 2 title 'road u_r', " +
        "'' skip 1 using 1:($3*1e3) with lines lc rgb 'black' dt 2 lw 2 title 'exact', " +
        base::gnuplot_quote(directory / "time_history.csv") +
        " skip 1 using 1:($2*1e3) with lines lc rgb '#d62728' title 'computed'\n"
        "set ylabel 'contact force F [N] (mean over each step)'\n"
        "set yrange [" +
        format_number(-0.05 * force_top) + ":" + format_number(force_top) +
        "]\n"
        "plot " +
        base::gnuplot_quote(directory / "reference.csv") +
        " skip 1 using 1:5 with lines lc rgb 'black' dt 2 lw 2 title 'exact (impacts clipped)', " +
        base::gnuplot_quote(directory / "time_history.csv") +
        " skip 1 using 1:4 with lines lc rgb '#d62728' title 'computed'\n"
        "unset multiplot\n";
      return base::plot_png(directory / "time_history.png", commands, record, 1100, 800);
    }



    std::string
    describe_errors(const sdof::SdofErrors &e, const sdof::ExactSolution &exact, const double a0)
    {
      return "Errors against the exact piecewise-analytic solution (" +
             std::to_string(exact.n_impacts()) + " impacts, " + std::to_string(exact.n_phases()) +
             " phases):\n"
             "  max |u - u_exact|              = " +
             format_printf("%.4g", 1e9 * e.max_u_error) + " nm" +
             (a0 > 0 ? " (" + format_printf("%.4g", 100. * e.max_u_error / a0) + " % of A0)" : "") +
             "\n"
             "  max |v - v_exact|              = " +
             format_printf("%.4g", 1e6 * e.max_v_error) +
             " um/s\n"
             "  max |F - F_exact| (step means) = " +
             format_printf("%.4g", e.max_force_error) + " N (peak contact force " +
             format_printf("%.4g", e.peak_contact_force) +
             " N)\n"
             "  total impulse error            = " +
             format_printf("%.4g", 1e6 * e.impulse_error) +
             " ppm\n"
             "  max penetration at time steps  = " +
             format_printf("%.4g", 1e9 * e.max_penetration_grid) +
             " nm\n"
             "  max penetration inside steps   = " +
             format_printf("%.4g", 1e9 * e.max_penetration_step) +
             " nm\n"
             "  fraction of time in contact    = " +
             format_printf("%.4f", e.contact_fraction) + " (exact " +
             format_printf("%.4f", e.exact_contact_fraction) + ")\n";
    }
  } // namespace analysis
} // namespace greentread
