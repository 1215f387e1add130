#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/base/parameters.h>
#include <greentread/base/progress.h>
#include <greentread/periodic/harmonic_ring.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <cmath>
#include <deque>

namespace greentread
{
  namespace periodic
  {
    namespace
    {
      /// The largest number of harmonics tried before giving up.
      constexpr unsigned int max_harmonics = 20000;

      /// Whether the symmetric @p A is positive definite (LDL^T with every
      /// pivot positive).
      bool
      positive_definite(const Eigen::SparseMatrix<double> &A)
      {
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
        return ldlt.info() == Eigen::Success && (ldlt.vectorD().array() > 0.).all();
      }

      /**
       * The static terms (w_i / W_i)^T K_n^{-1} (w_j / W_j) of the harmonics
       * @p first to @p first + @p count - 1, spread over the threads, each
       * thread with its own factorisation: the same figures as one after the
       * other, in a fraction of the time. A harmonic whose static stiffness
       * is not positive definite gets an empty matrix.
       */
      std::vector<Eigen::MatrixXd>
      static_terms_of(const fe::HarmonicSection &section,
                      const Eigen::MatrixXd     &loads,
                      const unsigned int         first,
                      const unsigned int         count)
      {
        const unsigned int           n_threads = std::max(1u, dealii::MultithreadInfo::n_threads());
        std::vector<Eigen::MatrixXd> terms(count);
        std::vector<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> ldlt(n_threads);
        std::vector<char>                                               analysed(n_threads, 0);
        base::for_each_index(count, n_threads, [&](const std::size_t i, const unsigned int t) {
          const Eigen::SparseMatrix<double> K = section.stiffness(first + i);
          if (!analysed[t])
            ldlt[t].analyzePattern(K);
          analysed[t] = 1;
          ldlt[t].factorize(K);
          if (ldlt[t].info() == Eigen::Success && (ldlt[t].vectorD().array() > 0.).all())
            terms[i] = loads.transpose() * ldlt[t].solve(loads);
        });
        return terms;
      }
    } // namespace



