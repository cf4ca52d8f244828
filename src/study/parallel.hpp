// Running a study's members on a pool of threads (Boost.Asio's thread_pool): the one place
// where converge and sweep run work in parallel.
#pragma once

#include <boost/asio/post.hpp>
#include <boost/asio/thread_pool.hpp>

#include <algorithm>
#include <cstddef>

namespace gbssn1d {

/// Calls task(k) for k = 0 ... n - 1 on at most `jobs` threads, in order of k, and waits for
/// all. The tasks must not throw (each study records its members' failures itself).
template <class Task>
void run_tasks(std::size_t n, int jobs, Task&& task) {
  const std::size_t threads = std::clamp<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)),
                                                      1, std::max<std::size_t>(n, 1));
  boost::asio::thread_pool pool(threads);
  for (std::size_t k = 0; k < n; ++k)
    boost::asio::post(pool, [&task, k] { task(k); });
  pool.join();
}

} // namespace gbssn1d
