// Error against run time of the rolling contact of a whole patch:
// the same problem with the direct convolution (the reference) and the modal
// recursion, side by side in one run: run time, time per step, the fraction
// of the machine's peak floating-point rate the modal update reaches, and
// the difference in contact stress and in one-third-octave band levels.
//
// The patch model is the default tyre's identified one (--model
// output/tyre_road_contact/patch_model.h5, written by prm/tyre_road_contact.prm
// with --set "Patch model/Source=identified" and, as it is not passive,
// --set "Patch model/Allow non-passive=true") or, without one, a
// synthetic model of the same size: 10 x 12 points and 120 modes from 100 Hz
// to 4 kHz with imaginary residues and a local compliance.
//
// modal-paper (Eq. 12-15) is not offered for patches: it overflows for the
// default tyre's poles within a few ms (see benchmarks/sdof_convergence).

#include "benchmark_options.h"

#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/contact/rolling.h>
#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <thread>

using namespace greentread;

namespace
{
  modal::PatchModel
  synthetic_model()
  {
    const unsigned int nx = 10, ny = 12, n = nx * ny, n_modes = 120;
    const double       dx = 6.684e-3, dy = 7.65e-3;
    modal::PatchModel  m;
    for (unsigned int i = 0; i < nx; ++i)
      for (unsigned int j = 0; j < ny; ++j)
        m.points.push_back({{(i - 4.5) * dx, (j - 5.5) * dy, 0.27235}});
    for (unsigned int k = 0; k < n_modes; ++k)
      {
        const double    f = 100. * std::pow(40., double(k) / (n_modes - 1));
        const double    w = 2. * M_PI * f, zeta = 0.03, wd = w * std::sqrt(1. - zeta * zeta);
        const double    kx = 0.5 + (k * 7 % 11), ky = 0.5 + (k * 5 % 13);
        Eigen::VectorXd phi(n);
        for (unsigned int p = 0; p < n; ++p)
          phi[p] = std::cos(kx * m.points[p][0] / (nx * dx) * M_PI + k) *
                   std::cos(ky * m.points[p][1] / (ny * dy) * M_PI + 0.3 * k);
        const double mass = 0.05 * (1. + k);
        m.lambda.emplace_back(-zeta * w, wd);
        m.real.push_back(false);
        m.residues.push_back((phi * phi.transpose()).cast<std::complex<double>>() /
                             std::complex<double>(0., 2. * mass * wd));
      }
    m.instantaneous = Eigen::MatrixXd::Zero(n, n);
    for (unsigned int p = 0; p < n; ++p)
      for (unsigned int q = 0; q < n; ++q)
        {
          const double r        = std::hypot((m.points[p][0] - m.points[q][0]) / dx,
                                             (m.points[p][1] - m.points[q][1]) / dy);
          m.instantaneous(p, q) = r < 1e-9 ? 5e-6 : (r < 1.01 ? 1e-6 : 0.);
        }
    m.errors = Eigen::MatrixXd::Zero(n, n);
    m.f_max  = 4000.;
    return m;
  }

  struct Run
  {
    double                       seconds = 0.;
    std::vector<double>          centre;
    std::vector<Eigen::VectorXd> stress;
    contact::RollingSummary      summary;
  };
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      const auto              options = benchmark::parse(argc, argv, "rolling_contact");
      const modal::PatchModel model =
        options.model.empty() ? synthetic_model() : modal::read_patch_model(options.model.string());
      const unsigned int n_p     = model.n_points();
      const unsigned int threads = std::min(2u, std::max(1u, std::thread::hardware_concurrency()));

      // The problem: road-A at 90 km/h, one road sample per step.
      std::vector<road::WavelengthBand> bands;
      std::vector<double>               levels;
      road::texture_preset("road-A", bands, levels);
      const double          spacing = 3.84e-4;
      const road::Texture   texture = road::synthetic_texture(bands, levels, spacing, 6000, 300, 1);
      const road::PatchRoad road(texture, model.points, road::RoadSampling::envelope, "road-A");
      const double          V = 90. / 3.6, dt = spacing / V;
      const Eigen::VectorXd tread  = contact::tread_heights(model.points);
      unsigned int          centre = 0;
      for (unsigned int p = 0; p < n_p; ++p)
        if (std::hypot(model.points[p][0], model.points[p][1]) <
            std::hypot(model.points[centre][0], model.points[centre][1]))
          centre = p;
      const contact::PatchRoadHeights heights = [&road](const double s, Eigen::VectorXd &z,
                                                        Eigen::VectorXd &slope) {
        road.heights(s, z, slope);
      };
      contact::RollingSetup setup;
      setup.speed       = V;
      setup.time_step   = dt;
      setup.static_load = 600.;
      const auto   eq   = contact::start_contact(model.static_compliance(), tread, heights, setup);
      const double area = 6.684e-3 * 7.65e-3;

      const auto run = [&](convolution::PatchConvolution &conv, const unsigned int n_steps) {
        Run        r;
        const auto observe = [&](const contact::RollingStep &s) {
          r.centre.push_back(s.force[centre] / area);
          r.stress.push_back(s.force / area);
        };
        const auto            start    = std::chrono::steady_clock::now();
        contact::RollingSetup this_run = setup;
        this_run.n_steps               = n_steps;
        r.summary = contact::roll_patch(conv, tread, heights, eq, this_run, observe);
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return r;
      };

