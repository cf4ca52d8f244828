// The extrapolated h_AH of boxes (evolution/horizon_extrapolated.hpp): the radii
// found after the last hierarchy steps are kept, four of them, and h_AH at a stage's time is the
// cubic through them, so that a horizon moving as a cubic in t is followed without error of its
// own. The tracker here searches states made for it: 1+log trumpets whose mass M(t) is a cubic
// in t, whose horizon radius is proportional to M.
#include "evolution/horizon_extrapolated.hpp"
#include "evolution/horizon_tracker.hpp"
#include "initial_data/initial_data.hpp"

#include "../simulation_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

using namespace gbssn1d;
using gbssn1d::testing::simulation;
using gbssn1d::testing::small_trumpet_params;

namespace {

/// The Lagrange polynomial through the points (t, h) at t.
double lagrange(const std::vector<std::array<double, 2>>& points, double t) {
  double sum = 0.0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    double w = 1.0;
    for (std::size_t m = 0; m < points.size(); ++m)
      if (m != j)
        w *= (t - points[m][0]) / (points[j][0] - points[m][0]);
    sum += w * points[j][1];
  }
  return sum;
}

/// The 1+log trumpet on five boxes (rmax 32 M, N = 20) with the horizon shift (A = 0.5, h = 1),
/// its levels' states and right-hand sides, and a horizon tracker over them (extrapolated h_AH).
struct BoxesTracker {
  static Params params() {
    Params p;
    p.grid = RadialGrid::boxes;
    p.levels = 5;
    p.rmax = 32.0;
    p.N = 20;
    p.id = InitialDataKind::onelog_trumpet;
    p.rahA = 0.5;
    p.rah0 = 1.0;
    return p;
  }
  static std::vector<GbssnRhs> rhs_of(const Simulation& sim) {
    std::vector<GbssnRhs> r;
    for (std::size_t l = 0; l < sim.layout().levels(); ++l)
      r.emplace_back(sim.layout().grid(l), sim.config().rhs);
    return r;
  }
  const Simulation sim = simulation(params());
  std::vector<State> levels = sim.level_states();
  std::vector<GbssnRhs> rhs = rhs_of(sim);
  std::unique_ptr<HorizonTracker> made =
      make_horizon_tracker(sim.config(), sim.layout(), levels, rhs);
  HorizonTracker& tracker = *made;
};

} // namespace

// Guards the length of the extrapolated mode's history (horizon_extrapolated.cpp, search_at_step):
// four radii, not three (with three the extrapolation is quadratic, and r_AH on boxes moved at
// 1e-6 without any test failing).
TEST_CASE("boxes' extrapolated h_AH: the cubic through the last four radii found, exact for a "
          "horizon moving as a cubic in t") {
  BoxesTracker boxes;
  const Simulation& sim = boxes.sim;
  std::vector<State>& levels = boxes.levels;
  std::vector<GbssnRhs>& rhs = boxes.rhs;
  HorizonTracker& tracker = boxes.tracker;
  REQUIRE(tracker.mode() == HorizonTracker::Mode::extrapolated);

  auto M_of = [](double t) { return 1.0 + 0.02 * t + 0.03 * t * t * t; };
  auto set_mass = [&](double t) {
    InitialDataParams id;
    id.kind = InitialDataKind::onelog_trumpet;
    id.M = M_of(t);
    for (std::size_t l = 0; l < levels.size(); ++l)
      levels[l] = initial_data(sim.layout().grid(l), id, Formulation::bssn);
  };
  const double dt = 0.25;
  set_mass(0.0);
  tracker.start(0.0);
  for (long n = 1; n <= 6; ++n) {
    set_mass(static_cast<double>(n) * dt);
    tracker.after_step(n, static_cast<double>(n - 1) * dt, static_cast<double>(n) * dt);
  }
  // the last four searches, oldest first
  const auto& history = tracker.history();
  REQUIRE(history.size() == 4);
  for (std::size_t k = 0; k < 4; ++k)
    CHECK(history[k][0] == doctest::Approx(static_cast<double>(k + 3) * dt));
  // h_AH / M of the last search: the trumpet's horizon in units of its mass
  const double c = history.back()[1] / M_of(6 * dt);
  CHECK(c == doctest::Approx(0.83).epsilon(0.02));
  for (const double t : {1.55, 1.6, 1.75}) {
    INFO("t = " << t);
    const auto h = tracker.radius(t);
    REQUIRE(h);
    // the cubic through the kept radii ...
    CHECK(*h == doctest::Approx(lagrange(history, t)).epsilon(1e-12));
    // ... which follows the horizon the finder finds at t (its error, of the grid, varies
    // smoothly with M), ten times closer than the quadratic through the last three radii (which
    // misses it by 2e-4 to 2e-3 here)
    set_mass(t);
    const auto fresh = make_horizon_tracker(sim.config(), sim.layout(), levels, rhs);
    fresh->start(t);
    REQUIRE(fresh->history().size() == 1);
    const double found = fresh->history().back()[1];
    const double quadratic = lagrange({history.begin() + 1, history.end()}, t);
    CHECK(std::abs(*h - found) < 1e-4);
    CHECK(std::abs(*h - found) < 0.1 * std::abs(quadratic - found));
  }
}

