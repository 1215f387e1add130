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
  } // namespace base
} // namespace greentread
