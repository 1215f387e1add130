// The per-step cost of a patch's convolution update (history and advance,
// no contact solve) against the number of points N_p, for the rank-one model
// of the ring's own modes (Patch model/Source = fe modes: O(N_p N_m) per
// step) with its shapes in double and in single precision (Convolution/Shape
// precision) and, where it fits in memory, the full form of the same model (a
// dense N_p x N_p residue per mode, O(N_p^2 N_m), the identified model's
// form), side by side in one run, with the largest difference of their
// displacement histories over the run. The update runs as in a rolling run
// with a static residual: the displacement alone (history_u), the start
// load the last step's end. The rank-one update runs step by step (one pass
// over the shapes per step, the reference) and, where the update chooses
// them (at least 128 shape rows per point), in time blocks of 4, 8 and 16
// steps (one pass per block, convolution/mode_patch_convolution.h); the set-up
// (the blocks' lag kernels, formed on the first step) is printed apart from
// the time per step.
//
// The models are synthetic: N_m modes from 60 Hz to 8 kHz with 3% damping,
// shapes of a ring's tread (cosines along and across), a small static
// residual, on a 60 x 80 mm patch of N_p points.
//
// With --model DIR/modal_model.h5 (the saved stage of a run with
// 'Patch model/Source = fe modes', e.g. the main job's) the tyre's own model
// is timed too, in both precisions (its full form would not fit in memory).
//
//   patch_update_cost [--quick] [--output DIR] [--model DIR/modal_model.h5]

#include "benchmark_options.h"

#include <greentread/base/exceptions.h>
#include <greentread/convolution/mode_patch_convolution.h>
#include <greentread/convolution/patch_convolution.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <thread>

using namespace greentread;

namespace
{
  modal::PatchModel
  synthetic_modes(const unsigned int nx, const unsigned int ny, const unsigned int n_modes)
  {
    synthesis::ModeSynthesis s;
    const unsigned int       P = nx * ny;
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
    return synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.);
  }


  struct Timing
  {
    double                       ms_per_step = 0., setup_ms = 0.;
    std::vector<Eigen::VectorXd> u;
  };

  /// @p steps steps of history + advance under a load that varies smoothly.
  Timing
  time_update(convolution::PatchConvolution &c, const unsigned int steps, const bool keep)
  {
    const unsigned int     P = c.n_points();
    Eigen::VectorXd        u(P), v(P);
    convolution::PatchLoad load(P);
    Timing                 t;
    auto                   start = std::chrono::steady_clock::now();
    for (unsigned int n = 0; n < steps; ++n)
      {
        if (n == 1)
          {
            // The first step holds the set-up: timed apart.
            const auto now = std::chrono::steady_clock::now();
            t.setup_ms     = 1e3 * std::chrono::duration<double>(now - start).count();
            start          = now;
          }
        if (c.influence().instantaneous)
          c.history_u(u);
        else
          c.history(u, v);
        if (keep)
          t.u.push_back(u);
        // The start is the last step's end, as in a rolling run (the same
        // vector, not the same formula evaluated again: with contracted
        // multiply-adds two evaluations may differ in the last bit).
        load.component[1] = load.component[2];
        for (unsigned int p = 0; p < P; ++p)
          load.component[2](p) = 1. + std::sin(1e-2 * (n + 1) + p);
        c.advance(load);
      }
    t.ms_per_step =
      1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
      (steps - 1);
    return t;
  }
} // namespace