// Guards the start's pilot (horizon_extrapolated.cpp, local_cubic): subcycled boxes take h_AH over
// their first steps from a pilot run without subcycling, whose radii at every step of the finest
// box are the nodes; between them h_AH(t) is the cubic through the four nodes around t, two at
// or before t and two after (the first or last four at the ends). With the nodes one place off
// centre h_AH is still a cubic through four of them, and the run's r_AH moved by only 1.1e-11,
// within the pilot test's 1e-6 (test_boxes.cpp). Here the nodes are a smooth h(t) at the finest
// box's step, and the tracker's h_AH is checked against the centred cubic written out here.
// Measured: no difference at all (the same sums); the bound is a few ulp of h ~ 0.85, where the
// nodes one place later or earlier differ by 1.2e-5. And the centred cubic is the closer one: its
// largest error on h(t) is 4.6e-6 (measured), checked against 1.25 times that (one place later:
// 8.2e-6, earlier: 7.6e-6).
TEST_CASE("the start's pilot: h_AH between the pilot's radii is the cubic through the two radii "
          "before t and the two after") {
  BoxesTracker boxes;
  REQUIRE(boxes.tracker.mode() == HorizonTracker::Mode::extrapolated);
  auto& tracker = dynamic_cast<ExtrapolatedRadius&>(boxes.tracker);
  REQUIRE(tracker.wants_start_nodes());
  tracker.start(0.0);
  REQUIRE(tracker.history().size() == 1);
  // the pilot's radii: a horizon moving smoothly, not as a cubic, at the finest box's step
  auto h_of = [](double t) { return 0.85 + 0.05 * std::sin(2.0 * t) + 0.02 * std::exp(-t); };
  const double dt = 0.125;
  const std::size_t n = 13;
  std::vector<std::array<double, 2>> nodes;
  for (std::size_t k = 0; k < n; ++k)
    nodes.push_back({static_cast<double>(k) * dt, h_of(static_cast<double>(k) * dt)});
  tracker.seed_start(nodes);
  double worst_node = 0.0, worst_h = 0.0, worst_t = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k)
    for (const double s : {0.0, 0.1, 0.37, 0.5, 0.81}) {
      const double t = (static_cast<double>(k) + s) * dt;
      const auto h = tracker.radius(t);
      REQUIRE(h);
      // nodes k - 1 ... k + 2 around t in [t_k, t_k+1), clamped to the first or last four
      const std::size_t first = std::min(k > 0 ? k - 1 : 0, n - 4);
      const double centred = lagrange({nodes.begin() + static_cast<std::ptrdiff_t>(first),
                                       nodes.begin() + static_cast<std::ptrdiff_t>(first + 4)},
                                      t);
      if (std::abs(*h - centred) > worst_node) {
        worst_node = std::abs(*h - centred);
        worst_t = t;
      }
      worst_h = std::max(worst_h, std::abs(*h - h_of(t)));
    }
  INFO("largest difference from the centred cubic " << worst_node << " (t = " << worst_t
                                                    << "), from h(t) " << worst_h);
  CHECK(worst_node <= 4e-16);
  CHECK(worst_h <= 1.25 * 4.6e-6);
}

