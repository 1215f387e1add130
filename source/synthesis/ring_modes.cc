#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/base/progress.h>
#include <greentread/base/serial_blas.h>
#include <greentread/synthesis/ring_modes.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <thread>
#include <type_traits>

namespace greentread
{
  namespace synthesis
  {
    namespace
    {
      /// The eigenvalues and right eigenvectors of the dense @p L by LAPACK's
      /// zgeev (blocked: about three times faster than Eigen's
      /// ComplexEigenSolver at the few hundred modes of a wavenumber).
      /// One call at a time (base/serial_blas.h): the wavenumbers are
      /// searched on several threads. False if it fails.
      bool
      eigen_decomposition(Eigen::MatrixXcd L, Eigen::VectorXcd &lambda, Eigen::MatrixXcd &vectors)
      {
        const auto                    lock  = base::lock_serial_blas();
        const dealii::types::blas_int n     = L.rows();
        dealii::types::blas_int       lwork = -1, info = 0, one = 1;
        lambda.resize(n);
        vectors.resize(n, n);
        std::complex<double> query, unused;
        std::vector<double>  rwork(2 * n);
        dealii::geev("N", "V", &n, L.data(), &n, lambda.data(), &unused, &one, vectors.data(), &n,
                     &query, &lwork, rwork.data(), &info);
        lwork = static_cast<dealii::types::blas_int>(query.real());
        std::vector<std::complex<double>> work(std::max<dealii::types::blas_int>(lwork, 1));
        dealii::geev("N", "V", &n, L.data(), &n, lambda.data(), &unused, &one, vectors.data(), &n,
                     work.data(), &lwork, rwork.data(), &info);
        return info == 0 && lambda.allFinite() && vectors.allFinite();
      }

      /// The same for a real @p L by dgeev: a quarter of zgeev's arithmetic.
      /// Its complex eigenvalues come in conjugate pairs, with the real and
      /// imaginary parts of the first one's vector in two columns; both are
      /// returned as complex columns, as zgeev gives them.
      bool
      eigen_decomposition(Eigen::MatrixXd L, Eigen::VectorXcd &lambda, Eigen::MatrixXcd &vectors)
      {
        const auto                    lock  = base::lock_serial_blas();
        const dealii::types::blas_int n     = L.rows();
        dealii::types::blas_int       lwork = -1, info = 0, one = 1;
        Eigen::VectorXd               wr(n), wi(n);
        Eigen::MatrixXd               vr(n, n);
        double                        query = 0., unused = 0.;
        dealii::geev("N", "V", &n, L.data(), &n, wr.data(), wi.data(), &unused, &one, vr.data(), &n,
                     &query, &lwork, &info);
        lwork = static_cast<dealii::types::blas_int>(query);
        std::vector<double> work(std::max<dealii::types::blas_int>(lwork, 1));
        dealii::geev("N", "V", &n, L.data(), &n, wr.data(), wi.data(), &unused, &one, vr.data(), &n,
                     work.data(), &lwork, &info);
        if (info != 0)
          return false;
        lambda.resize(n);
        vectors.resize(n, n);
        for (Eigen::Index j = 0; j < n; ++j)
          {
            lambda(j) = {wr(j), wi(j)};
            if (wi(j) == 0.)
              vectors.col(j) = vr.col(j).cast<std::complex<double>>();
            else if (wi(j) > 0. && j + 1 < n)
              {
                vectors.col(j).real() = vr.col(j);
                vectors.col(j).imag() = vr.col(j + 1);
                vectors.col(j + 1)    = vectors.col(j).conjugate();
                lambda(j + 1)         = std::conj(lambda(j));
                ++j;
              }
            else
              return false;
          }
        return lambda.allFinite() && vectors.allFinite();
      }

      /// a(r, q): Bloch mode r seen by the unit load of point q,
      /// sum over q's entries (n, s, w) of w e^{i phi n} psi_r(s).
      Eigen::MatrixXcd
      bloch_point_values(const WavenumberModes        &modes,
                         const periodic::PeriodicCell &cell,
                         const periodic::ContactPatch &patch)
      {
        const double     phi = 2. * M_PI * modes.wavenumber / cell.n_cells;
        Eigen::MatrixXcd a   = Eigen::MatrixXcd::Zero(modes.omega.size(), patch.points.size());
        for (std::size_t q = 0; q < patch.points.size(); ++q)
          for (const auto &e : patch.points[q].load)
            a.col(q) +=
              e.weight * std::polar(1., phi * e.cell) * modes.shapes.row(e.dof).transpose();
        return a;
      }
    } // namespace



