// Where the modal stage's time goes: the mode search (periodic::bloch_modes)
// of single wavenumbers of the default tyre's cell (8 mm mesh, 256 cells,
// inflated, modes to 8 kHz), on one thread, with one to four slices of
// [0, cut-off^2]. For each: the time of the search and of the damping's
// coupling (coupled_point_modes), the sparse solves, the Krylov dimension,
// the largest relative residual, and the largest relative difference of
// the frequencies from those of one slice (the reference: one shift below
// zero, no locking).
//
//   mode_search_cost [--quick]   --quick: the coarse tyre, modes to 3 kHz

#include "benchmark_options.h"

#include <greentread/base/blas_kernels.h>
#include <greentread/periodic/bloch_modes.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/periodic/ring_modes.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

using namespace greentread;

int
main(int argc, char **argv)
{
  // The coupling's zgeev with the kernels the application uses.
  base::use_native_blas_kernels(argv);
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto options = benchmark::parse(argc, argv, "mode_search_cost");
  geometry::GeometryParameters geometry;
  geometry.geo_file = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
  periodic::PatchRequest request;
  request.load = periodic::PointLoad::tributary_area;
  if (options.quick)
    {
      geometry.mesh_size = 0.04;
      geometry.n_cells   = 16;
    }
  const periodic::InflatedTyre tyre(geometry, fe::MaterialParameters(),
                                    fe::InflationParameters(), request);
  const std::vector<unsigned int> ks = options.quick ? std::vector<unsigned int>{0, 3} :
                                                       std::vector<unsigned int>{0, 1, 16, 64, 128};
  std::cout << "Mode search of the " << (options.quick ? "coarse" : "default") << " tyre's cell ("
            << tyre.periodic_cell.size() << " DoFs, " << tyre.periodic_cell.n_cells
            << " cells), modes to " << (options.quick ? 3000 : 8000) << " Hz, one thread\n"
            << "slices    k  modes  solves  dimension  residual  freq. vs 1 slice  search [s]  "
               "coupling [s]\n";
  std::vector<Eigen::VectorXd> reference(ks.size());
  for (unsigned int slices = 1; slices <= 4; ++slices)
    {
      double total = 0.;
      for (std::size_t i = 0; i < ks.size(); ++i)
        {
          periodic::ModeSearch search;
          search.cutoff     = 2. * M_PI * (options.quick ? 3000. : 8000.);
          search.slices     = slices;
          const auto t0     = std::chrono::steady_clock::now();
          const auto modes  = periodic::bloch_modes(tyre.periodic_cell, ks[i], search);
          const auto t1     = std::chrono::steady_clock::now();
          const auto ring   = periodic::coupled_point_modes(modes, tyre.periodic_cell, tyre.patch, true);
          const auto t2     = std::chrono::steady_clock::now();
          const double a    = std::chrono::duration<double>(t1 - t0).count(),
                       b    = std::chrono::duration<double>(t2 - t1).count();
          total += a + b;
          if (slices == 1)
            reference[i] = modes.omega;
          double difference = modes.omega.size() == reference[i].size() ? 0. : INFINITY;
          if (std::isfinite(difference))
            difference = ((modes.omega - reference[i]).cwiseQuotient(reference[i])).cwiseAbs().maxCoeff();
          std::printf("%6u %4u %6ld %7u %10u %9.1e %17.1e %11.2f %13.2f\n", slices, ks[i],
                      long(modes.omega.size()), modes.n_solves, modes.krylov_dimension,
                      modes.max_residual, difference, a, b);
          (void)ring;
        }
      std::printf("slices %u: %.2f s over the %zu wavenumbers\n", slices, total, ks.size());
    }
}
