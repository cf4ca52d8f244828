// The verdict of a convergence study (study/verdict.hpp) on made-up norms and differences:
// what it accepts, what it refuses, what it names, and its four classes on both sides of each
// boundary (the whole run's RMS order 1, a window's RMS order 0, the finer value 10 times the
// round-off floor).
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
  CHECK(v.items[0].converges());                 // the coarser pair is fine
  CHECK(v.kind() == ConvergenceClass::diverges); // the finer member worse over a tenth of the run
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
  CHECK(v.kind() == ConvergenceClass::pre_asymptotic); // order 2 there: still falling
  const OrderJudgement& j = *v.failure();
  CHECK(j.first_below == 8);
  CHECK(j.windows_below >= 1);
  CHECK(j.window_order < 2.5);
  CHECK(j.p_rms > 2.5); // the whole run's RMS alone would have hidden it
}

TEST_CASE(
    "verdict: times at round-off are not judged, and a study that judged nothing is no pass") {
  // a finer norm of 1e-13 with a floor of 1: no time is judged
  OrderSeries s = norm_pair(100, 200, 4.0, 1.0);
  for (auto& f : s.fine)
    f *= 1e3; // a "non-converging" finer value, but all at round-off
  const Verdict v = judge_convergence({s}, 4.0);
  CHECK(v.items[0].judged == 0);
  CHECK(v.items[0].at_floor == 41);
  CHECK(std::isnan(v.items[0].p_rms));
  CHECK(v.weakest() == nullptr);
  // the item alone reads "at the floor", but the study judged nothing at all: not judged, and
  // not a pass (it named a non-converging finer member "round-off")
  CHECK(v.items[0].kind == ConvergenceClass::to_floor);
  CHECK(v.nothing_judged);
  CHECK(v.kind() == ConvergenceClass::unjudged);
  CHECK_FALSE(v.converges());
  CHECK(v.failure() == &v.items[0]);
  // the same item beside one that was judged: the study converges until the floor
  const Verdict both = judge_convergence({s, norm_pair(100, 200, 4.0, 1e-30)}, 4.0);
  CHECK_FALSE(both.nothing_judged);
  CHECK(both.kind() == ConvergenceClass::to_floor);
  CHECK(both.converges());
  CHECK(class_words(both.kind()) == "converges until the round-off floor");
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
  CHECK(brief.items[0].p_rms == doctest::Approx(1.97).epsilon(0.01));
  CHECK(brief.kind() == ConvergenceClass::pre_asymptotic); // falling, below 2.5
  CHECK(resolutions_text(v.failure()->N) == "N = 100, 150 and 200");
}

TEST_CASE("verdict: a non-finite finer value never passes") {
  OrderSeries s = norm_pair(100, 200, 4.0);
  s.fine[40] = std::numeric_limits<double>::quiet_NaN();
  CHECK(order_at(s.N, s.coarse[40], s.fine[40]) == -std::numeric_limits<double>::infinity());
  CHECK(judge_convergence({s}, 4.0).items[0].below == 1);
}

namespace {

/// A norm pair at N = 100, 200, 41 times: the finer value ratio times the coarser (order
/// -log2(ratio)), with times [from, to) at ratio_there instead.
OrderSeries ratio_pair(double ratio, std::size_t from = 0, std::size_t to = 0,
                       double ratio_there = 1.0) {
  OrderSeries s{"H_L2_ext", {100, 200}, {}, {}, {}};
  for (std::size_t q = 0; q <= 40; ++q) {
    const double c = 1e-4 * (1.0 + 0.3 * std::sin(0.5 * static_cast<double>(q)));
    s.coarse.push_back(c);
    s.fine.push_back(c * (q >= from && q < to ? ratio_there : ratio));
    s.floor.push_back(1e-16);
  }
  return s;
}

} // namespace