    Eigen::MatrixXd
    point_shapes(const WavenumberModes        &modes,
                 const periodic::PeriodicCell &cell,
                 const periodic::ContactPatch &patch)
    {
      const unsigned int k = modes.wavenumber, N = cell.n_cells;
      return point_shapes(bloch_point_values(modes, cell, patch), N, k == 0 || 2 * k == N);
    }



    Eigen::MatrixXd
    point_shapes(const Eigen::MatrixXcd &a, const double N, const bool real)
    {
      const Eigen::Index m = a.rows(), P = a.cols();
      if (real)
        return a.real() / std::sqrt(N);
      Eigen::MatrixXd shapes(2 * m, P);
      const double    scale = std::sqrt(2. / N);
      for (Eigen::Index r = 0; r < m; ++r)
        {
          shapes.row(2 * r)     = scale * a.row(r).real();
          shapes.row(2 * r + 1) = scale * a.row(r).imag();
        }
      return shapes;
    }



    PointModes
    coupled_point_modes(const WavenumberModes        &modes,
                        const periodic::PeriodicCell &cell,
                        const periodic::ContactPatch &patch,
                        const bool                    couple)
    {
      const unsigned int k = modes.wavenumber, N = cell.n_cells;
      return coupled_point_modes(modes, bloch_point_values(modes, cell, patch), N,
                                 k == 0 || 2 * k == N, couple);
    }



    PointModes
    coupled_point_modes(const WavenumberModes  &modes,
                        const Eigen::MatrixXcd &a,
                        const double            N,
                        const bool              real,
                        const bool              couple)
    {
      const Eigen::Index m = modes.omega.size(), P = a.cols(), per = real ? 1 : 2;
      const auto         diagonal = [&]() {
        PointModes out;
        out.shapes = point_shapes(a, N, real);
        out.shapes_imag.setZero(out.shapes.rows(), P);
        out.omega.resize(per * m);
        out.damping_ratio.resize(per * m);
        for (Eigen::Index r = 0; r < per * m; ++r)
          {
            out.omega(r)         = modes.omega(r / per);
            out.damping_ratio(r) = modes.damping_ratio(r / per);
          }
        return out;
      };
      // With a proportional damping B is diagonal up to the modes' own
      // accuracy (relative residuals of 1e-9), and the coupled form would
      // equal the diagonal one.
      const Eigen::MatrixXcd &B = modes.modal_damping;
      const double            off =
        m > 0 ? (B - Eigen::MatrixXcd(B.diagonal().asDiagonal())).cwiseAbs().maxCoeff() : 0.;
      if (!couple || m == 0 || !(off > 1e-8 * B.diagonal().cwiseAbs().maxCoeff()))
        return diagonal();

      // (s^2 I + s B + W^2) x = 0 in the modal coordinates, B = Psi^H C Psi,
      // linearised with z = [W x; s x]: s z = [[0, W], [-W, -B]] z.
      // A real B (the harmonic route's) takes the real solver.
      const auto linearised = [&](const auto &damping) {
        using Matrix                        = std::decay_t<decltype(damping)>;
        Matrix     L                        = Matrix::Zero(2 * m, 2 * m);
        const auto omega                    = modes.omega.template cast<typename Matrix::Scalar>();
        L.topRightCorner(m, m).diagonal()   = omega;
        L.bottomLeftCorner(m, m).diagonal() = -omega;
        L.bottomRightCorner(m, m)           = -damping;
        return L;
      };
      Eigen::VectorXcd lambda;
      Eigen::MatrixXcd z;
      const bool       decomposed =
        B.imag().isZero(0.) ?
                eigen_decomposition(linearised(Eigen::MatrixXd(B.real())), lambda, z) :
                eigen_decomposition(linearised(B), lambda, z);
      if (!decomposed)
        return diagonal();
      const Eigen::MatrixXcd x = modes.omega.cwiseInverse().asDiagonal() * z.topRows(m);

      // Each pole above the real axis with its mirror below: the problem is
      // Hermitian, so the poles come in conjugate pairs, and the mirror's
      // vector y is the pole's left vector. A pole near the real axis
      // (over-critical) or a pair not found: the diagonal form.
      std::vector<Eigen::Index> up, down;
      for (Eigen::Index r = 0; r < 2 * m; ++r)
        {
          const double xi = -lambda(r).real() / std::abs(lambda(r));
          if (!(xi >= 0. && xi < 0.99))
            return diagonal();
          (lambda(r).imag() > 0. ? up : down).push_back(r);
        }
      if (up.size() != std::size_t(m))
        return diagonal();
      std::vector<bool> taken(2 * m, false);
      PointModes        out;
      out.omega.resize(per * m);
      out.damping_ratio.resize(per * m);
      out.shapes.resize(per * m, P);
      out.shapes_imag.resize(per * m, P);
      for (Eigen::Index i = 0; i < m; ++i)
        {
          const Eigen::Index u    = up[i];
          Eigen::Index       d    = -1;
          double             best = std::numeric_limits<double>::infinity();
          for (const Eigen::Index r : down)
            if (!taken[r] && std::abs(lambda(r) - std::conj(lambda(u))) < best)
              {
                best = std::abs(lambda(r) - std::conj(lambda(u)));
                d    = r;
              }
          if (d < 0 || best > 1e-6 * std::abs(lambda(u)))
            return diagonal();
          taken[d]                   = true;
          const periodic::Complex l  = lambda(u);
          const double            wd = l.imag();
          // The residue of (s^2 I + s B + W^2)^-1 at l is x y^H / mu.
          const Eigen::VectorXcd  q2   = 2. * l * x.col(u) + modes.modal_damping * x.col(u);
          const periodic::Complex mu   = x.col(d).dot(q2);
          const Eigen::VectorXcd  psi1 = a.transpose() * x.col(u);
          const Eigen::VectorXcd  psi2 = (a.transpose() * x.col(d)).conjugate();
          out.omega.segment(per * i, per).setConstant(std::abs(l));
          out.damping_ratio.segment(per * i, per).setConstant(-l.real() / std::abs(l));
          // Shapes psi such that psi psi^T / (2 j w_d) is the residue at l (and
          // their conjugates at conj(l)), w_d = Im l.
          if (real)
            {
              // (1/N) psi1 psi2^T / mu, with psi2 = alpha psi1.
              const double            size = psi1.squaredNorm();
              const periodic::Complex alpha =
                size > 0. ? psi1.dot(psi2) / size : periodic::Complex(0.);
              const Eigen::VectorXcd shape =
                std::sqrt(periodic::Complex(0., 2. * wd) * alpha / (N * mu)) * psi1;
              out.shapes.row(i)      = shape.real().transpose();
              out.shapes_imag.row(i) = shape.imag().transpose();
              continue;
            }
          // k and N - k together: (1/N)(psi1 psi2^T + psi2 psi1^T) / mu
          // = (p p^T + q q^T) / (2 N mu), p = psi1 + psi2, q = (psi1 - psi2) / j.
          const periodic::Complex scale  = std::sqrt(periodic::Complex(0., wd) / (N * mu));
          const Eigen::VectorXcd  p      = scale * (psi1 + psi2);
          const Eigen::VectorXcd  q      = scale * (psi1 - psi2) / periodic::Complex(0., 1.);
          out.shapes.row(2 * i)          = p.real().transpose();
          out.shapes_imag.row(2 * i)     = p.imag().transpose();
          out.shapes.row(2 * i + 1)      = q.real().transpose();
          out.shapes_imag.row(2 * i + 1) = q.imag().transpose();
        }
      out.coupled = true;
      return out;
    }



