#pragma once

#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <string>

/**
 * @file
 * Progress of long loops, on standard error so that standard output stays
 * comparable by numdiff.
 */

namespace greentread
{
  namespace base
  {
    /// The wall-clock seconds since @p start.
    inline double
    seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /**
     * @brief Prints "label: 42% (8400/20000), 3.1 s, about 4.3 s left" at most
     * every @p interval seconds, and nothing for loops that end sooner.
     */
    class Progress
    {
    public:
      Progress(std::string label, std::size_t total, double interval = 2.0);

      /// Report that @p done of the total items are finished.
      void
      update(std::size_t done)
      {
        if (done >= next_check)
          check(done);
      }

      /// The loop grew: @p new_total items in all.
      void
      extend(std::size_t new_total)
      {
        total = new_total;
      }

      /// Print the final line if anything was printed before.
      void
      finish();

    private:
      void
      check(std::size_t done);

      std::string                           label;
      std::size_t                           total;
      double                                interval;
      std::size_t                           next_check;
      std::size_t                           stride;
      bool                                  printed = false;
      std::chrono::steady_clock::time_point start;
      std::chrono::steady_clock::time_point last;
    };
  } // namespace base
} // namespace greentread
