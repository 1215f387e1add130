// The whole fast pipeline against the finite-element transient:
// the rolling contact of a coarse ring, computed by GreenTread's fast paths
// (a patch model, LSCE or the ring's own modes, with a convolution, direct
// or modal-recursive) and by the reference, which uses none of them: the
// full ring, all N cells assembled, integrated by Newmark's average
// acceleration, with the contact solved at the same points each step
// (reference/newmark_ring.h). Same ring, points, road, static start and
// contact law: only the structure's response differs.
//
// 1. The structure alone (no contact), under a smooth 2 ms force pulse at
//    every point: the ring's modes at each cut-off with the exact recursion
//    against the reference, for dt = 40, 20, 10, 5 us, with a damping that
//    the modes diagonalise (no inflation, one loss factor) and with the
//    tyre's per-layer damping; the observed order in dt.
// 2. The rolling contact over the sinusoid and road-A at 90 km/h over
//    0.3 m, one road sample per step, on the 4 x 3 points the coarse ring
//    resolves: each path's run time and its
//    difference from the reference, for the total force and the centre
//    point's stress: the largest difference over the peak, the largest
//    band-level difference (one-third octaves from the lowest band the
//    record resolves to 5 kHz), the mean force, and the contact's matrix at
//    the centre point (its displacement at a step's end per unit force at
//    that end), which decides the forces at the step's scale.
// 3. The same with dt halved, with the highest cut-off.
// 4. The tread surface's mass moved inward ('Materials/Tread pattern/Surface
//    mass = moved inward'), in the reference and in the modes alike: the
//    contact nodes carry no mass, and dt is halved twice for every cut-off;
//    beside each run, how far its force moved from the run at twice its step.
// 5. The same with a damping the modes diagonalise (no inflation, the tread's
//    loss factor 0.1 everywhere, so C = aM + bK): what is left when the
//    damping's modal coupling is not in the way.
//
//   fe_transient [--quick] [--output DIR] [--part N]   (N = 1..5; default: all)

#include "benchmark_options.h"
#include <greentread/base/exceptions.h>
#include <greentread/reference/transient_comparison.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

