#pragma once

#include <greentread/periodic/bloch_modes.h>
#include <greentread/periodic/contact_patch.h>

#include <deal.II/base/mpi.h>

#include <Eigen/Dense>

#include <vector>

/**
 * @file
 * The ring's real modes at the contact points, from its Bloch modes.
 *
 * A Bloch mode psi of wavenumber k, seen by the unit loads of the points
 * (ContactPoint::load), gives a_q = sum over q's entries (n, s, w) of
 * w e^{i phi n} psi(s). The Bloch solver's g = (1/N) sum_k W_k^H D_k^{-1} W_k
 * then holds, for k and N - k together, (a a^H + conj(a a^H)) / N
 * = (2/N)(Re a Re a^T + Im a Im a^T) over the mode's denominator: the two
 * degenerate Bloch waves are one real cos-type and one real sin-type mode
 * of the ring with shapes sqrt(2/N) Re a and sqrt(2/N) Im a. For k = 0 and
 * k = N/2 the problem is real and there is one mode, sqrt(1/N) a.
 */

namespace greentread
{
  namespace periodic
  {
    /// The ring's modes up to a cut-off, at the contact points.
    struct RingModes
    {
      /// Per mode, ascending in frequency: w_r [rad/s], the damping ratio
      /// and the wavenumber k (0 .. N/2) it comes from.
      Eigen::VectorXd              omega, damping_ratio;
      std::vector<unsigned int>    wavenumber;
      /// The mass-normalised shapes at the points, [mode][point].
      Eigen::MatrixXd shapes;
      /// Per wavenumber 0 .. N/2: the Bloch frequencies [rad/s] (each once,
      /// for the dispersion curves) and their damping ratios.
      std::vector<Eigen::VectorXd> branches, branch_damping;
      /// The search's worst relative residual, and its solves.
      double       max_residual = 0.;
      unsigned int n_solves     = 0;

      unsigned int
      size() const
      {
        return static_cast<unsigned int>(omega.size());
      }
    };

    /**
     * @brief The modes of the ring of @p cell up to @p search.cutoff at the
     * points of @p patch. Wavenumber k is searched by rank k mod n_ranks of
     * @p comm, and the results gathered on every rank, in the order of k,
     * so that the result does not depend on the number of ranks.
     * @throws NumericalError on every rank if any search fails.
     */
    RingModes
    ring_modes(const PeriodicCell &cell,
               const ContactPatch &patch,
               const ModeSearch   &search,
               MPI_Comm            comm,
               bool                show_progress);

    /**
     * @brief The real ring modes that one Bloch wavenumber's @p modes give
     * at the points of @p patch: one per Bloch mode for k = 0 and k = N/2,
     * a cos and a sin one otherwise. Returns [mode][point].
     */
    Eigen::MatrixXd
    point_shapes(const BlochModes &modes, const PeriodicCell &cell, const ContactPatch &patch);
  } // namespace periodic
} // namespace greentread
