#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/base/parameters.h>
#include <greentread/base/progress.h>
#include <greentread/synthesis/harmonic_modes.h>

#include <Eigen/SparseCholesky>

#include <Spectra/SymEigsSolver.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace greentread
{
  namespace synthesis
  {
    namespace
    {
      using Sparse = Eigen::SparseMatrix<double>;

      /**
       * The shift-invert operator in standard form: with M = B B^T
       * (B = P^T L, the sparse Cholesky factor of M with its fill-reducing
       * permutation), x -> B^T (K - s M)^{-1} B x. Its eigenvalues are
       * 1 / (w^2 - s) with eigenvectors y = B^T U, and a Lanczos on it needs
       * no products with M: Spectra's generalised driver spent a third of
       * the search in them, several per step for its M-inner products.
       */
      class StandardShiftInvert
      {
      public:
        using Scalar = double;

        StandardShiftInvert(const Eigen::SimplicialLDLT<Sparse> &shifted_,
                            const Eigen::SimplicialLLT<Sparse>  &mass_)
            : shifted(shifted_)
            , mass(mass_)
        {
        }

        Eigen::Index
        rows() const
        {
          return mass.rows();
        }
        Eigen::Index
        cols() const
        {
          return mass.cols();
        }

        void
        perform_op(const double *x_in, double *y_out) const
        {
          const Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
          Eigen::Map<Eigen::VectorXd>             y(y_out, rows());
          Eigen::VectorXd                         z = mass.matrixL() * x;
          z                                         = mass.permutationPinv() * z;
          z                                         = shifted.solve(z);
          z                                         = mass.permutationP() * z;
          y.noalias()                               = mass.matrixU() * z;
        }

        /// U = B^{-T} y, M-orthonormal when the y are orthonormal.
        Eigen::MatrixXd
        shapes(const Eigen::MatrixXd &y) const
        {
          Eigen::MatrixXd u = mass.matrixU().solve(y);
          return mass.permutationPinv() * u;
        }

      private:
        const Eigen::SimplicialLDLT<Sparse> &shifted;
        const Eigen::SimplicialLLT<Sparse>  &mass;
      };

      /**
       * The shift-invert operator with the modes already found projected
       * out, P A P with P = I - Y Y^T (Y orthonormal, in standard form):
       * their eigenvalues become 0, so that a search for the largest finds
       * those left. One Krylov space holds a near-degenerate pair as about
       * one vector, so a search can miss a pair's other member; searched
       * again with the first deflated, it is found.
       */
      class Deflated
      {
      public:
        using Scalar = double;

        Deflated(const StandardShiftInvert &op_, const Eigen::MatrixXd &Y_)
            : op(op_)
            , Y(Y_)
        {
        }

        Eigen::Index
        rows() const
        {
          return op.rows();
        }
        Eigen::Index
        cols() const
        {
          return op.cols();
        }

        void
        perform_op(const double *x_in, double *y_out) const
        {
          const Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
          Eigen::Map<Eigen::VectorXd>             y(y_out, rows());
          const Eigen::VectorXd                   p = x - Y * (Y.transpose() * x);
          op.perform_op(p.data(), y_out);
          y -= Y * (Y.transpose() * y);
        }

      private:
        const StandardShiftInvert &op;
        const Eigen::MatrixXd     &Y;
      };

      /// L D L^T of K_n - s M, nudged off a zero pivot; its negative
      /// pivots count the eigenvalues below s (Sylvester). The pattern is
      /// the same for every n and s: @p ldlt is analysed once.
      void
      factorise_shifted(const fe::HarmonicSection     &section,
                        const unsigned int             n,
                        const double                   s,
                        Eigen::SimplicialLDLT<Sparse> &ldlt,
                        bool                          &analysed)
      {
        for (const double nudge : {0., 1e-9, -1e-9})
          {
            const Sparse A = section.shifted_stiffness(n, s * (1. + nudge));
            if (!analysed)
              ldlt.analyzePattern(A);
            analysed = true;
            ldlt.factorize(A);
            if (ldlt.info() == Eigen::Success && (ldlt.vectorD().array() != 0.).all())
              return;
          }
        throw NumericalError("the modes of harmonic " + std::to_string(n) +
                             ": K_n - s M at s = " + format_short(s) +
                             " rad^2/s^2 could not be factorised (a zero pivot "
                             "at every try)");
      }

      unsigned int
      negative_pivots(const Eigen::SimplicialLDLT<Sparse> &ldlt)
      {
        return static_cast<unsigned int>((ldlt.vectorD().array() < 0.).count());
      }
    } // namespace



    unsigned int
    count_harmonic_modes(const fe::HarmonicSection &section,
                         const unsigned int         n,
                         const double               cutoff)
    {
      Eigen::SimplicialLDLT<Sparse> ldlt;
      bool                          analysed = false;
      factorise_shifted(section, n, cutoff * cutoff, ldlt, analysed);
      return negative_pivots(ldlt);
    }



    namespace
    {
      /**
       * The modes of harmonic @p n in the slice (@p low, @p top] of w^2
       * [rad^2/s^2], which the inertia counts @p wanted: their eigenvalues in
       * @p slice_lambda and their shapes returned, one column each. The
       * first slice (@p first) is shifted below zero, so that its lowest
       * modes keep small relative residuals; the others to their middle.
       * A count a search misses is searched again with what it found
       * projected out (Deflated), twice at most. Adds its solves and Krylov
       * dimensions to @p modes' counters.
       */
      Eigen::MatrixXd
      search_slice(const fe::HarmonicSection          &section,
                   const unsigned int                  n,
                   const bool                          first,
                   const double                        low,
                   const double                        top,
                   const double                        cut2,
                   const unsigned int                  wanted,
                   Eigen::SimplicialLDLT<Sparse>      &ldlt,
                   bool                               &analysed,
                   const Eigen::SimplicialLLT<Sparse> &mass,
                   WavenumberModes                    &modes,
                   std::vector<double>                &slice_lambda)
      {
        const Eigen::Index size  = section.size();
        const double       shift = first ? -cut2 / 400. : 0.5 * (low + top);
        factorise_shifted(section, n, shift, ldlt, analysed);
        StandardShiftInvert op(ldlt, mass);
        // The slice's modes in standard form (the deflation's Y) and as
        // shapes. A first search asks for the count (and a few more in a
        // slice shifted to its middle); a count it misses is searched
        // again with what it found projected out (Deflated), twice at most.
        Eigen::MatrixXd Y(size, 0);
        slice_lambda.clear();
        for (unsigned int pass = 0; pass < 3 && slice_lambda.size() < wanted; ++pass)
          {
            const unsigned int missing = wanted - slice_lambda.size();
            const Eigen::Index extra   = std::min<Eigen::Index>(
              first && pass == 0 ? 0 : missing / 4 + 4, size - Y.cols() - missing - 2);
            const Eigen::Index nev = missing + std::max<Eigen::Index>(extra, 0);
            const Eigen::Index ncv = std::min<Eigen::Index>(
              size - Y.cols(), std::max<Eigen::Index>(2 * nev + 1, nev + 20));
            const auto found = [&](auto &solver) {
              solver.init();
              solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-11,
                             Spectra::SortRule::LargestAlge);
              if (solver.info() != Spectra::CompInfo::Successful)
                throw NumericalError("the modes of harmonic " + std::to_string(n) +
                                     ": Spectra's shift-invert Lanczos did not converge on " +
                                     std::to_string(nev) + " modes near " +
                                     format_short(std::sqrt(std::max(shift, 0.)) / (2. * M_PI)) +
                                     " Hz");
              modes.n_solves += static_cast<unsigned int>(solver.num_operations());
              modes.krylov_dimension += static_cast<unsigned int>(ncv);
              const Eigen::VectorXd nu = solver.eigenvalues();
              const Eigen::MatrixXd y  = solver.eigenvectors();
              for (Eigen::Index r = 0; r < nu.size(); ++r)
                {
                  if (nu(r) == 0.)
                    continue;
                  const double l = shift + 1. / nu(r);
                  if (!(l > low && l <= top * (1. + 1e-12)) || slice_lambda.size() == wanted)
                    continue;
                  Y.conservativeResize(Eigen::NoChange, Y.cols() + 1);
                  Y.col(Y.cols() - 1) = y.col(r);
                  slice_lambda.push_back(l);
                }
            };
            if (pass == 0)
              {
                Spectra::SymEigsSolver<StandardShiftInvert> solver(op, nev, ncv);
                found(solver);
              }
            else
              {
                // Y's columns from separate searches: orthonormal again.
                const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Y);
                const Eigen::MatrixXd                       Q =
                  qr.householderQ() * Eigen::MatrixXd::Identity(size, Y.cols());
                Deflated                         deflated(op, Q);
                Spectra::SymEigsSolver<Deflated> solver(deflated, nev, ncv);
                found(solver);
              }
          }
        if (slice_lambda.size() != wanted)
          throw NumericalError("the modes of harmonic " + std::to_string(n) + ": " +
                               std::to_string(slice_lambda.size()) + " eigenvalues found in (" +
                               format_short(std::max(low, 0.)) + ", " + format_short(top) +
                               "] rad^2/s^2 after three searches, where the inertia counts " +
                               std::to_string(wanted));
        return op.shapes(Y);
      }
    } // namespace



    WavenumberModes
    harmonic_modes(const fe::HarmonicSection &section,
                   const unsigned int         n,
                   const double               cutoff,
                   const unsigned int         modes_per_slice)
    {
      WavenumberModes modes;
      modes.wavenumber                   = n;
      const Sparse                  K    = section.stiffness(n);
      const Sparse                 &M    = section.mass();
      const double                  cut2 = cutoff * cutoff;
      const Eigen::Index            size = section.size();
      Eigen::SimplicialLDLT<Sparse> ldlt;
      bool                          analysed = false;
      factorise_shifted(section, n, cut2, ldlt, analysed);
      const unsigned int m = negative_pivots(ldlt);
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
      Eigen::SimplicialLLT<Sparse> mass(M);
      if (mass.info() != Eigen::Success)
        throw NumericalError("the modes of harmonic " + std::to_string(n) +
                             ": the section's mass matrix is not positive definite");

      // Slices of [0, w_c^2], equal in w^2 (the modes' number grows about
      // as w^2), each searched with its own shift and factorisation: the
      // Lanczos work grows with the square of its basis, so k slices of
      // m / k modes cost about 1/k of one search for all m. The first is
      // shifted below zero (its lowest modes keep small relative
      // residuals), so the modes nearest its shift are exactly the count
      // below its top. Each other one is shifted to its middle: the modes
      // nearest the shift are then those inside it, and a few more are
      // asked for so that the ones at its ends converge fast; those
      // outside it are dropped, and the count in it must be met exactly.
      const unsigned int        slices = std::max(1u, (m + modes_per_slice - 1) / modes_per_slice);
      std::vector<double>       top(slices);
      std::vector<unsigned int> below(slices + 1, 0);
      for (unsigned int j = 0; j < slices; ++j)
        top[j] = cut2 * (j + 1) / slices;
      below[slices] = m;
      for (unsigned int j = 0; j + 1 < slices; ++j)
        {
          factorise_shifted(section, n, top[j], ldlt, analysed);
          below[j + 1] = negative_pivots(ldlt);
        }
      std::vector<double> lambda, slice_lambda;
      Eigen::MatrixXd     U(size, m);
      for (unsigned int j = 0; j < slices; ++j)
        {
          const unsigned int wanted = below[j + 1] - below[j];
          if (wanted == 0)
            continue;
          const Eigen::MatrixXd slice_u =
            search_slice(section, n, j == 0, j == 0 ? -cut2 : top[j - 1], top[j], cut2, wanted,
                         ldlt, analysed, mass, modes, slice_lambda);
          for (unsigned int r = 0; r < wanted && lambda.size() < m; ++r)
            {
              U.col(lambda.size()) = slice_u.col(r);
              lambda.push_back(slice_lambda[r]);
            }
        }

      // Ascending, each residual checked.
      std::vector<unsigned int> order(m);
      for (unsigned int r = 0; r < m; ++r)
        order[r] = r;
      std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
        return lambda[a] < lambda[b];
      });
      // Row-major: Eigen's product of a column-major sparse matrix with a
      // dense one adds rows of the dense one, which are then contiguous
      // (three times faster than with columns).
      using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
      RowMajor V(size, m);
      for (unsigned int r = 0; r < m; ++r)
        V.col(r) = U.col(order[r]);
      const RowMajor MV = M * V, KV = K * V;
      modes.omega.resize(m);
      for (unsigned int r = 0; r < m; ++r)
        {
          const double l = lambda[order[r]];
          if (!(l > 0.))
            throw NumericalError("the modes of harmonic " + std::to_string(n) + ": eigenvalue " +
                                 format_printf("%.6g", l) + " found, not one of the " +
                                 std::to_string(m) + " counted in (0, w_c^2]");
          const double scale = 1. / std::sqrt(V.col(r).dot(MV.col(r)));
          V.col(r) *= scale;
          const double residual = (KV.col(r) - l * MV.col(r)).norm() / KV.col(r).norm();
          if (!(residual < 1e-6))
            throw NumericalError("the modes of harmonic " + std::to_string(n) + ": mode " +
                                 std::to_string(r) + " has a relative residual of " +
                                 format_printf("%.2g", residual));
          modes.max_residual = std::max(modes.max_residual, residual);
          modes.omega(r)     = std::sqrt(l);
        }
      const RowMajor        CV = section.damping(n) * V;
      const Eigen::MatrixXd B  = V.transpose() * CV;
      modes.modal_damping      = B.cast<std::complex<double>>();
      modes.damping_ratio      = B.diagonal().cwiseQuotient(2. * modes.omega);
      modes.shapes             = V.cast<std::complex<double>>();
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
      // (one factorisation each, cheap beside the search). Harmonics N to
      // N + 7 have none (checked first), so the count ends by N + 7 and every
      // harmonic it keeps is one the Green's functions sum (n_k <= N).
      // The counts are taken in batches over the threads (one factorisation
      // each), then read in order.
      periodic::check_mode_cutoff(ring, cutoff);
      const unsigned int        n_threads = std::max(1u, dealii::MultithreadInfo::n_threads());
      std::vector<unsigned int> counts;
      unsigned int              n_k = 0;
      for (unsigned int n = 0, empty = 0; empty < 8; ++n)
        {
          if (n == counts.size())
            {
              counts.resize(n + 8 * n_threads);
              base::for_each_index(
                8 * n_threads, n_threads, [&](const std::size_t i, unsigned int) {
                  counts[n + i] = count_harmonic_modes(ring.section, n + i, cutoff);
                });
            }
          if (counts[n] == 0)
            {
              ++empty;
              continue;
            }
          empty = 0;
          n_k   = n + 1;
        }
      const unsigned int P = ring.angle.size();
      return gather_ring_modes(
        n_k, P,
        [&](const unsigned int n) {
          WavenumberModes       modes = harmonic_modes(ring.section, n, cutoff);
          const double          s     = std::sqrt(ring.weight(n));
          Eigen::MatrixXcd      a(modes.omega.size(), P);
          const Eigen::MatrixXd seen =
            modes.omega.size() > 0 ? Eigen::MatrixXd(modes.shapes.real().transpose() * ring.loads) :
                                     Eigen::MatrixXd(0, ring.loads.cols());
          for (unsigned int p = 0; p < P; ++p)
            a.col(p) = s * std::polar(1., n * ring.angle[p]) *
                       seen.col(ring.strip[p]).cast<std::complex<double>>();
          modes.shapes.resize(0, 0); // not needed past here
          PointModes points =
            coupled_point_modes(modes, a, n == 0 ? 1. : 2., n == 0, couple_damping);
          return std::make_pair(std::move(modes), std::move(points));
        },
        "harmonics", comm, show_progress, couple_damping);
    }
  } // namespace synthesis
} // namespace greentread
