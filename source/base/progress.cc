#include <greentread/base/progress.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <thread>
#include <vector>

namespace greentread
{
  namespace base
  {
    Progress::Progress(std::string label_, const std::size_t total_, const double interval_)
        : label(std::move(label_))
        , total(std::max<std::size_t>(total_, 1))
        , interval(interval_)
        , next_check(1)
        , stride(std::max<std::size_t>(total / 1000, 1))
        , start(std::chrono::steady_clock::now())
        , last(start)
    {
    }



    void
    Progress::check(const std::size_t done)
    {
      next_check         = done + stride;
      const auto   now   = std::chrono::steady_clock::now();
      const double since = std::chrono::duration<double>(now - last).count();
      if (since < interval)
        return;
      last                 = now;
      const double elapsed = std::chrono::duration<double>(now - start).count();
      const double left =
        done > 0 ? elapsed * double(total - std::min(done, total)) / double(done) : 0.;
      char line[256];
      std::snprintf(line, sizeof(line), "%s: %3.0f%% (%zu/%zu), %.1f s, about %.1f s left",
                    label.c_str(), 100. * double(done) / double(total), done, total, elapsed, left);
      std::cerr << line << std::endl;
      printed = true;
    }



    void
    Progress::finish()
    {
      if (!printed)
        return;
      const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      char line[256];
      std::snprintf(line, sizeof(line), "%s: done (%zu), %.1f s", label.c_str(), total, elapsed);
      std::cerr << line << std::endl;
    }



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
      const auto                      work = [&](const unsigned int t) {
        for (std::size_t i = next++; i < count; i = next++)
          try
            {
              item(i, t);
            }
          catch (...)
            {
              failure[i] = std::current_exception();
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
