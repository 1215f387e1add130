#pragma once

#include <greentread/base/progress.h>

#include <atomic>
#include <cstddef>
#include <functional>

/**
 * @file
 * The threads of a stage's independent jobs: the Green's functions' lines,
 * the ring's harmonics, a study's runs. Implemented in
 * source/base/job_runner.cc.
 */

namespace greentread
{
  namespace base
  {
    /**
     * Runs @p work on @p n_threads threads, the calling thread being one of
     * them, and returns when all have returned. With a @p progress, the
     * calling thread reports @p done out of @p total every 0.2 s until the
     * work is done or @p failed() says a worker has given up.
     */
    void
    run_on_threads(unsigned int                     n_threads,
                   const std::function<void()>     &work,
                   const std::atomic<unsigned int> &done,
                   std::size_t                      total,
                   Progress                        *progress,
                   const std::function<bool()>     &failed);

    /**
     * @brief Calls @p item(i, t) for i = 0 .. @p count - 1 on up to
     * @p n_threads threads (the calling one among them, t = 0), the items
     * taken in order; t < @p n_threads numbers the thread, for state a
     * thread keeps between its items. Once an item has thrown, no thread
     * starts another (the items under way finish), and the exception of the
     * lowest i is rethrown here. The items' results go where @p item puts
     * them, by index, so they do not depend on the number of threads.
     */
    void
    for_each_index(std::size_t                                           count,
                   unsigned int                                          n_threads,
                   const std::function<void(std::size_t, unsigned int)> &item);
  } // namespace base
} // namespace greentread
