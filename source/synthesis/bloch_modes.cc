#include <greentread/base/exceptions.h>
#include <greentread/periodic/green_solvers.h>
#include <greentread/synthesis/bloch_modes.h>
#include <greentread/synthesis/shared_pattern.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace greentread
{
  namespace synthesis
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
        /// A basis kept M-orthogonal to the columns of @p locked_ as well
        /// (modes found already, with @p mass_locked_ = M locked_).
        /// At most @p limit columns. The storage starts at 512 columns and
        /// doubles as the basis grows: reserving all of them at once, n x n
        /// for V, M V and H, was refused (std::bad_alloc) above about
        /// 38,000 unknowns, where each exceeds the machine's memory.
        Basis(const internal::SharedPattern &KM_,
              const Dense                   &locked_,
              const Dense                   &mass_locked_,
              const Eigen::Index             limit_)
            : KM(KM_)
            , locked(locked_)
            , mass_locked(mass_locked_)
            , limit(limit_)
            , V(KM_.size(), std::min<Eigen::Index>(limit_, 512))
            , MV(KM_.size(), V.cols())
            , H(V.cols(), V.cols())
        {
        }

        Eigen::Index
        size() const
        {
          return m;
        }
        Eigen::Index
        capacity() const
        {
          return limit;
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
            project_out(X, pass == 0);
          const bool cancelled = !(X.norm() > 1e-6 * before);
          // Directions below 1e-10 of the block's largest are round-off;
          // after a third pass, below 1e-8 of their unit size they were in
          // the basis already.
          Dense      MX, KX;
          const bool weak = orthonormal(X, MX, KX, 1e-20, false) < 1e-8 || cancelled;
          if (weak)
            {
              project_out(X, true);
              orthonormal(X, MX, KX, 1e-16, true);
            }
          const Eigen::Index added = std::min<Eigen::Index>(X.cols(), capacity() - m);
          if (added == 0)
            return 0;
          reserve(m + added);
          V.middleCols(m, added)  = X.leftCols(added);
          MV.middleCols(m, added) = MX.leftCols(added);
          // The new columns of H, and its new rows by symmetry.
          H.block(0, m, m + added, added) = V.leftCols(m + added).adjoint() * KX.leftCols(added);
          H.block(m, 0, added, m)         = H.block(0, m, m, added).adjoint();
          const Dense corner              = H.block(m, m, added, added);
          H.block(m, m, added, added)     = 0.5 * (corner + corner.adjoint());
          m += added;
          return added;
        }

      private:
        /// Storage for at least @p columns columns (at most the limit),
        /// doubling, so that the copies cost at most twice the final size.
        void
        reserve(const Eigen::Index columns)
        {
          if (columns <= V.cols())
            return;
          const Eigen::Index grown = std::min(limit, std::max(columns, 2 * V.cols()));
          V.conservativeResize(Eigen::NoChange, grown);
          MV.conservativeResize(Eigen::NoChange, grown);
          H.conservativeResize(grown, grown);
        }

        /// X -= V (MV^H X), and the same against the locked modes if
        /// @p with_locked. Once against those is enough: they are modes (to
        /// residuals of about 1e-9), and T maps a vector M-orthogonal to a
        /// mode to one that is M-orthogonal to it too, so the coefficients
        /// against them stay small and nothing cancels; it is the
        /// cancellation against the growing basis that the second pass
        /// corrects. Their second projection was about two fifths of the
        /// Gram-Schmidt work of the upper slices.
        void
        project_out(Dense &X, const bool with_locked) const
        {
          if (with_locked && locked.cols() > 0 && X.cols() > 0)
            subtract_projection(locked, mass_locked, X);
          if (m > 0 && X.cols() > 0)
            subtract_projection(vectors(), mass_times_vectors(), X);
        }

        /**
         * X -= Q (MQ^H X) for a tall Q of many columns and an X of a few:
         * two passes of general products over chunks of 256 rows, so that
         * Q's chunk, packed by the product, stays in the second-level cache.
         * (One vector product per column of Q and chunk of 64 rows, as it
         * was, spent more time in the calls than in the arithmetic: the
         * default tyre's search took about a quarter longer.)
         */
        template <typename Tall>
        static void
        subtract_projection(const Tall &Q, const Tall &MQ, Dense &X)
        {
          constexpr Eigen::Index chunk = 256;
          const Eigen::Index     n = X.rows(), q = Q.cols();
          Dense                  W = Dense::Zero(q, X.cols());
          for (Eigen::Index r = 0; r < n; r += chunk)
            {
              const Eigen::Index len = std::min(chunk, n - r);
              W.noalias() += MQ.middleRows(r, len).adjoint() * X.middleRows(r, len);
            }
          for (Eigen::Index r = 0; r < n; r += chunk)
            {
              const Eigen::Index len = std::min(chunk, n - r);
              X.middleRows(r, len).noalias() -= Q.middleRows(r, len) * W;
            }
        }

        /// Replace @p X by M-orthonormal columns spanning it, strongest
        /// first, without the directions whose squared M-norm is below
        /// @p drop times the largest (or times 1, @p absolute, for columns
        /// of unit size), and set @p MX = M X, @p KX = K X. Returns the
        /// smallest kept squared norm over the largest (1 if none is kept).
        double
        orthonormal(Dense &X, Dense &MX, Dense &KX, const double drop, const bool absolute) const
        {
          KM.apply(X, {&KX, &MX});
          if (X.cols() == 0)
            return 1.;
          const Dense                                G = X.adjoint() * MX;
          const Eigen::SelfAdjointEigenSolver<Dense> eigen(0.5 * (G + G.adjoint()));
          const Eigen::VectorXd                     &lambda    = eigen.eigenvalues();
          const Eigen::Index                         n         = G.cols();
          const double                               largest   = lambda(n - 1);
          const double                               threshold = drop * (absolute ? 1. : largest);
          Eigen::Index                               keep      = 0;
          while (keep < n && largest > 0. && lambda(n - 1 - keep) > threshold)
            ++keep;
          Dense U(n, keep);
          for (Eigen::Index j = 0; j < keep; ++j)
            U.col(j) = eigen.eigenvectors().col(n - 1 - j) / std::sqrt(lambda(n - 1 - j));
          X  = X * U;
          MX = MX * U;
          KX = KX * U;
          return keep > 0 ? lambda(n - keep) / largest : 1.;
        }

        const internal::SharedPattern &KM;
        const Dense                   &locked, &mass_locked;
        const Eigen::Index             limit; ///< the most columns the basis may have
        Dense                          V, MV, H;
        Eigen::Index                   m = 0;
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

      double
      row_sum_norm(const periodic::SparseComplex &matrix)
      {
        Eigen::VectorXd sums = Eigen::VectorXd::Zero(matrix.rows());
        for (Eigen::Index c = 0; c < matrix.outerSize(); ++c)
          for (periodic::SparseComplex::InnerIterator it(matrix, c); it; ++it)
            sums(it.row()) += std::abs(it.value());
        return sums.maxCoeff();
      }

      /**
       * The number of eigenvalues of (K, M) below @p sigma: by Sylvester's
       * law of inertia, the number of negative pivots of K - sigma M =
       * L D L^H (M semidefinite; with K positive definite a massless DoF
       * adds a positive pivot only). Without pivoting the factorisation
       * could meet a zero pivot where a leading block is singular at
       * @p sigma; a shift moved by 1e-9 of itself then gives the same count
       * unless an eigenvalue lies within that of @p sigma.
       */
      Eigen::Index
      count_below(const periodic::SparseComplex &K,
                  const periodic::SparseComplex &M,
                  const double                   sigma,
                  const std::string             &which)
      {
        for (const double nudge : {0., 1e-9, -1e-9})
          {
            const periodic::SparseComplex A = K - (sigma * (1. + nudge)) * M;
            Eigen::SimplicialLDLT<periodic::SparseComplex, Eigen::Lower> ldlt(A);
            if (ldlt.info() != Eigen::Success)
              continue;
            const auto  &d        = ldlt.vectorD();
            Eigen::Index negative = 0;
            bool         zero     = false;
            for (Eigen::Index i = 0; i < d.size(); ++i)
              {
                negative += d(i).real() < 0.;
                zero = zero || !(std::abs(d(i).real()) > 0.);
              }
            if (!zero)
              return negative;
          }
        throw NumericalError("the inertia of K - s M of " + which +
                             " at s = " + format_short(sigma) +
                             " rad^2/s^2 could not be computed: its LDL^H factorisation met a "
                             "zero pivot at every try");
      }

      /// The problem of one wavenumber: K, C, M folded with its phase.
      struct Problem
      {
        periodic::SparseComplex K, C, M;
        /// K and M together, M and C alone (products with tall blocks).
        internal::SharedPattern KM, MM, CC;
        double                  norm_K, norm_M;
        std::string             which;
      };

      /// The modes one slice found: w^2 ascending, shapes M-orthonormal.
      struct Slice
      {
        std::vector<double> theta;
        Dense               shapes;
        unsigned int        n_solves = 0, dimension = 0;
        double              worst = 0.;
      };

      /**
       * The @p expected modes with w^2 <= @p upper that are M-orthogonal
       * to @p locked: the Krylov space of T = (K - shift M)^-1 M, grown
       * until @p expected Ritz values are at or below @p upper and every
       * one of them has converged. On the space M-orthogonal to the locked
       * modes, Ritz values are upper bounds of the remaining eigenvalues in
       * order, whatever the shift: once as many are below @p upper as
       * there are eigenvalues there (the inertia), none is missing.
       */
      Slice
      search_slice(const Problem     &problem,
                   const Dense       &locked,
                   const Dense       &mass_locked,
                   const double       shift,
                   const double       upper,
                   const Eigen::Index expected,
                   const ModeSearch  &search,
                   const unsigned     seed)
      {
        const periodic::SparseComplex &K = problem.K, &M = problem.M;
        Slice                          slice;
        if (expected == 0)
          {
            slice.shapes.resize(K.rows(), 0);
            return slice;
          }
        const periodic::SparseComplex                                        A = K - shift * M;
        Eigen::SparseLU<periodic::SparseComplex, Eigen::COLAMDOrdering<int>> lu;
        lu.analyzePattern(A);
        lu.factorize(A);
        if (lu.info() != Eigen::Success)
          throw NumericalError("the shifted stiffness K - s M of " + problem.which +
                               " (s = " + format_short(shift) +
                               " rad^2/s^2) could not be factorised: is the cell held "
                               "against rigid motion?");
        const Eigen::Index n = A.rows(), b = std::min<Eigen::Index>(search.block, n);
        Basis              basis(problem.KM, locked, mass_locked, n - locked.cols());

        std::mt19937                           random(seed);
        std::uniform_real_distribution<double> uniform(-1., 1.);
        Dense                                  X(n, b);
        for (Eigen::Index j = 0; j < b; ++j)
          for (Eigen::Index i = 0; i < n; ++i)
            X(i, j) = periodic::Complex(uniform(random), uniform(random));

        // The start is T X, not X: every vector of the Krylov space is then
        // in the range of T, where the modes are. With a singular M (mass
        // moved off the contact surface) a random start has components in
        // M's null space that T never removes, and they swamp the
        // Rayleigh-Ritz step.
        X = lu.solve(Dense(M * X));
        ++slice.n_solves;
        // The residual against K x (as ARPACK judges T), unless it is at
        // rounding level: against the size of K and M, a mode far below the
        // stiffest layer cannot do better than eps ||K|| / w^2.
        double     worst = 0.;
        const auto judge = [&](const double theta, const auto &x, const auto &Kx, const auto &Mx) {
          const double misfit   = (Kx - theta * Mx).norm();
          const double residual = misfit / Kx.norm();
          const double backward =
            misfit / ((problem.norm_K + std::abs(theta) * problem.norm_M) * x.norm());
          worst = std::max(worst, residual);
          return std::make_pair(residual <= search.tolerance ||
                                  backward <= 1e3 * std::numeric_limits<double>::epsilon(),
                                residual);
        };

        Eigen::Index last_first = 0, last_added = basis.add(X), next_check = 8 * b;
        // The highest wanted pair converges last, and geometrically in the
        // basis size once it is there: its residual at the previous check
        // places the next one where it should meet the tolerance.
        double       previous_residual = 0.;
        Eigen::Index previous_size     = 0;
        bool         counted           = false;
        while (true)
          {
            const bool full = basis.size() == basis.capacity() || last_added == 0;
            if (basis.size() >= next_check || full)
              {
                // Rayleigh-Ritz on the M-orthonormal basis: the Ritz values
                // alone until as many as expected are below the bound, the
                // vectors too from then on (by interlacing, their number
                // below it never falls as the basis grows).
                const Dense                          H = basis.projected_stiffness();
                Eigen::SelfAdjointEigenSolver<Dense> ritz(H, counted ? Eigen::ComputeEigenvectors :
                                                                       Eigen::EigenvaluesOnly);
                Eigen::Index                         below = 0;
                while (below < ritz.eigenvalues().size() && ritz.eigenvalues()(below) <= upper)
                  ++below;
                if (below > expected)
                  throw NumericalError(problem.which + " has " + std::to_string(below) +
                                       " Ritz values up to " + format_short(upper) +
                                       " rad^2/s^2 but only " + std::to_string(expected) +
                                       " eigenvalues there by the inertia of K - s M");
                double top = 0.;
                worst      = 0.;
                if (below == expected)
                  {
                    if (!counted)
                      ritz.compute(H);
                    counted                      = true;
                    const Eigen::VectorXd &theta = ritz.eigenvalues();
                    const Eigen::VectorXcd x = basis.vectors() * ritz.eigenvectors().col(below - 1);
                    const Eigen::VectorXcd Kx = K * x, Mx = basis.mass_times_vectors() *
                                                            ritz.eigenvectors().col(below - 1);
                    const auto highest = judge(theta(below - 1), x, Kx, Mx);
                    top                = highest.second;
                    bool converged     = highest.first;
                    if (converged)
                      {
                        const Dense Y  = ritz.eigenvectors().leftCols(below);
                        const Dense VY = basis.vectors() * Y;
                        const Dense MY = basis.mass_times_vectors() * Y;
                        Dense       KY;
                        problem.KM.apply(VY, {&KY});
                        for (Eigen::Index j = 0; j < below && converged; ++j)
                          converged = judge(theta(j), VY.col(j), KY.col(j), MY.col(j)).first;
                        if (converged)
                          {
                            slice.theta.assign(theta.data(), theta.data() + below);
                            slice.shapes = VY;
                          }
                      }
                  }
                if (below == expected && slice.shapes.cols() == below)
                  {
                    slice.dimension = static_cast<unsigned int>(basis.size());
                    slice.worst     = worst;
                    return slice;
                  }
                if (full)
                  throw NumericalError("the mode search of " + problem.which +
                                       " did not converge in " + std::to_string(basis.size()) +
                                       " vectors (worst relative residual " + format_short(worst) +
                                       ")");
                const Eigen::Index step = std::max<Eigen::Index>(4 * b, basis.size() / 10);
                next_check              = basis.size() + step;
                if (top > 0. && previous_residual > top)
                  {
                    const double per_vector =
                      std::log(previous_residual / top) / double(basis.size() - previous_size);
                    const double needed = std::log(top / search.tolerance) / per_vector;
                    next_check =
                      basis.size() + std::clamp<Eigen::Index>(
                                       static_cast<Eigen::Index>(std::ceil(needed)), b, step);
                  }
                previous_residual = top;
                previous_size     = basis.size();
              }
            // The next block: T applied to the last block added.
            const Dense Y =
              lu.solve(Dense(basis.mass_times_vectors().middleCols(last_first, last_added)));
            ++slice.n_solves;
            last_first = basis.size();
            last_added = basis.add(Y);
          }
      }
    } // namespace



    WavenumberModes
    bloch_modes(const periodic::PeriodicCell &cell, const unsigned int k, const ModeSearch &search)
    {
      const double        phi = 2. * M_PI * k / cell.n_cells;
      periodic::BlochCell bloch(cell);
      const auto          part = [&](const periodic::Complex a, const periodic::Complex c,
                            const periodic::Complex m) {
        bloch.set_combination(a, c, m);
        return periodic::SparseComplex(bloch.assemble(phi));
      };
      return hermitian_modes(part(1., 0., 0.), part(0., 1., 0.), part(0., 0., 1.), k,
                             "Bloch wavenumber " + std::to_string(k), search);
    }



    WavenumberModes
    hermitian_modes(periodic::SparseComplex K,
                    periodic::SparseComplex C,
                    periodic::SparseComplex M,
                    const unsigned int      k,
                    const std::string      &which,
                    const ModeSearch       &search)
    {
      if (!(search.cutoff > 0.) || search.block == 0 || search.slices == 0)
        throw NumericalError("bloch_modes: the cut-off must be positive and the block size "
                             "and the number of slices at least 1 (" +
                             which + ")");
      Problem problem;
      problem.K      = std::move(K);
      problem.C      = std::move(C);
      problem.M      = std::move(M);
      problem.KM     = internal::SharedPattern({&problem.K, &problem.M});
      problem.MM     = internal::SharedPattern({&problem.M});
      problem.CC     = internal::SharedPattern({&problem.C});
      problem.norm_K = row_sum_norm(problem.K);
      problem.norm_M = row_sum_norm(problem.M);
      problem.which  = which;

      // Slice s holds w^2 in (c^2 s / S, c^2 (s + 1) / S], c the cut-off:
      // about as many modes each, as their number grows about as w^2. The
      // first is shifted below zero (K - s M positive definite, even for an
      // unheld cell), the others at their middle, with the modes below
      // them locked (deflated), so each basis holds only its slice's modes
      // and the Gram-Schmidt work, which grows with the square of the
      // basis, shrinks. At the middle no wanted mode is further from the
      // shift than half the slice, and the modes converged in 16% fewer
      // solves than with the shift at the lower end (the default tyre,
      // wavenumbers 0, 1, 16, 64, 128: 95 to 113 against 116 to 134).
      // The first slice stays shifted at its bottom: in the middle the
      // lowest modes, far below the shift in relative terms, stopped at
      // relative residuals of 1e-5 to 1e-4 (accepted on their backward
      // error, but less accurate than from a shift below them).
      const double        cut2 = search.cutoff * search.cutoff;
      Dense               locked(problem.M.rows(), 0), mass_locked(problem.M.rows(), 0);
      std::vector<double> theta;
      WavenumberModes     modes;
      modes.wavenumber = k;
      for (unsigned int s = 0; s < search.slices; ++s)
        {
          const double lower = cut2 * s / search.slices, upper = cut2 * (s + 1) / search.slices;
          const double shift = s == 0 ? -cut2 / 400. : 0.5 * (lower + upper);
          const Eigen::Index expected =
            count_below(problem.K, problem.M, upper, which) - locked.cols();
          const Slice slice = search_slice(problem, locked, mass_locked, shift, upper, expected,
                                           search, 12345u + k + 7919u * s);
          modes.n_solves += slice.n_solves;
          modes.krylov_dimension += slice.dimension;
          modes.max_residual     = std::max(modes.max_residual, slice.worst);
          const Eigen::Index had = locked.cols(), added = slice.shapes.cols();
          locked.conservativeResize(Eigen::NoChange, had + added);
          locked.rightCols(added) = slice.shapes;
          if (s + 1 < search.slices)
            {
              mass_locked.conservativeResize(Eigen::NoChange, had + added);
              Dense mass_shapes;
              problem.MM.apply(slice.shapes, {&mass_shapes});
              mass_locked.rightCols(added) = mass_shapes;
            }
          theta.insert(theta.end(), slice.theta.begin(), slice.theta.end());
        }

      // In order of frequency (a mode a slice missed below its lower end
      // would be found by the next one, out of order).
      std::vector<Eigen::Index> order(theta.size());
      for (std::size_t j = 0; j < order.size(); ++j)
        order[j] = static_cast<Eigen::Index>(j);
      std::stable_sort(order.begin(), order.end(), [&](const Eigen::Index a, const Eigen::Index b) {
        return theta[a] < theta[b];
      });
      const Eigen::Index count = static_cast<Eigen::Index>(order.size());
      modes.omega.resize(count);
      modes.damping_ratio.resize(count);
      modes.shapes.resize(problem.M.rows(), count);
      for (Eigen::Index j = 0; j < count; ++j)
        {
          const double t = theta[order[j]];
          if (!(t > 0.))
            throw NumericalError(
              which + " has a mode of zero or negative stiffness (w^2 = " + format_short(t) +
              "): the cell is not held against rigid motion, or the "
              "prestress makes it unstable");
          modes.omega(j)      = std::sqrt(t);
          modes.shapes.col(j) = locked.col(order[j]);
          fix_phase(modes.shapes.col(j));
        }
      Dense damped;
      problem.CC.apply(modes.shapes, {&damped});
      modes.modal_damping = modes.shapes.adjoint() * damped;
      for (Eigen::Index j = 0; j < count; ++j)
        modes.damping_ratio(j) = modes.modal_damping(j, j).real() / (2. * modes.omega(j));
      return modes;
    }
  } // namespace synthesis
} // namespace greentread
