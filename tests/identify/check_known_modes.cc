// The identify scene's poles against the known modes of the FRF it was given:
// prm/example_frf.csv is the driving point g_00 of the synthetic tyre-like
// matrix (benchmarks/common/synthetic_green.h), whose modes are known
// exactly. For every known mode below 3.6 kHz (the band's edge rings at 4 kHz)
// that carries at least 1% of the FRF (the L1 norm of its own response over
// the band against the FRF's, as benchmarks/identification/identification.cc
// counts it), the nearest identified pole in the scene's modal_parameters.csv,
// relative to |lambda|.
//
//   check_known_modes MODAL_PARAMETERS_CSV BOUND
//
// Prints each mode and the worst error; exits 1 above BOUND.

#include <greentread/modal/modal_model.h>

#include <deal.II/base/mpi.h>

#include <complex>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../../benchmarks/common/synthetic_green.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 3)
    {
      std::cerr << "usage: check_known_modes MODAL_PARAMETERS_CSV BOUND\n";
      return 2;
    }
  std::ifstream file(argv[1]);
  if (!file)
    {
      std::cerr << "check_known_modes: cannot read '" << argv[1] << "'\n";
      return 2;
    }
  std::vector<std::complex<double>> identified;
  std::string                       line;
  std::getline(file, line); // i,j,lambda_re,lambda_im,R_re,R_im
  while (std::getline(file, line))
    {
      if (line.empty() || line[0] == '#') // the run's parameters follow the rows
        continue;
      std::istringstream in(line);
      std::string        field[4];
      for (auto &f : field)
        std::getline(in, f, ',');
      identified.emplace_back(std::stod(field[2]), std::stod(field[3]));
    }
  const double bound = std::stod(argv[2]);

  const benchmark::SyntheticGreen green;
  const auto                      truth    = green.model(0, 0);
  const auto                      frf      = green.frf(0, 0, 4., 1001); // as the example file
  double                          worst    = 0.;
  unsigned int                    compared = 0;
  for (const auto &t : truth.terms())
    {
      const double f = t.lambda.imag() / (2. * M_PI);
      if (f > 3600.)
        continue;
      // The mode's weight in the FRF, as the identification benchmark
      // counts it; below 1%, the data hardly hold it.
      if (benchmark::SyntheticGreen::weight(t, frf) < 0.01)
        continue;
      double nearest = INFINITY;
      for (const auto &l : identified)
        nearest = std::min(nearest, std::abs(l - t.lambda) / std::abs(t.lambda));
      std::printf("known mode at %7.1f Hz: nearest identified pole %.2e (relative)\n", f, nearest);
      worst = std::max(worst, nearest);
      ++compared;
    }
  std::printf("%u known modes compared with %zu identified poles: worst %.3g (bound %g)\n",
              compared, identified.size(), worst, bound);
  if (compared < 10 || !(worst <= bound))
    {
      std::cerr << "check_known_modes: "
                << (compared < 10 ? "too few modes compared" : "an identified pole is off") << '\n';
      return 1;
    }
  return 0;
}
