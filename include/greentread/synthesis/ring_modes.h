#pragma once

#include <greentread/periodic/contact_patch.h>
#include <greentread/synthesis/bloch_modes.h>

#include <deal.II/base/mpi.h>

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <utility>
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
 *
 * **The damping's coupling.** A damping that is not proportional (one
 * Rayleigh pair per layer) is not diagonal in the modes: B = Psi^H C Psi
 * has off-diagonal terms, and ring modes with real shapes and the diagonal
 * xi_r = B_rr / (2 w_r) leave them out. coupled_point_modes() keeps them:
 * the modes of one wavenumber are coupled only among themselves (C does not
 * mix wavenumbers), so the complex modes of (s^2 I + s B + W^2) x = 0, a
 * dense problem of twice the number of Bloch modes, solved once per
 * wavenumber, give the exact transfer within the modes' subspace. Pole l
 * (Im l > 0, with its left vector y from the pole conj(l)) has the residue
 * x y^H / (y^H (2 l I + B) x) in the modal coordinates; at the points, with
 * k and N - k together, it is sum psi psi^T / (2 j w_d), w_d = Im l, with two
 * complex shapes psi per pole (one for k = 0 and N/2). With proportional
 * damping the shapes are real and equal the diagonal form's.
 */

namespace greentread
{
  namespace synthesis
  {
    /// The ring's modes up to a cut-off, at the contact points.
    struct RingModes
    {
      /// Per mode, ascending in frequency: w_r [rad/s], the damping ratio
      /// and the wavenumber k (0 .. N/2) it comes from.
      Eigen::VectorXd           omega, damping_ratio;
      std::vector<unsigned int> wavenumber;
      /// The shapes at the points, [mode][point]: mass-normalised real
      /// shapes, or with the damping's coupling the complex shapes psi of
      /// coupled_point_modes(), real part here and imaginary part in
      /// shapes_imag (empty without the coupling).
      Eigen::MatrixXd shapes, shapes_imag;
      /// Wavenumbers where the coupling was asked for but the diagonal form
      /// was kept (a pole near the real axis, over-critical).
      unsigned int uncoupled = 0;
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
     * so that the result does not depend on the number of ranks. With
     * @p couple_damping the modes are those of coupled_point_modes(),
     * otherwise real shapes with the diagonal damping ratios.
     * @throws NumericalError on every rank if any search fails.
     */
    RingModes
    ring_modes(const periodic::PeriodicCell &cell,
               const periodic::ContactPatch &patch,
               const ModeSearch             &search,
               MPI_Comm                      comm,
               bool                          show_progress,
               bool                          couple_damping = true);

    /// One wavenumber's ring modes at the points: per mode w [rad/s], the
    /// damping ratio and the shape (real and imaginary parts, [mode][point]).
    struct PointModes
    {
      Eigen::VectorXd omega, damping_ratio;
      Eigen::MatrixXd shapes, shapes_imag;
      /// Whether the damping's coupling is in (false: the diagonal form).
      bool coupled = false;
    };

    /**
     * @brief The ring modes of one wavenumber's @p modes at the points of
     * @p patch, with the damping's coupling (@p couple) or in the diagonal
     * form (point_shapes() and the Bloch damping ratios). A pole with a
     * damping ratio of 0.99 or more, or one whose conjugate is not found,
     * falls back to the diagonal form for the whole wavenumber.
     */
    PointModes
    coupled_point_modes(const WavenumberModes        &modes,
                        const periodic::PeriodicCell &cell,
                        const periodic::ContactPatch &patch,
                        bool                          couple);

    /**
     * @brief The core of coupled_point_modes() for any ring: the modes'
     * values @p a at the points (a(r, q): mode r seen by point q's unit load,
     * complex), such that the ring's g holds (1 / N) a a^T for a @p real
     * problem and (1 / N)(a a^H + conj(a a^H)) otherwise. For the Bloch
     * cell N is the number of cells; for a harmonic of an axisymmetric
     * ring (synthesis/harmonic_modes.h), 1 for n = 0 and 2 otherwise.
     */
    PointModes
    coupled_point_modes(const WavenumberModes  &modes,
                        const Eigen::MatrixXcd &a,
                        double                  N,
                        bool                    real,
                        bool                    couple);

    /// The diagonal form of the same: one real mode per row of @p a for a
    /// @p real problem, a cos and a sin one otherwise. Returns [mode][point].
    Eigen::MatrixXd
    point_shapes(const Eigen::MatrixXcd &a, double N, bool real);

    /// One wavenumber's (or harmonic's) modes and their ring modes at the
    /// points.
    using ModesOfWavenumber = std::function<std::pair<WavenumberModes, PointModes>(unsigned int k)>;

    /**
     * @brief The machinery of ring_modes() for any source of modes:
     * wavenumbers 0 .. @p n_k - 1 by @p modes_of, k on rank k mod n_ranks
     * of @p comm and on threads, gathered on every rank in the order of k
     * and sorted by frequency. @p what names the wavenumbers in the
     * progress line.
     * @throws NumericalError on every rank if any fails.
     */
    RingModes
    gather_ring_modes(unsigned int             n_k,
                      unsigned int             P,
                      const ModesOfWavenumber &modes_of,
                      const std::string       &what,
                      MPI_Comm                 comm,
                      bool                     show_progress,
                      bool                     couple_damping);

    /**
     * @brief The real ring modes that one Bloch wavenumber's @p modes give
     * at the points of @p patch: one per Bloch mode for k = 0 and k = N/2,
     * a cos and a sin one otherwise. Returns [mode][point].
     */
    Eigen::MatrixXd
    point_shapes(const WavenumberModes        &modes,
                 const periodic::PeriodicCell &cell,
                 const periodic::ContactPatch &patch);
  } // namespace synthesis
} // namespace greentread
