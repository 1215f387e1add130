// Where the modal stage's time goes, in four parts (--part N; 0: parts 1
// and 2).
//
// 1. The mode search (synthesis::bloch_modes) of single wavenumbers of the
//    default tyre's cell (8 mm mesh, 256 cells, inflated, modes to 8 kHz),
//    on one thread, with one to four slices of [0, cut-off^2]. For each:
//    the time of the search and of the damping's coupling
//    (coupled_point_modes), the sparse solves, the Krylov dimension, the
//    largest relative residual, and the largest relative difference of the
//    frequencies from those of one slice (the reference: one shift below
//    zero, no locking).
// 2. The graded cells of the Green's functions' mesh study (the
//    crown at half the mesh size, 'Crown refinement=2'): 8 mm with 256
//    cells and 4 mm with 512, three wavenumbers each (0, N/8, N/2), the
//    default search (three slices): the largest relative residual and the
//    time per wavenumber, and from its mean the ring's modes of all N/2 + 1
//    wavenumbers on two threads, as the modal stage would take them on such
//    a ring.
// 3. The same for the graded 2 mm cell with 1024 cells, the ring that issue
//    14's 2% needs (79,389 DoFs per cell; green_mesh_convergence --part 3).
// 4. The same for the 4 mm cell with 512 cells and the crown at a third of
//    the mesh size ('Crown refinement=3'; green_mesh_convergence --part 5).
//
//   mode_search_cost [--quick] [--part N]   --quick: the coarse tyre, modes to 3 kHz

#include "benchmark_options.h"

#include <greentread/base/blas_kernels.h>
#include <greentread/base/output.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/synthesis/bloch_modes.h>
#include <greentread/synthesis/ring_modes.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

using namespace greentread;

namespace
{
  /// The modes of wavenumber @p k with @p search, and the seconds of the
  /// search and of the damping's coupling (its result is not kept).
  struct TimedSearch
  {
    synthesis::WavenumberModes modes;
    double                     search = 0., coupling = 0.;
  };

  TimedSearch
  timed_search(const periodic::InflatedTyre &tyre,
               const unsigned int            k,
               const synthesis::ModeSearch  &search)
  {
    TimedSearch timed;
    const auto  t0 = std::chrono::steady_clock::now();
    timed.modes    = synthesis::bloch_modes(tyre.periodic_cell, k, search);
    const auto t1  = std::chrono::steady_clock::now();
    synthesis::coupled_point_modes(timed.modes, tyre.periodic_cell, tyre.patch, true);
    const auto t2  = std::chrono::steady_clock::now();
    timed.search   = std::chrono::duration<double>(t1 - t0).count();
    timed.coupling = std::chrono::duration<double>(t2 - t1).count();
    return timed;
  }