    namespace
    {
      /// One wavenumber's result, packed as doubles for the gather:
      /// k, m, the m frequencies, the m damping ratios, residual, solves,
      /// coupled (0 or 1), the number of ring modes r, then per ring mode
      /// w, xi, its P shape values and their P imaginary parts.
      void
      pack(const WavenumberModes &modes, const PointModes &ring, std::vector<double> &out)
      {
        out.push_back(modes.wavenumber);
        out.push_back(modes.omega.size());
        out.insert(out.end(), modes.omega.data(), modes.omega.data() + modes.omega.size());
        out.insert(out.end(), modes.damping_ratio.data(),
                   modes.damping_ratio.data() + modes.damping_ratio.size());
        out.push_back(modes.max_residual);
        out.push_back(modes.n_solves);
        out.push_back(ring.coupled ? 1. : 0.);
        out.push_back(ring.shapes.rows());
        for (Eigen::Index r = 0; r < ring.shapes.rows(); ++r)
          {
            out.push_back(ring.omega(r));
            out.push_back(ring.damping_ratio(r));
            for (Eigen::Index p = 0; p < ring.shapes.cols(); ++p)
              out.push_back(ring.shapes(r, p));
            for (Eigen::Index p = 0; p < ring.shapes.cols(); ++p)
              out.push_back(ring.shapes_imag(r, p));
          }
      }
    } // namespace



    RingModes
    ring_modes(const periodic::PeriodicCell &cell,
               const periodic::ContactPatch &patch,
               const ModeSearch             &search,
               const MPI_Comm                comm,
               const bool                    show_progress,
               const bool                    couple_damping)
    {
      return gather_ring_modes(
        cell.n_cells / 2 + 1, patch.points.size(),
        [&](const unsigned int k) {
          WavenumberModes modes  = bloch_modes(cell, k, search);
          PointModes      points = coupled_point_modes(modes, cell, patch, couple_damping);
          // Moved, not copied: the shapes over [L, I] are megabytes per wavenumber.
          return std::make_pair(std::move(modes), std::move(points));
        },
        "wavenumbers", comm, show_progress, couple_damping);
    }