TEST_CASE("verdict classes: the whole run's RMS order 0.99 does not converge, 1.01 is "
          "pre-asymptotic") {
  const Verdict low = judge_convergence({ratio_pair(std::pow(2.0, -0.99))}, 4.0);
  CHECK(low.items[0].p_rms == doctest::Approx(0.99));
  CHECK(low.kind() == ConvergenceClass::diverges);
  CHECK(class_words(low.kind()) == "does not converge");
  CHECK(low.failure() == &low.items[0]);
  const Verdict high = judge_convergence({ratio_pair(std::pow(2.0, -1.01))}, 4.0);
  CHECK(high.items[0].p_rms == doctest::Approx(1.01));
  CHECK(high.kind() == ConvergenceClass::pre_asymptotic);
  CHECK(class_words(high.kind()) == "pre-asymptotic");
  CHECK_FALSE(high.converges());
  CHECK(high.failure() == &high.items[0]);
  // at 2.51 it converges (the threshold 2.5 is the other boundary), at 2.49 it does not yet
  CHECK(judge_convergence({ratio_pair(std::pow(2.0, -2.51))}, 4.0).kind()
        == ConvergenceClass::converges);
  CHECK(judge_convergence({ratio_pair(std::pow(2.0, -2.49))}, 4.0).kind()
        == ConvergenceClass::pre_asymptotic);
  // field differences (not windowed): the same boundary at order 1
  OrderSeries f{"alpha", {100, 150, 200}, {}, {}, {}, false};
  for (double p : {0.99, 1.01}) {
    f.coarse.assign(20, std::pow(100.0, -p) - std::pow(150.0, -p));
    f.fine.assign(20, std::pow(150.0, -p) - std::pow(200.0, -p));
    f.floor.assign(20, 1e-16);
    const Verdict v = judge_convergence({f}, 4.0);
    INFO(p);
    CHECK(v.items[0].p_rms == doctest::Approx(p).epsilon(1e-6));
    CHECK(v.kind() == (p < 1 ? ConvergenceClass::diverges : ConvergenceClass::pre_asymptotic));
  }
}

TEST_CASE("verdict classes: a tenth of the run at RMS order -0.1 does not converge, at +0.1 is "
          "pre-asymptotic") {
  // order 4 but over the third window (times 8 to 11 of 41), where the finer member is 2^0.1
  // times worse, or 2^0.1 times better, than the coarser
  const Verdict worse = judge_convergence({ratio_pair(1.0 / 16, 8, 12, std::pow(2.0, 0.1))}, 4.0);
  const OrderJudgement& w = worse.items[0];
  CHECK(w.p_rms > 1.0); // the whole run's errors fall
  CHECK(w.windows_worse == 1);
  CHECK(w.worse_order == doctest::Approx(-0.1));
  CHECK(w.worse_begin == 8);
  CHECK(w.worse_end == 11);
  CHECK(worse.kind() == ConvergenceClass::diverges);
  const Verdict better = judge_convergence({ratio_pair(1.0 / 16, 8, 12, std::pow(2.0, -0.1))}, 4.0);
  CHECK(better.items[0].p_rms > 1.0);
  CHECK(better.items[0].windows_worse == 0);
  CHECK(better.items[0].windows_below == 1);
  CHECK(better.kind() == ConvergenceClass::pre_asymptotic);
  // one diverging item outweighs a pre-asymptotic one before it: it is the one named
  const Verdict both =
      judge_convergence({ratio_pair(1.0 / 4), ratio_pair(1.0 / 16, 8, 12, 1.1)}, 4.0);
  CHECK(both.kind() == ConvergenceClass::diverges);
  CHECK(both.failure() == &both.items[1]);
}

