#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/periodic/green_solvers.h>
#include <greentread/periodic/harmonic_ring.h>

#include <optional>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

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
    /**
     * @brief Subsection "Green's functions".
     */
    struct GreenParameters
    {
      double       max_frequency = 4000.;
      double       frequency_step = 15.625;
      std::string  method         = "bloch";
      /// 'Harmonic tolerance': the harmonic method's tail bound.
      double       harmonic_tolerance = 1e-3;
      PatchRequest patch;
      /// "auto" or "i,j; i,j; ...".
      std::string pairs = "auto";
      /// Frequency of the operating deflection shape [Hz], < 0 for none.
      double deflection_frequency = 500.;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Lines 0, df, ..., f_max.
      unsigned int
      n_lines() const;

      /// What the `harmonic` method needs, or nothing for another method.
      std::optional<HarmonicOptions>
      harmonic() const;

      /// The pairs (i, j) to write as CSV for @p patch.
      std::vector<std::pair<unsigned int, unsigned int>>
      csv_pairs(const ContactPatch &patch) const;
    };

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