    HarmonicRing::HarmonicRing(const fe::HarmonicSection &section,
                               const ContactPatch        &patch,
                               const double               tolerance,
                               const double               max_omega)
        : section(section)
        , arc(patch.arc)
    {
      if (patch.load != PointLoad::tributary_area)
        throw InputError("parameter 'Green's functions/Point load' = node is not allowed with "
                         "'Method' = harmonic: a point force's harmonic series does not "
                         "converge (its displacement is singular); allowed: tributary area");
      const unsigned int ny = patch.points_across;
      loads.resize(section.size(), ny);
      for (unsigned int j = 0; j < ny; ++j)
        {
          const double y    = patch.points[j].y;
          const auto [w, W] = section.tread_strip(y - 0.5 * patch.dy, y + 0.5 * patch.dy);
          loads.col(j)      = w / W;
        }
      for (std::size_t p = 0; p < patch.points.size(); ++p)
        {
          strip.push_back(p % ny);
          angle.push_back(patch.points[p].angle);
        }

      // Static sums until the tail's bound meets the tolerance, then more
      // harmonics until the highest line is well below the next ones.
      // The terms are computed ahead in batches over the threads and taken
      // one at a time, so that the choice of N is the sequential one; a
      // batch's terms past N are dropped.
      Eigen::VectorXd             driving = Eigen::VectorXd::Zero(ny);
      std::vector<double>         h;
      std::deque<Eigen::MatrixXd> ahead; // harmonics n, n + 1, ...
      unsigned int                n     = 0;
      const unsigned int          batch = 8 * std::max(1u, dealii::MultithreadInfo::n_threads());
      const auto                  add_harmonic = [&]() {
        if (ahead.empty())
          for (auto &H : static_terms_of(section, loads, n, std::min(batch, max_harmonics - n)))
            ahead.push_back(std::move(H));
        const Eigen::MatrixXd H = std::move(ahead.front());
        ahead.pop_front();
        if (H.size() == 0)
          throw NumericalError("the harmonic ring: the static stiffness of harmonic " +
                                                std::to_string(n) +
                                                " is not positive definite (an unheld "
                                                                 "section, or a prestress that buckles it)");
        driving += weight(n) * H.diagonal();
        h.push_back(H.diagonal().maxCoeff());
        static_terms.push_back(H);
        ++n;
      };
      const auto tail = [&]() {
        const unsigned int last = n - 1, half = std::max(1u, last / 2);
        decay = half < last ? std::log(h[half] / h[last]) / std::log(double(last) / half) : 0.;
        decay = std::clamp(decay, 0., 1.);
        return 4. * h[last] / (M_PI * arc * arc * last * (1. + decay)) / driving.minCoeff();
      };
      while (n < 8)
        add_harmonic();
      while ((tail_bound = tail()) > tolerance)
        {
          if (n >= max_harmonics)
            throw NumericalError("the harmonic ring: " + std::to_string(max_harmonics) +
                                 " harmonics leave a tail of " + format_printf("%.2g", tail_bound) +
                                 " of the driving point, above 'Green's functions/Harmonic "
                                 "tolerance' = " +
                                 format_short(tolerance));
          add_harmonic();
        }
      const double shift = 2. * max_omega * max_omega;
      while (!positive_definite(section.shifted_stiffness(n, shift)))
        {
          const unsigned int target = std::min(max_harmonics, n + std::max(8u, n / 4));
          if (n >= max_harmonics)
            throw NumericalError("the harmonic ring: harmonic " + std::to_string(n) +
                                 " still has a mode below sqrt(2) times the highest line");
          while (n < target)
            add_harmonic();
        }
      tail_bound           = tail();
      n_harmonics          = n;
      this->tolerance      = tolerance;
      const Eigen::Index P = angle.size();
      static_green         = Eigen::MatrixXd::Zero(P, P);
      for (unsigned int k = 0; k < n; ++k)
        for (Eigen::Index p = 0; p < P; ++p)
          for (Eigen::Index q = 0; q < P; ++q)
            static_green(p, q) +=
              weight(k) * std::cos(k * (angle[p] - angle[q])) * static_terms[k](strip[p], strip[q]);
    }



    double
    HarmonicRing::weight(const unsigned int n) const
    {
      if (n == 0)
        return 1. / (2. * M_PI);
      const double x = 0.5 * n * arc;
      const double s = std::sin(x) / x;
      return s * s / M_PI;
    }



    std::string
    HarmonicRing::describe() const
    {
      return "  harmonic ring: the section's " + std::to_string(section.size()) +
             " unknowns per harmonic (degree " + std::to_string(section.degree()) + "), " +
             std::to_string(n_harmonics) + " harmonics (0 to " + std::to_string(n_harmonics - 1) +
             "), static tail at most " + format_printf("%.2g", tail_bound) +
             " of the smallest driving point (decay n^-" + format_printf("%.2f", decay) +
             "), inflated tread growth " + format_printf("%.4g", 1e3 * section.tread_growth()) +
             " mm\n";
    }



    void
    check_mode_cutoff(const HarmonicRing &ring, const double cutoff)
    {
      for (unsigned int n = ring.n_harmonics; n < ring.n_harmonics + 8; ++n)
        if (!positive_definite(ring.section.shifted_stiffness(n, cutoff * cutoff)))
          throw InputError(
            "parameter 'Patch model/Mode cutoff' = " + format_number(cutoff / (2. * M_PI)) +
            " Hz is not allowed: harmonic " + std::to_string(n) +
            " has a mode below it, and the Green's functions "
            "sum harmonics 0 to " +
            std::to_string(ring.n_harmonics - 1) +
            " only; allowed: a lower cut-off, or a smaller 'Green's "
            "functions/Harmonic tolerance' (more harmonics)");
    }



    HarmonicGreenSolver::HarmonicGreenSolver(const HarmonicRing &ring)
        : ring(ring)
    {
    }



