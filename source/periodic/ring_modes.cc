#include <greentread/base/exceptions.h>
#include <greentread/base/progress.h>
#include <greentread/periodic/ring_modes.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <cmath>
#include <mutex>
#include <numeric>
#include <thread>

namespace greentread
{
  namespace periodic
  {
    Eigen::MatrixXd
    point_shapes(const BlochModes &modes, const PeriodicCell &cell, const ContactPatch &patch)
    {
      const unsigned int N = cell.n_cells, k = modes.wavenumber, P = patch.points.size();
      const double       phi  = 2. * M_PI * k / N;
      const bool         real = k == 0 || 2 * k == N;
      const Eigen::Index m    = modes.omega.size();
      Eigen::MatrixXcd   a    = Eigen::MatrixXcd::Zero(m, P);
      for (unsigned int q = 0; q < P; ++q)
        for (const auto &e : patch.points[q].load)
          a.col(q) += e.weight * std::polar(1., phi * e.cell) * modes.shapes.row(e.dof).transpose();
      if (real)
        return a.real() / std::sqrt(double(N));
      Eigen::MatrixXd shapes(2 * m, P);
      const double    scale = std::sqrt(2. / N);
      for (Eigen::Index r = 0; r < m; ++r)
        {
          shapes.row(2 * r)     = scale * a.row(r).real();
          shapes.row(2 * r + 1) = scale * a.row(r).imag();
        }
      return shapes;
    }



    namespace
    {
      /// One wavenumber's result, packed as doubles for the gather:
      /// k, m, the m frequencies, the m damping ratios, residual, solves,
      /// the number of real modes r, then r x P shapes.
      void
      pack(const BlochModes &modes, const Eigen::MatrixXd &shapes, std::vector<double> &out)
      {
        out.push_back(modes.wavenumber);
        out.push_back(modes.omega.size());
        out.insert(out.end(), modes.omega.data(), modes.omega.data() + modes.omega.size());
        out.insert(out.end(), modes.damping_ratio.data(),
                   modes.damping_ratio.data() + modes.damping_ratio.size());
        out.push_back(modes.max_residual);
        out.push_back(modes.n_solves);
        out.push_back(shapes.rows());
        for (Eigen::Index r = 0; r < shapes.rows(); ++r)
          for (Eigen::Index p = 0; p < shapes.cols(); ++p)
            out.push_back(shapes(r, p));
      }
    } // namespace



    RingModes
    ring_modes(const PeriodicCell &cell,
               const ContactPatch &patch,
               const ModeSearch   &search,
               const MPI_Comm      comm,
               const bool          show_progress)
    {
      const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
      const unsigned int N = cell.n_cells, P = patch.points.size(), n_k = N / 2 + 1;

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
                const BlochModes modes = bloch_modes(cell, mine[i], search);
                pack(modes, point_shapes(modes, cell, patch), packed[i]);
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
            std::to_string(mine.size()) + " of " + std::to_string(n_k) + " wavenumbers)",
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
      std::vector<Eigen::VectorXd> rows;
      result.branches.resize(n_k);
      result.branch_damping.resize(n_k);
      for (const auto &from : gathered)
        for (std::size_t at = 0; at < from.size();)
          {
            const auto k = static_cast<unsigned int>(from[at++]);
            const auto m = static_cast<Eigen::Index>(from[at++]);
            result.branches[k] = Eigen::Map<const Eigen::VectorXd>(from.data() + at, m);
            at += m;
            result.branch_damping[k] = Eigen::Map<const Eigen::VectorXd>(from.data() + at, m);
            at += m;
            result.max_residual = std::max(result.max_residual, from[at++]);
            result.n_solves += static_cast<unsigned int>(from[at++]);
            const auto r = static_cast<Eigen::Index>(from[at++]);
            for (Eigen::Index j = 0; j < r; ++j)
              {
                // Real modes come one per Bloch mode, or a cos/sin pair.
                const Eigen::Index bloch = r == m ? j : j / 2;
                omega.push_back(result.branches[k](bloch));
                damping.push_back(result.branch_damping[k](bloch));
                wavenumber.push_back(k);
                rows.emplace_back(Eigen::Map<const Eigen::VectorXd>(from.data() + at, P));
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
      for (Eigen::Index i = 0; i < n_modes; ++i)
        {
          result.omega(i)         = omega[order[i]];
          result.damping_ratio(i) = damping[order[i]];
          result.wavenumber.push_back(wavenumber[order[i]]);
          result.shapes.row(i) = rows[order[i]].transpose();
        }
      return result;
    }
  } // namespace periodic
} // namespace greentread
