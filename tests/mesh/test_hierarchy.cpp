// Box-in-box refinement (mesh/hierarchy.hpp) against independent facts: polynomials that the
// prolongation and restriction stencils must reproduce exactly, Boost.Odeint's RK4 step that a
// one-level hierarchy must reproduce bit for bit, and a gauge pulse crossing two refinement
// boundaries whose difference to a single grid at the finest spacing must converge away at the
// design order.
#include "gbssn/rhs.hpp"
#include "grid/interpolation.hpp"
#include "initial_data/initial_data.hpp"
#include "mesh/hierarchy.hpp"

#include "../test_support.hpp"

#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace gbssn1d;
using gbssn1d::testing::fit_order;

namespace {

/// Every variable of a state from f(r) at every point (ghosts included): the polynomials below
/// have each variable's parity, so the origin ghosts hold the parity images.
State polynomial_state(const Grid& g, const std::function<double(double, int)>& p) {
  State u = make_state(g);
  for (const auto& e : registry)
    for (std::size_t i = 0; i < g.n_total(); ++i)
      field(u, g, e.var)[i] = p(g.r()[i], e.parity);
  return u;
}

/// Degree-d polynomial of parity `parity` (even: 1 + r^2 + ..., odd: r + r^3 + ...).
double poly(double r, int parity, int degree) {
  double sum = 0.0;
  for (int k = parity > 0 ? 0 : 1; k <= degree; k += 2)
    sum += std::pow(r / 4.0, k) * (1.0 + 0.1 * k);
  return sum;
}

} // namespace

TEST_CASE("prolongation reproduces polynomials up to degree 5 of either parity, also at r = 0") {
  for (int degree : {0, 1, 2, 3, 4, 5}) {
    const HierarchySpec spec{.levels = 2, .N = 32, .rmax = 16.0};
    const auto grids = make_levels(spec);
    auto p = [&](double r, int parity) { return poly(r, parity, degree); };
    const State coarse = polynomial_state(grids[0], p);
    State fine = make_state(grids[1]);
    prolongate(grids[0], coarse, grids[1], fine, Grid::n_ghost, grids[1].n_total());
    double err = 0.0;
    for (const auto& e : registry)
      for (std::size_t i = Grid::n_ghost; i < grids[1].n_total(); ++i)
        err =
            std::max(err, std::abs(field(fine, grids[1], e.var)[i] - p(grids[1].r()[i], e.parity)));
    INFO("degree " << degree);
    CHECK(err < 1e-13);
  }
  // degree 6: the error falls as the 6th power of the coarse spacing
  std::vector<double> h, err;
  for (std::size_t N : {32, 64, 128}) {
    const auto grids = make_levels({.levels = 2, .N = N, .rmax = 16.0});
    auto p = [](double r, int) { return std::pow(r / 4.0, 6); };
    const State coarse = polynomial_state(grids[0], p);
    State fine = make_state(grids[1]);
    prolongate(grids[0], coarse, grids[1], fine, Grid::n_ghost, grids[1].n_total());
    double e = 0.0;
    for (std::size_t i = Grid::n_ghost; i < grids[1].n_total(); ++i)
      e = std::max(e, std::abs(field(fine, grids[1], Var::alpha)[i] - p(grids[1].r()[i], 1)));
    h.push_back(grids[0].dx());
    err.push_back(e);
  }
  CHECK(fit_order(h, err) == doctest::Approx(6.0).epsilon(0.02));
}

TEST_CASE("restriction reproduces polynomials up to degree 5 at the coarse centres") {
  for (int degree : {0, 1, 2, 3, 4, 5}) {
    const auto grids = make_levels({.levels = 2, .N = 40, .rmax = 16.0});
    auto p = [&](double r, int parity) { return poly(r, parity, degree); };
    const State fine = polynomial_state(grids[1], p);
    State coarse = make_state(grids[0]);
    restrict_to_coarse(grids[1], fine, grids[0], coarse);
    const std::size_t cells = restricted_cells(40);
    REQUIRE(cells == 14); // 2j + 3 <= 40 - 9 - 1
    double err = 0.0;
    for (const auto& e : registry)
      for (std::size_t j = 0; j < cells + Grid::n_ghost; ++j) // origin ghosts by parity too
        err = std::max(err,
                       std::abs(field(coarse, grids[0], e.var)[j] - p(grids[0].r()[j], e.parity)));
    INFO("degree " << degree);
    CHECK(err < 1e-13);
    // and nothing beyond the fine level's exact region is touched
    CHECK(field(coarse, grids[0], Var::alpha)[Grid::n_ghost + cells] == 0.0);
  }
}

