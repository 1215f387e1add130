#pragma once

#include <greentread/periodic/periodic_cell.h>
#include <greentread/synthesis/wavenumber_modes.h>

#include <Eigen/Dense>

/**
 * @file
 * The undamped modes of the ring, one circumferential wavenumber at a time.
 *
 * A ring of N identical cells is block circulant, so its modes are Bloch
 * waves: u_m = psi e^{i phi m} in cell m, phi = 2 pi k / N, where psi solves
 * the Hermitian problem of the reduced cell (BlochCell)
 *   K_phi psi = w^2 M_phi psi,   psi^H M_phi psi = 1,
 * with K_phi and M_phi the cell's K + Kp and M folded onto [L, I].
 * Wavenumbers k and N - k have the same frequencies, with conjugate shapes.
 */

namespace greentread
{
  namespace synthesis
  {
    /// How far and how tightly bloch_modes() searches.
    struct ModeSearch
    {
      /// Keep the modes with w_r <= cutoff [rad/s].
      double cutoff = 0.;
      /// A Ritz pair counts as converged when ||K x - w^2 M x|| / ||K x||
      /// is below this, or when it is at rounding level (backward error
      /// ||K x - w^2 M x|| / ((||K|| + w^2 ||M||) ||x||) below 1e3 eps).
      double tolerance = 1e-9;
      /// Vectors added per step: a block Krylov space holds at most this
      /// many copies of a repeated mode, so one repeated more often would
      /// leave the count short of the inertia's and the search would fail
      /// rather than miss it (the cell's modes are distinct, and k, N - k
      /// are separate problems).
      unsigned int block = 4;
      /// Slices of [0, cutoff^2] searched one after the other, each with
      /// its own factorisation and with the modes of those below it locked.
      /// Chosen by `benchmarks/mode_search_cost` (one thread, the default
      /// tyre's wavenumbers 0, 1, 16, 64 and 128, search and coupling):
      /// 8.35 s with one slice, 7.15 s with two, 6.77 s with three, 7.70 s
      /// with four (before the shift moved to a slice's middle: 71 to 79 s for
      /// the whole modal stage, three slices the fastest).
      unsigned int slices = 3;
    };

    /**
     * @brief The modes of wavenumber @p k of @p cell up to the cut-off.
     *
     * Shift-invert block Krylov with Rayleigh-Ritz, over slices of
     * [0, cutoff^2] (ModeSearch::slices, equal in w^2) taken in turn:
     * - How many modes a slice holds is known before the search: by
     *   Sylvester's law of inertia, the number of eigenvalues below s is
     *   the number of negative pivots of K_phi - s M_phi = L D L^H (sparse,
     *   AMD ordering). A slice's search stops once that many Ritz values
     *   lie in it and every one has converged. Ritz values are upper
     *   bounds of the eigenvalues in order, so none can then be missing.
     * - The first slice is searched with the shift s = -(cutoff / 20)^2
     *   (K_phi - s M_phi positive definite, even for an unheld cell), each
     *   other one with the shift at its middle, and with the modes found
     *   below it locked: its basis is kept M-orthogonal to them, and the
     *   Ritz values on that space are still upper bounds of the remaining
     *   eigenvalues in order, whatever the shift. Each basis then holds
     *   about a third of the modes, and the Gram-Schmidt work, which grows
     *   with the square of the basis, falls.
     * - The Krylov space of T = (K_phi - s M_phi)^{-1} M_phi starts from
     *   the block T X, X fixed pseudo-random vectors (so that it lies in
     *   T's range, where the modes are, also when M is singular: mass
     *   moved off the contact surface leaves its DoFs massless). It is kept
     *   M-orthonormal by block classical Gram-Schmidt (two passes, a third
     *   where they cancel), with V^H K V grown with it.
     * - The Ritz values are computed every 10% of growth; once enough lie
     *   in the slice, the highest is judged first (it converges last), and
     *   its residual's geometric fall places the next check.
     * The sparse factorisation is the Bloch solver's (supernodal LU with
     * COLAMD), one per slice. Spectra and ARPACK's symmetric drivers are
     * real only, and the real form of twice the size repeats every
     * eigenvalue, so this small driver is written here and tested against
     * dense solves.
     *
     * @throws NumericalError if a factorisation fails, the inertia cannot
     * be computed, or the search does not converge within the size of the
     * cell, naming the wavenumber.
     */
    WavenumberModes
    bloch_modes(const periodic::PeriodicCell &cell, unsigned int k, const ModeSearch &search);

    /**
     * @brief The search of bloch_modes() on any Hermitian pencil: the modes
     * of (K, M) below the cut-off, with the damping C in their basis. K, C
     * and M share one pattern; @p k seeds the start blocks and is stored as
     * the wavenumber, @p which names the problem in errors.
     */
    WavenumberModes
    hermitian_modes(periodic::SparseComplex K,
                    periodic::SparseComplex C,
                    periodic::SparseComplex M,
                    unsigned int            k,
                    const std::string      &which,
                    const ModeSearch       &search);
  } // namespace synthesis
} // namespace greentread
