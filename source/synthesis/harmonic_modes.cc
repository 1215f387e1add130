#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/synthesis/harmonic_modes.h>

#include <Eigen/SparseCholesky>

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace synthesis
  {
    unsigned int
    count_harmonic_modes(const fe::HarmonicSection &section, const unsigned int n,
                         const double cutoff)
    {
      const Eigen::SparseMatrix<double> A =
        section.stiffness(n) - cutoff * cutoff * section.mass();
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
      if (ldlt.info() != Eigen::Success)
        throw NumericalError("the modes of harmonic " + std::to_string(n) +
                             ": K_n - w_c^2 M could not be factorised to count them (a mode "
                             "exactly at the cut-off?)");
      return static_cast<unsigned int>((ldlt.vectorD().array() < 0.).count());
    }



    BlochModes
    harmonic_modes(const fe::HarmonicSection &section, const unsigned int n, const double cutoff)
    {
      BlochModes modes;
      modes.wavenumber     = n;
      const unsigned int m = count_harmonic_modes(section, n, cutoff);
      const Eigen::Index size = section.size();
      if (m == 0)
        {
          modes.omega.resize(0);
          modes.damping_ratio.resize(0);
          modes.modal_damping.resize(0, 0);
          return modes;
        }
      if (Eigen::Index(m) + 2 > size)
        throw NumericalError("the modes of harmonic " + std::to_string(n) + ": " +
                             std::to_string(m) + " of the section's " + std::to_string(size) +
                             " eigenvalues lie below the cut-off; refine the section or lower "
                             "'Patch model/Mode cutoff'");
      const Eigen::SparseMatrix<double> K = section.stiffness(n);
      const Eigen::SparseMatrix<double> &M = section.mass();
      using Op  = Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse>;
      using BOp = Spectra::SparseSymMatProd<double>;
      Op           op(K, M);
      BOp          bop(M);
      // The shift below zero keeps K - s M positive definite; the
      // eigenvalues nearest it are the lowest, exactly the m counted.
      const double       shift = -std::pow(cutoff / 20., 2);
      const Eigen::Index ncv   = std::min<Eigen::Index>(size, std::max<Eigen::Index>(2 * m + 1, m + 20));
      Spectra::SymGEigsShiftSolver<Op, BOp, Spectra::GEigsMode::ShiftInvert> solver(op, bop, m, ncv,
                                                                                     shift);
      solver.init();
      solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-11, Spectra::SortRule::SmallestAlge);
      if (solver.info() != Spectra::CompInfo::Successful)
        throw NumericalError("the modes of harmonic " + std::to_string(n) +
                             ": Spectra's shift-invert Lanczos did not converge on " +
                             std::to_string(m) + " modes");
      const Eigen::VectorXd lambda = solver.eigenvalues();
      Eigen::MatrixXd       U      = solver.eigenvectors();
      modes.n_solves               = static_cast<unsigned int>(solver.num_operations());
      modes.krylov_dimension       = static_cast<unsigned int>(ncv);
      modes.omega.resize(m);
      for (unsigned int r = 0; r < m; ++r)
        {
          if (!(lambda(r) > 0.) || lambda(r) > cutoff * cutoff * (1. + 1e-9))
            throw NumericalError("the modes of harmonic " + std::to_string(n) +
                                 ": eigenvalue " + format_printf("%.6g", lambda(r)) +
                                 " found, not one of the " + std::to_string(m) +
                                 " counted in (0, w_c^2]");
          U.col(r) /= std::sqrt(U.col(r).dot(M * U.col(r)));
          const Eigen::VectorXd KU = K * U.col(r);
          const double residual    = (KU - lambda(r) * (M * U.col(r))).norm() / KU.norm();
          if (!(residual < 1e-6))
            throw NumericalError("the modes of harmonic " + std::to_string(n) + ": mode " +
                                 std::to_string(r) + " has a relative residual of " +
                                 format_printf("%.2g", residual));
          modes.max_residual = std::max(modes.max_residual, residual);
          modes.omega(r)     = std::sqrt(lambda(r));
        }
      const Eigen::MatrixXd B = U.transpose() * (section.damping(n) * U);
      modes.modal_damping     = B.cast<std::complex<double>>();
      modes.damping_ratio     = B.diagonal().cwiseQuotient(2. * modes.omega);
      modes.shapes            = U.cast<std::complex<double>>();
      return modes;
    }



    RingModes
    harmonic_ring_modes(const periodic::HarmonicRing &ring,
                        const double                  cutoff,
                        const MPI_Comm                comm,
                        const bool                    show_progress,
                        const bool                    couple_damping)
    {
      // The harmonics with a mode below the cut-off: every rank counts them
      // (one factorisation each, cheap beside the search).
      unsigned int n_k = 0;
      for (unsigned int n = 0, empty = 0; empty < 8; ++n)
        {
          if (count_harmonic_modes(ring.section, n, cutoff) == 0)
            {
              ++empty;
              continue;
            }
          if (n >= ring.n_harmonics)
            throw InputError("parameter 'Patch model/Mode cutoff' = " +
                             format_number(cutoff / (2. * M_PI)) + " Hz is not allowed: harmonic " +
                             std::to_string(n) + " has a mode below it, and the Green's "
                             "functions sum harmonics 0 to " +
                             std::to_string(ring.n_harmonics - 1) +
                             " only; allowed: a lower cut-off, or a smaller 'Green's "
                             "functions/Harmonic tolerance' (more harmonics)");
          empty = 0;
          n_k   = n + 1;
        }
      const unsigned int P = ring.angle.size();
      return gather_ring_modes(
        n_k, P,
        [&](const unsigned int n) {
          BlochModes       modes = harmonic_modes(ring.section, n, cutoff);
          const double     s     = std::sqrt(ring.weight(n));
          Eigen::MatrixXcd a(modes.omega.size(), P);
          const Eigen::MatrixXd seen =
            modes.omega.size() > 0 ? Eigen::MatrixXd(modes.shapes.real().transpose() * ring.loads) :
                                     Eigen::MatrixXd(0, ring.loads.cols());
          for (unsigned int p = 0; p < P; ++p)
            a.col(p) = s * std::polar(1., n * ring.angle[p]) *
                       seen.col(ring.strip[p]).cast<std::complex<double>>();
          modes.shapes.resize(0, 0); // not needed past here
          PointModes points = coupled_point_modes(modes, a, n == 0 ? 1. : 2., n == 0, couple_damping);
          return std::make_pair(std::move(modes), std::move(points));
        },
        "harmonics", comm, show_progress, couple_damping);
    }
  } // namespace synthesis
} // namespace greentread
