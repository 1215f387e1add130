#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/plot.h>
#include <greentread/scenes/sdof_scene.h>
#include <greentread/sdof/exact_solution.h>
#include <greentread/sdof/sdof_solver.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace greentread
{
  namespace scenes
  {
    SdofScene::SdofScene(dealii::ParameterHandler &prm_, const GlobalParameters &global_)
      : prm(prm_)
      , global(global_)
    {
      oscillator.parse_parameters(prm);
      road.parse_parameters(prm);
      contact.parse_parameters(prm);
      convolution.parse_parameters(prm);
      identification.parse_parameters(prm);
    }



    void
    SdofScene::run()
    {
      namespace fs = std::filesystem;
      const fs::path directory = base::prepare_output_directory(global.output_directory);
      std::vector<std::string> stages = {"Scene",   "Output directory", "Oscillator", "Road",
                                         "Contact", "Time stepping",    "Convolution"};
      if (oscillator.identified_green)
        stages.push_back("Identification");
      const auto record = base::ParameterRecord::from(prm, "sdof", stages);

      const sdof::Oscillator osc(oscillator);
      const auto             profile = road.create();
      const road::RoadTrack  track{*profile, oscillator.speed, 0.};
      const double           dt      = contact.time_step;
      const unsigned int     n_steps = contact.n_steps();

      std::cout << "GreenTread: scene 'sdof', a 1-DoF oscillator on a sinusoidal road "
                   "(Meftah et al. 2013, Section 3)\n"
                << "  oscillator: M = " << format_number(osc.mass())
                << " kg, K = " << format_number(osc.stiffness())
                << " N/m, xi = " << format_number(osc.damping_ratio())
                << ", f0 = " << format_printf("%.4g", osc.natural_frequency() / (2 * M_PI)) << " Hz\n"
                << "  road: A0 = " << format_number(road.amplitude)
                << " m, lambda_r = " << format_number(road.wavelength)
                << " m, V0 = " << format_number(oscillator.speed) << " m/s\n"
                << "  time: dt = " << format_number(dt) << " s, " << n_steps << " steps\n";

      // The round trip: the Green's function from LSCE of the oscillator's FRF.
      std::unique_ptr<modal::Identification> identified;
      if (oscillator.identified_green)
        {
          const auto frf =
            sdof::frequency_response(osc, oscillator.frf_max_frequency, oscillator.frf_line_spacing);
          identified = std::make_unique<modal::Identification>(modal::identify(frf, identification));
          const auto exact = osc.modal_model();
          double     pole_error = INFINITY;
          for (const auto &term : identified->model.terms())
            pole_error = std::min(pole_error, std::abs(term.lambda - exact.terms()[0].lambda) /
                                                std::abs(exact.terms()[0].lambda));
          std::cout << "  Green's function: identified by LSCE from the oscillator's FRF, "
                    << frf.values.size() << " lines to " << format_number(frf.f_max())
                    << " Hz: N_m = " << identified->n_modes << ", E = "
                    << format_printf("%.3g", identified->error) << ", pole error "
                    << format_printf("%.3g", pole_error) << "\n";
          modal::write_frf_csv(directory / "frf.csv", frf, record);
          base::AtomicFile file(directory / "modal_parameters.csv");
          file.stream().precision(16);
          file.stream() << "i,j,lambda_re,lambda_im,R_re,R_im\n";
          for (const auto &term : identified->model.terms())
            file.stream() << "0,0," << term.lambda.real() << ',' << term.lambda.imag() << ','
                          << term.residue.real() << ',' << term.residue.imag() << '\n';
          record.write_comments(file.stream());
          file.commit();
        }
      auto conv = sdof::make_convolution(osc, convolution, dt, n_steps,
                                         identified ? &identified->model : nullptr);
      std::cout << "  contact: " << contact::to_string(contact.law);
      if (contact.law == contact::ContactLaw::penalty)
        std::cout << " (kc = " << format_number(contact.contact_stiffness) << " N/m)";
      std::cout << "; convolution: " << conv->name()
                << (convolution.method == convolution::Method::direct ? " (N_g = " : " (N_m = ")
                << conv->size() << ")\n";

      const sdof::SdofRun run = sdof::solve(osc, track, *conv, contact);
      double              round_trip = NAN;
      if (identified)
        {
          // The same run with the exact modal form, for the round trip.
          auto       exact_conv = sdof::make_convolution(osc, convolution, dt, n_steps);
          const auto reference  = sdof::solve(osc, track, *exact_conv, contact, false);
          round_trip            = 0.;
          for (unsigned int n = 0; n <= n_steps; ++n)
            round_trip = std::max(round_trip, std::abs(run.u[n] - reference.u[n]));
        }

      const auto exact_start = std::chrono::steady_clock::now();
      const sdof::ExactSolution exact(osc, track, n_steps * dt);
      const sdof::SdofErrors    e = sdof::compare(run, exact, track);
      const double              exact_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - exact_start).count();

      // Outputs, each written under a temporary name and renamed.
      {
        base::AtomicFile file(directory / "time_history.csv");
        auto            &out = file.stream();
        out << "t,u,v,F\n";
        for (unsigned int n = 0; n <= n_steps; ++n)
          out << run.t[n] << ',' << run.u[n] << ',' << run.v[n] << ',' << run.F[n] << '\n';
        record.write_comments(out);
        file.commit();
      }
      {
        base::AtomicFile file(directory / "reference.csv");
        auto            &out = file.stream();
        out << "t,u_road,u_exact,v_exact,F_exact\n";
        for (unsigned int n = 0; n <= n_steps; ++n)
          {
            const double t = run.t[n];
            out << t << ',' << track.height(t) << ',' << exact.displacement(t) << ','
                << exact.velocity(t) << ','
                << (n == 0 ? 0. : exact.impulse(run.t[n - 1], t) / dt) << '\n';
          }
        record.write_comments(out);
        file.commit();
      }
      {
        base::AtomicFile file(directory / "summary.csv");
        auto            &out = file.stream();
        out << "quantity,value,unit\n"
            << "max_u_error," << e.max_u_error << ",m\n"
            << "max_u_error_relative_to_A0,"
            << (road.amplitude > 0 ? e.max_u_error / road.amplitude : 0.) << ",1\n"
            << "max_v_error," << e.max_v_error << ",m/s\n"
            << "max_force_error," << e.max_force_error << ",N\n"
            << "peak_contact_force," << e.peak_contact_force << ",N\n"
            << "total_impulse_error," << e.impulse_error << ",1\n"
            << "max_penetration_at_steps," << e.max_penetration_grid << ",m\n"
            << "max_penetration_inside_steps," << e.max_penetration_step << ",m\n"
            << "contact_fraction," << e.contact_fraction << ",1\n"
            << "exact_contact_fraction," << e.exact_contact_fraction << ",1\n"
            << "impacts_exact," << exact.n_impacts() << ",1\n"
            << "time_step," << dt << ",s\n"
            << "steps," << n_steps << ",1\n"
            << (convolution.method == convolution::Method::direct ? "N_g," : "N_m,")
            << run.size << ",1\n"
            << "run_time," << run.run_time << ",s\n";
        for (unsigned int b = 0; b < run.branch_count.size(); ++b)
          out << "steps_" << contact::to_string(static_cast<contact::KinematicBranch>(b)) << ','
              << run.branch_count[b] << ",1\n";
        record.write_comments(out);
        file.commit();
      }
      {
        base::AtomicFile file(directory / "parameters.prm");
        file.stream() << "# Every parameter of this run; 'greentread parameters.prm' repeats it.\n";
        prm.print_parameters(file.stream(), dealii::ParameterHandler::ShortPRM);
        file.commit();
      }

      const double force_top = std::max(1.0, 1.3 * e.peak_contact_force);
      const std::string label =
        contact::to_string(contact.law) + ", " + conv->name() + ", dt = " + format_number(dt) + " s";
      std::string commands =
        "set datafile separator ','\n"
        "set multiplot layout 2,1 title 'GreenTread sdof: " + label + "'\n"
        "set grid\nset key top right\n"
        "set xlabel 't [s]'\nset ylabel 'u [mm]'\n"
        "plot " + base::gnuplot_quote(directory / "reference.csv") +
        " skip 1 using 1:($2*1e3) with lines lc rgb '#999999' lw 2 title 'road u_r', " +
        "'' skip 1 using 1:($3*1e3) with lines lc rgb 'black' dt 2 lw 2 title 'exact', " +
        base::gnuplot_quote(directory / "time_history.csv") +
        " skip 1 using 1:($2*1e3) with lines lc rgb '#d62728' title 'computed'\n"
        "set ylabel 'contact force F [N] (mean over each step)'\n"
        "set yrange [" + format_number(-0.05 * force_top) + ":" + format_number(force_top) + "]\n"
        "plot " + base::gnuplot_quote(directory / "reference.csv") +
        " skip 1 using 1:5 with lines lc rgb 'black' dt 2 lw 2 title 'exact (impacts clipped)', " +
        base::gnuplot_quote(directory / "time_history.csv") +
        " skip 1 using 1:4 with lines lc rgb '#d62728' title 'computed'\n"
        "unset multiplot\n";
      const bool plotted =
        base::plot_png(directory / "time_history.png", commands, record, 1100, 800);

      const double a0 = road.amplitude;
      std::cout << "Errors against the exact piecewise-analytic solution ("
                << exact.n_impacts() << " impacts, " << exact.n_phases() << " phases):\n"
                // Small errors in nm, um/s and ppm: the regression tests'
                // numdiff passes any difference below 1e-6 in the printed
                // unit, which is then 1e-15 m, 1e-12 m/s and 1e-12.
                << "  max |u - u_exact|              = " << format_printf("%.4g", 1e9 * e.max_u_error) << " nm"
                << (a0 > 0 ? " (" + format_printf("%.4g", 100. * e.max_u_error / a0) + " % of A0)" : "")
                << "\n"
                << "  max |v - v_exact|              = " << format_printf("%.4g", 1e6 * e.max_v_error) << " um/s\n"
                << "  max |F - F_exact| (step means) = " << format_printf("%.4g", e.max_force_error)
                << " N (peak contact force " << format_printf("%.4g", e.peak_contact_force) << " N)\n"
                << "  total impulse error            = " << format_printf("%.4g", 1e6 * e.impulse_error) << " ppm\n"
                << "  max penetration at time steps  = " << format_printf("%.4g", 1e9 * e.max_penetration_grid)
                << " nm\n"
                << "  max penetration inside steps   = " << format_printf("%.4g", 1e9 * e.max_penetration_step)
                << " nm\n"
                << "  fraction of time in contact    = " << format_printf("%.4f", e.contact_fraction)
                << " (exact " << format_printf("%.4f", e.exact_contact_fraction) << ")\n";
      if (identified)
        std::cout << "  max |u - u(exact modal form)|  = " << format_printf("%.4g", 1e9 * round_trip)
                  << " nm (the round trip through LSCE)\n";
      if (contact.law == contact::ContactLaw::kinematic)
        {
          std::cout << "  contact steps by branch:";
          for (unsigned int b = 1; b < run.branch_count.size(); ++b)
            std::cout << ' ' << contact::to_string(static_cast<contact::KinematicBranch>(b))
                      << ' ' << run.branch_count[b];
          std::cout << '\n';
        }
      if (global.print_timings)
        std::cout << "Run time: " << format_printf("%.4g", run.run_time) << " s for the time loop ("
                  << format_printf("%.3g", 1e9 * run.run_time / n_steps) << " ns per step), "
                  << format_printf("%.3g", exact_time) << " s for the exact reference\n";
      std::cout << "Wrote time_history.csv, reference.csv, summary.csv, parameters.prm"
                << (plotted ? ", time_history.png" : "")
                << (identified ? ", frf.csv, modal_parameters.csv" : "") << " in "
                << directory.string() << "\n";
    }
  } // namespace scenes
} // namespace greentread
