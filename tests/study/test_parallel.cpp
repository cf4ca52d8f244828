// The studies' thread pool: every task runs once, and a task's exception reaches the caller
// (an exception leaving a pool thread would abort the program: exit 134, no summary).
#include "study/parallel.hpp"

#include <doctest/doctest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

using gbssn1d::run_tasks;

TEST_CASE("run_tasks: every task once, and a task's exception is rethrown to the caller, later "
          "tasks are not started") {
  std::vector<std::atomic<int>> runs(50);
  run_tasks(runs.size(), 3, [&](std::size_t k) { ++runs[k]; });
  for (const auto& r : runs)
    CHECK(r == 1);

  std::atomic<int> started = 0;
  auto failing = [&](std::size_t k) {
    ++started;
    if (k == 2)
      throw std::runtime_error("member 2 could not write its status");
  };
  CHECK_THROWS_WITH_AS(run_tasks(20, 1, failing), "member 2 could not write its status",
                       std::runtime_error);
  CHECK(started == 3); // one thread, in order: 0, 1, 2, and nothing after the failure
  CHECK_THROWS_AS(run_tasks(20, 4, failing), std::runtime_error); // from any thread
}