int
main(int argc, char **argv)
{
  // No thread limit: the update's two tasks must run on two threads.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  try
    {
      const auto         options = benchmark::parse(argc, argv, "patch_update_cost");
      const unsigned int threads = std::min(2u, std::max(1u, std::thread::hardware_concurrency()));
      const unsigned int n_modes = options.quick ? 200 : 3000;
      const unsigned int steps   = options.quick ? 50 : 300;
      const double       dt      = 15.36e-6; // one road sample of 384 um at 90 km/h
      std::cout << "Patch convolution update per step (history + advance, no contact), dt = "
                   "15.36 us, "
                << threads << " threads, " << steps << " steps; synthetic models of " << n_modes
                << " modes\n"
                << "  N_p  shape rows  form (shapes, steps per block)  set-up ms  ms/step  MB "
                   "read/step  GFLOP/step  GFLOP/s  % of peak  max |u - u_ref| / max |u_ref|\n";
      base::AtomicFile csv_file(options.output / "patch_update_cost.csv");
      auto            &csv = csv_file.stream();
      csv << "points,shape_rows,form,block_steps,setup_ms,ms_per_step,mb_per_step,gflop_per_step,"
             "gflops,peak_fraction,difference\n";

      struct Case
      {
        std::string       name;
        modal::PatchModel model;
        bool              full; // build the full form as the reference
      };
      std::vector<Case>                              cases;
      const std::vector<std::array<unsigned int, 2>> grids =
        options.quick ?
          std::vector<std::array<unsigned int, 2>>{{{10, 12}}, {{20, 24}}} :
          std::vector<std::array<unsigned int, 2>>{{{10, 12}}, {{20, 24}}, {{40, 48}}};
      for (const auto &[nx, ny] : grids)
        cases.push_back({"synthetic", synthetic_modes(nx, ny, n_modes), nx * ny == 120});
      if (!options.model.empty())
        {
          const auto synthesis = synthesis::read_modal_model(options.model.string());
          cases.push_back(
            {"tyre", synthesis::to_patch_model(synthesis, Eigen::MatrixXd(), 4000.), false});
          std::cout << "  (tyre: " << options.model.string() << ", " << synthesis.n_modes()
                    << " modes)\n";
        }

      for (const auto &c : cases)
        {
          const unsigned int P = c.model.n_points();
          const double rows = double(c.model.shapes.rows()) * (c.model.shapes_imag.size() ? 2 : 1);
          const auto   make = [&](const convolution::ShapePrecision precision,
                                const unsigned int                block) {
            return convolution::make_rank_one_patch_convolution(c.model, dt, threads, precision,
                                                                  block);
          };
          using convolution::ShapePrecision;
          // The reference: double shapes, step by step.
          auto         reference_conv = make(ShapePrecision::double_precision, 1);
          const Timing reference      = time_update(*reference_conv, steps, true);
          const auto   difference     = [&](const Timing &a, const Timing &b) {
            double diff = 0., size = 0.;
            for (unsigned int n = 0; n < steps; ++n)
              {
                diff = std::max(diff, (a.u[n] - b.u[n]).cwiseAbs().maxCoeff());
                size = std::max(size, b.u[n].cwiseAbs().maxCoeff());
              }
            return diff / size;
          };
          // Per step: the modal forces of the end load (one multiply-add per
          // shape value) and the displacement history (one more), step by
          // step or in blocks; the shapes read once per pass, that is once
          // per step or once per block. Single precision reads half the
          // bytes and its peak is twice double's.
          const double bytes = 8. * rows * P, flops = 2. * rows * P * 2.;
          const double peak = benchmark::peak_flops(threads);
          const auto   row = [&](const std::string &form, const unsigned int block, const Timing &t,
                               const double b, const double f, const double pk,
                               const std::string &diff) {
            const double rate = f / (1e-3 * t.ms_per_step);
            std::cout << format_printf("%5.0f", P) << format_printf("%12.0f", rows) << "  " << form
                      << std::string(8 - form.size(), ' ') << format_printf("%5.0f", block)
                      << format_printf("%28.1f", t.setup_ms)
                      << format_printf("%9.3f", t.ms_per_step) << format_printf("%14.1f", b / 1e6)
                      << format_printf("%12.4f", f / 1e9) << format_printf("%9.2f", rate / 1e9)
                      << format_printf("%10.1f", 100. * rate / pk) << "   " << diff << '\n';
            csv << P << ',' << rows << ',' << form << ',' << block << ',' << t.setup_ms << ','
                << t.ms_per_step << ',' << b / 1e6 << ',' << f / 1e9 << ',' << rate / 1e9 << ','
                << rate / pk << ',' << diff << '\n';
          };
          row("double", 1, reference, bytes, flops, peak, "(reference)");
          for (const auto precision :
               {ShapePrecision::double_precision, ShapePrecision::single_precision})
            for (const unsigned int block : {1u, 4u, 8u, 16u})
              {
                const bool single = precision == ShapePrecision::single_precision;
                if (!single && block == 1)
                  continue;
                // Blocks where the update chooses them (at least 128 shape
                // rows per point: the tyre's model, not the synthetic ones).
                if (block != 1 && rows < 128. * P)
                  continue;
                auto         conv = make(precision, block);
                const Timing t    = time_update(*conv, steps, true);
                const double diff = difference(t, reference);
                // Against the step-by-step double-precision update: single
                // precision rounds the shapes to float (1.5e-7 to 2.8e-7 on the
                // synthetic models, 1.6e-6 on the tyre's, whose sums are
                // longer); double blocks differ by round-off (2.2e-14). Bounds
                // about 3x.
                if (!(diff <= (single ? (rows > 10000 ? 5e-6 : 8e-7) : 7e-14)))
                  {
                    std::cerr << "patch_update_cost: " << (single ? "single" : "double")
                              << "-precision shapes in blocks of " << block
                              << " differ from the reference by " << diff << '\n';
                    return 1;
                  }
                row(single ? "single" : "double", block, t, (single ? 0.5 : 1.) * bytes / block,
                    flops, (single ? 2. : 1.) * peak, format_printf("%.2e", diff));
              }
          if (!c.full)
            continue;
          auto dense =
            convolution::make_modal_patch_convolution(synthesis::full_form(c.model), dt, threads);
          const Timing full = time_update(*dense, steps, true);
          const double diff = difference(full, reference);
          row("full", 1, full, 2. * 2. * 8. * rows * double(P) * P,
              2. * 2. * 2. * rows * double(P) * P, peak, format_printf("%.2e", diff));
          // The dense residues of the same modes: round-off (2.5e-15 with
          // --quick, 1.8e-14 on the full run's 3000 modes); bound 3x.
          if (!(diff <= 6e-14))
            {
              std::cerr << "patch_update_cost: the rank-one and full forms differ by " << diff
                        << '\n';
              return 1;
            }
        }
      csv_file.commit();
      std::cout << "Wrote " << (options.output / "patch_update_cost.csv").string() << '\n';
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << "patch_update_cost: " << e.what() << '\n';
      return 1;
    }
}
