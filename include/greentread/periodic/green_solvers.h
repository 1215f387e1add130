#pragma once

#include <greentread/periodic/contact_patch.h>
#include <greentread/periodic/periodic_cell.h>

#include <Eigen/Dense>

#include <array>
#include <memory>
#include <string>
#include <vector>

/**
 * @file
 * The Green's functions g_ij(w) of the whole ring at the contact points, by
 * three methods that must agree:
 * - `doubling`, the paper's (Eqs. 46-49): the cell's interior condensed,
 *   the free part of the ring built by doubling along the binary digits of
 *   N_l, the contact cells assembled around it;
 * - `bloch`, beyond the paper: the ring of identical cells is block
 *   circulant, so a discrete Fourier transform over the cells splits it
 *   exactly into N/2 + 1 sparse cell problems with Bloch-periodic faces;
 * - `full-ring`, the reference: all N cells assembled and solved directly.
 */

namespace greentread
{
  namespace periodic
  {
    /// How well the solves of one frequency went.
    struct SolveDiagnostics
    {
      /// Largest normwise backward error |D x - b| / (|D| |x| + |b|) of any
      /// solve: round-off (1e-16) for a stable solve.
      double max_residual = 0.;
      /// Largest condition estimate of any matrix inverted or factorised
      /// (a lower bound on the 1-norm condition number).
      double max_condition = 0.;

      void
      merge(const SolveDiagnostics &other)
      {
        max_residual  = std::max(max_residual, other.max_residual);
        max_condition = std::max(max_condition, other.max_condition);
      }
    };

    /**
     * @brief The Bloch-reduced cell: with u_m = u e^{i phi m} in cell m, the
     * right face is e^{i phi} times the left one, and the ring's equations
     * for one wavenumber reduce to D_phi = P^H D P over [L, I] (size
     * n_face + n_interior). D_{-phi} = D_phi^T, because D is symmetric.
     */
    class BlochCell
    {
    public:
      explicit BlochCell(const PeriodicCell &cell);

      /// Take D(w) = K + Kp + j w C - w^2 M for the following assemble().
      void
      set_frequency(double omega);

      /// Take a (K + Kp) + c C + m M for the following assemble(): (1, 0, 0)
      /// gives the Bloch stiffness K_phi, (0, 0, 1) the mass M_phi.
      void
      set_combination(Complex a, Complex c, Complex m);

      /// D_phi at the current frequency; its pattern never changes.
      const SparseComplex &
      assemble(double phi);

      unsigned int
      size() const
      {
        return n_reduced;
      }

    private:
      std::size_t
      position(int row, int column) const;

      unsigned int  n_reduced;
      SparseComplex matrix;
      /// [K, C, M][phase class: none, e^{i phi}, e^{-i phi}], per entry.
      std::array<std::array<std::vector<double>, 3>, 3> parts;
      /// D(w) per phase class.
      std::array<std::vector<Complex>, 3> at_frequency;
    };

    /**
     * @brief Computes g(w) between the contact points: g(p, q) is the
     * response of point p to the unit load of point q (ContactPoint::load:
     * the radial displacement of p's node under a force on q's, or the mean
     * radial displacement over p's tributary rectangle under a traction over
     * q's), in
     * the convention D(w) = K + Kp + j w C - w^2 M (so Im g(p, p) <= 0).
     *
     * One object per thread: it keeps its factorisations.
     */
    class GreenSolver
    {
    public:
      virtual ~GreenSolver() = default;

      /**
       * @brief The P x P matrix g(w), P the number of contact points.
       * @throws NumericalError if a matrix is singular or so ill-conditioned
       * that the result cannot be trusted (an undamped resonance), naming
       * the frequency.
       */
      virtual Eigen::MatrixXcd
      solve(double omega, SolveDiagnostics &diagnostics) = 0;

      /**
       * @brief The columns @p columns of g(w) (P x columns.size()): every
       * point's response to a unit load at each of those points. By default
       * the whole of g is solved and the columns copied; `bloch` solves for
       * those loads only, one right-hand side each, which is what makes a
       * column of a very fine ring affordable (the mesh study's check).
       */
      virtual Eigen::MatrixXcd
      solve_columns(double                           omega,
                    const std::vector<unsigned int> &columns,
                    SolveDiagnostics                &diagnostics);
    };

    /// The methods, as the parameter names them.
    enum class Method
    {
      bloch,
      doubling,
      full_ring,
      harmonic
    };

    /// "bloch", "doubling", "full-ring" or "harmonic".
    Method
    parse_method(const std::string &name);

    class HarmonicRing;

    /**
     * @brief The one selection point of the methods: a solver for
     * @p method. @p cell, @p patch and @p harmonic must outlive it;
     * @p harmonic is the ring of the `harmonic` method (periodic/harmonic_ring.h),
     * which the other methods do not use.
     * @throws NumericalError if @p method is `harmonic` and @p harmonic is null.
     */
    std::unique_ptr<GreenSolver>
    make_green_solver(Method              method,
                      const PeriodicCell &cell,
                      const ContactPatch &patch,
                      const HarmonicRing *harmonic = nullptr);

    /**
     * @brief The whole ring's response at @p omega to the unit load @p load
     * (a contact point's, ContactPoint::load), by the Bloch transform over
     * all N wavenumbers: column m holds the DoFs [L, I] of cell m, in
     * cylindrical components.
     * @throws NumericalError as GreenSolver::solve().
     */
    Eigen::MatrixXcd
    ring_response(const PeriodicCell           &cell,
                  double                        omega,
                  const std::vector<LoadEntry> &load,
                  SolveDiagnostics             &diagnostics);

    /// Above this condition estimate a solve is refused (an undamped
    /// resonance): about 1e-16 x 1e13 = 1e-3 relative accuracy left.
    constexpr double condition_limit = 1e13;
    /// Above this backward error a solve is refused (a stable LU stays
    /// near 1e-16).
    constexpr double residual_limit = 1e-10;
  } // namespace periodic
} // namespace greentread
