// Diagnostics: the central extrapolation of an even field, the cell-width-weighted L2 norms,
// and horizon.dat as a run writes it.
#include "config/params.hpp"
#include "diagnostics/constraints.hpp"
#include "evolution/simulation.hpp"
#include "initial_data/initial_data.hpp"

#include "../test_support.hpp"

#include "../simulation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

using namespace gbssn1d;
using gbssn1d::testing::simulation;
using gbssn1d::testing::small_trumpet_params;

TEST_CASE("central_value is exact for even quadratics, on uniform and sinh grids") {
  for (const Grid& g :
       {Grid(RadialMap::uniform(10.0), 100), Grid(RadialMap::sinh(100.0, 0.02, 400), 400)}) {
    std::vector<double> f(g.n_total());
    for (std::size_t i = 0; i < f.size(); ++i)
      f[i] = 0.3 - 1.7 * g.r()[i] * g.r()[i];
    CHECK(central_value(f, g) == doctest::Approx(0.3).epsilon(1e-13));
    // a quartic term is not captured: even extrapolation from r1, r2 of r^4 gives exactly
    // -r1^2 r2^2, an error of 2nd order in the spacing
    for (std::size_t i = 0; i < f.size(); ++i)
      f[i] += std::pow(g.r()[i], 4);
    const double r1 = g.r()[g.first_interior()], r2 = g.r()[g.first_interior() + 1];
    CHECK(central_value(f, g) == doctest::Approx(0.3 - r1 * r1 * r2 * r2).epsilon(1e-13));
    CHECK(r1 * r1 * r2 * r2 > 1e-12); // the check above would not see a wrong formula otherwise
  }
}

TEST_CASE("l2_norm: cell-width weights, the range selects points, an empty range gives NaN") {
  const Grid g(RadialMap::sinh(50.0, 0.05, 200), 200);
  std::vector<double> ones(g.n_interior(), 2.0);
  CHECK(l2_norm(ones, g, 0.0, 1e9) == doctest::Approx(2.0).epsilon(1e-14));
  // f = r: the weighted mean of r^2 over [a, b] approximates (b^3 - a^3) / (3 (b - a))
  std::vector<double> r(g.n_interior());
  for (std::size_t k = 0; k < r.size(); ++k)
    r[k] = g.r()[g.first_interior() + k];
  const double expected = std::sqrt((std::pow(10.0, 3) - 1.0) / (3.0 * 9.0));
  CHECK(l2_norm(r, g, 1.0, 10.0) == doctest::Approx(expected).epsilon(2e-3));
  // no point in the range: no value (NaN), never a vanishing norm
  CHECK(std::isnan(l2_norm(r, g, 60.0, 70.0)));
  const double r0 = g.r()[g.first_interior() + 10], r1 = g.r()[g.first_interior() + 11];
  CHECK(std::isnan(l2_norm(r, g, 0.4 * r0 + 0.6 * r1, 0.3 * r0 + 0.7 * r1))); // between two cells
  CHECK(l2_norm(r, g, r0, r0) == r0);                                         // one point
}

TEST_CASE("the areal and interior norms of an empty window are NaN, not 0") {
  const Grid g(RadialMap::uniform(10.0), 100);
  std::vector<double> R(g.n_interior()), f(g.n_interior(), 3.0);
  for (std::size_t k = 0; k < R.size(); ++k)
    R[k] = 1.5 + g.r()[g.first_interior() + k]; // a trumpet-like sheet: R from 1.55 to 11.45
  CHECK(l2_norm_areal(f, R, 2.0, 5.0) == doctest::Approx(3.0));
  CHECK(std::isnan(l2_norm_areal(f, R, 50.0, 60.0)));   // beyond the grid
  CHECK(std::isnan(l2_norm_areal(f, R, 0.5, 1.0)));     // inside the innermost point
  CHECK(std::isnan(l2_norm_areal(f, R, 2.001, 2.002))); // between two points
  CHECK(l2_norm_interior(f, R, g, 1.8) == doctest::Approx(3.0));
  CHECK(std::isnan(l2_norm_interior(f, R, g, 1.0))); // the innermost point already has R > 1
}

TEST_CASE("the areal norm weights an end cell by its one-sided dR, an interior cell by half "
          "its neighbours' distance") {
  // R = 1 ... 5, uniform: every cell's |dR| is 1, the first and last one-sided (R_1 - R_0,
  // R_4 - R_3), the others centred ((R_{k+1} - R_{k-1}) / 2). By hand: sqrt((9 + 4 * 1) / 5).
  const std::vector<double> R{1.0, 2.0, 3.0, 4.0, 5.0};
  const std::vector<double> f{3.0, 1.0, 1.0, 1.0, 1.0};
  CHECK(l2_norm_areal(f, R, 1.0, 5.0) == doctest::Approx(std::sqrt(13.0 / 5.0)).epsilon(1e-15));
  // the outer end: sqrt((1 + 1 + 9) / 3) over R = 3, 4, 5
  const std::vector<double> g{1.0, 1.0, 1.0, 1.0, 3.0};
  CHECK(l2_norm_areal(g, R, 3.0, 5.0) == doctest::Approx(std::sqrt(11.0 / 3.0)).epsilon(1e-15));
  // non-uniform: R = 1, 2, 4, 8; weights 1, 1.5, 3, 4; f^2 = 1, 4, 9, 16
  const std::vector<double> Rn{1.0, 2.0, 4.0, 8.0}, fn{1.0, 2.0, 3.0, 4.0};
  CHECK(l2_norm_areal(fn, Rn, 0.5, 9.0)
        == doctest::Approx(std::sqrt((1.0 + 4.0 * 1.5 + 9.0 * 3.0 + 16.0 * 4.0) / 9.5))
               .epsilon(1e-15));
}

