#include <greentread/base/exceptions.h>
#include <greentread/periodic/bloch_modes.h>
#include <greentread/periodic/green_solvers.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace greentread
{
  namespace periodic
  {
    namespace
    {
      using Dense = Eigen::MatrixXcd;

      /**
       * The growing M-orthonormal basis V, with MV = M V kept for the inner
       * products and H = V^H K V grown with it (the Rayleigh-Ritz matrix),
       * stored in preallocated columns.
       */
      class Basis
      {
      public:
        Basis(const SparseComplex &K_, const SparseComplex &M_, const Eigen::Index capacity)
          : K(K_)
          , M(M_)
          , V(M_.rows(), capacity)
          , MV(M_.rows(), capacity)
          , H(capacity, capacity)
        {}

        Eigen::Index
        size() const
        {
          return m;
        }
        Eigen::Index
        capacity() const
        {
          return V.cols();
        }
        auto
        vectors() const
        {
          return V.leftCols(m);
        }
        auto
        mass_times_vectors() const
        {
          return MV.leftCols(m);
        }
        /// V^H K V, Hermitian.
        auto
        projected_stiffness() const
        {
          return H.topLeftCorner(m, m);
        }

        /// Add the part of X that is M-orthogonal to the basis, as
        /// M-orthonormal columns; directions already in the basis (to
        /// round-off) are dropped. Block classical Gram-Schmidt, twice
        /// ("twice is enough" while the block keeps more than about 1e-6 of
        /// its size), then the block made orthonormal by its Gram matrix's
        /// eigenvectors. If the passes cancelled more than that, or the
        /// orthonormalisation amplified a weak direction by more than 1e4
        /// (and its error against the basis with it), once more against
        /// the basis and within itself. All block products: the basis, tens
        /// of megabytes, does not stay in cache, and each pass reads it
        /// once. Returns the number added.
        Eigen::Index
        add(Dense X)
        {
          const double before = X.norm();
          for (int pass = 0; pass < 2; ++pass)
            project_out(X);
          const bool cancelled = !(X.norm() > 1e-6 * before);
          // Directions below 1e-10 of the block's largest are round-off;
          // after a third pass, below 1e-8 of their unit size they were in
          // the basis already.
          Dense      MX;
          const bool weak = orthonormal(X, MX, 1e-20, false) < 1e-8 || cancelled;
          if (weak)
            {
              project_out(X);
              orthonormal(X, MX, 1e-16, true);
            }
          const Eigen::Index added = std::min<Eigen::Index>(X.cols(), capacity() - m);
          if (added == 0)
            return 0;
          const Dense KX          = K * X.leftCols(added);
          V.middleCols(m, added)  = X.leftCols(added);
          MV.middleCols(m, added) = MX.leftCols(added);
          // The new columns of H, and its new rows by symmetry.
          H.block(0, m, m + added, added) = V.leftCols(m + added).adjoint() * KX;
          H.block(m, 0, added, m)         = H.block(0, m, m, added).adjoint();
          const Dense corner              = H.block(m, m, added, added);
          H.block(m, m, added, added)     = 0.5 * (corner + corner.adjoint());
          m += added;
          return added;
        }

      private:
        void
        project_out(Dense &X) const
        {
          if (m > 0 && X.cols() > 0)
            X -= vectors() * (mass_times_vectors().adjoint() * X);
        }

        /// Replace @p X by M-orthonormal columns spanning it, strongest
        /// first, without the directions whose squared M-norm is below
        /// @p drop times the largest (or times 1, @p absolute, for columns
        /// of unit size), and set @p MX = M X. Returns the smallest kept
        /// squared norm over the largest (1 if none is kept).
        double
        orthonormal(Dense &X, Dense &MX, const double drop, const bool absolute) const
        {
          MX = M * X;
          if (X.cols() == 0)
            return 1.;
          const Dense G = X.adjoint() * MX;
          const Eigen::SelfAdjointEigenSolver<Dense> eigen(0.5 * (G + G.adjoint()));
          const Eigen::VectorXd &lambda    = eigen.eigenvalues();
          const Eigen::Index     n         = G.cols();
          const double           largest   = lambda(n - 1);
          const double           threshold = drop * (absolute ? 1. : largest);
          Eigen::Index           keep      = 0;
          while (keep < n && largest > 0. && lambda(n - 1 - keep) > threshold)
            ++keep;
          Dense U(n, keep);
          for (Eigen::Index j = 0; j < keep; ++j)
            U.col(j) = eigen.eigenvectors().col(n - 1 - j) / std::sqrt(lambda(n - 1 - j));
          X  = X * U;
          MX = MX * U;
          return keep > 0 ? lambda(n - keep) / largest : 1.;
        }

        const SparseComplex &K, &M;
        Dense                V, MV, H;
        Eigen::Index         m = 0;
      };

      /// Rotate @p v so that its largest entry is real and positive: a
      /// fixed phase, so that a real problem (k = 0, N/2) gives real shapes.
      void
      fix_phase(Eigen::Ref<Eigen::VectorXcd> v)
      {
        Eigen::Index largest;
        v.cwiseAbs().maxCoeff(&largest);
        v *= std::polar(1., -std::arg(v(largest)));
      }
    } // namespace



    BlochModes
    bloch_modes(const PeriodicCell &cell, const unsigned int k, const ModeSearch &search)
    {
      const std::string which = "Bloch wavenumber " + std::to_string(k);
      if (!(search.cutoff > 0.) || search.block == 0)
        throw NumericalError("bloch_modes: the cut-off must be positive and the block size at "
                             "least 1 (" + which + ")");
      const double phi = 2. * M_PI * k / cell.n_cells;
      BlochCell    bloch(cell);
      const auto   part = [&](const Complex a, const Complex c, const Complex m) {
        bloch.set_combination(a, c, m);
        return SparseComplex(bloch.assemble(phi));
      };
      const SparseComplex K = part(1., 0., 0.), C = part(0., 1., 0.), M = part(0., 0., 1.);
      const double        shift = -std::pow(search.cutoff / 20., 2);
      const SparseComplex A     = part(1., 0., -shift);

      Eigen::SparseLU<SparseComplex, Eigen::COLAMDOrdering<int>> lu;
      lu.analyzePattern(A);
      lu.factorize(A);
      if (lu.info() != Eigen::Success)
        throw NumericalError("the shifted stiffness K - s M of " + which +
                             " could not be factorised: is the cell held against rigid motion?");

      const auto row_sum_norm = [](const SparseComplex &matrix) {
        Eigen::VectorXd sums = Eigen::VectorXd::Zero(matrix.rows());
        for (Eigen::Index c = 0; c < matrix.outerSize(); ++c)
          for (SparseComplex::InnerIterator it(matrix, c); it; ++it)
            sums(it.row()) += std::abs(it.value());
        return sums.maxCoeff();
      };
      const double       norm_K = row_sum_norm(K), norm_M = row_sum_norm(M);
      const Eigen::Index n = A.rows(), b = std::min<Eigen::Index>(search.block, n);
      Basis              basis(K, M, n);
      BlochModes         modes;
      modes.wavenumber = k;

      std::mt19937                           random(12345u + k);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      Dense                                  X(n, b);
      for (Eigen::Index j = 0; j < b; ++j)
        for (Eigen::Index i = 0; i < n; ++i)
          X(i, j) = Complex(uniform(random), uniform(random));

      // The start is T X, not X: every vector of the Krylov space is then in
      // the range of T, where the modes are. With a singular M (mass moved
      // off the contact surface) a random start has components in M's null
      // space that T never removes, and they swamp the Rayleigh-Ritz step.
      X = lu.solve(Dense(M * X));
      ++modes.n_solves;
      const double wanted = std::pow(1.1 * search.cutoff, 2), kept = std::pow(search.cutoff, 2);
      Eigen::Index last_first = 0, last_added = basis.add(X), next_check = 8 * b;
      while (true)
        {
          const bool full = basis.size() == basis.capacity() || last_added == 0;
          if (basis.size() >= next_check || full)
            {
              // Rayleigh-Ritz on the M-orthonormal basis.
              const Dense H = basis.projected_stiffness();
              const Eigen::SelfAdjointEigenSolver<Dense> ritz(H);
              const Eigen::VectorXd &theta = ritz.eigenvalues();
              Eigen::Index           below = 0;
              while (below < theta.size() && theta(below) <= wanted)
                ++below;
              bool   converged = below < theta.size() || full;
              double worst     = 0.;
              // The residual against K x (as ARPACK judges T = (K - sM)^-1 M), unless
              // it is at rounding level: against the size of K and M, a mode far
              // below the stiffest layer cannot do better than eps ||K|| / w^2.
              const auto judge = [&](const Eigen::Index j, const auto &x, const auto &Kx,
                                     const auto &Mx) {
                const double misfit   = (Kx - theta(j) * Mx).norm();
                const double residual = misfit / Kx.norm();
                const double backward =
                  misfit / ((norm_K + std::abs(theta(j)) * norm_M) * x.norm());
                worst = std::max(worst, residual);
                return residual <= search.tolerance ||
                       backward <= 1e3 * std::numeric_limits<double>::epsilon();
              };
              // The highest wanted pair converges last: judge it alone first,
              // and the others (block products) only once it has converged.
              if (converged && below > 0)
                {
                  const Eigen::VectorXcd x = basis.vectors() * ritz.eigenvectors().col(below - 1);
                  const Eigen::VectorXcd Kx = K * x,
                                         Mx = basis.mass_times_vectors() *
                                              ritz.eigenvectors().col(below - 1);
                  converged = judge(below - 1, x, Kx, Mx);
                }
              Dense VY;
              if (converged)
                {
                  const Dense Y = ritz.eigenvectors().leftCols(below);
                  VY            = basis.vectors() * Y;
                  const Dense KY = K * VY, MY = basis.mass_times_vectors() * Y;
                  for (Eigen::Index j = 0; j < below && converged; ++j)
                    converged = judge(j, VY.col(j), KY.col(j), MY.col(j));
                }
              if (converged)
                {
                  Eigen::Index count = 0;
                  while (count < below && theta(count) <= kept)
                    ++count;
                  modes.omega.resize(count);
                  modes.damping_ratio.resize(count);
                  modes.shapes = VY.leftCols(count);
                  for (Eigen::Index j = 0; j < count; ++j)
                    {
                      if (!(theta(j) > 0.))
                        throw NumericalError(which + " has a mode of zero or negative stiffness "
                                             "(w^2 = " + format_short(theta(j)) +
                                             "): the cell is not held against rigid motion, or "
                                             "the prestress makes it unstable");
                      modes.omega(j) = std::sqrt(theta(j));
                      fix_phase(modes.shapes.col(j));
                    }
                  modes.modal_damping = modes.shapes.adjoint() * (C * modes.shapes);
                  for (Eigen::Index j = 0; j < count; ++j)
                    modes.damping_ratio(j) =
                      modes.modal_damping(j, j).real() / (2. * modes.omega(j));
                  modes.krylov_dimension = static_cast<unsigned int>(basis.size());
                  modes.max_residual     = worst;
                  return modes;
                }
              if (full)
                throw NumericalError("the mode search of " + which + " did not converge in " +
                                     std::to_string(basis.size()) +
                                     " vectors (worst relative residual " +
                                     format_short(worst) + ")");
              next_check = basis.size() + std::max<Eigen::Index>(4 * b, basis.size() / 10);
            }
          // The next block: T applied to the last block added.
          const Dense Y =
            lu.solve(Dense(basis.mass_times_vectors().middleCols(last_first, last_added)));
          ++modes.n_solves;
          last_first = basis.size();
          last_added = basis.add(Y);
        }
    }
  } // namespace periodic
} // namespace greentread
