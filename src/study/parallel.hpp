// Running a study's members on a pool of threads (Boost.Asio's thread_pool): the one place
// where converge and sweep run work in parallel.
#pragma once

#include <boost/asio/post.hpp>
#include <boost/asio/thread_pool.hpp>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>

namespace gbssn1d {

/// Calls task(k) for k = 0 ... n - 1 on at most `jobs` threads, in order of k, and waits for
/// all. Each study records its members' own failures itself; an exception that still leaves a
/// task (a failed write of the study's own files, memory) starts no further task and is
/// rethrown here, in the caller's thread, once the running ones have ended: it never crosses a
/// thread (which would abort the program).
template <class Task>
void run_tasks(std::size_t n, int jobs, Task&& task) {
  const std::size_t threads = std::clamp<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)),
                                                      1, std::max<std::size_t>(n, 1));
  std::atomic<bool> failed = false;
  std::exception_ptr first;
  std::mutex mutex;
  {
    boost::asio::thread_pool pool(threads);
    for (std::size_t k = 0; k < n; ++k)
      boost::asio::post(pool, [&, k] {
        if (failed)
          return;
        try {
          task(k);
        } catch (...) {
          const std::lock_guard lock(mutex);
          if (!first)
            first = std::current_exception();
          failed = true;
        }
      });
    pool.join();
  }
  if (first)
    std::rethrow_exception(first);
}

} // namespace gbssn1d