using namespace greentread;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const auto    options = benchmark::parse(argc, argv, "fe_transient");
      const bool    quick   = options.quick;
      std::ofstream csv(options.output / "fe_transient.csv");
      csv << "study,damping,road,path,modes,dt_us,seconds,difference,stress_difference,"
             "force_band_dB,stress_band_dB,mean_force_N,step_compliance_m_per_N,rms_difference\n";

      reference::TransientCaseSetup setup;
      setup.geo_file   = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
      setup.patch.load = periodic::PointLoad::tributary_area;
      setup.distance   = quick ? 0.03 : 0.3;
      if (quick)
        {
          setup.patch.points_along  = 4;
          setup.patch.points_across = 3;
        }
      const std::vector<double> cutoffs =
        quick ? std::vector<double>{4000.} : std::vector<double>{4000., 8000., 16000.};
      const std::vector<double> steps =
        quick ? std::vector<double>{4e-5, 2e-5} : std::vector<double>{4e-5, 2e-5, 1e-5, 5e-6};

      const auto wanted = [&](const unsigned int part) {
        return options.part == 0 || options.part == part;
      };
      // 1. The structure alone.
      benchmark::Checks checks("fe_transient");
      for (const bool proportional : {true, false})
        if (wanted(1))
          {
            reference::TransientCaseSetup structure = setup;
            structure.proportional_damping          = proportional;
            structure.max_frequency                 = 0.;
            const reference::TransientCase study(structure);
            const char                    *damping = proportional ? "proportional" : "per-layer";
            std::printf("The structure alone, %s damping (%s):\n%s\n", damping,
                        proportional ? "no inflation, loss factor 0.05 everywhere" :
                                       "the tyre's, inflated",
                        study.describe().c_str());
            std::vector<reference::PathModel>         models;
            std::vector<const reference::PathModel *> pointers;
            for (const double f : cutoffs)
              models.push_back(study.mode_model(f));
            for (const auto &m : models)
              pointers.push_back(&m);
            std::printf(
              "  max |u - u_ref| / max |u_ref| under a 2 ms pulse, modal recursion:\n  %-8s",
              "dt [us]");
            for (const auto &m : models)
              std::printf(" %14s (%5u modes, %5.1f s)", m.name.c_str(), m.model.n_terms(),
                          m.seconds);
            std::printf("   order\n");
            double previous = NAN;
            for (const double dt : steps)
              {
                const auto   start = std::chrono::steady_clock::now();
                const auto   e     = study.driven_difference(pointers, dt, 2e-3);
                const double took =
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                std::printf("  %-8.4g", 1e6 * dt);
                for (std::size_t m = 0; m < e.size(); ++m)
                  {
                    std::printf(" %39.3e", e[m]);
                    csv << "structure," << damping << ",pulse,\"" << models[m].name << "\","
                        << models[m].model.n_terms() << ',' << 1e6 * dt << ',' << took << ','
                        << e[m] << ",,,,,,\n";
                  }
                std::printf("   %s\n",
                            std::isnan(previous) ?
                              "" :
                              format_printf("%.2f", std::log2(previous / e.back())).c_str());
                // Against the finite-element transient at dt = 20 us, a step
                // of both runs: 1.69e-4 to 1.93e-4 (bound about 3x), at
                // second order from 40 us (1.97 to 2.00).
                if (std::abs(dt - 20e-6) < 1e-12)
                  {
                    checks.at_most(std::string(damping) + " damping, the modes against the FE "
                                                          "transient at dt = 20 us",
                                   e.back(), 5.5e-4);
                    checks.at_least(std::string(damping) + " damping, order from 40 to 20 us",
                                    std::log2(previous / e.back()), 1.8);
                  }
                std::fflush(stdout);
                previous = e.back();
              }
            std::printf("\n");
          }

      // 2. The rolling contact.
      reference::TransientCaseSetup rolling = setup;
      rolling.patch.points_along            = 4;
      rolling.patch.points_across           = 3;
      // The mean of a run's total force [N].
      const auto mean = [](const std::vector<double> &f) {
        double sum = 0.;
        for (const double x : f)
          sum += x;
        return sum / f.size();
      };
      if (wanted(2) || wanted(3))
        {
          std::printf("Building the rolling case: Green's functions every %g Hz to %g Hz, the LSCE "
                      "patch model, the modes...\n",
                      setup.frequency_step, setup.max_frequency);
          std::fflush(stdout);
          // The coarse ring resolves 4 x 3 points on the patch: with 10 x 12, many
          // rectangles share one 4 cm face, their loads are dependent and G(0) is
          // singular (the static contact's LCP refuses it).
          const reference::TransientCase study(rolling);
          std::printf("%s\n", study.describe().c_str());
          // The contact's matrix is the response within one step: it needs the
          // modes up to about 1 / dt (65 kHz here), so the cut-off goes higher.
          std::vector<reference::PathModel> models;
          models.push_back(study.lsce_model());
          std::vector<double> rolling_cutoffs = cutoffs;
          if (!quick)
            rolling_cutoffs.push_back(32000.);
          for (const double f : rolling_cutoffs)
            models.push_back(study.mode_model(f));
          const double dt = study.road_time_step();
          for (const std::string road : {"sinusoid", "road-A"})
            {
              std::printf("\n%s at %g km/h over %.2f m, dt = %.4g us (%u steps):\n", road.c_str(),
                          setup.speed_kmh, setup.distance, 1e6 * dt, study.steps(dt));
              std::printf("  %-40s %9s %11s %11s %10s %10s %11s %12s %10s\n", "path", "time [s]",
                          "dF / F_max", "ds / s_max", "dL_F [dB]", "dL_s [dB]", "mean F [N]",
                          "W_cc [m/N]", "rms dF");
              const auto reference = study.reference(road, dt);
              const auto row       = [&](const std::string &path, const unsigned int modes,
                                   const reference::TransientRun &run) {
                const auto d = reference::compare(run, reference, dt);
                std::printf("  %-40s %9.2f %11.2e %11.2e %10.2f %10.2f %11.1f %12.3e %10.3f%s\n",
                                  path.c_str(), run.seconds, d.force, d.stress, d.force_band,
                                  d.stress_band, mean(run.force), run.step_compliance, d.force_rms,
                            run.failed_steps ?
                                    format_printf("  (%g failed steps)", run.failed_steps).c_str() :
                                    "");
                std::fflush(stdout);
                // The path's name has commas: quoted, as a CSV field must be.
                csv << "rolling,per-layer," << road << ",\"" << path << "\"," << modes << ','
                    << 1e6 * dt << ',' << run.seconds << ',' << d.force << ',' << d.stress << ','
                    << d.force_band << ',' << d.stress_band << ',' << mean(run.force) << ','
                    << run.step_compliance << ',' << d.force_rms << '\n';
              };
              row("reference: Newmark, full ring", 0, reference);
              for (std::size_t m = 0; m < models.size(); ++m)
                for (const auto method :
                     {convolution::Method::direct, convolution::Method::modal_recursive})
                  {
                    // The direct sum's kernels cost N_m N_p^2 per lag: the two smallest models
                    // only.
                    if (method == convolution::Method::direct && m > 1)
                      continue;
                    row(models[m].name + ", " + convolution::to_string(method),
                        models[m].model.n_terms(), study.fast(road, dt, models[m], method));
                  }
            }
          // 3. dt halved, with the highest cut-off: does the contact follow?
          if (!quick && wanted(3))
            {
              const auto  &model = models.back();
              const double half  = 0.5 * dt;
              std::printf("\nHalf the time step, %s (modal-recursive), dt = %.4g us:\n",
                          model.name.c_str(), 1e6 * half);
              std::printf("  %-10s %11s %11s %10s %10s %14s %14s %10s\n", "road", "dF / F_max",
                          "ds / s_max", "dL_F [dB]", "dL_s [dB]", "W_cc ref [m/N]",
                          "W_cc fast [m/N]", "rms dF");
              for (const std::string road : {"sinusoid", "road-A"})
                {
                  const auto reference = study.reference(road, half);
                  const auto run =
                    study.fast(road, half, model, convolution::Method::modal_recursive);
                  const auto d = reference::compare(run, reference, half);
                  std::printf("  %-10s %11.2e %11.2e %10.2f %10.2f %14.3e %14.3e %10.3f\n",
                              road.c_str(), d.force, d.stress, d.force_band, d.stress_band,
                              reference.step_compliance, run.step_compliance, d.force_rms);
                  std::fflush(stdout);
                  csv << "rolling half dt,per-layer," << road << ",\"" << model.name << "\","
                      << model.model.n_terms() << ',' << 1e6 * half << ',' << run.seconds << ','
                      << d.force << ',' << d.stress << ',' << d.force_band << ',' << d.stress_band
                      << ",," << run.step_compliance << ',' << d.force_rms << '\n';
                }
            }
        }
      // 4. The tread surface's mass moved inward, in the reference and in the
      //    modes alike: dt halved twice, every cut-off; 5. the same with a
      //    damping that the modes diagonalise.
      for (const unsigned int part : {4u, 5u})
        if (!quick && wanted(part))
          {
            reference::TransientCaseSetup massless = rolling;
            massless.surface_mass_inward           = true;
            if (part == 5)
              {
                massless.proportional_damping = true;
                massless.loss_factor          = 0.1;
              }
            const char                    *damping = part == 4 ? "per-layer" : "proportional 0.1";
            const reference::TransientCase moved(massless);
            const double                   dt = moved.road_time_step();
            std::printf("\n%u. The tread surface's mass moved inward (massless contact nodes), "
                        "%s, modal-recursive:\n%s\n",
                        part,
                        part == 4 ?
                          "the tyre's per-layer damping" :
                          "no inflation, the tread's loss factor 0.1 everywhere (C = aM + bK)",
                        moved.describe().c_str());
            std::vector<reference::PathModel> moved_models;
            for (const double f : {8000., 16000., 32000.})
              {
                moved_models.push_back(moved.mode_model(f));
                std::printf("  %s: %u terms, the residual relaxing in %.3g us\n",
                            moved_models.back().name.c_str(), moved_models.back().model.n_terms(),
                            1e6 * moved_models.back().model.residual_relaxation);
              }
            // The largest change of the total force between a run and one at
            // half its step, at their common times, over the finer one's peak.
            const auto change = [](const std::vector<double> &coarse,
                                   const std::vector<double> &fine) {
              double largest = 0., peak = 0.;
              for (std::size_t n = 1; n <= coarse.size() && 2 * n <= fine.size(); ++n)
                {
                  largest = std::max(largest, std::abs(coarse[n - 1] - fine[2 * n - 1]));
                  peak    = std::max(peak, std::abs(fine[2 * n - 1]));
                }
              return largest / peak;
            };
            for (const std::string road : {"sinusoid", "road-A"})
              {
                std::printf("  %s:\n  %-8s %-28s %9s %11s %11s %10s %10s %11s %12s %12s %8s\n",
                            road.c_str(), "dt [us]", "path", "time [s]", "dF / F_max", "ds / s_max",
                            "dL_F [dB]", "dL_s [dB]", "mean F [N]", "W_cc [m/N]", "dt/2 moves F",
                            "rms dF");
                std::vector<reference::TransientRun> previous;
                for (const double fraction : {1., 0.5, 0.25})
                  {
                    const double                         step = fraction * dt;
                    std::vector<reference::TransientRun> runs{moved.reference(road, step)};
                    for (const auto &m : moved_models)
                      runs.push_back(
                        moved.fast(road, step, m, convolution::Method::modal_recursive));
                    for (std::size_t r = 0; r < runs.size(); ++r)
                      {
                        const auto       &run  = runs[r];
                        const auto        d    = reference::compare(run, runs[0], step);
                        const std::string name = r == 0 ? "reference" : moved_models[r - 1].name;
                        const std::string moved_by =
                          previous.empty() ?
                            "" :
                            format_printf("%.3e", change(previous[r].force, run.force));
                        std::printf("  %-8.4g %-28s %9.2f %11.2e %11.2e %10.2f %10.2f %11.1f "
                                    "%12.3e %12s %8.3f\n",
                                    1e6 * step, name.c_str(), run.seconds, d.force, d.stress,
                                    d.force_band, d.stress_band, mean(run.force),
                                    run.step_compliance, moved_by.c_str(), d.force_rms);
                        csv << "rolling surface mass inward," << damping << ',' << road << ",\""
                            << name << "\"," << (r == 0 ? 0u : moved_models[r - 1].model.n_terms())
                            << ',' << 1e6 * step << ',' << run.seconds << ',' << d.force << ','
                            << d.stress << ',' << d.force_band << ',' << d.stress_band << ','
                            << mean(run.force) << ',' << run.step_compliance << ',' << d.force_rms
                            << '\n';
                      }
                    std::fflush(stdout);
                    previous = runs;
                  }
              }
          }
      std::printf("\nWrote %s\n", (options.output / "fe_transient.csv").string().c_str());
      return checks.exit_code();
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "fe_transient: %s\n", e.what());
      return 1;
    }
}
