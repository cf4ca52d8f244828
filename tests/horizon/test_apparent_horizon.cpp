// The apparent-horizon finder on the three initial data sets: M_AH -> M at 4th order or better,
// |M_AH - M| < 1e-6 at spacing M/64, and the coordinate radius where the data put it.
#include "config/params.hpp"
#include "evolution/simulation.hpp"
#include "horizon/apparent_horizon.hpp"

#include "../test_support.hpp"

#include "../simulation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace gbssn1d;
using gbssn1d::testing::fit_order;
using gbssn1d::testing::simulation;

namespace {

Params grid_params(const char* id, int n) {
  Params p;
  p.id = id;
  p.grid = "uniform";
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
  State flat = make_state(g);
  for (Var v : {Var::alpha, Var::chi, Var::a, Var::b})
    for (double& f : field(flat, g, v))
      f = 1.0;
  CHECK_FALSE(find_horizons(flat, g, {}).horizon().has_value());
  CHECK(find_horizons(flat, g, {}).surfaces.empty());
}
