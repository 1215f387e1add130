// Do the Green's functions converge with the mesh? The default scene's
// contact patch (10 x 12 points on 60 x 80 mm, each a tributary-area load) on
// the default section at three mesh levels, each twice as fine in every
// direction as the one before ('Geometry/Mesh size' halved and 'Number of
// cells' doubled). For each level: the DoFs of the cell, the time per
// frequency (Bloch, one core), and at 0, 1, 2 and 4 kHz the driving point at
// the patch centre and its transfers to the next point along x and across y;
// then each level's difference from the finest, and the observed order
// p = log2(|g_1 - g_2| / |g_2 - g_3|) from the three levels.
//
//   green_mesh_convergence [--quick] [--output DIR]

#include <greentread/periodic/green_solvers.h>
#include <greentread/periodic/green_stage.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <vector>

#include "benchmark_options.h"

using namespace greentread;

namespace
{
  struct Level
  {
    double       mesh_size;
    unsigned int n_cells;
  };

  /// What one level gives: the three functions at each frequency.
  struct Result
  {
    unsigned int cell_dofs = 0;
    double       seconds   = 0.; ///< per frequency
    /// [frequency][driving, along x, across y]
    std::vector<std::array<std::complex<double>, 3>> g;
  };

  Result
  run(const Level &level, const std::vector<double> &frequencies)
  {
    geometry::GeometryParameters geometry;
    geometry.geo_file  = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
    geometry.mesh_size = level.mesh_size;
    geometry.n_cells   = level.n_cells;
    periodic::PatchRequest request; // the default: 10 x 12 on 60 x 80 mm
    request.load = periodic::PointLoad::tributary_area;
    // The scenes' inflated tyre: mesh, K, M, C, the inflation and Kp.
    const periodic::InflatedTyre tyre(geometry, fe::MaterialParameters(),
                                      fe::InflationParameters(), request);
    const auto  &patch  = tyre.patch;
    const auto   solver = periodic::make_green_solver(periodic::Method::bloch, tyre.periodic_cell,
                                                    patch);
    const unsigned int ny     = patch.points_across;
    const unsigned int centre = (patch.points_along / 2) * ny + ny / 2;
    Result             result;
    result.cell_dofs = tyre.model->dof_handler().n_dofs();
    periodic::SolveDiagnostics diagnostics;
    const auto                 start = std::chrono::steady_clock::now();
    for (const double f : frequencies)
      {
        const auto g = solver->solve(2. * M_PI * f, diagnostics);
        result.g.push_back({{g(centre, centre), g(centre, centre + ny), g(centre, centre + 1)}});
      }
    result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
      frequencies.size();
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto options = benchmark::parse(argc, argv, "green_mesh_convergence");
  const std::vector<Level> levels =
    options.quick ? std::vector<Level>{{0.04, 32}, {0.02, 64}, {0.01, 128}} :
                    std::vector<Level>{{0.016, 128}, {0.008, 256}, {0.004, 512}};
  const std::vector<double> frequencies =
    options.quick ? std::vector<double>{0., 1000.} : std::vector<double>{0., 1000., 2000., 4000.};
  const char *names[3] = {"driving point", "transfer along x", "transfer across y"};

  std::printf("Green's functions of the default patch (10 x 12 tributary-area points on 60 x 80 "
              "mm), Bloch on one core,\nat three mesh levels, each twice as fine in every "
              "direction.\n\n");
  std::vector<Result> results;
  for (const auto &level : levels)
    {
      results.push_back(run(level, frequencies));
      std::printf("mesh %.3f m, N = %4u: %7u cell DoFs, %8.3g s per frequency\n", level.mesh_size,
                  level.n_cells, results.back().cell_dofs, results.back().seconds);
      std::fflush(stdout);
    }

  std::ofstream csv(options.output / "green_mesh_convergence.csv");
  csv << "mesh_size,n_cells,cell_dofs,seconds_per_frequency,frequency_Hz,function,re_um_per_N,"
         "im_um_per_N,difference_from_finest\n";
  const Result &finest = results.back();
  std::printf("\n%-18s %6s | %-26s | %-26s | %-26s | %s\n", "function", "f [Hz]",
              "|g| [um/N], difference: 1", "2", "3 (finest)", "order");
  for (unsigned int q = 0; q < 3; ++q)
    for (std::size_t k = 0; k < frequencies.size(); ++k)
      {
        std::printf("%-18s %6.0f |", names[q], frequencies[k]);
        for (std::size_t l = 0; l < levels.size(); ++l)
          {
            const auto   g    = results[l].g[k][q];
            const double diff = std::abs(g - finest.g[k][q]) / std::abs(finest.g[k][q]);
            if (l + 1 < levels.size())
              std::printf(" %10.5g %13.2f%% |", 1e6 * std::abs(g), 100. * diff);
            else
              std::printf(" %10.5g %15s |", 1e6 * std::abs(g), "");
            csv << levels[l].mesh_size << ',' << levels[l].n_cells << ','
                << results[l].cell_dofs << ',' << results[l].seconds << ',' << frequencies[k]
                << ',' << names[q] << ',' << 1e6 * g.real() << ',' << 1e6 * g.imag() << ','
                << diff << '\n';
          }
        const double d12 = std::abs(results[0].g[k][q] - results[1].g[k][q]);
        const double d23 = std::abs(results[1].g[k][q] - results[2].g[k][q]);
        std::printf(" %5.2f\n", std::log2(d12 / d23));
      }
  std::printf("\nWrote %s\n", (options.output / "green_mesh_convergence.csv").string().c_str());
}
