// The per-step cost of a patch's convolution update (history and advance,
// no contact solve) against the number of points N_p, for the rank-one model
// of the ring's own modes (Patch model/Source = fe modes: O(N_p N_m) per
// step) and, where it fits in memory, the full form of the same model (a
// dense N_p x N_p residue per mode, O(N_p^2 N_m), the identified model's
// form), side by side in one run, with the largest difference of their
// displacement histories over the run.
//
// The models are synthetic: N_m modes from 60 Hz to 8 kHz with 3% damping,
// shapes of a ring's tread (cosines along and across), a small static
// residual, on a 60 x 80 mm patch of N_p points.
//
//   patch_update_cost [--quick] [--output DIR]

#include "benchmark_options.h"

#include <greentread/base/exceptions.h>
#include <greentread/contact/patch_convolution.h>
#include <greentread/modal/mode_synthesis.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <thread>

using namespace greentread;

namespace
{
  modal::PatchModel
  synthetic_modes(const unsigned int nx, const unsigned int ny, const unsigned int n_modes)
  {
    modal::ModeSynthesis s;
    const unsigned int   P = nx * ny;
    for (unsigned int i = 0; i < nx; ++i)
      for (unsigned int j = 0; j < ny; ++j)
        s.points.push_back({{0.06 * ((i + 0.5) / nx - 0.5), 0.08 * ((j + 0.5) / ny - 0.5), 0.27}});
    s.frequency_hz.resize(n_modes);
    s.damping_ratio = Eigen::VectorXd::Constant(n_modes, 0.03);
    s.shapes.resize(n_modes, P);
    for (unsigned int k = 0; k < n_modes; ++k)
      {
        s.frequency_hz(k) = 60. * std::pow(8000. / 60., (k + 0.5) / n_modes);
        const double a = 1. + k % 17, b = 1. + k % 5;
        for (unsigned int p = 0; p < P; ++p)
          s.shapes(k, p) = 0.1 * std::cos(a * M_PI * s.points[p][0] / 0.06 + k) *
                           std::cos(b * M_PI * s.points[p][1] / 0.08 + 0.3 * k);
      }
    s.instantaneous = 1e-7 * Eigen::MatrixXd::Identity(P, P);
    return modal::to_patch_model(s, Eigen::MatrixXd(), 4000.);
  }


  struct Timing
  {
    double                       ms_per_step = 0.;
    std::vector<Eigen::VectorXd> u;
  };

  /// @p steps steps of history + advance under a load that varies smoothly.
  Timing
  time_update(contact::PatchConvolution &c, const unsigned int steps, const bool keep)
  {
    const unsigned int P = c.n_points();
    Eigen::VectorXd    u(P), v(P);
    contact::PatchLoad load(P);
    Timing             t;
    const auto         start = std::chrono::steady_clock::now();
    for (unsigned int n = 0; n < steps; ++n)
      {
        c.history(u, v);
        if (keep)
          t.u.push_back(u);
        for (unsigned int p = 0; p < P; ++p)
          {
            load.component[1](p) = 1. + std::sin(1e-2 * n + p);
            load.component[2](p) = 1. + std::sin(1e-2 * (n + 1) + p);
          }
        c.advance(load);
      }
    t.ms_per_step =
      1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
    return t;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      const auto         options = benchmark::parse(argc, argv, "patch_update_cost");
      const unsigned int threads = std::min(2u, std::max(1u, std::thread::hardware_concurrency()));
      const unsigned int n_modes = options.quick ? 200 : 3000;
      const unsigned int steps   = options.quick ? 50 : 300;
      const double       dt      = 15.36e-6; // one road sample of 384 um at 90 km/h
      std::cout << "Patch convolution update per step (history + advance, no contact), " << n_modes
                << " modes, dt = 15.36 us, " << threads << " threads, " << steps << " steps\n"
                << "  N_p    form       ms/step   MB read/step  GFLOP/step  GFLOP/s  % of peak"
                   "  max |u - u_full| / max |u_full|\n";
      std::ofstream csv(options.output / "patch_update_cost.csv");
      csv << "points,form,modes,ms_per_step,mb_per_step,gflop_per_step,gflops,peak_fraction,"
             "difference\n";
      const std::vector<std::array<unsigned int, 2>> grids =
        options.quick ? std::vector<std::array<unsigned int, 2>>{{{10, 12}}, {{20, 24}}} :
                        std::vector<std::array<unsigned int, 2>>{{{10, 12}}, {{20, 24}}, {{40, 48}}};
      for (const auto &[nx, ny] : grids)
        {
          const unsigned int P     = nx * ny;
          const auto         model = synthetic_modes(nx, ny, n_modes);
          auto fast = contact::make_modal_patch_convolution(model, dt, threads);
          const Timing rank_one = time_update(*fast, steps, P == 120);
          // Per step: one pass over the N_m x N_p shapes (the modal forces of
          // four load components, then the displacement and velocity histories).
          const double bytes = 8. * n_modes * P, flops = 2. * n_modes * P * (4. + 2.);
          const auto   row   = [&](const char *form, const Timing &t, const double b,
                               const double f, const std::string &difference) {
            const double rate = f / (1e-3 * t.ms_per_step);
            std::cout << format_printf("%5.0f", P) << "    " << form
                      << format_printf("%10.3f", t.ms_per_step) << format_printf("%14.1f", b / 1e6)
                      << format_printf("%12.4f", f / 1e9) << format_printf("%9.2f", rate / 1e9)
                      << format_printf("%10.1f", 100. * rate / benchmark::peak_flops(threads)) << "   "
                      << difference << '\n';
            csv << P << ',' << form << ',' << n_modes << ',' << t.ms_per_step << ',' << b / 1e6
                << ',' << f / 1e9 << ',' << rate / 1e9 << ',' << rate / benchmark::peak_flops(threads) << ','
                << difference << '\n';
          };
          if (P != 120)
            {
              row("rank-one", rank_one, bytes, flops, "(full form not built: N_m N_p^2 residues)");
              continue;
            }
          auto         dense = contact::make_modal_patch_convolution(modal::full_form(model), dt, threads);
          const Timing full  = time_update(*dense, steps, true);
          double       diff = 0., size = 0.;
          for (unsigned int n = 0; n < steps; ++n)
            {
              diff = std::max(diff, (rank_one.u[n] - full.u[n]).cwiseAbs().maxCoeff());
              size = std::max(size, full.u[n].cwiseAbs().maxCoeff());
            }
          row("rank-one", rank_one, bytes, flops, format_printf("%.2e", diff / size));
          row("full    ", full, 2. * 2. * 8. * n_modes * double(P) * P,
              2. * 2. * 2. * n_modes * double(P) * P, "(reference)");
          if (!(diff <= 1e-9 * size))
            {
              std::cerr << "patch_update_cost: the rank-one and full forms differ by "
                        << diff / size << '\n';
              return 1;
            }
        }
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << "patch_update_cost: " << e.what() << '\n';
      return 1;
    }
}
