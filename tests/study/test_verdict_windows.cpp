// The verdict's consecutive windows (study/verdict.cpp, judge_convergence) tile the judged times:
// every judged time lies in exactly one window, the last time too, so that one bad time, alone
// in a long run, is seen by its window wherever it lies.
#include "study/verdict.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>

using namespace gbssn1d;

namespace {

/// n times at order 4 between N = 100 and 200, but time `bad`, where the finer value equals the
/// coarser one (order 0).
OrderSeries one_bad_time(std::size_t n, std::size_t bad) {
  OrderSeries s{"H_L2_R", {100, 200}, {}, {}, {}};
  for (std::size_t q = 0; q < n; ++q) {
    const double coarse = 1e-3 * (1.0 + 0.2 * std::sin(0.7 * static_cast<double>(q)));
    s.coarse.push_back(coarse);
    s.fine.push_back(q == bad ? coarse : coarse / 16.0);
    s.floor.push_back(1e-16);
  }
  return s;
}

} // namespace

// Guards the windows' bounds: a window that dropped its last time let a run whose only bad time
// was its last (109 judged times) "converge".
TEST_CASE("verdict: the windows tile every judged time, the last one too: one bad time anywhere "
          "is found by its window") {
  for (const std::size_t n : {57u, 109u, 200u}) {
    CHECK(judge_convergence({one_bad_time(n, n)}, 4.0).converges()); // no bad time: converges
    for (std::size_t bad = 0; bad < n; ++bad) {
      INFO(n << " judged times, the bad one at " << bad);
      const Verdict v = judge_convergence({one_bad_time(n, bad)}, 4.0);
      const OrderJudgement& j = v.items.at(0);
      CHECK(j.judged == n);
      CHECK(j.windows == kWindows);
      CHECK(j.p_rms > v.threshold); // the whole run's RMS alone would not see it
      CHECK_FALSE(v.converges());
      CHECK(v.kind() == ConvergenceClass::pre_asymptotic);
      CHECK(j.windows_below == 1); // in one window, and that window holds it
      CHECK(j.window_begin <= bad);
      CHECK(bad <= j.window_end);
      CHECK(j.window_end - j.window_begin + 1 >= n / kWindows);
      CHECK(j.window_end - j.window_begin + 1 <= n / kWindows + 1);
    }
  }
}
