#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/periodic/green_parameters.h>
#include <greentread/periodic/green_solvers.h>
#include <greentread/periodic/harmonic_ring.h>

#include <deal.II/base/mpi.h>

/**
 * @file
 * The periodic stage: the Green's functions of the inflated ring at the
 * contact points over a frequency grid, shared among the MPI ranks (and the
 * threads of each).
 */

namespace greentread
{
  namespace periodic
  {
    /// What the frequency loop reports.
    struct GreenRunReport
    {
      SolveDiagnostics diagnostics; ///< the worst over all frequencies and ranks
      double           seconds = 0.;
      unsigned int     ranks = 1, threads = 1;
    };

    /**
     * @brief g(f, i, j) on the grid k df, k = 0 .. n_lines - 1, by @p method.
     *
     * Line k is computed by rank k mod n_ranks, on that rank's threads; the
     * result is summed onto rank 0, so it is bitwise the serial one. Ranks
     * other than 0 get an empty matrix.
     * @throws NumericalError on every rank if any rank fails, with the first
     * failure's message.
     */
    base::FrequencyResponseMatrix
    compute_green_functions(const PeriodicCell &cell,
                            const ContactPatch &patch,
                            Method              method,
                            double              df,
                            unsigned int        n_lines,
                            MPI_Comm            comm,
                            bool                show_progress,
                            GreenRunReport     &report,
                            const HarmonicRing *harmonic = nullptr);
  } // namespace periodic
} // namespace greentread
