// How many of the ring's modes does the patch model need? The synthesis
// from the ring's own modes (Patch model/Source = fe modes) truncated at
// several cut-offs, each with its own static residual G_r = G(0) - sum over
// the kept modes, against the direct Green's functions on every line: E of
// Eq. (50) per pair (median, 90th percentile, worst, worst driving point),
// the passivity and the definiteness of G_r, beside what each costs when
// rolling: the modes kept, the bytes the update reads per step and its
// measured time per step (history and advance, N_p points, no contact).
//
// Truncating a model computed up to the highest cut-off is the model that
// cut-off computes (the modes below it are the same), so one modal stage
// serves every row.
//
//   mode_cutoff --model DIR/modal_model.h5   the saved stages of a run of the
//                                            tyre-road-contact scene with
//                                            'Patch model/Source = fe modes'
//                                            (green_functions.h5 beside it)
//   mode_cutoff [--quick]                    the tests' coarse tyre (16 cells,
//                                            4 x 3 tributary points), lines
//                                            to 2 kHz, computed here

#include "benchmark_options.h"

#include <greentread/base/exceptions.h>
#include <greentread/convolution/patch_convolution.h>
#include <greentread/periodic/green_solvers.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/synthesis/mode_synthesis.h>
#include <greentread/synthesis/mode_truncation.h>
#include <greentread/synthesis/ring_modes.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <thread>

using namespace greentread;

namespace
{
  /// The coarse tyre's direct Green's functions (lines to 2 kHz every 50 Hz)
  /// and its modes up to @p cutoff_hz.
  std::pair<base::FrequencyResponseMatrix, synthesis::ModeSynthesis>
  coarse_tyre(const double cutoff_hz)
  {
    geometry::GeometryParameters geometry;
    geometry.geo_file  = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
    geometry.mesh_size = 0.04;
    geometry.n_cells   = 16;
    periodic::PatchRequest request;
    request.load          = periodic::PointLoad::tributary_area;
    request.points_along  = 4;
    request.points_across = 3;
    request.length        = 0.06;
    request.width         = 0.05;
    const periodic::InflatedTyre tyre(geometry, fe::MaterialParameters(), fe::InflationParameters(),
                                      request);
    base::FrequencyResponseMatrix green;
    green.df      = 50.;
    green.n_lines = 41;
    for (const auto &p : tyre.patch.points)
      green.points.push_back({{p.x, p.y, p.radius}});
    const auto solver =
      periodic::make_green_solver(periodic::Method::bloch, tyre.periodic_cell, tyre.patch);
    periodic::SolveDiagnostics diagnostics;
    for (unsigned int l = 0; l < green.n_lines; ++l)
      {
        const Eigen::MatrixXcd g = solver->solve(2. * M_PI * l * green.df, diagnostics);
        for (Eigen::Index i = 0; i < g.rows(); ++i)
          for (Eigen::Index j = 0; j < g.cols(); ++j)
            green.values.push_back(g(i, j));
      }
    synthesis::ModeSearch search;
    search.cutoff = 2. * M_PI * cutoff_hz;
    const auto modes =
      synthesis::ring_modes(tyre.periodic_cell, tyre.patch, search, MPI_COMM_SELF, false);
    return {green, synthesis::synthesise(modes.omega, modes.damping_ratio, modes.shapes,
                                         modes.shapes_imag, green)};
  }

  /// Milliseconds per step of the rank-one update of @p model.
  double
  update_ms(const modal::PatchModel &model, const unsigned int threads)
  {
    const double           dt = 15.36e-6;
    auto                   c  = convolution::make_modal_patch_convolution(model, dt, threads);
    const unsigned int     P = model.n_points(), steps = 200;
    Eigen::VectorXd        u(P), v(P);
    convolution::PatchLoad load(P);
    load.component[1].setConstant(1.);
    load.component[2].setConstant(1.);
    const auto start = std::chrono::steady_clock::now();
    for (unsigned int n = 0; n < steps; ++n)
      {
        c->history(u, v);
        c->advance(load);
      }
    return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
           steps;
  }
} // namespace