      std::cout << "Rolling contact, " << (options.model.empty() ? "synthetic" : "tyre")
                << " patch model: " << n_p << " points, " << model.n_terms()
                << " poles; road-A at 90 km/h, dt = " << format_printf("%.4g", 1e6 * dt)
                << " us, static load 600 N\n\n";

      // 1. The timing target: 2 m with the modal recursion.
      const double       long_distance = options.quick ? 0.1 : 2.;
      const unsigned int long_steps    = static_cast<unsigned int>(long_distance / (V * dt));
      auto               modal_long = convolution::make_modal_patch_convolution(model, dt, threads);
      const Run          target     = run(*modal_long, long_steps);
      const double       flops_per_step =
        8. * n_p * double(n_p) * model.n_terms() + 8. * n_p * double(model.n_terms());
      const double rate = flops_per_step * long_steps / target.seconds;
      std::cout << "modal-recursive over " << long_distance << " m (" << long_steps
                << " steps): " << format_printf("%.2f", target.seconds) << " s ("
                << (target.seconds < 30. ? "within" : "OVER") << " the 30 s target), "
                << format_printf("%.3f", 1e3 * target.seconds / long_steps) << " ms per step, "
                << format_printf("%.2f", rate / 1e9) << " GFLOP/s in the update = "
                << format_printf("%.1f", 100. * rate / benchmark::peak_flops(threads))
                << "% of the " << threads << "-core peak ("
                << format_printf("%.0f", benchmark::peak_flops(threads) / 1e9)
                << " GFLOP/s); failed steps " << target.summary.failed_steps << "\n\n";

      // 2. Error against run time: direct (reference) and modal over a
      // distance the direct sum can afford (its cost grows with the square
      // of the steps, its kernels take 64 N_p^2 bytes per step), long enough
      // for the bands from 250 Hz.
      const double       short_distance = options.quick ? 0.05 : 0.5;
      const unsigned int short_steps    = static_cast<unsigned int>(short_distance / (V * dt));
      auto      direct    = convolution::make_direct_patch_convolution(model, dt, short_steps + 1);
      const Run reference = run(*direct, short_steps);
      auto      modal     = convolution::make_modal_patch_convolution(model, dt, threads);
      const Run fast      = run(*modal, short_steps);
      double    diff = 0., peak = 0.;
      for (unsigned int n = 0; n < short_steps; ++n)
        {
          diff = std::max(diff, (fast.stress[n] - reference.stress[n]).cwiseAbs().maxCoeff());
          peak = std::max(peak, reference.stress[n].cwiseAbs().maxCoeff());
        }
      double band_diff = NAN;
      if (short_steps * dt > 0.018)
        {
          const auto a = analysis::third_octave_spectrum(reference.centre, dt, 100., 250., 5000.);
          const auto b = analysis::third_octave_spectrum(fast.centre, dt, 100., 250., 5000.);
          band_diff    = 0.;
          for (std::size_t k = 0; k < a.level.size(); ++k)
            band_diff = std::max(band_diff, std::abs(a.level[k] - b.level[k]));
        }
      std::cout << "over " << short_distance << " m (" << short_steps << " steps):\n"
                << "  method            run time [s]   per step [ms]   max |d sigma| / max sigma"
                << "   max |d L_f| [dB], 250 Hz-5 kHz\n"
                << "  direct            " << format_printf("%12.2f", reference.seconds)
                << format_printf("%16.3f", 1e3 * reference.seconds / short_steps)
                << "   (reference)\n"
                << "  modal-recursive   " << format_printf("%12.2f", fast.seconds)
                << format_printf("%16.3f", 1e3 * fast.seconds / short_steps)
                << format_printf("%28.2e", diff / peak)
                << (std::isnan(band_diff) ? std::string("   (record too short)") :
                                            format_printf("%19.2e", band_diff))
                << "\n  modal-paper       not offered for patches (overflows)\n";
      std::ofstream csv(options.output / "rolling_contact.csv");
      csv << "method,distance_m,steps,seconds,ms_per_step,max_rel_stress_difference,"
             "max_band_difference_dB\n"
          << "modal-recursive," << long_distance << ',' << long_steps << ',' << target.seconds
          << ',' << 1e3 * target.seconds / long_steps << ",,\n"
          << "direct," << short_distance << ',' << short_steps << ',' << reference.seconds << ','
          << 1e3 * reference.seconds / short_steps << ",0,0\n"
          << "modal-recursive," << short_distance << ',' << short_steps << ',' << fast.seconds
          << ',' << 1e3 * fast.seconds / short_steps << ',' << diff / peak << ',' << band_diff
          << '\n';
      if (target.summary.failed_steps + reference.summary.failed_steps + fast.summary.failed_steps)
        {
          std::cerr << "rolling_contact: some contact solves failed\n";
          return 1;
        }
      // The recursion against the direct sum: round-off that grows with the
      // steps, 4.3e-14 over --quick's 130 steps and 6.9e-12 over the full
      // run's 1302; bounds 3x each.
      benchmark::Checks checks("rolling_contact");
      checks.at_most("stress difference, modal-recursive against direct (relative)", diff / peak,
                     options.quick ? 1.3e-13 : 2e-11);
      return checks.exit_code();
    }
  catch (const std::exception &e)
    {
      std::cerr << "rolling_contact: " << e.what() << '\n';
      return 1;
    }
}