TEST_CASE("levels: odd N and too few cells for the buffer are refused") {
  CHECK_THROWS_AS(make_levels({.levels = 2, .N = 33, .rmax = 16.0}), std::invalid_argument);
  CHECK_THROWS_AS(make_levels({.levels = 2, .N = 12, .rmax = 16.0}), std::invalid_argument);
  CHECK_NOTHROW(make_levels({.levels = 1, .N = 33, .rmax = 16.0}));
  const auto grids = make_levels({.levels = 3, .N = 16, .rmax = 16.0});
  CHECK(grids[2].r()[grids[2].end_interior() - 1] == doctest::Approx(4.0 - 0.125));
}

namespace {

/// Flat space with a lapse pulse (even in r) of amplitude 0.01 at r0 = 5, width 1.
State pulse(const Grid& g) {
  State u = make_state(g);
  for (std::size_t i = 0; i < g.n_total(); ++i) {
    const double r = g.r()[i];
    for (Var v : {Var::chi, Var::a, Var::b})
      field(u, g, v)[i] = 1.0;
    field(u, g, Var::alpha)[i] =
        1.0 + 0.01 * (std::exp(-(r - 5.0) * (r - 5.0)) + std::exp(-(r + 5.0) * (r + 5.0)));
  }
  return u;
}

} // namespace

TEST_CASE("a one-level hierarchy steps exactly as Boost.Odeint's RK4 on the single grid") {
  const HierarchySpec spec{.levels = 1, .N = 200, .rmax = 20.0};
  const Grid grid = make_levels(spec)[0];
  GbssnRhs rhs(grid, RhsParams{});
  BergerOliger bo(spec, 0.25, {pulse(grid)}, {std::ref(rhs)});
  GbssnRhs rhs_single(grid, RhsParams{});
  State u = pulse(grid), dudt;
  boost::numeric::odeint::runge_kutta4<State> rk4;
  const double dt = 0.25 * grid.min_spacing();
  double t = 0.0;
  for (int n = 0; n < 20; ++n) {
    rhs_single(u, dudt, t);
    rk4.do_step(std::ref(rhs_single), u, dudt, t, dt);
    t += dt;
    bo.step();
  }
  CHECK(bo.state(0) == u); // bit for bit
  CHECK(bo.time() == doctest::Approx(t));
  CHECK(bo.evaluations(0) == 80);
}

namespace {

/// RMS over output times (every 0.5 up to t_end) of alpha(hierarchy) - alpha(single grid at
/// the finest spacing), sampled on the coarsest level's cells with r in [0.5, 20], each from
/// the finest level that holds it exactly.
double pulse_difference(std::size_t N, TimeInterpolation time, bool subcycling, double t_end) {
  const HierarchySpec spec{
      .levels = 3, .N = N, .rmax = 32.0, .subcycling = subcycling, .time_interpolation = time};
  const auto grids = make_levels(spec);
  std::vector<GbssnRhs> rhs;
  std::vector<State> u;
  for (const auto& g : grids) {
    rhs.emplace_back(g, RhsParams{});
    u.push_back(pulse(g));
  }
  std::vector<LevelRhs> level_rhs;
  for (auto& r : rhs)
    level_rhs.push_back(std::ref(r));
  BergerOliger bo(spec, 0.25, u, level_rhs);

  const Grid single(RadialMap::uniform(32.0), 4 * N);
  GbssnRhs rhs_single(single, RhsParams{});
  State v = pulse(single), dvdt;
  boost::numeric::odeint::runge_kutta4<State> rk4;
  const double dt_fine = bo.dt(2);
  double t = 0.0, sum = 0.0;
  int samples = 0;
  const auto steps_per_coarse = static_cast<int>(std::lround(bo.dt(0) / dt_fine));
  while (bo.time() < t_end - 1e-9) {
    bo.step();
    for (int s = 0; s < steps_per_coarse; ++s) {
      rhs_single(v, dvdt, t);
      rk4.do_step(std::ref(rhs_single), v, dvdt, t, dt_fine);
      t += dt_fine;
    }
    if (std::abs(bo.time() / 0.5 - std::round(bo.time() / 0.5)) > 1e-9)
      continue;
    const auto alpha_single = field(std::as_const(v), single, Var::alpha);
    for (std::size_t j = grids[0].first_interior(); j < grids[0].end_interior(); ++j) {
      const double r = grids[0].r()[j];
      if (r < 0.5 || r > 20.0)
        continue;
      std::size_t l = 0; // the finest level whose exact region holds r
      for (std::size_t k = 1; k < grids.size(); ++k)
        if (r < grids[k].r()[grids[k].end_interior() - buffer_cells])
          l = k;
      const double a = interpolate_at_radius(grids[l], field(bo.state(l), grids[l], Var::alpha), r);
      const double d = a - interpolate_at_radius(single, alpha_single, r);
      sum += d * d;
      ++samples;
    }
  }
  // the coarse levels hold the restriction of the finer ones where those are exact
  for (std::size_t l = 0; l + 1 < grids.size(); ++l)
    for (std::size_t j = 0; j < restricted_cells(N); ++j) {
      const double r = grids[l].r()[Grid::n_ghost + j];
      CHECK(
          field(bo.state(l), grids[l], Var::alpha)[Grid::n_ghost + j]
          == doctest::Approx(interpolate_at_radius(
                                 grids[l + 1], field(bo.state(l + 1), grids[l + 1], Var::alpha), r))
                 .epsilon(1e-13));
    }
  return std::sqrt(sum / samples);
}

} // namespace

