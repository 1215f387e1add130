#pragma once

#include <mutex>

/**
 * @file
 * One lock for every call into BLAS and LAPACK (UMFPACK's factorisations and
 * solves, LAPACK's eigen-solvers).
 *
 * The BLAS that scripts/setup.sh installs, Debian's serial OpenBLAS, is not
 * thread-safe: two threads inside it at once corrupt each other's buffers
 * (measured: two concurrent zgeev calls on 400 x 400 matrices returned wrong
 * eigenvalues in 18 runs of 20; the doubling and full-ring Green's functions
 * on two threads stopped at a spurious "nearly singular" check). The stages
 * spread their work over threads, so each such call holds this lock; Eigen's
 * own dense and sparse code, which does most of the work, needs none.
 */

namespace greentread
{
  namespace base
  {
    /// Hold the returned lock for the whole of a BLAS or LAPACK call.
    inline std::unique_lock<std::mutex>
    lock_serial_blas()
    {
      static std::mutex blas;
      return std::unique_lock<std::mutex>(blas);
    }
  } // namespace base
} // namespace greentread