TEST_CASE("verdict classes: a finer value 9 times its floor is at the floor, 11 times is judged") {
  // the finer member worse than the coarser (order < 0) at every time: at 9 times its floor
  // that is round-off (converges until the floor); at 11 times it is judged, and fails
  for (double factor : {9.0, 11.0}) {
    OrderSeries s = ratio_pair(1.5);
    for (std::size_t q = 0; q < s.fine.size(); ++q)
      s.floor[q] = s.fine[q] / factor;
    const Verdict v = judge_convergence({s}, 4.0);
    INFO(factor);
    CHECK(v.items[0].judged == (factor < 10 ? 0U : 41U));
    CHECK(v.items[0].at_floor == (factor < 10 ? 41U : 0U));
    // at 9 times: nothing judged in the whole study, which is no pass
    CHECK(v.kind() == (factor < 10 ? ConvergenceClass::unjudged : ConvergenceClass::diverges));
  }
  // converging at order 4 until the finer member reaches the floor at t = 15: those times are
  // not judged, and the verdict says the floor was reached
  OrderSeries s = ratio_pair(1.0 / 16);
  for (std::size_t q = 30; q < s.fine.size(); ++q) {
    s.fine[q] = s.coarse[q]; // round-off: as large as the coarser value
    s.floor[q] = s.fine[q] / 9.0;
  }
  const Verdict v = judge_convergence({s, ratio_pair(1.0 / 16)}, 4.0);
  CHECK(v.items[0].judged == 30);
  CHECK(v.items[0].at_floor == 11);
  CHECK(v.items[0].first_floor == 30);
  CHECK(v.items[0].floor_value == s.floor[30]);
  CHECK(v.items[0].p_rms == doctest::Approx(4.0));
  CHECK(v.items[0].kind == ConvergenceClass::to_floor);
  CHECK(v.items[1].kind == ConvergenceClass::converges);
  CHECK(v.kind() == ConvergenceClass::to_floor);
  CHECK(v.converges());
  CHECK(v.failure() == nullptr);
  // without any time at the floor: converges
  CHECK(judge_convergence({ratio_pair(1.0 / 16)}, 4.0).kind() == ConvergenceClass::converges);
  CHECK(class_words(ConvergenceClass::converges) == "converges");
}

TEST_CASE("verdict: exact zeros are neither judged nor at the floor, a non-finite finer value "
          "is judged") {
  OrderSeries s = ratio_pair(1.0 / 16);
  s.coarse[0] = s.fine[0] = 0.0; // G^r of the initial data
  s.fine[1] = std::numeric_limits<double>::quiet_NaN();
  const Verdict v = judge_convergence({s}, 4.0);
  CHECK(v.items[0].judged == 40);
  CHECK(v.items[0].at_floor == 0);
  CHECK(v.kind() == ConvergenceClass::diverges);
  // no time at all: nothing judged, nothing at the floor, nothing valued: not judged
  const Verdict none = judge_convergence({OrderSeries{"H_L2_ext", {100, 200}, {}, {}, {}}}, 4.0);
  CHECK(none.kind() == ConvergenceClass::unjudged);
  CHECK_FALSE(none.converges());
  CHECK(none.weakest() == nullptr);
}

TEST_CASE("verdict: a norm without a value at any time (an empty window) is not judged, never "
          "'converges'") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  OrderSeries empty = ratio_pair(1.0 / 16);
  empty.quantity = "H_L2_R";
  for (double& c : empty.coarse)
    c = nan;
  for (double& f : empty.fine)
    f = nan;
  const Verdict v = judge_convergence({ratio_pair(1.0 / 16), empty}, 4.0);
  CHECK(v.items[0].kind == ConvergenceClass::converges);
  CHECK(v.items[1].kind == ConvergenceClass::unjudged);
  CHECK(v.items[1].judged == 0);
  CHECK(v.items[1].valued == 0);
  CHECK(v.kind() == ConvergenceClass::unjudged);
  CHECK_FALSE(v.converges());
  REQUIRE(v.failure() != nullptr);
  CHECK(v.failure()->quantity == "H_L2_R");
  CHECK(class_words(v.kind()) == "not judged");
  // the coarser member empty, the finer not (a window between the coarse cells): not judged
  OrderSeries coarse_empty = ratio_pair(1.0 / 16);
  for (double& c : coarse_empty.coarse)
    c = nan;
  CHECK(judge_convergence({coarse_empty}, 4.0).kind() == ConvergenceClass::unjudged);
  // one valued time is too short to judge; eleven are enough
  coarse_empty.coarse[7] = ratio_pair(1.0 / 16).coarse[7];
  CHECK(judge_convergence({coarse_empty}, 4.0).kind() == ConvergenceClass::unjudged);
  CHECK(judge_convergence({coarse_empty}, 4.0).items[0].too_short);
  for (std::size_t q = 8; q < 18; ++q)
    coarse_empty.coarse[q] = ratio_pair(1.0 / 16).coarse[q];
  CHECK(judge_convergence({coarse_empty}, 4.0).kind() == ConvergenceClass::converges);
  // a study that does not converge says so, whatever is not judged besides
  CHECK(judge_convergence({ratio_pair(1.0), empty}, 4.0).kind() == ConvergenceClass::diverges);
}