TEST_CASE("a gauge pulse crossing two refinement boundaries converges to the single fine grid") {
  // the pulse (speed sqrt(2)) leaves level 2 (r < 8) at t ~ 2 and level 1 (r < 16) at t ~ 8
  std::vector<double> h{1.0, 0.5, 0.25};
  struct Case {
    const char* name;
    TimeInterpolation time;
    bool subcycling;
    double min_order;
  };
  for (const Case& c : {Case{"dense, subcycling", TimeInterpolation::dense, true, 3.5},
                        Case{"quadratic, subcycling", TimeInterpolation::quadratic, true, 1.8},
                        Case{"no subcycling", TimeInterpolation::dense, false, 3.5}}) {
    std::vector<double> err;
    for (std::size_t N : {32, 64, 128})
      err.push_back(pulse_difference(N, c.time, c.subcycling, 12.0));
    const double p = fit_order(h, err);
    MESSAGE(std::string(c.name) << ": RMS difference " << err[0] << ", " << err[1] << ", " << err[2]
                                << "; order " << p);
    CHECK(p >= c.min_order);
  }
}

// The stationary 1+log trumpet (equations document, Sec. 13) on four nested boxes: every
// change of the fields is truncation error, so the RMS over t = 1 ... 10 M of the change in
// r in [1, 10] M (across the refinement boundaries at 4 and 8 M, each r from the finest level
// holding it exactly) must fall at 4th order.
TEST_CASE("the 1+log trumpet on boxes stays stationary at 4th order through refinement "
          "boundaries") {
  InitialDataParams id;
  id.kind = InitialDataKind::onelog_trumpet;
  std::vector<double> h, change;
  for (std::size_t N : {64, 96, 128}) { // finest spacing M/16, M/24, M/32
    const HierarchySpec spec{.levels = 4, .N = N, .rmax = 32.0};
    const auto grids = make_levels(spec);
    std::vector<GbssnRhs> rhs;
    std::vector<State> u;
    for (const auto& g : grids) {
      rhs.emplace_back(g, RhsParams{});
      u.push_back(initial_data(g, id));
    }
    const std::vector<State> initial = u;
    std::vector<LevelRhs> level_rhs;
    for (auto& r : rhs)
      level_rhs.push_back(std::ref(r));
    BergerOliger bo(spec, 0.25, u, level_rhs);
    double sum = 0.0;
    int samples = 0;
    while (bo.time() < 10.0 - 1e-9) {
      bo.step();
      if (std::abs(bo.time() - std::round(bo.time())) > 1e-9)
        continue;
      for (std::size_t l = 0; l < grids.size(); ++l) {
        const Grid& g = grids[l];
        const double inner = l + 1 < grids.size()
                                 ? grids[l + 1].r()[grids[l + 1].end_interior() - buffer_cells]
                                 : 0.0;
        for (std::size_t i = g.first_interior(); i < g.end_interior() - buffer_cells; ++i) {
          const double r = g.r()[i];
          if (r < std::max(1.0, inner) || r > 10.0)
            continue;
          for (Var v : {Var::alpha, Var::chi, Var::K}) {
            const double d = field(bo.state(l), g, v)[i] - field(initial[l], g, v)[i];
            sum += d * d;
            ++samples;
          }
        }
      }
    }
    h.push_back(grids.back().dx());
    change.push_back(std::sqrt(sum / samples));
  }
  const double p = fit_order(h, change);
  MESSAGE("trumpet on 4 boxes, RMS change over t = 1 ... 10 M: "
          << change[0] << ", " << change[1] << ", " << change[2] << "; order " << p);
  CHECK(p >= 3.5);
}
