// The apparent-horizon finder on the three initial data sets: M_AH -> M at 4th order or better,
// |M_AH - M| < 1e-6 at spacing M/64, and the coordinate radius where the data put it.
#include "config/params.hpp"
#include "evolution/observe.hpp"
#include "evolution/simulation.hpp"
#include "horizon/apparent_horizon.hpp"

#include "../test_support.hpp"

#include "../simulation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace gbssn1d;
using gbssn1d::testing::fit_order;
using gbssn1d::testing::simulation;

namespace {

Params grid_params(const char* id, int n) {
  Params p;
  p.id = InitialDataChoice::parse(id);
  p.grid = RadialGrid::uniform;
  p.N = n;
  p.rmax = 10.0;
  p.tmax = 0.0;
  return p;
}

/// Closed-form isotropic radius of the Baumgarte-Naculich trumpet (Sec. 9.5), M = 1.
double bn_isotropic_radius(double R) {
  const double M = 1.0;
  const double s2 = std::sqrt(2.0);
  return (2 * R + M + std::sqrt(4 * R * R + 4 * M * R + 3 * M * M)) / 4
         * std::pow((4 + 3 * s2) * (2 * R - 3 * M)
                        / (8 * R + 6 * M + 3 * std::sqrt(8 * R * R + 8 * M * R + 6 * M * M)),
                    1 / s2);
}

} // namespace

TEST_CASE("apparent horizon of the three initial data: M_AH converges to M at order >= 4") {
  for (const char* id : {"wormhole", "maximal-trumpet", "1log-trumpet"}) {
    std::vector<double> h, err;
    double r_ah_finest = 0;
    for (int n : {160, 320, 640}) { // spacing M/16 ... M/64
      const Simulation sim = simulation(grid_params(id, n));
      const auto found = find_horizons(sim.state(), sim.grid(), {});
      REQUIRE(found.horizon().has_value());
      h.push_back(sim.grid().dx());
      err.push_back(std::abs(found.horizon()->mass - 1.0));
      r_ah_finest = found.horizon()->r;
    }
    const double p = fit_order(h, err);
    MESSAGE(std::string(id) << ": |M_AH - M| = " << err[0] << ", " << err[1] << ", " << err[2]
                            << "; fitted order " << p << "; r_AH = " << r_ah_finest);
    CHECK(p >= 3.6);
    CHECK(err.back() < 1e-6); // spacing M/64
    if (std::string(id) == "wormhole")
      CHECK(std::abs(r_ah_finest - 0.5) < 1e-6);
    if (std::string(id) == "maximal-trumpet")
      CHECK(std::abs(r_ah_finest - bn_isotropic_radius(2.0)) < 1e-6);
  }
}

TEST_CASE("the finder reports every marginal surface, the outermost outer one as the horizon") {
  // Static isotropic Schwarzschild with the static lapse has a single minimal surface at M/2.
  const Simulation sim = simulation(grid_params("wormhole", 200));
  const auto found = find_horizons(sim.state(), sim.grid(), {});
  REQUIRE(found.surfaces.size() == 1);
  CHECK(found.surfaces[0].outer);
  // Flat space has no horizon.
  const Grid g(RadialMap::uniform(10.0), 100);
  State flat = make_state(g, Formulation::bssn);
  for (Var v : {Var::alpha, Var::chi, Var::a, Var::b})
    for (double& f : field(flat, g, v))
      f = 1.0;
  CHECK_FALSE(find_horizons(flat, g, {}).horizon().has_value());
  CHECK(find_horizons(flat, g, {}).surfaces.empty());
}

