#include <greentread/base/exceptions.h>
#include <greentread/base/serial_blas.h>
#include <greentread/periodic/green_solvers.h>
#include <greentread/periodic/harmonic_ring.h>
#include <greentread/periodic/ring_chain.h>

#include <Eigen/LU>
#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace periodic
  {
    Method
    parse_method(const std::string &name)
    {
      if (name == "bloch")
        return Method::bloch;
      if (name == "doubling")
        return Method::doubling;
      if (name == "full-ring")
        return Method::full_ring;
      if (name == "harmonic")
        return Method::harmonic;
      throw InputError("parameter 'Green's functions/Method' = " + name +
                       " is not allowed; allowed: bloch, doubling, full-ring, harmonic");
    }



    namespace
    {
      // The Bloch cell problems: Eigen's supernodal LU with COLAMD was the
      // fastest on the tyre cell (AMD: 70 times slower, measured). The long
      // chains of cells (the full ring, Eq. 49): UMFPACK, whose ordering
      // suits them far better.
      using SparseLU = Eigen::SparseLU<SparseComplex, Eigen::COLAMDOrdering<int>>;
      using ChainLU  = Eigen::UmfPackLU<SparseComplex>;
      using Dense    = Eigen::MatrixXcd;

      std::string
      at_frequency(const double omega)
      {
        return "f = " + format_short(omega / (2. * M_PI)) + " Hz";
      }

      /// Throw unless the factorisation worked.
      template <typename LU>
      void
      require_factorised(const LU &lu, const double omega, const std::string &what)
      {
        if (lu.info() != Eigen::Success)
          throw NumericalError("the dynamic stiffness " + what + " is singular at " +
                               at_frequency(omega) +
                               ": an undamped resonance? Give the materials a loss factor or "
                               "move the frequency grid");
      }

      /// |z| without std::abs's overflow guard (hypot), which dominated
      /// the checks; the entries here are far from overflow.
      inline double
      magnitude(const Complex z)
      {
        return std::sqrt(z.real() * z.real() + z.imag() * z.imag());
      }

      /// The largest column sum of |A| (the 1-norm).
      double
      norm_1(const SparseComplex &A)
      {
        double largest = 0.;
        for (int c = 0; c < A.outerSize(); ++c)
          {
            double sum = 0.;
            for (SparseComplex::InnerIterator it(A, c); it; ++it)
              sum += magnitude(it.value());
            largest = std::max(largest, sum);
          }
        return largest;
      }

      /**
       * Check A X = B for unit-vector columns B, on one combination of the
       * columns, x = X w and b = B w with weights w_j = 1 + j / n (a single
       * sparse product instead of one per column: a wrong column shows in it
       * unless it cancels against the others, which these weights make all
       * but impossible):
       * - the normwise backward error |A x - b| / (|A|_1 |x| + |b|), which a
       *   stable LU keeps near round-off however ill-conditioned A is;
       * - the condition lower bound |A|_1 max_j |X_j|_1 (each X_j a column
       *   of A^{-1}): the forward error is about their product.
       * Throws past the limits.
       */
      void
      check_solution(const SparseComplex &A,
                     const Dense         &X,
                     const Dense         &B,
                     const double         omega,
                     const std::string   &what,
                     SolveDiagnostics    &diagnostics)
      {
        Eigen::VectorXcd w(X.cols());
        for (int j = 0; j < X.cols(); ++j)
          w(j) = 1. + double(j) / X.cols();
        const Eigen::VectorXcd b      = B * w;
        const Eigen::VectorXcd x      = X * w;
        const double           A_norm = norm_1(A);
        Eigen::VectorXcd       r      = A * x;
        r -= b;
        const double residual = r.norm() / (A_norm * x.norm() + b.norm());
        double       inverse  = 0.;
        for (int j = 0; j < X.cols(); ++j)
          {
            double sum = 0.;
            for (int i = 0; i < X.rows(); ++i)
              sum += magnitude(X(i, j));
            inverse = std::max(inverse, sum);
          }
        const double condition = A_norm * inverse;
        if (!std::isfinite(residual) || !std::isfinite(condition))
          throw NumericalError("the solve of " + what + " at " + at_frequency(omega) +
                               " gave NaN or inf");
        if (condition > condition_limit || residual > residual_limit)
          throw NumericalError("the dynamic stiffness " + what + " is nearly singular at " +
                               at_frequency(omega) +
                               ": condition number >= " + format_short(condition) +
                               ", backward error " + format_short(residual) +
                               ": an undamped resonance? Give the materials a loss factor or "
                               "move the frequency grid");
        diagnostics.max_residual  = std::max(diagnostics.max_residual, residual);
        diagnostics.max_condition = std::max(diagnostics.max_condition, condition);
      }

      /// Refuse a column of g beyond the patch's @p n_points points.
      void
      require_points(const std::vector<unsigned int> &columns, const std::size_t n_points)
      {
        for (const unsigned int j : columns)
          if (j >= n_points)
            throw NumericalError("solve_columns: point " + std::to_string(j) +
                                 " asked, the patch has " + std::to_string(n_points));
      }

      /// The distinct reference DoFs of the contact points' loads.
      std::vector<unsigned int>
      contact_dofs(const ContactPatch &patch)
      {
        std::vector<unsigned int> dofs;
        for (const auto &p : patch.points)
          for (const auto &e : p.load)
            dofs.push_back(e.dof);
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        return dofs;
      }



      /**
       * Bloch: the ring's response to a unit force at cell n is
       * (1/N) sum_k e^{i phi_k (m - n)} D_k^{-1} e_b, phi_k = 2 pi k / N.
       * With S_k = D_k^{-1} restricted to the loads' distinct DoFs, and
       * W_k(s, q) = sum of w e^{-i phi_k n} over the entries (n, s, w) of
       * point q, wavenumber k adds W_k^H S_k W_k (and its transpose for
       * N - k, since D_{N-k} = D_k^T).
       */
      class BlochSolver : public GreenSolver
      {
      public:
        BlochSolver(const PeriodicCell &cell_, const ContactPatch &patch_)
            : cell(cell_)
            , patch(patch_)
            , bloch(cell_)
            , dofs(contact_dofs(patch_))
        {
          for (const auto &p : patch.points)
            {
              std::vector<unsigned int> slots;
              for (const auto &e : p.load)
                slots.push_back(static_cast<unsigned int>(
                  std::lower_bound(dofs.begin(), dofs.end(), e.dof) - dofs.begin()));
              slot.push_back(slots);
            }
        }

        Dense
        solve(const double omega, SolveDiagnostics &diagnostics) override
        {
          bloch.set_frequency(omega);
          const unsigned int N = cell.n_cells, n_slots = dofs.size();
          Dense              B = Dense::Zero(bloch.size(), n_slots);
          for (unsigned int s = 0; s < n_slots; ++s)
            B(dofs[s], s) = 1.;
          const unsigned int P = patch.points.size();
          Dense              g = Dense::Zero(P, P);
          for (unsigned int k = 0; 2 * k <= N; ++k)
            {
              const double         phi = 2. * M_PI * k / N;
              const SparseComplex &D_k = factorise(phi, omega, k);
              const Dense          X   = lu.solve(B);
              check_solution(D_k, X, B, omega, "of Bloch wavenumber " + std::to_string(k),
                             diagnostics);
              Dense S(n_slots, n_slots);
              for (unsigned int s = 0; s < n_slots; ++s)
                S.row(s) = X.row(dofs[s]);
              const Dense W = weights(phi);
              const Dense C = W.adjoint() * S * W;
              g += C;
              if (k != 0 && 2 * k != N)
                g += C.transpose();
            }
          return g / static_cast<double>(N);
        }

        /// The loads @p columns only: per wavenumber k one solve with D_k
        /// for them, and one with D_k^T for wavenumber N - k (D_{N-k} =
        /// D_k^T, W_{N-k} = conj(W_k)), each with columns.size() right-hand
        /// sides B W_k e_j.
        Dense
        solve_columns(const double                     omega,
                      const std::vector<unsigned int> &columns,
                      SolveDiagnostics                &diagnostics) override
        {
          bloch.set_frequency(omega);
          const unsigned int N = cell.n_cells, n_slots = dofs.size();
          const unsigned int P = patch.points.size(), n_columns = columns.size();
          require_points(columns, P);
          Dense g = Dense::Zero(P, n_columns);
          for (unsigned int k = 0; 2 * k <= N; ++k)
            {
              const double         phi      = 2. * M_PI * k / N;
              const SparseComplex &D_k      = factorise(phi, omega, k);
              const Dense          W        = weights(phi);
              const auto           response = [&](const bool transposed) {
                Dense B = Dense::Zero(bloch.size(), n_columns);
                for (unsigned int s = 0; s < n_slots; ++s)
                  for (unsigned int c = 0; c < n_columns; ++c)
                    B(dofs[s], c) = transposed ? std::conj(W(s, columns[c])) : W(s, columns[c]);
                const std::string what =
                  "of Bloch wavenumber " + std::to_string(transposed ? N - k : k);
                const Dense X = transposed ? Dense(lu.transpose().solve(B)) : Dense(lu.solve(B));
                if (transposed)
                  check_solution(SparseComplex(D_k.transpose()), X, B, omega, what, diagnostics);
                else
                  check_solution(D_k, X, B, omega, what, diagnostics);
                Dense at_loads(n_slots, n_columns);
                for (unsigned int s = 0; s < n_slots; ++s)
                  at_loads.row(s) = X.row(dofs[s]);
                return at_loads;
              };
              g += W.adjoint() * response(false);
              if (k != 0 && 2 * k != N)
                g += W.transpose() * response(true);
            }
          return g / static_cast<double>(N);
        }

      private:
        /// D_k at @p phi, factorised into lu.
        const SparseComplex &
        factorise(const double phi, const double omega, const unsigned int k)
        {
          const SparseComplex &D_k = bloch.assemble(phi);
          if (!analysed)
            {
              lu.analyzePattern(D_k);
              analysed = true;
            }
          lu.factorize(D_k);
          require_factorised(lu, omega, "of Bloch wavenumber " + std::to_string(k));
          return D_k;
        }

        /// W_k (n_slots x P): W(s, q) = sum of w e^{-i phi n} over the
        /// entries (n, s, w) of point q's load.
        Dense
        weights(const double phi) const
        {
          Dense W = Dense::Zero(dofs.size(), patch.points.size());
          for (unsigned int q = 0; q < patch.points.size(); ++q)
            for (std::size_t e = 0; e < patch.points[q].load.size(); ++e)
              {
                const auto &entry = patch.points[q].load[e];
                W(slot[q][e], q) += entry.weight * std::polar(1., -phi * entry.cell);
              }
          return W;
        }

        const PeriodicCell                    &cell;
        const ContactPatch                    &patch;
        BlochCell                              bloch;
        const std::vector<unsigned int>        dofs;
        std::vector<std::vector<unsigned int>> slot; ///< per point, per load entry
        SparseLU                               lu;
        bool                                   analysed = false;
      };



      /// The reference: all N cells assembled, one sparse solve.
      /// Factorise the chain's matrix @p A (analysed already), solve for
      /// unit loads at the contact points, check, and read g off.
      Dense
      solve_chain(ChainLU             &lu,
                  const SparseComplex &A,
                  const RingChain     &chain,
                  const ContactPatch  &patch,
                  const double         omega,
                  const std::string   &what,
                  SolveDiagnostics    &diagnostics)
      {
        auto lock = base::lock_serial_blas();
        lu.factorize(A);
        if (lu.info() != Eigen::Success && lu.umfpackFactorizeReturncode() != UMFPACK_OK &&
            lu.umfpackFactorizeReturncode() != UMFPACK_WARNING_singular_matrix)
          throw NumericalError(
            "UMFPACK could not factorise the dynamic stiffness " + what + " at " +
            at_frequency(omega) + " (UMFPACK status " +
            std::to_string(lu.umfpackFactorizeReturncode()) +
            (lu.umfpackFactorizeReturncode() == UMFPACK_ERROR_out_of_memory ?
               ": out of memory; its 32-bit indices cap the factors near 2^31 entries" :
               std::string()) +
            "): the ring is too large for a direct solve; use Method = bloch");
        require_factorised(lu, omega, what);
        const Dense B = chain.loads(patch).cast<Complex>();
        const Dense X = lu.solve(B);
        lock.unlock();
        check_solution(A, X, B, omega, what, diagnostics);
        return chain.at_points(patch, X);
      }



      class FullRingSolver : public GreenSolver
      {
      public:
        FullRingSolver(const PeriodicCell &cell_, const ContactPatch &patch_)
            : cell(cell_)
            , patch(patch_)
            , ring{cell_.n_face, cell_.n_interior, cell_.n_cells, cell_.n_cells}
        {
        }

        Dense
        solve(const double omega, SolveDiagnostics &diagnostics) override
        {
          const SparseComplex A = ring.assemble(cell.dynamic_stiffness(omega));
          if (!analysed)
            {
              const auto lock = base::lock_serial_blas();
              lu.analyzePattern(A);
              analysed = true;
            }
          return solve_chain(lu, A, ring, patch, omega, "of the full ring", diagnostics);
        }

      private:
        const PeriodicCell &cell;
        const ContactPatch &patch;
        const RingChain     ring;
        ChainLU             lu;
        bool                analysed = false;
      };



      /// A stretch of cells condensed onto its two end faces (Eq. 46).
      struct SuperElement
      {
        Dense LL, LR, RL, RR;
      };

      /// Eq. (47): A followed by B, the face between them eliminated.
      SuperElement
      join(const SuperElement &A,
           const SuperElement &B,
           const double        omega,
           SolveDiagnostics   &diagnostics)
      {
        const Eigen::PartialPivLU<Dense> S(A.RR + B.LL);
        const double                     condition = 1. / S.rcond();
        if (!std::isfinite(condition) || condition > condition_limit)
          throw NumericalError("the doubling (Eq. 47) meets a nearly singular D_RR + D_LL at " +
                               at_frequency(omega) + ": condition number about " +
                               format_short(condition) +
                               ": an undamped resonance? Give the materials a loss factor or "
                               "move the frequency grid");
        diagnostics.max_condition = std::max(diagnostics.max_condition, condition);
        const Dense X1            = S.solve(A.RL);
        const Dense X2            = S.solve(B.LR);
        return {A.LL - A.LR * X1, -A.LR * X2, -B.RL * X1, B.RR - B.RL * X2};
      }



      /// The paper's method: doubling for the free part, then Eq. (49).
      class DoublingSolver : public GreenSolver
      {
      public:
        DoublingSolver(const PeriodicCell &cell_, const ContactPatch &patch_)
            : cell(cell_)
            , patch(patch_)
            , contact{cell_.n_face, cell_.n_interior, patch_.n_contact_cells,
                      patch_.n_contact_cells + 1}
        {
        }

        Dense
        solve(const double omega, SolveDiagnostics &diagnostics) override
        {
          const SparseComplex D  = cell.dynamic_stiffness(omega);
          const unsigned int  nf = cell.n_face, ni = cell.n_interior;

          // The cell condensed onto its faces: S = D_bb - D_bI D_II^-1 D_Ib.
          SuperElement one;
          {
            SparseComplex D_II = D.block(nf, nf, ni, ni);
            D_II.makeCompressed();
            SparseLU interior;
            interior.analyzePattern(D_II);
            interior.factorize(D_II);
            require_factorised(interior, omega, "of the cell's interior");
            Dense D_Ib(ni, 2 * nf);
            D_Ib << Dense(D.block(nf, 0, ni, nf)), Dense(D.block(nf, nf + ni, ni, nf));
            const Dense Y = interior.solve(D_Ib);
            // The backward error, as check_solution() measures it.
            const double residual =
              (D_II * Y - D_Ib).norm() / (norm_1(D_II) * Y.norm() + D_Ib.norm() + 1e-300);
            if (!(residual < residual_limit))
              throw NumericalError("the condensation of the cell's interior at " +
                                   at_frequency(omega) + " left a backward error of " +
                                   format_short(residual));
            diagnostics.max_residual = std::max(diagnostics.max_residual, residual);
            const auto rows = [&](const int first, const int columns_first, const int n_columns) {
              return Dense(D.block(first, columns_first, nf, n_columns));
            };
            const Dense DL_I = rows(0, nf, ni), DR_I = rows(nf + ni, nf, ni);
            one.LL = rows(0, 0, nf) - DL_I * Y.leftCols(nf);
            one.LR = rows(0, nf + ni, nf) - DL_I * Y.rightCols(nf);
            one.RL = rows(nf + ni, 0, nf) - DR_I * Y.leftCols(nf);
            one.RR = rows(nf + ni, nf + ni, nf) - DR_I * Y.rightCols(nf);
          }

          // The free part, N_l cells, along the binary digits of N_l (Eq. 48).
          const unsigned int n_free  = cell.n_cells - patch.n_contact_cells;
          SuperElement       power   = one, free_part;
          bool               started = false;
          for (unsigned int bits = n_free; bits != 0; bits >>= 1)
            {
              if (bits & 1u)
                {
                  free_part = started ? join(free_part, power, omega, diagnostics) : power;
                  started   = true;
                }
              if (bits >> 1)
                power = join(power, power, omega, diagnostics);
            }

          // Eq. (49): the contact cells, then the free part from the last
          // contact face back round to the first.
          std::vector<Eigen::Triplet<Complex>> entries;
          contact.add(D, entries);
          const unsigned int first = 0, last = patch.n_contact_cells * nf;
          for (unsigned int i = 0; i < nf; ++i)
            for (unsigned int j = 0; j < nf; ++j)
              {
                entries.emplace_back(last + i, last + j, free_part.LL(i, j));
                entries.emplace_back(last + i, first + j, free_part.LR(i, j));
                entries.emplace_back(first + i, last + j, free_part.RL(i, j));
                entries.emplace_back(first + i, first + j, free_part.RR(i, j));
              }
          SparseComplex A(contact.size(), contact.size());
          A.setFromTriplets(entries.begin(), entries.end());
          A.makeCompressed();
          ChainLU lu;
          {
            const auto lock = base::lock_serial_blas();
            lu.analyzePattern(A);
          }
          return solve_chain(lu, A, contact, patch, omega, "of the ring (Eq. 49)", diagnostics);
        }

      private:
        const PeriodicCell &cell;
        const ContactPatch &patch;
        const RingChain     contact;
      };
    } // namespace



    Eigen::MatrixXcd
    ring_response(const PeriodicCell           &cell,
                  const double                  omega,
                  const std::vector<LoadEntry> &load,
                  SolveDiagnostics             &diagnostics)
    {
      BlochCell bloch(cell);
      bloch.set_frequency(omega);
      const unsigned int N = cell.n_cells, n = bloch.size();
      Dense              u = Dense::Zero(n, N);
      SparseLU           lu;
      // All N wavenumbers, one factorisation each: this is one frequency,
      // and the transposed solves D_{N-k} = D_k^T would save only half.
      for (unsigned int k = 0; k < N; ++k)
        {
          const double         phi = 2. * M_PI * k / N;
          const SparseComplex &D_k = bloch.assemble(phi);
          if (k == 0)
            lu.analyzePattern(D_k);
          lu.factorize(D_k);
          require_factorised(lu, omega, "of Bloch wavenumber " + std::to_string(k));
          // A load at cell c carries e^{-i phi c}.
          Dense b = Dense::Zero(n, 1);
          for (const auto &e : load)
            b(e.dof, 0) += e.weight * std::polar(1., -phi * e.cell);
          const Dense x = lu.solve(b);
          check_solution(D_k, x, b, omega, "of Bloch wavenumber " + std::to_string(k), diagnostics);
          for (unsigned int m = 0; m < N; ++m)
            u.col(m) += std::polar(1., phi * static_cast<double>(m)) * x.col(0);
        }
      return u / static_cast<double>(N);
    }



    Eigen::MatrixXcd
    GreenSolver::solve_columns(const double                     omega,
                               const std::vector<unsigned int> &columns,
                               SolveDiagnostics                &diagnostics)
    {
      const Eigen::MatrixXcd g = solve(omega, diagnostics);
      require_points(columns, g.cols());
      Eigen::MatrixXcd picked(g.rows(), columns.size());
      for (std::size_t c = 0; c < columns.size(); ++c)
        picked.col(c) = g.col(columns[c]);
      return picked;
    }



    std::unique_ptr<GreenSolver>
    make_green_solver(const Method        method,
                      const PeriodicCell &cell,
                      const ContactPatch &patch,
                      const HarmonicRing *harmonic)
    {
      switch (method)
        {
          case Method::bloch:
            return std::make_unique<BlochSolver>(cell, patch);
          case Method::doubling:
            return std::make_unique<DoublingSolver>(cell, patch);
          case Method::full_ring:
            return std::make_unique<FullRingSolver>(cell, patch);
          case Method::harmonic:
            if (harmonic == nullptr)
              throw NumericalError("make_green_solver: the harmonic method without its ring");
            return std::make_unique<HarmonicGreenSolver>(*harmonic);
        }
      throw NumericalError("make_green_solver: unknown method");
    }
  } // namespace periodic
} // namespace greentread
