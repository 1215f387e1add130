#include <greentread/analysis/sdof_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/scenes/sdof_scene.h>
#include <greentread/sdof/exact_solution.h>
#include <greentread/sdof/sdof_solver.h>

#include <algorithm>
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



    namespace
    {
      /// What the scene rolls: the oscillator, the road, the time stepping.
      void
      print_setup(const sdof::Oscillator     &osc,
                  const road::RoadParameters &road,
                  const double                speed,
                  const double                dt,
                  const unsigned int          n_steps)
      {
        std::cout << "GreenTread: scene 'sdof', a 1-DoF oscillator on a sinusoidal road "
                     "(Meftah et al. 2013, Section 3)\n"
                  << "  oscillator: M = " << format_number(osc.mass())
                  << " kg, K = " << format_number(osc.stiffness())
                  << " N/m, xi = " << format_number(osc.damping_ratio())
                  << ", f0 = " << format_printf("%.4g", osc.natural_frequency() / (2 * M_PI))
                  << " Hz\n"
                  << "  road: A0 = " << format_number(road.amplitude)
                  << " m, lambda_r = " << format_number(road.wavelength)
                  << " m, V0 = " << format_number(speed) << " m/s\n"
                  << "  time: dt = " << format_number(dt) << " s, " << n_steps << " steps\n";
      }

      /// The largest |u - u'| between @p run and the same run with the
      /// oscillator's exact modal form: the round trip through LSCE [m].
      double
      round_trip_error(const sdof::Oscillator                   &osc,
                       const road::RoadTrack                    &track,
                       const sdof::SdofRun                      &run,
                       const convolution::ConvolutionParameters &convolution,
                       const contact::ContactParameters         &contact,
                       const double                              dt,
                       const unsigned int                        n_steps)
      {
        auto       exact_conv = sdof::make_convolution(osc, convolution, dt, n_steps);
        const auto reference  = sdof::solve(osc, track, *exact_conv, contact, false);
        double     error      = 0.;
        for (unsigned int n = 0; n <= n_steps; ++n)
          error = std::max(error, std::abs(run.u[n] - reference.u[n]));
        return error;
      }

      /// The kinematic rule's steps by branch, when it counted them.
      void
      print_branches(const sdof::SdofRun &run)
      {
        if (run.branches)
          {
            std::cout << "  contact steps by branch:";
            for (unsigned int b = 1; b < run.branch_count.size(); ++b)
              std::cout << ' ' << contact::to_string(static_cast<contact::KinematicBranch>(b))
                        << ' ' << run.branch_count[b];
            std::cout << '\n';
          }
      }
    } // namespace



    void
    SdofScene::run()
    {
      namespace fs                       = std::filesystem;
      const fs::path           directory = base::prepare_output_directory(global.output_directory);
      std::vector<std::string> stages    = {"Scene",   "Output directory", "Oscillator", "Road",
                                            "Contact", "Time stepping",    "Convolution"};
      if (oscillator.identified_green)
        stages.push_back("Identification");
      const auto record = base::ParameterRecord::from(prm, "sdof", stages);

      const sdof::Oscillator osc(oscillator);
      const auto             profile = road.create();
      const road::RoadTrack  track{*profile, oscillator.speed, 0.};
      const double           dt      = contact.time_step;
      const unsigned int     n_steps = contact.n_steps();

      print_setup(osc, road, oscillator.speed, dt, n_steps);

      // The round trip: the Green's function from LSCE of the oscillator's FRF.
      std::unique_ptr<sdof::IdentifiedGreen> identified;
      if (oscillator.identified_green)
        {
          identified = std::make_unique<sdof::IdentifiedGreen>(
            sdof::identify_green(osc, oscillator, identification));
          std::cout << "  Green's function: identified by LSCE from the oscillator's FRF, "
                    << identified->frf.values.size() << " lines to "
                    << format_number(identified->frf.f_max())
                    << " Hz: N_m = " << identified->identification.n_modes
                    << ", E = " << format_printf("%.3g", identified->identification.error)
                    << ", pole error " << format_printf("%.3g", identified->pole_error) << "\n";
          base::write_frf_csv(directory / "frf.csv", identified->frf, record);
          analysis::write_modal_parameters(directory / "modal_parameters.csv",
                                           identified->identification.model, record);
        }
      auto              conv = sdof::make_convolution(osc, convolution, dt, n_steps,
                                         identified ? &identified->identification.model : nullptr);
      const std::string size_name =
        convolution.method == convolution::Method::direct ? "N_g" : "N_m";
      std::cout << "  contact: " << contact.describe() << "; convolution: " << conv->name() << " ("
                << size_name << " = " << conv->size() << ")\n";

      const sdof::SdofRun run = sdof::solve(osc, track, *conv, contact);
      // The same run with the exact modal form, for the round trip.
      const double round_trip =
        identified ? round_trip_error(osc, track, run, convolution, contact, dt, n_steps) : NAN;

      const auto                exact_start = std::chrono::steady_clock::now();
      const sdof::ExactSolution exact(osc, track, n_steps * dt);
      const sdof::SdofErrors    e = sdof::compare(run, exact, track);
      const double              exact_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - exact_start).count();

      analysis::write_time_history(directory / "time_history.csv", run, record);
      analysis::write_reference(directory / "reference.csv", run, exact, track, record);
      analysis::write_summary(directory / "summary.csv", run, e, exact, road.amplitude, size_name,
                              record);
      {
        base::AtomicFile file(directory / "parameters.prm");
        file.stream() << "# Every parameter of this run; 'greentread parameters.prm' repeats it.\n";
        prm.print_parameters(file.stream(), dealii::ParameterHandler::ShortPRM);
        file.commit();
      }
      const bool plotted =
        analysis::plot_time_history(directory,
                                    contact::to_string(contact.law) + ", " + conv->name() +
                                      ", dt = " + format_number(dt) + " s",
                                    e.peak_contact_force, record);

      std::cout << analysis::describe_errors(e, exact, road.amplitude);
      if (identified)
        std::cout << "  max |u - u(exact modal form)|  = "
                  << format_printf("%.4g", 1e9 * round_trip)
                  << " nm (the round trip through LSCE)\n";
      print_branches(run);
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
