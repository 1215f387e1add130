#pragma once

#include <string>

/**
 * @file
 * OpenBLAS's kernels for the processor it runs on.
 *
 * The BLAS that scripts/setup.sh installs, Debian 12's OpenBLAS 0.3.21, is
 * built for every x86 processor and picks its kernels when the library is
 * loaded. A processor newer than it knows (this project's Intel Xeon,
 * family 6 model 207) gets the oldest, Prescott's (SSE3): LAPACK's zgeev of
 * the damping's coupling (synthesis/ring_modes.h) then took twice as long as
 * with the AVX-512 kernels (benchmarks/mode_search_cost: 1.10 s against
 * 0.57 s over its five wavenumbers). OpenBLAS reads OPENBLAS_CORETYPE only
 * when it is loaded, so the choice takes a new process image.
 */

namespace greentread
{
  namespace base
  {
    /**
     * If OpenBLAS fell back to the Prescott kernels on a processor with
     * AVX-512 (or AVX2), run this program again, the same arguments, with
     * OPENBLAS_CORETYPE=SkylakeX (or Haswell): execv of /proc/self/exe,
     * same process, before anything else has started (call it first in
     * main, before MPI_Init). Does nothing if OPENBLAS_CORETYPE is set
     * already (the user's choice is kept, and the new image does not loop),
     * if the BLAS is not OpenBLAS, or if OpenBLAS knew the processor;
     * returns normally if the execv fails.
     */
    void
    use_native_blas_kernels(char **argv);

    /// "OpenBLAS (SkylakeX kernels)", or "not OpenBLAS".
    std::string
    blas_kernels();
  } // namespace base
} // namespace greentread
