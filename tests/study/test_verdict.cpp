// The verdict of a convergence study (study/verdict.hpp) on made-up norms and differences:
// what it accepts, what it refuses, and what it names.
#include "study/verdict.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace gbssn1d;

namespace {

/// A norm with exact value 0 at N = a, b: C N^-p (1 + 0.3 sin t) over 41 times t = 0, 0.5, ... 20.
OrderSeries norm_pair(double a, double b, double p, double floor = 1e-16) {
  OrderSeries s{"H_L2_R", {a, b}, {}, {}, {}};
  for (int q = 0; q <= 40; ++q) {
    const double shape = 1e-2 * (1.0 + 0.3 * std::sin(0.5 * q));
    s.coarse.push_back(shape * std::pow(a, -p));
    s.fine.push_back(shape * std::pow(b, -p));
    s.floor.push_back(floor);
  }
  return s;
}

} // namespace

TEST_CASE("verdict: norms falling at the design order converge") {
  const Verdict v = judge_convergence({norm_pair(100, 200, 4.0), norm_pair(200, 400, 4.0)}, 4.0);
  CHECK(v.converges());
  CHECK(v.threshold == 2.5);
  REQUIRE(v.items.size() == 2);
  CHECK(v.items[0].judged == 41);
  CHECK(v.items[0].below == 0);
  CHECK(v.items[0].p_rms == doctest::Approx(4.0));
  CHECK(v.items[1].worst == doctest::Approx(4.0));
  // at 2nd order they do not, against a design order of 4; against 2 they do
  CHECK_FALSE(judge_convergence({norm_pair(100, 200, 2.0)}, 4.0).converges());
  CHECK(judge_convergence({norm_pair(100, 200, 2.0)}, 2.0).converges());
}

TEST_CASE("verdict: a finer member whose norm grows from some time on is named, with the time") {
  OrderSeries s = norm_pair(200, 400, 4.0);
  for (std::size_t q = 30; q < s.fine.size(); ++q) // from t = 15 the finer member drifts away
    s.fine[q] = s.coarse[q] * std::exp(0.5 * static_cast<double>(q - 29));
  const Verdict v = judge_convergence({norm_pair(100, 200, 4.0), s}, 4.0);
  CHECK_FALSE(v.converges());
  const OrderJudgement* f = v.failure();
  REQUIRE(f != nullptr);
  CHECK(f->quantity == "H_L2_R");
  CHECK(f->N == std::vector<double>{200, 400});
  CHECK(f->first_below == 30); // t = 15, the first time the order falls below 2.5
  CHECK(f->worst_at == 40);
  CHECK(f->worst < -5.0);
  CHECK(f->below == 11);
  CHECK(resolutions_text(f->N) == "N = 200 and 400");
  CHECK(v.items[0].converges); // the coarser pair is fine
}

TEST_CASE("verdict: a dip at single times is tolerated, a tenth of the run below is not") {
  OrderSeries brief = norm_pair(100, 200, 4.0), longer = brief;
  brief.fine[10] = brief.coarse[10] / 4; // order 2 at one time of 41
  for (std::size_t q = 8; q < 16; ++q)   // order 2 from t = 4 to 7.5
    longer.fine[q] = longer.coarse[q] / 4;
  const Verdict ok = judge_convergence({brief}, 4.0);
  CHECK(ok.converges());
  CHECK(ok.items[0].below == 1); // reported, but not decisive
  CHECK(ok.items[0].windows == 10);
  const Verdict v = judge_convergence({longer}, 4.0);
  CHECK_FALSE(v.converges());
  const OrderJudgement& j = *v.failure();
  CHECK(j.first_below == 8);
  CHECK(j.windows_below >= 1);
  CHECK(j.window_order < 2.5);
  CHECK(j.p_rms > 2.5); // the whole run's RMS alone would have hidden it
}

TEST_CASE("verdict: times at round-off are not judged") {
  // a coarse norm of 1e-13 with a floor of 1e-10: no time is judged, nothing fails
  OrderSeries s = norm_pair(100, 200, 4.0, 1.0);
  for (auto& f : s.fine)
    f *= 1e3; // a "non-converging" finer value, but all at round-off
  const Verdict v = judge_convergence({s}, 4.0);
  CHECK(v.converges());
  CHECK(v.items[0].judged == 0);
  CHECK(std::isnan(v.items[0].p_rms));
  CHECK(v.weakest() == nullptr);
}

TEST_CASE("verdict: field differences over three resolutions") {
  // |f_a - f_b| and |f_b - f_c| of f = f_exact + C N^-4 at N = 100, 150, 200
  OrderSeries s{"chi", {100, 150, 200}, {}, {}, {}};
  const double e1 = std::pow(100.0, -4), e2 = std::pow(150.0, -4), e3 = std::pow(200.0, -4);
  for (int q = 0; q < 20; ++q) {
    s.coarse.push_back(e1 - e2);
    s.fine.push_back(e2 - e3);
    s.floor.push_back(1e-16);
  }
  Verdict v = judge_convergence({s}, 4.0);
  CHECK(v.converges());
  CHECK(v.items[0].p_rms == doctest::Approx(4.0).epsilon(1e-6));
  // the finer difference as large as the coarser: no order in (0, 30] fits, "< 0"
  for (std::size_t q = 12; q < 20; ++q)
    s.fine[q] = s.coarse[q];
  v = judge_convergence({s}, 4.0);
  CHECK_FALSE(v.converges());
  CHECK(v.failure()->first_below == 12);
  CHECK(v.failure()->worst == -std::numeric_limits<double>::infinity());
  CHECK(order_text(v.failure()->worst) == "< 0");
  // judged by the whole run's RMS alone (not windowed), the last two fifths still fail it
  s.windowed = false;
  CHECK_FALSE(judge_convergence({s}, 4.0).converges());
  for (std::size_t q = 12; q < 18; ++q) // a third of the run at order < 0 would fail a window
    s.fine[q] = e2 - e3;
  const Verdict brief = judge_convergence({s}, 4.0);
  CHECK(brief.items[0].windows == 0);
  CHECK(brief.converges() == (brief.items[0].p_rms >= 2.5));
  CHECK(resolutions_text(v.failure()->N) == "N = 100, 150 and 200");
}

TEST_CASE("verdict: a non-finite finer value never passes") {
  OrderSeries s = norm_pair(100, 200, 4.0);
  s.fine[40] = std::numeric_limits<double>::quiet_NaN();
  CHECK(order_at(s.N, s.coarse[40], s.fine[40]) == -std::numeric_limits<double>::infinity());
  CHECK(judge_convergence({s}, 4.0).items[0].below == 1);
}