    RingModes
    gather_ring_modes(const unsigned int       n_k,
                      const unsigned int       P,
                      const ModesOfWavenumber &modes_of,
                      const std::string       &what,
                      const MPI_Comm           comm,
                      const bool               show_progress,
                      const bool               couple_damping)
    {
      const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);

      std::vector<unsigned int> mine;
      for (unsigned int k = rank; k < n_k; k += n_ranks)
        mine.push_back(k);
      std::vector<std::vector<double>> packed(mine.size());
      std::atomic<unsigned int>        next{0}, done{0};
      std::mutex                       mutex;
      std::string                      failure;
      const auto                       work = [&]() {
        for (unsigned int i = next++; i < mine.size(); i = next++)
          {
            try
              {
                const auto [modes, points] = modes_of(mine[i]);
                pack(modes, points, packed[i]);
                ++done;
              }
            catch (const std::exception &e)
              {
                std::lock_guard<std::mutex> lock(mutex);
                if (failure.empty())
                  failure = e.what();
                return;
              }
          }
      };
      const unsigned int n_threads =
        std::max(1u, std::min<unsigned int>(dealii::MultithreadInfo::n_threads(), mine.size()));
      std::unique_ptr<base::Progress> progress;
      if (show_progress && rank == 0)
        progress = std::make_unique<base::Progress>(
          "ring modes (" + (n_ranks == 1 ? std::string() : "rank 0's ") +
            std::to_string(mine.size()) + " of " + std::to_string(n_k) + " " + what + ")",
          mine.size());
      base::run_on_threads(n_threads, work, done, mine.size(), progress.get(), [&]() {
        std::lock_guard<std::mutex> lock(mutex);
        return !failure.empty();
      });
      throw_if_any_rank_failed(comm, failure.empty() ? RankFailure::none : RankFailure::numerical,
                               "ring modes: " + failure);

      std::vector<double> local;
      for (const auto &p : packed)
        local.insert(local.end(), p.begin(), p.end());
      const auto gathered = dealii::Utilities::MPI::all_gather(comm, local);

      // Unpack per wavenumber, then order all real modes by frequency.
      RingModes                    result;
      std::vector<double>          omega, damping;
      std::vector<unsigned int>    wavenumber;
      std::vector<Eigen::VectorXd> rows, rows_imag;
      result.branches.resize(n_k);
      result.branch_damping.resize(n_k);
      for (const auto &from : gathered)
        for (std::size_t at = 0; at < from.size();)
          {
            const auto k       = static_cast<unsigned int>(from[at++]);
            const auto m       = static_cast<Eigen::Index>(from[at++]);
            result.branches[k] = Eigen::Map<const Eigen::VectorXd>(from.data() + at, m);
            at += m;
            result.branch_damping[k] = Eigen::Map<const Eigen::VectorXd>(from.data() + at, m);
            at += m;
            result.max_residual = std::max(result.max_residual, from[at++]);
            result.n_solves += static_cast<unsigned int>(from[at++]);
            if (couple_damping && from[at] == 0. && m > 0)
              ++result.uncoupled;
            ++at;
            const auto r = static_cast<Eigen::Index>(from[at++]);
            for (Eigen::Index j = 0; j < r; ++j)
              {
                omega.push_back(from[at++]);
                damping.push_back(from[at++]);
                wavenumber.push_back(k);
                rows.emplace_back(Eigen::Map<const Eigen::VectorXd>(from.data() + at, P));
                at += P;
                rows_imag.emplace_back(Eigen::Map<const Eigen::VectorXd>(from.data() + at, P));
                at += P;
              }
          }
      std::vector<std::size_t> order(omega.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](const std::size_t a, const std::size_t b) {
        return omega[a] < omega[b] || (omega[a] == omega[b] && wavenumber[a] < wavenumber[b]);
      });
      const Eigen::Index n_modes = order.size();
      result.omega.resize(n_modes);
      result.damping_ratio.resize(n_modes);
      result.shapes.resize(n_modes, P);
      result.shapes_imag.resize(n_modes, P);
      for (Eigen::Index i = 0; i < n_modes; ++i)
        {
          result.omega(i)         = omega[order[i]];
          result.damping_ratio(i) = damping[order[i]];
          result.wavenumber.push_back(wavenumber[order[i]]);
          result.shapes.row(i)      = rows[order[i]].transpose();
          result.shapes_imag.row(i) = rows_imag[order[i]].transpose();
        }
      if (!couple_damping)
        result.shapes_imag.resize(0, 0);
      return result;
    }
  } // namespace synthesis
} // namespace greentread
