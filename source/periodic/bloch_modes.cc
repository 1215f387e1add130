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
       * The growing M-orthonormal basis V (with MV = M V kept for the inner
       * products), stored in preallocated columns.
       */
      class Basis
      {
      public:
        Basis(const SparseComplex &M_, const Eigen::Index capacity)
          : M(M_)
          , V(M_.rows(), capacity)
          , MV(M_.rows(), capacity)
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

        /// Add the part of X that is M-orthogonal to the basis, as
        /// M-orthonormal columns; directions already in the basis (to
        /// round-off) are dropped. Returns the number added.
        Eigen::Index
        add(Dense X)
        {
          const Eigen::Index room = capacity() - m;
          for (int pass = 0; pass < 2; ++pass)
            if (m > 0)
              X -= vectors() * (mass_times_vectors().adjoint() * X);
          // Within the block: the Gram matrix's eigenvectors, scaled.
          const Dense G = X.adjoint() * (M * X);
          const Eigen::SelfAdjointEigenSolver<Dense> eigen(0.5 * (G + G.adjoint()));
          const double largest = eigen.eigenvalues().maxCoeff();
          Eigen::Index added   = 0;
          for (Eigen::Index j = G.cols() - 1; j >= 0 && added < room; --j)
            {
              const double lambda = eigen.eigenvalues()(j);
              if (!(lambda > 1e-20 * largest) || !(largest > 0.))
                break;
              Eigen::VectorXcd v = X * eigen.eigenvectors().col(j) / std::sqrt(lambda);
              // One more pass against everything kept (the block's own
              // columns included), then normalise.
              for (int pass = 0; pass < 2; ++pass)
                if (m > 0)
                  v -= vectors() * (mass_times_vectors().adjoint() * v);
              Eigen::VectorXcd Mv   = M * v;
              const double     norm = std::sqrt(std::abs(v.dot(Mv)));
              if (!(norm > 1e-8))
                continue;
              V.col(m)  = v / norm;
              MV.col(m) = Mv / norm;
              ++m;
              ++added;
            }
          return added;
        }

      private:
        const SparseComplex &M;
        Dense                V, MV;
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
      Basis              basis(M, n);
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
      const double wanted = std::pow(1.25 * search.cutoff, 2), kept = std::pow(search.cutoff, 2);
      Eigen::Index last_first = 0, last_added = basis.add(X), next_check = 8 * b;
      while (true)
        {
          const bool full = basis.size() == basis.capacity() || last_added == 0;
          if (basis.size() >= next_check || full)
            {
              // Rayleigh-Ritz on the M-orthonormal basis.
              const Dense KV = K * basis.vectors();
              const Dense H  = basis.vectors().adjoint() * KV;
              const Eigen::SelfAdjointEigenSolver<Dense> ritz(0.5 * (H + H.adjoint()));
              const Eigen::VectorXd &theta = ritz.eigenvalues();
              Eigen::Index           below = 0;
              while (below < theta.size() && theta(below) <= wanted)
                ++below;
              bool         converged = below < theta.size() || full;
              double       worst     = 0.;
              const Dense  Y         = ritz.eigenvectors().leftCols(below);
              const Dense  VY        = basis.vectors() * Y;
              const Dense  KY = KV * Y, MY = basis.mass_times_vectors() * Y;
              for (Eigen::Index j = 0; j < below && converged; ++j)
                {
                  // The residual against K x (as ARPACK judges T = (K - sM)^-1 M), unless
                  // it is at rounding level: against the size of K and M, a mode far
                  // below the stiffest layer cannot do better than eps ||K|| / w^2.
                  const double misfit   = (KY.col(j) - theta(j) * MY.col(j)).norm();
                  const double residual = misfit / KY.col(j).norm();
                  const double backward =
                    misfit / ((norm_K + std::abs(theta(j)) * norm_M) * VY.col(j).norm());
                  worst     = std::max(worst, residual);
                  converged = residual <= search.tolerance ||
                              backward <= 1e3 * std::numeric_limits<double>::epsilon();
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
              next_check = basis.size() + std::max<Eigen::Index>(4 * b, basis.size() / 4);
            }
          // The next block: T applied to the last block added.
          const Dense last = basis.vectors().middleCols(last_first, last_added);
          const Dense Y    = lu.solve(Dense(M * last));
          ++modes.n_solves;
          last_first = basis.size();
          last_added = basis.add(Y);
        }
    }
  } // namespace periodic
} // namespace greentread
