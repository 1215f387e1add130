#include <greentread/base/job_runner.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <thread>
#include <vector>

namespace greentread
{
  namespace base
  {
    void
    run_on_threads(const unsigned int               n_threads,
                   const std::function<void()>     &work,
                   const std::atomic<unsigned int> &done,
                   const std::size_t                total,
                   Progress                        *progress,
                   const std::function<bool()>     &failed)
    {
      std::vector<std::thread> threads;
      for (unsigned int t = 1; t < n_threads; ++t)
        threads.emplace_back(work);
      if (progress != nullptr)
        {
          // The calling thread works too, and reports between its items.
          std::thread main_worker(work);
          while (done < total && !failed())
            {
              progress->update(done);
              std::this_thread::sleep_for(std::chrono::milliseconds(200));
            }
          main_worker.join();
          progress->finish();
        }
      else
        work();
      for (auto &t : threads)
        t.join();
    }



    void
    for_each_index(const std::size_t                                     count,
                   const unsigned int                                    n_threads,
                   const std::function<void(std::size_t, unsigned int)> &item)
    {
      std::vector<std::exception_ptr> failure(count);
      std::atomic<std::size_t>        next{0};
      std::atomic<bool>               failed{false};
      const auto                      work = [&](const unsigned int t) {
        for (std::size_t i = next++; i < count && !failed; i = next++)
          try
            {
              item(i, t);
            }
          catch (...)
            {
              failure[i] = std::current_exception();
              failed     = true;
            }
      };
      std::vector<std::thread> threads;
      for (unsigned int t = 1; t < std::min<std::size_t>(std::max(1u, n_threads), count); ++t)
        threads.emplace_back(work, t);
      work(0);
      for (auto &t : threads)
        t.join();
      for (const auto &e : failure)
        if (e)
          std::rethrow_exception(e);
    }
  } // namespace base
} // namespace greentread