// --ah-interval T (horizon_tracker.cpp, HeldRadius::search_due): a search after the first step at
// or past each multiple of T, whatever the step, so that every member of a study holds h_AH for the
// same time. Guards the multiple's round-off (3 x (1/3) must reach 1) and that the hold is counted
// in time, not in steps.
TEST_CASE("--ah-interval: h_AH is searched for after the first step at or past each multiple "
          "of T and held in between, for any step") {
  Params p = small_trumpet_params(64, 8.0);
  p.rahA = 0.5;
  p.rah0 = 1.0;
  p.ah_interval = 1.0;
  const Simulation sim = simulation(p);
  std::vector<State> levels = sim.level_states();
  std::vector<GbssnRhs> rhs;
  rhs.emplace_back(sim.layout().grid(0), sim.config().rhs);
  auto set_mass = [&](double t) {
    InitialDataParams id;
    id.kind = InitialDataKind::onelog_trumpet;
    id.M = 1.0 + 0.05 * t;
    levels[0] = initial_data(sim.layout().grid(0), id, Formulation::bssn);
  };
  struct Case {
    double dt;
    std::vector<long> searched; // the steps after which a search is due
  };
  for (const Case& c : {Case{1.0 / 3.0, {3, 6, 9}}, Case{0.3, {4, 7, 10}}, Case{0.25, {4, 8, 12}},
                        Case{1.5, {1, 2, 3, 4}}}) {
    INFO("dt = " << c.dt);
    const auto made = make_horizon_tracker(sim.config(), sim.layout(), levels, rhs);
    HorizonTracker& tracker = *made;
    REQUIRE(tracker.mode() == HorizonTracker::Mode::held);
    set_mass(0.0);
    tracker.start(0.0);
    REQUIRE(rhs[0].horizon_radius());
    std::vector<long> searched;
    const long steps = c.dt > 1.0 ? 4 : static_cast<long>(std::lround(3.0 / c.dt));
    for (long n = 1; n <= steps; ++n) {
      const double before = *rhs[0].horizon_radius();
      set_mass(static_cast<double>(n) * c.dt);
      tracker.after_step(n, static_cast<double>(n - 1) * c.dt, static_cast<double>(n) * c.dt);
      if (*rhs[0].horizon_radius() != before)
        searched.push_back(n);
    }
    CHECK(searched == c.searched);
  }
}

// Guards the midstep-update schedule (horizon_tracker.cpp, HeldRadius): its search is on the
// 2nd RK substage (evaluation 4k + 1) of every n-th step, and no other evaluation searches
// (with 4k + 2, the 3rd substage, no test failed in an independent mutation round).
TEST_CASE("--rah-variant midstep-update searches on the 2nd RK substage of every n-th step only") {
  for (const int every : {1, 2}) {
    CAPTURE(every);
    Params p = small_trumpet_params(64, 16.0);
    p.rahA = 0.5;
    p.rah0 = 1.0;
    p.ah_every = AhEvery::parse(std::to_string(every));
    p.rah_variant = ShiftVariant::midstep_update;
    const Simulation sim = simulation(p);
    std::vector<State> levels = sim.level_states();
    std::vector<GbssnRhs> rhs{GbssnRhs(sim.grid(), sim.config().rhs)};
    const auto made = make_horizon_tracker(sim.config(), sim.layout(), levels, rhs);
    HorizonTracker& tracker = *made;
    REQUIRE(tracker.mode() == HorizonTracker::Mode::held);
    const double held = 0.123; // no horizon lies there: a search finds the data's, r = 0.83
    const double r_AH = sim.horizons().horizon()->r;
    for (std::uint64_t evaluation = 0; evaluation < 20; ++evaluation) {
      CAPTURE(evaluation);
      const auto h = tracker.at_evaluation(0, levels[0], sim.grid(), 0.0, evaluation, held);
      REQUIRE(h.has_value());
      const bool searches = evaluation % static_cast<std::uint64_t>(4 * every) == 1;
      CHECK(*h == (searches ? doctest::Approx(r_AH).epsilon(1e-6) : doctest::Approx(held)));
    }
  }
}
