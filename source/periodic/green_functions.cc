#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/base/progress.h>
#include <greentread/periodic/green_functions.h>

#include <deal.II/base/multithread_info.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

namespace greentread
{
  namespace periodic
  {
    base::FrequencyResponseMatrix
    compute_green_functions(const PeriodicCell &cell,
                            const ContactPatch &patch,
                            const Method        method,
                            const double        df,
                            const unsigned int  n_lines,
                            const MPI_Comm      comm,
                            const bool          show_progress,
                            GreenRunReport     &report,
                            const HarmonicRing *harmonic)
    {
      const auto         start   = std::chrono::steady_clock::now();
      const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
      const unsigned int P       = patch.points.size();

      // This rank's lines: k = rank, rank + n_ranks, ...
      std::vector<unsigned int> lines;
      for (unsigned int k = rank; k < n_lines; k += n_ranks)
        lines.push_back(k);
      const unsigned int n_threads =
        std::max(1u, std::min<unsigned int>(dealii::MultithreadInfo::n_threads(), lines.size()));

      std::vector<double>       values(2 * std::size_t(n_lines) * P * P, 0.);
      std::atomic<unsigned int> next{0}, done{0};
      std::mutex                mutex;
      std::string               failure;
      SolveDiagnostics          diagnostics;
      base::Progress            progress(n_ranks == 1 ?
                                           "Green's functions (" + std::to_string(n_lines) + " frequencies)" :
                                           "Green's functions (rank 0's " + std::to_string(lines.size()) +
                                             " of " + std::to_string(n_lines) + " frequencies)",
                              lines.size());
      const auto work = [&]() {
        try
          {
            auto             solver = make_green_solver(method, cell, patch, harmonic);
            SolveDiagnostics mine;
            for (unsigned int l = next++; l < lines.size(); l = next++)
              {
                {
                  std::lock_guard<std::mutex> lock(mutex);
                  if (!failure.empty())
                    return;
                }
                const unsigned int k   = lines[l];
                const auto         g   = solver->solve(2. * M_PI * k * df, mine);
                double            *out = values.data() + 2 * std::size_t(k) * P * P;
                for (unsigned int i = 0; i < P; ++i)
                  for (unsigned int j = 0; j < P; ++j)
                    {
                      out[2 * (i * P + j)]     = g(i, j).real();
                      out[2 * (i * P + j) + 1] = g(i, j).imag();
                    }
                ++done;
              }
            std::lock_guard<std::mutex> lock(mutex);
            diagnostics.merge(mine);
          }
        catch (const std::exception &e)
          {
            std::lock_guard<std::mutex> lock(mutex);
            if (failure.empty())
              failure = e.what();
          }
      };
      base::run_on_threads(n_threads, work, done, lines.size(),
                           show_progress && rank == 0 ? &progress : nullptr, [&]() {
                             std::lock_guard<std::mutex> lock(mutex);
                             return !failure.empty();
                           });

      // Every rank learns whether any failed; the lowest failing rank's
      // message is the one reported.
      throw_if_any_rank_failed(comm, failure.empty() ? RankFailure::none : RankFailure::numerical,
                               "Green's functions: " + failure);

      base::FrequencyResponseMatrix green;
      green.df      = df;
      green.n_lines = n_lines;
      if (n_ranks > 1)
        {
          std::vector<double> sum(rank == 0 ? values.size() : 0);
          MPI_Reduce(values.data(), sum.data(), static_cast<int>(values.size()), MPI_DOUBLE,
                     MPI_SUM, 0, comm);
          values.swap(sum);
        }
      report.diagnostics.max_residual = dealii::Utilities::MPI::max(diagnostics.max_residual, comm);
      report.diagnostics.max_condition =
        dealii::Utilities::MPI::max(diagnostics.max_condition, comm);
      report.ranks   = n_ranks;
      report.threads = n_threads;
      report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (rank == 0)
        {
          for (const auto &p : patch.points)
            green.points.push_back({{p.x, p.y, p.radius}});
          green.values.resize(std::size_t(n_lines) * P * P);
          for (std::size_t e = 0; e < green.values.size(); ++e)
            green.values[e] = {values[2 * e], values[2 * e + 1]};
        }
      return green;
    }
  } // namespace periodic
} // namespace greentread