    Eigen::MatrixXcd
    HarmonicGreenSolver::solve(const double omega, SolveDiagnostics &diagnostics)
    {
      using SparseC        = Eigen::SparseMatrix<Complex>;
      const Eigen::Index P = ring.angle.size();
      Eigen::MatrixXcd   g = ring.static_green.cast<Complex>();
      n_dynamic            = 0;
      if (omega == 0.)
        return g;
      const Eigen::MatrixXcd   loads    = ring.loads.cast<Complex>();
      const auto               parts    = ring.section.dynamic_stiffness(omega);
      const double             smallest = ring.static_green.diagonal().minCoeff();
      const double             a        = ring.arc;
      Eigen::SparseLU<SparseC> lu;
      std::vector<double>      d;
      // The three parts share the section's pattern (fe/harmonic_section.h):
      // D_n is then one pass over their values, not two sparse sums.
      const bool shared =
        fe::same_pattern(parts[0], parts[1]) && fe::same_pattern(parts[0], parts[2]);
      SparseC D = parts[0];
      for (unsigned int n = 0; n < ring.n_harmonics; ++n)
        {
          const double n1 = n, n2 = n1 * n1;
          if (shared)
            {
              const Complex *a = parts[0].valuePtr(), *b = parts[1].valuePtr(),
                            *c = parts[2].valuePtr();
              Complex *v       = D.valuePtr();
              for (Eigen::Index i = 0; i < D.nonZeros(); ++i)
                v[i] = a[i] + n1 * b[i] + n2 * c[i];
            }
          else
            D = parts[0] + n1 * parts[1] + n2 * parts[2];
          if (n == 0)
            lu.analyzePattern(D);
          lu.factorize(D);
          if (lu.info() != Eigen::Success)
            throw NumericalError("the harmonic ring: D(w) of harmonic " + std::to_string(n) +
                                 " is singular at " + format_short(omega / (2. * M_PI)) +
                                 " Hz (an undamped resonance)");
          const Eigen::MatrixXcd X = lu.solve(loads);
          // Normwise backward error of each solve, with the 1-norm of D.
          double norm_D = 0.;
          for (Eigen::Index c = 0; c < D.outerSize(); ++c)
            {
              double column = 0.;
              for (SparseC::InnerIterator it(D, c); it; ++it)
                column += std::abs(it.value());
              norm_D = std::max(norm_D, column);
            }
          for (Eigen::Index j = 0; j < X.cols(); ++j)
            {
              const double r = (D * X.col(j) - loads.col(j)).norm() /
                               (norm_D * X.col(j).norm() + loads.col(j).norm());
              if (!std::isfinite(r) || r > residual_limit)
                throw NumericalError("the harmonic ring: the solve of harmonic " +
                                     std::to_string(n) + " at " +
                                     format_short(omega / (2. * M_PI)) +
                                     " Hz has a backward error of " + format_printf("%.2g", r));
              diagnostics.max_residual = std::max(diagnostics.max_residual, r);
            }
          const Eigen::MatrixXcd dH = loads.transpose() * X - ring.static_terms[n].cast<Complex>();
          const double           w  = ring.weight(n);
          for (Eigen::Index p = 0; p < P; ++p)
            for (Eigen::Index q = 0; q < P; ++q)
              g(p, q) += w * std::cos(n * (ring.angle[p] - ring.angle[q])) *
                         dH(ring.strip[p], ring.strip[q]);
          n_dynamic = n + 1;

          // The dynamic differences' tail from here on.
          d.push_back(dH.cwiseAbs().maxCoeff());
          if (n < 8)
            continue;
          const unsigned int half  = n / 2;
          const double       decay = std::clamp(
                  d[half] > 0. && d[n] > 0. ? std::log(d[half] / d[n]) / std::log(double(n) / half) : 0.,
            0., 3.);
          const double tail = 4. * d[n] / (M_PI * a * a * n * (1. + decay)) / smallest;
          if (tail <= ring.tolerance &&
              positive_definite(ring.section.shifted_stiffness(n + 1, 2. * omega * omega)))
            break;
        }
      return g;
    }
  } // namespace periodic
} // namespace greentread