int
main(int argc, char **argv)
{
  // The ring modes ask their communicator's rank: MPI must be up.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const auto         options = benchmark::parse(argc, argv, "mode_cutoff");
      const unsigned int threads = std::min(2u, std::max(1u, std::thread::hardware_concurrency()));
      base::FrequencyResponseMatrix green;
      synthesis::ModeSynthesis      all;
      std::vector<double>           cutoffs;
      if (options.model.empty())
        {
          const double top     = options.quick ? 5000. : 10000.;
          std::tie(green, all) = coarse_tyre(top);
          cutoffs              = options.quick ? std::vector<double>{2500., 5000.} :
                                                 std::vector<double>{2500., 3000., 4000., 5000., 7000., 10000.};
          std::cout << "The coarse tyre (4 cm mesh, 16 cells, 4 x 3 tributary points), lines to "
                       "2 kHz\n";
        }
      else
        {
          all = synthesis::read_modal_model(options.model.string());
          green =
            base::read_green_hdf5((options.model.parent_path() / "green_functions.h5").string());
          const double f_max = green.df * (green.n_lines - 1), top = all.frequency_hz.maxCoeff();
          for (const double r : {1.125, 1.25, 1.5, 1.75, 2., 2.5, 3.})
            if (r * f_max < 0.999 * top)
              cutoffs.push_back(r * f_max);
          cutoffs.push_back(top); // every mode of the file
          std::cout << options.model.string() << ": " << all.n_modes() << " modes up to "
                    << format_number(top) << " Hz, " << green.n_points() << " points, lines to "
                    << format_number(f_max) << " Hz\n";
        }
      const unsigned int P = green.n_points();
      std::cout << "  cut-off [Hz]   modes   E median    E p90   E worst  driving  passivity"
                   "       G_r   MB/step  ms/step\n";
      std::ofstream csv(options.output / "mode_cutoff.csv");
      csv << "cutoff_hz,modes,median,p90,worst,driving_worst,passivity,residual_definiteness,"
             "mb_per_step,ms_per_step\n";
      double last_median = NAN, last_worst = NAN; // at the highest cut-off
      for (const double cutoff : cutoffs)
        {
          const auto         synthesis = synthesis::truncate(all, cutoff, green);
          const Eigen::Index m         = synthesis.n_modes();
          const bool         coupled   = all.shapes_imag.size() > 0;
          const auto         errors    = synthesis::compare(synthesis, green);
          double             driving   = 0.;
          for (unsigned int i = 0; i < P; ++i)
            driving = std::max(driving, errors.pair_error[i * P + i]);
          // The update reads the shapes once per step (ModePatchConvolution).
          const double mb = (coupled ? 16. : 8.) * m * P / 1e6;
          const double ms =
            update_ms(synthesis::to_patch_model(synthesis, Eigen::MatrixXd(), 0.), threads);
          std::cout << format_printf("%14.0f", cutoff) << format_printf("%8.0f", m)
                    << format_printf("%10.3f%%", 100. * errors.median)
                    << format_printf("%8.3f%%", 100. * errors.p90)
                    << format_printf("%9.3f%%", 100. * errors.worst)
                    << format_printf("%8.3f%%", 100. * driving)
                    << format_printf("%11.2g", errors.passivity)
                    << format_printf("%10.2g", synthesis.residual_definiteness())
                    << format_printf("%10.1f", mb) << format_printf("%9.3f", ms) << '\n';
          csv << cutoff << ',' << m << ',' << errors.median << ',' << errors.p90 << ','
              << errors.worst << ',' << driving << ',' << errors.passivity << ','
              << synthesis.residual_definiteness() << ',' << mb << ',' << ms << '\n';
          if (!(errors.passivity > -1e-10) || !(synthesis.residual_definiteness() > -1e-10))
            {
              std::cerr << "mode_cutoff: not passive at the cut-off " << cutoff << " Hz\n";
              return 1;
            }
          last_median = errors.median;
          last_worst  = errors.worst;
        }
      // The synthesis with every mode against the direct lines. The coarse
      // tyre: 0.090% worst at 5 kHz (--quick), bound 3x; the full run's
      // 10 kHz cut-off is below it. A model of --model: the modal stage's own
      // targets (median 0.5%, worst pair 2%), as the tyre's figures change
      // with the tyre.
      benchmark::Checks checks("mode_cutoff");
      if (options.model.empty())
        checks.at_most("worst E against the direct lines, every mode", last_worst, 0.0027);
      else
        {
          checks.at_most("median E against the direct lines, every mode", last_median, 0.005);
          checks.at_most("worst E against the direct lines, every mode", last_worst, 0.02);
        }
      return checks.exit_code();
    }
  catch (const std::exception &e)
    {
      std::cerr << "mode_cutoff: " << e.what() << '\n';
      return 1;
    }
}