TEST_CASE("verdict: 10 judged times are too short to judge whatever their orders, 11 are judged") {
  // the times after the first n are at the floor (not judged): n judged times remain
  const auto first = [](OrderSeries s, std::size_t n) {
    for (std::size_t q = n; q < s.fine.size(); ++q)
      s.floor[q] = s.fine[q]; // within 10 times its floor
    return s;
  };
  for (double ratio : {1.0 / 16, 1.0, 2.0}) { // converging, not falling, the finer worse
    INFO(ratio);
    const Verdict ten = judge_convergence({first(ratio_pair(ratio), 10)}, 4.0);
    CHECK(ten.items[0].judged == 10);
    CHECK(ten.items[0].too_short);
    CHECK(ten.kind() == ConvergenceClass::unjudged);
    CHECK_FALSE(ten.converges());
    REQUIRE(ten.failure() != nullptr);
    const Verdict eleven = judge_convergence({first(ratio_pair(ratio), 11)}, 4.0);
    CHECK(eleven.items[0].judged == 11);
    CHECK_FALSE(eleven.items[0].too_short);
    CHECK(eleven.kind() == (ratio < 1.0 ? ConvergenceClass::to_floor : ConvergenceClass::diverges));
  }
  // a single time once decided: "over t = 0.75 ... 0.75 (a tenth of the run)"
  const Verdict one = judge_convergence({first(ratio_pair(1.0 / 16, 0, 1, 2.0), 1)}, 4.0);
  CHECK(one.items[0].too_short);
  CHECK(one.items[0].windows_worse == 1);
  CHECK(one.kind() == ConvergenceClass::unjudged);
}

TEST_CASE("verdict: the item named is the worst of the study's class, and H's class is its own") {
  // two pre-asymptotic items: order 2 (G) and 1.5 (M); the worse, M, is named whatever the
  // order given; H converges
  OrderSeries g = ratio_pair(0.25), m = ratio_pair(std::pow(2.0, -1.5)), h = ratio_pair(1.0 / 16);
  g.quantity = "G_L2_ext";
  m.quantity = "M_L2_R";
  for (const auto& order : {std::vector<OrderSeries>{h, g, m}, std::vector<OrderSeries>{m, h, g}}) {
    const Verdict v = judge_convergence(order, 4.0);
    CHECK(v.kind() == ConvergenceClass::pre_asymptotic);
    REQUIRE(v.failure() != nullptr);
    CHECK(v.failure()->quantity == "M_L2_R");
    CHECK(v.kind_of("H_") == ConvergenceClass::converges);
    CHECK(v.kind_of("G_") == ConvergenceClass::pre_asymptotic);
    CHECK(v.kind_of("Theta_") == ConvergenceClass::unjudged); // no such item
  }
  // H's class is the worst of its norms'
  OrderSeries h_r = ratio_pair(1.0);
  h_r.quantity = "H_L2_R";
  CHECK(judge_convergence({h, h_r, g}, 4.0).kind_of("H_") == ConvergenceClass::diverges);
}

TEST_CASE("the round-off floor: eps (M/dr_min)^2, as measured on the stationary trumpet") {
  // measured (H_L2_R, standard gauge, default sinh grid): 3-8e-11 at dr_min = M/400,
  // 1.2-2.4e-10 at M/800 (relative comparisons: doctest's Approx would pass any two numbers
  // this small)
  CHECK(round_off_floor(1.0, 1.0 / 400) / 3.55e-11 == doctest::Approx(1.0).epsilon(0.01));
  CHECK(round_off_floor(1.0, 1.0 / 800) / 1.42e-10 == doctest::Approx(1.0).epsilon(0.01));
  // relative to the quantity's scale: the same at M = 2 with every length doubled
  CHECK(round_off_floor(2.0, 2.0 / 400) / round_off_floor(1.0, 1.0 / 400) == doctest::Approx(1.0));
  CHECK(round_off_floor(1.0, 0.1) / 2.220446e-14 == doctest::Approx(1.0).epsilon(1e-6));
}