// Time-symmetric data (K = A_a = 0, flat conformal metric) whose areal radius R(r) = psi^2 r
// has two minima and a maximum between: Theta_+ is proportional to dR/dr, so the marginal
// surfaces are the zeros of R'(r) = 1 - M^2/(4 r^2) - B exp(-((r - r1)/s)^2), found here by
// bisection of that closed form; the minima are outer trapping boundaries and the apparent
// horizon is the outermost of them, not the one at M/2.
TEST_CASE("with several marginal surfaces the horizon is the outermost outer one") {
  const double M = 1.0, B = 2.0, r1 = 3.0, s = 0.5;
  auto R = [&](double r) {
    return r + M + M * M / (4 * r) - B * s * std::sqrt(M_PI) / 2 * (std::erf((r - r1) / s) + 1);
  };
  auto dR = [&](double r) {
    return 1 - M * M / (4 * r * r) - B * std::exp(-((r - r1) / s) * ((r - r1) / s));
  };
  auto root = [&](double lo, double hi) {
    for (int k = 0; k < 200; ++k) {
      const double mid = 0.5 * (lo + hi);
      (dR(lo) * dR(mid) <= 0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const double inner = root(0.3, 1.0), middle = root(1.5, 3.0), outer = root(3.0, 4.5);
  REQUIRE(dR(0.3) < 0);
  REQUIRE(dR(1.5) > 0);
  REQUIRE(dR(3.0) < 0);
  REQUIRE(dR(4.5) > 0);
  const Grid g(RadialMap::uniform(10.0), 800);
  State u = make_state(g, Formulation::bssn);
  for (std::size_t i = g.first_interior(); i < g.n_total(); ++i) {
    const double r = g.r()[i], psi2 = R(r) / r;
    field(u, g, Var::chi)[i] = 1.0 / (psi2 * psi2); // chi = psi^-4
    for (Var v : {Var::alpha, Var::a, Var::b})
      field(u, g, v)[i] = 1.0;
  }
  fill_origin_ghosts(u, g);
  const auto found = find_horizons(u, g, {});
  REQUIRE(found.surfaces.size() == 3);
  CHECK(found.surfaces[0].r == doctest::Approx(outer).epsilon(1e-7));
  CHECK(found.surfaces[1].r == doctest::Approx(middle).epsilon(1e-7));
  CHECK(found.surfaces[2].r == doctest::Approx(inner).epsilon(1e-7));
  CHECK(found.surfaces[0].outer);
  CHECK_FALSE(found.surfaces[1].outer);
  CHECK(found.surfaces[2].outer);
  REQUIRE(found.horizon().has_value());
  CHECK(found.horizon()->r == doctest::Approx(outer).epsilon(1e-7));
  CHECK(found.horizon()->mass == doctest::Approx(R(outer) / 2).epsilon(1e-7));
  // the search near a seed, with and without the areal radius: from the middle surface (no
  // outer one in its window) and from outside every window, the whole grid's outermost
  for (const double seed : {middle, 8.0})
    for (const bool areal_radius : {true, false}) {
      const auto near = find_horizon_near(u, g, {}, seed, 8, areal_radius);
      REQUIRE(near.has_value());
      CHECK(near->r == found.horizon()->r);
    }
}

// The finder scans down to the first interior cell: at N = 96 over 16 M (spacing M/6) the
// wormhole's throat, r = M/2, lies between the third and fourth cells (r = 0.417 and 0.583),
// inside the three innermost cells the finder once skipped. Theta_+ there is differenced through
// the origin's parity ghosts as the evolution differences it; the root agrees with a fine grid's.
TEST_CASE("the finder reaches the first cells: the wormhole's throat at N = 96 over 16 M") {
  Params p = grid_params("wormhole", 96);
  p.rmax = 16.0;
  const Simulation coarse = simulation(p);
  const double dr = coarse.grid().dr()[coarse.grid().first_interior()];
  REQUIRE(coarse.grid().r()[coarse.grid().first_interior() + 2] < 0.5);
  REQUIRE(coarse.grid().r()[coarse.grid().first_interior() + 3] > 0.5);
  const auto found = find_horizons(coarse.state(), coarse.grid(), {});
  REQUIRE(found.horizon().has_value());
  const double r_coarse = found.horizon()->r;
  p.N = 960;
  const Simulation fine = simulation(p);
  const auto fine_found = find_horizons(fine.state(), fine.grid(), {});
  REQUIRE(fine_found.horizon().has_value());
  MESSAGE("r_AH = " << r_coarse << " at M/6, " << fine_found.horizon()->r << " at M/60");
  CHECK(r_coarse > 2.5 * dr);
  CHECK(r_coarse < 3.5 * dr);
  CHECK(std::abs(fine_found.horizon()->r - 0.5) < 1e-6);
  CHECK(std::abs(r_coarse - fine_found.horizon()->r) < 0.1 * dr);
  // the search near a seed reaches them too
  const auto near = find_horizon_near(coarse.state(), coarse.grid(), {}, 0.5);
  REQUIRE(near.has_value());
  CHECK(near->r == r_coarse);
}

TEST_CASE("a horizon in the cell that straddles the scan's inner limit is found: the wormhole's "
          "throat on the edge of the finest box") {
  // uniform M/6: nodes at r = 0.4167 and 0.5833 around the throat at r = M/2; the scan's inner
  // limit between the lower node and the throat (where a coarser level's limit, the extent of
  // the box inside it, can lie) still holds the throat
  Params p = grid_params("wormhole", 96);
  p.rmax = 16.0;
  const Simulation sim = simulation(p);
  const std::size_t i = sim.grid().first_interior();
  REQUIRE(sim.grid().r()[i + 2] < 0.45);
  REQUIRE(sim.grid().r()[i + 3] > 0.55);
  HorizonFinderParams limited;
  limited.r_min = 0.45;
  const auto found = find_horizons(sim.state(), sim.grid(), limited);
  REQUIRE(found.horizon().has_value());
  CHECK(std::abs(found.horizon()->r - 0.5) < 0.02);
  limited.r_min = 0.6; // beyond the cell: no horizon
  CHECK_FALSE(find_horizons(sim.state(), sim.grid(), limited).horizon().has_value());

  // eight boxes to 64 M at N = 32: the finest covers r <= 0.5, so the throat lies on its edge
  // and in the first cell of the next level's search
  Params b = grid_params("wormhole", 32);
  b.grid = RadialGrid::boxes;
  b.rmax = 64.0;
  b.levels = 8;
  const Simulation boxes = simulation(b);
  REQUIRE(boxes.layout().extent(boxes.layout().levels() - 1) == doctest::Approx(0.5));
  const auto on_edge = find_all_horizons(boxes.layout(), boxes.level_states(), {}, 0.0);
  REQUIRE(on_edge.horizon().has_value());
  CHECK(std::abs(on_edge.horizon()->r - 0.5) < 0.02);
}

// The RK substages' search (find_horizon_near without the areal radius) must find the same
// horizon as the full one, bit for bit, from a seed inside its window and from one outside it
// (the whole-grid scan), on uniform and sinh grids; R_areal and mass are NaN, not stale values.
TEST_CASE("the substage search without the areal radius finds the full search's r, bit for bit") {
  for (const char* id : {"wormhole", "maximal-trumpet", "1log-trumpet"})
    for (const char* grid : {"uniform", "sinh"}) {
      Params p = grid_params(id, 240);
      p.grid = GridChoice::parse(grid);
      const Simulation sim = simulation(p);
      const auto full = find_horizons(sim.state(), sim.grid(), {});
      REQUIRE(full.horizon().has_value());
      const double r_AH = full.horizon()->r;
      for (const double seed : {r_AH, r_AH + 0.05, 8.0}) { // 8 M: outside the window
        CAPTURE(id);
        CAPTURE(grid);
        CAPTURE(seed);
        const auto with_R = find_horizon_near(sim.state(), sim.grid(), {}, seed);
        const auto r_only = find_horizon_near(sim.state(), sim.grid(), {}, seed, 8, false);
        REQUIRE(with_R.has_value());
        REQUIRE(r_only.has_value());
        CHECK(with_R->r == r_AH);
        CHECK(r_only->r == r_AH);
        CHECK(r_only->outer);
        CHECK(with_R->R_areal == full.horizon()->R_areal);
        CHECK(std::isnan(r_only->R_areal));
        CHECK(std::isnan(r_only->mass));
      }
    }
}

// Guards the finder's tolerance (apparent_horizon.cpp, scan): --ah-tol is a tolerance in r, and
// the root is bracketed in the grid coordinate x, so the bracket's tolerance is --ah-tol dx/dr.
// Divided by dx/dr instead, it was (dr/dx)^2 times looser: 64 times at the default sinh grid's
// horizon (r_AH off by 4.6e-5 and 5.0e-5 here with --ah-tol 1e-6) and rmax^2 times on a uniform
// grid (x = r/rmax; 2.1e-3 and 2.6e-3 here), while the tolerances of every other test are met by
// the finder's fast convergence alone. The root found with --ah-tol 1e-6 and 1e-8 is compared
// with the root found to 1e-13 on the same data (the same interpolant of Theta_+, whose root is
// what the tolerance bounds). Measured: the same root at both tolerances on these grids, and
// within 0.02 of the tolerance on coarser uniform grids (M/10, M/4).
TEST_CASE("--ah-tol bounds the error of the horizon's radius in r, on the sinh and the uniform "
          "grid") {
  for (const char* id : {"maximal-trumpet", "1log-trumpet"})
    for (const char* grid : {"sinh", "uniform"}) {
      Params p; // the default grid: sinh, N = 400 to 1000 M, innermost cell 0.02 M
      p.id = InitialDataChoice::parse(id);
      p.grid = GridChoice::parse(grid);
      if (p.grid == RadialGrid::uniform) {
        p.rmax = 100.0;
        p.N = 2000; // M/20
      }
      p.tmax = 0.0;
      const Simulation sim = simulation(p);
      HorizonFinderParams finder = sim.config().horizon_search.finder;
      finder.tolerance = 1e-13;
      const auto tight = find_horizons(sim.state(), sim.grid(), finder).horizon();
      REQUIRE(tight.has_value());
      const std::string data = id, kind = grid;
      for (const double tol : {1e-6, 1e-8}) {
        CAPTURE(data);
        CAPTURE(kind);
        CAPTURE(tol);
        finder.tolerance = tol;
        const auto found = find_horizons(sim.state(), sim.grid(), finder).horizon();
        REQUIRE(found.has_value());
        INFO("r_AH = " << found->r << ", to 1e-13: " << tight->r);
        CHECK(std::abs(found->r - tight->r) <= tol);
        const auto near = find_horizon_near(sim.state(), sim.grid(), finder, tight->r, 8, false);
        REQUIRE(near.has_value());
        CHECK(std::abs(near->r - tight->r) <= tol);
      }
    }
}