  /// Parts 2 to 4: the default search on graded cells (mesh size, number
  /// of cells; the crown's elements 1 / @p crown_refinement of the mesh
  /// size), three wavenumbers each.
  void
  graded_cells(const bool                                          quick,
               const std::vector<std::pair<double, unsigned int>> &levels,
               const unsigned int                                  crown_refinement = 2)
  {
    std::printf(
      "\nThe graded cells (Crown refinement=%u), modes to %g Hz, three slices, one "
      "thread\n"
      "mesh [mm]  cells   DoFs     k  modes  solves  residual  search [s]  coupling [s]\n",
      crown_refinement, quick ? 3000. : 8000.);
    for (const auto &[mesh_size, n_cells] : levels)
      {
        geometry::GeometryParameters geometry;
        geometry.geo_file        = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
        geometry.mesh_size       = mesh_size;
        geometry.n_cells         = n_cells;
        geometry.other_constants = "Crown refinement=" + std::to_string(crown_refinement);
        periodic::PatchRequest request;
        request.load = periodic::PointLoad::tributary_area;
        const periodic::InflatedTyre    tyre(geometry, fe::MaterialParameters(),
                                             fe::InflationParameters(), request);
        double                          total = 0.;
        const std::vector<unsigned int> ks    = {0, n_cells / 8, n_cells / 2};
        for (const unsigned int k : ks)
          {
            synthesis::ModeSearch search;
            search.cutoff    = 2. * M_PI * (quick ? 3000. : 8000.);
            const auto timed = timed_search(tyre, k, search);
            total += timed.search + timed.coupling;
            std::printf("%9.0f %6u %6u %5u %6ld %7u %9.1e %11.2f %13.2f\n", 1e3 * mesh_size,
                        n_cells, tyre.periodic_cell.size(), k, long(timed.modes.omega.size()),
                        timed.modes.n_solves, timed.modes.max_residual, timed.search,
                        timed.coupling);
          }
        std::printf("  the ring's modes of all %u wavenumbers on two threads: about %.0f s\n",
                    n_cells / 2 + 1, total / ks.size() * (n_cells / 2 + 1) / 2.);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  // The coupling's zgeev with the kernels the application uses.
  base::use_native_blas_kernels(argv);
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto options = benchmark::parse(argc, argv, "mode_search_cost");
  using Levels       = std::vector<std::pair<double, unsigned int>>;
  const Levels part_2_levels =
    options.quick ? Levels{{0.04, 16}} : Levels{{0.008, 256}, {0.004, 512}};
  if (options.part >= 2 && options.part <= 4)
    {
      const Levels finer = options.part == 3 ? Levels{{0.002, 1024}} : Levels{{0.004, 512}};
      graded_cells(options.quick,
                   options.part == 2 ? part_2_levels :
                   options.quick     ? Levels{{0.04, 16}} :
                                       finer,
                   options.part == 4 ? 3 : 2);
      return 0;
    }
  geometry::GeometryParameters geometry;
  geometry.geo_file = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
  periodic::PatchRequest request;
  request.load = periodic::PointLoad::tributary_area;
  if (options.quick)
    {
      geometry.mesh_size = 0.04;
      geometry.n_cells   = 16;
    }
  const periodic::InflatedTyre tyre(geometry, fe::MaterialParameters(), fe::InflationParameters(),
                                    request);
  const std::vector<unsigned int> ks =
    options.quick ? std::vector<unsigned int>{0, 3} : std::vector<unsigned int>{0, 1, 16, 64, 128};
  std::cout << "Mode search of the " << (options.quick ? "coarse" : "default") << " tyre's cell ("
            << tyre.periodic_cell.size() << " DoFs, " << tyre.periodic_cell.n_cells
            << " cells), modes to " << (options.quick ? 3000 : 8000) << " Hz, one thread\n"
            << "slices    k  modes  solves  dimension  residual  freq. vs 1 slice  search [s]  "
               "coupling [s]\n";
  std::vector<Eigen::VectorXd> reference(ks.size());
  // The slices' frequencies against one slice's: within the search's
  // tolerance, 3.0e-11 at most with --quick and 4.3e-10 in full; bounds 3x.
  benchmark::Checks checks("mode_search_cost");
  double            worst_difference = 0.;
  base::AtomicFile  csv_file(options.output / "mode_search_cost.csv");
  auto             &csv = csv_file.stream();
  csv << "slices,k,modes,solves,krylov_dimension,max_residual,difference_vs_one_slice,search_s,"
         "coupling_s\n";
  for (unsigned int slices = 1; slices <= 4; ++slices)
    {
      double total = 0.;
      for (std::size_t i = 0; i < ks.size(); ++i)
        {
          synthesis::ModeSearch search;
          search.cutoff     = 2. * M_PI * (options.quick ? 3000. : 8000.);
          search.slices     = slices;
          const auto  timed = timed_search(tyre, ks[i], search);
          const auto &modes = timed.modes;
          total += timed.search + timed.coupling;
          if (slices == 1)
            reference[i] = modes.omega;
          double difference = modes.omega.size() == reference[i].size() ? 0. : INFINITY;
          if (std::isfinite(difference))
            difference =
              ((modes.omega - reference[i]).cwiseQuotient(reference[i])).cwiseAbs().maxCoeff();
          worst_difference = std::max(worst_difference, difference);
          std::printf("%6u %4u %6ld %7u %10u %9.1e %17.1e %11.2f %13.2f\n", slices, ks[i],
                      long(modes.omega.size()), modes.n_solves, modes.krylov_dimension,
                      modes.max_residual, difference, timed.search, timed.coupling);
          csv << slices << ',' << ks[i] << ',' << modes.omega.size() << ',' << modes.n_solves << ','
              << modes.krylov_dimension << ',' << modes.max_residual << ',' << difference << ','
              << timed.search << ',' << timed.coupling << '\n';
        }
      std::printf("slices %u: %.2f s over the %zu wavenumbers\n", slices, total, ks.size());
    }
  checks.at_most("frequencies of 2 to 4 slices against one slice's (relative)", worst_difference,
                 options.quick ? 1e-10 : 1.3e-9);
  csv_file.commit();
  std::printf("Wrote %s\n", (options.output / "mode_search_cost.csv").c_str());
  if (options.part == 0)
    graded_cells(options.quick, part_2_levels);
  return checks.exit_code();
}