TEST_CASE("horizon.dat: the named columns, the horizon of the data, n_roots") {
  namespace fs = std::filesystem;
  const fs::path dir = gbssn1d::testing::scratch("horizon_dat", true);
  Params p = small_trumpet_params(400, 20.0);
  p.tmax = 1.0;
  p.dt_series = 0.5;
  Simulation sim = simulation(p);
  {
    Output out(dir, "test = true\n", Formulation::bssn, {});
    sim.run(&out);
  }
  const auto h = gbssn1d::testing::read_table((dir / "horizon.dat").string());
  CHECK(h.columns == horizon_columns());
  REQUIRE(h.rows.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(h.at(k, "r_ah") == doctest::Approx(0.8304).epsilon(1e-3));
    CHECK(h.at(k, "M_ah") == doctest::Approx(1.0).epsilon(1e-5));
    CHECK(h.at(k, "M_ah") == doctest::Approx(h.at(k, "R_ah") / 2).epsilon(1e-15));
    CHECK(h.at(k, "n_roots") == 1.0);
    CHECK(std::isnan(h.at(k, "r_root2")));
  }
  const auto s = gbssn1d::testing::read_table((dir / "timeseries.dat").string());
  CHECK(s.at(2, "r_ah") == h.at(2, "r_ah"));
  fs::remove_all(dir);
}

// (T4) The Misner-Sharp mass is the mass inside each sphere: M at every point of every slice of
// Schwarzschild, whatever the coordinates (wormhole data's two sheets, both trumpets), so its
// error on exact data is the finite differences' alone and falls at their order. A Gaussian
// bump added to K (a slice no longer of Schwarzschild, momentarily) moves it where the bump is.
TEST_CASE("profiles' m_ms: M at every point of Schwarzschild slices, at the differences' order") {
  for (const InitialDataKind kind : {InitialDataKind::wormhole, InitialDataKind::onelog_trumpet,
                                     InitialDataKind::maximal_trumpet}) {
    InitialDataParams id;
    id.kind = kind;
    id.M = 1.5;
    INFO("initial data " << static_cast<int>(kind));
    std::vector<double> worst;
    for (const int N : {200, 400, 800}) {
      const Grid g(RadialMap::uniform(20.0), N);
      const State u = initial_data(g, id, Formulation::bssn);
      const DerivedProfiles d = derived_profiles(u, g);
      double e = 0.0; // over 0.5 M <= r <= 10 M: away from the puncture's stencils and the edge
      for (std::size_t k = 0; k < d.m_ms.size(); ++k) {
        const double r = g.r()[g.first_interior() + k];
        if (r >= 0.5 * id.M && r <= 10.0 * id.M)
          e = std::max(e, std::abs(d.m_ms[k] - id.M));
      }
      worst.push_back(e);
    }
    INFO("max |m_ms - M| at N = 200, 400, 800: " << worst[0] << ", " << worst[1] << ", "
                                                 << worst[2]);
    CHECK(worst[0] < 1e-4);
    CHECK(std::log2(worst[0] / worst[1]) > 3.5);
    CHECK(std::log2(worst[1] / worst[2]) > 3.5);
  }
  const Grid g(RadialMap::uniform(20.0), 400);
  InitialDataParams id;
  id.kind = InitialDataKind::onelog_trumpet;
  State u = initial_data(g, id, Formulation::bssn);
  auto K = field(u, g, Var::K);
  for (std::size_t i = 0; i < g.n_total(); ++i)
    K[i] += 0.1 * std::exp(-(g.r()[i] - 5.0) * (g.r()[i] - 5.0));
  const DerivedProfiles d = derived_profiles(u, g);
  double at5 = 0.0, at15 = 0.0;
  for (std::size_t k = 0; k < d.m_ms.size(); ++k) {
    const double r = g.r()[g.first_interior() + k];
    if (std::abs(r - 5.0) < 0.03)
      at5 = d.m_ms[k] - 1.0;
    if (std::abs(r - 15.0) < 0.03)
      at15 = d.m_ms[k] - 1.0;
  }
  CHECK(std::abs(at5) > 1e-2);
  CHECK(std::abs(at15) < 1e-6);
}
