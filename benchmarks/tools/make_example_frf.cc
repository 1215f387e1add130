// Writes the shipped example FRF prm/example_frf.csv: the driving point
// g_00 of the synthetic tyre-like Green's matrix (synthetic_green.h), 1001
// lines from 0 to 4000 Hz.
//
//   make_example_frf [FILE]        (default: prm/example_frf.csv)

#include <greentread/base/output.h>

#include <deal.II/base/mpi.h>

#include <iostream>

#include "synthetic_green.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  const std::string                        file = argc > 1 ? argv[1] : "prm/example_frf.csv";
  const benchmark::SyntheticGreen          green;
  greentread::base::ParameterRecord        record;
  record.header =
    "synthetic tyre-like Green's function g_00 (benchmarks/common/synthetic_green.h): " +
    std::to_string(green.frequency.size()) +
    " modes from 80 Hz, 1-3% damping; 1001 lines, df = 4 Hz";
  greentread::base::write_frf_csv(file, green.frf(0, 0, 4., 1001), record);
  std::cout << "wrote " << file << "\n";
  return 0;
}
