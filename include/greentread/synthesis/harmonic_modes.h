#pragma once

#include <greentread/periodic/harmonic_ring.h>
#include <greentread/synthesis/ring_modes.h>

#include <deal.II/base/mpi.h>

/**
 * @file
 * The modes of an axisymmetric ring from its section's harmonics, for the
 * modal synthesis (the `harmonic` method's mode source).
 *
 * Harmonic n has the real symmetric problem K_n U = w^2 M U on the section
 * (fe/harmonic_section.h). With U M-normalised, the ring has for n >= 1 two
 * modes of that frequency, U cos(n theta) / sqrt(pi) and U sin(n theta) /
 * sqrt(pi) (the two families), and for n = 0 one, U / sqrt(2 pi). Seen by
 * the unit loads of the points (periodic/harmonic_ring.h) they are
 *   a(r, p) = sqrt(weight(n)) (w_p / W_p)^T U_r e^{j n theta_p},
 * the cos mode the real part and the sin mode the imaginary part, so that
 * sum a a^H over the modes gives the harmonic's term of g. The damping's
 * coupling among the modes of one harmonic is kept as for the Bloch modes
 * (synthesis/ring_modes.h).
 */

namespace greentread
{
  namespace synthesis
  {
    /**
     * @brief The ring's modes up to @p cutoff [rad/s] at the points of
     * @p ring, harmonics spread over the ranks of @p comm and threads.
     *
     * The number of modes of harmonic n below the cut-off is known before
     * the search, by Sylvester's law of inertia (the negative pivots of
     * K_n - cutoff^2 M = L D L^T); the harmonics are taken up to the last
     * with a mode below it (8 in a row without one end the count). Each is
     * solved by harmonic_modes(), and each mode's residual is checked.
     * @throws InputError if a harmonic the Green's functions do not sum
     *         (n >= ring.n_harmonics) has a mode below the cut-off, naming
     *         'Patch model/Mode cutoff'.
     * @throws NumericalError on every rank if a search fails.
     */
    RingModes
    harmonic_ring_modes(const periodic::HarmonicRing &ring,
                        double                        cutoff,
                        MPI_Comm                      comm,
                        bool                          show_progress,
                        bool                          couple_damping = true);

    /**
     * @brief The modes of harmonic @p n of @p section below @p cutoff
     * [rad/s]: frequencies, damping ratios, the damping in the modal basis
     * and the M-normalised shapes over the section's unknowns (real, held
     * as complex for WavenumberModes).
     *
     * Spectra's Lanczos (SymEigsSolver) on the shift-invert operator in
     * standard form, B^T (K_n - s M)^{-1} B with M = B B^T (no products with
     * M inside the iteration), over slices of [0, cutoff^2] equal in w^2,
     * about @p modes_per_slice modes each, every slice with its own shift
     * and L D L^T factorisation. Each slice's count comes from the inertia
     * at its ends and must be met exactly. The slice size was chosen by
     * `benchmarks/harmonic_mode_search`.
     * @throws NumericalError naming the harmonic if a factorisation or a
     *         search fails, or a slice's count is not met.
     */
    WavenumberModes
    harmonic_modes(const fe::HarmonicSection &section,
                   unsigned int               n,
                   double                     cutoff,
                   unsigned int               modes_per_slice = 48);

    /// The number of eigenvalues of harmonic @p n below @p cutoff^2.
    unsigned int
    count_harmonic_modes(const fe::HarmonicSection &section, unsigned int n, double cutoff);
  } // namespace synthesis
} // namespace greentread
