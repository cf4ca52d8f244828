// The radial grid: cell centres, parity mirrors, the sinh map, and radial derivatives through
// the chain rule (fitted order 4 on uniform and sinh grids).
#include "gbssn/rhs.hpp"
#include "grid/grid.hpp"
#include "grid/interpolation.hpp"

#include "../test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>

using namespace gbssn1d;
using gbssn1d::testing::fit_order;

TEST_CASE("cell-centred uniform grid: no point at r = 0, ghosts mirror the interior") {
  const Grid g(RadialMap::uniform(10.0), 100);
  CHECK(Grid::n_ghost == 5); // the reach of the 8th-order upwind and dissipation stencils
  CHECK(g.n_total() == 110);
  CHECK(g.r()[g.first_interior()] == doctest::Approx(0.05));
  CHECK(g.r()[g.end_interior() - 1] == doctest::Approx(9.95));
  for (std::size_t i = 0; i < Grid::n_ghost; ++i)
    CHECK(g.r()[i] == doctest::Approx(-g.r()[Grid::mirror(i)]));
  CHECK(g.min_spacing() == doctest::Approx(0.1));
}

TEST_CASE("sinh grid: requested innermost spacing, reaches rmax, spacing grows outward") {
  const double rmax = 200.0, dr_inner = 0.01;
  const std::size_t n = 800;
  const Grid g(RadialMap::sinh(rmax, dr_inner, n), n);
  CHECK(g.map().r(1.0) == doctest::Approx(rmax).epsilon(1e-13));
  CHECK(g.map().dr_dx(0.0) * g.dx() == doctest::Approx(dr_inner).epsilon(1e-12));
  for (std::size_t i = g.first_interior() + 1; i < g.end_interior(); ++i)
    CHECK(g.dr()[i] > g.dr()[i - 1]);
  for (std::size_t i = 0; i < Grid::n_ghost; ++i)
    CHECK(g.r()[i] == doctest::Approx(-g.r()[Grid::mirror(i)]).epsilon(1e-14));
  CHECK_THROWS_AS(RadialMap::sinh(1.0, 0.1, 100), std::invalid_argument);
}

namespace {

struct DerivativeErrors {
  double d1, d2, adv;
};

/// Max errors of d_r f, d_r^2 f and the upwinded beta d_r f over r in [0.5, 8] for
/// f = alpha(r) placed on the grid, through the code's own point_data().
DerivativeErrors derivative_errors(const Grid& g, double beta) {
  auto f = [](double r) { return std::exp(-0.1 * r * r) * std::cos(0.8 * r) + 0.05 * r; };
  auto f1 = [](double r) {
    return std::exp(-0.1 * r * r) * (-0.2 * r * std::cos(0.8 * r) - 0.8 * std::sin(0.8 * r)) + 0.05;
  };
  auto f2 = [](double r) {
    const double e = std::exp(-0.1 * r * r), c = std::cos(0.8 * r), s = std::sin(0.8 * r);
    return e * ((0.04 * r * r - 0.2) * c + 0.32 * r * s - 0.64 * c);
  };
  State u = make_state(g, Formulation::bssn);
  auto alpha = field(u, g, Var::alpha);
  auto shift = field(u, g, Var::beta);
  for (std::size_t i = 0; i < g.n_total(); ++i) {
    alpha[i] = f(g.r()[i]);
    shift[i] = beta;
  }
  DerivativeErrors e{0, 0, 0};
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
    const double r = g.r()[i];
    if (r < 0.5 || r > 8.0)
      continue;
    const PointData p = point_data(u, g, i);
    e.d1 = std::max(e.d1, std::abs(p.d[Var::alpha] - f1(r)));
    e.d2 = std::max(e.d2, std::abs(p.dd[Var::alpha] - f2(r)));
    e.adv = std::max(e.adv, std::abs(p.adv[Var::alpha] - beta * f1(r)));
  }
  return e;
}

void check_orders(const std::function<Grid(std::size_t)>& make) {
  std::vector<double> h, e1, e2, eadv_plus, eadv_minus;
  for (std::size_t n : {160, 320, 640, 1280}) {
    const Grid g = make(n);
    h.push_back(g.dx());
    const auto plus = derivative_errors(g, 0.7);
    const auto minus = derivative_errors(g, -0.7);
    e1.push_back(plus.d1);
    e2.push_back(plus.d2);
    eadv_plus.push_back(plus.adv);
    eadv_minus.push_back(minus.adv);
  }
  MESSAGE("derivative orders: d1 " << fit_order(h, e1) << ", d2 " << fit_order(h, e2)
                                   << ", upwind(+) " << fit_order(h, eadv_plus) << ", upwind(-) "
                                   << fit_order(h, eadv_minus));
  CHECK(fit_order(h, e1) == doctest::Approx(4.0).epsilon(0.1));
  CHECK(fit_order(h, e2) == doctest::Approx(4.0).epsilon(0.1));
  CHECK(fit_order(h, eadv_plus) == doctest::Approx(4.0).epsilon(0.1));
  CHECK(fit_order(h, eadv_minus) == doctest::Approx(4.0).epsilon(0.1));
}

} // namespace

TEST_CASE("radial derivatives converge at 4th order on the uniform grid") {
  check_orders([](std::size_t n) { return Grid(RadialMap::uniform(10.0), n); });
}

TEST_CASE("radial derivatives converge at 4th order on the sinh grid (chain rule)") {
  // innermost spacing scales with the resolution, so the map is the same family
  check_orders([](std::size_t n) {
    return Grid(RadialMap::sinh(10.0, 2.0 / static_cast<double>(n), n), n);
  });
}

// Every registry variable gets its own quartic (scaled by 1 + k for the k-th), so that a
// variable gathered from the wrong row, or left out, fails.
TEST_CASE("point_data: derivatives and advection of quartics are exact, for every variable") {
  const Grid g(RadialMap::uniform(4.0), 16);
  State u = make_state(g, Formulation::bssn);
  auto p4 = [](double r) {
    return 1.0 + 0.2 * r - 0.3 * r * r + 0.05 * r * r * r - 0.01 * r * r * r * r;
  };
  auto p4_1 = [](double r) { return 0.2 - 0.6 * r + 0.15 * r * r - 0.04 * r * r * r; };
  auto p4_2 = [](double r) { return -0.6 + 0.3 * r - 0.12 * r * r; };
  auto scale = [](Var v) { return 1.0 + static_cast<double>(index(v)); };
  for (const auto& e : evolved(Formulation::bssn)) {
    auto f = field(u, g, e.var);
    for (std::size_t i = 0; i < g.n_total(); ++i)
      f[i] = scale(e.var) * p4(g.r()[i]);
  }
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
    const double r = g.r()[i];
    const PointData p = point_data(u, g, i);
    CHECK(p.r == r);
    for (const auto& e : evolved(Formulation::bssn)) {
      INFO(e.name << " at r = " << r);
      const double c = scale(e.var);
      CHECK(p.f[e.var] == c * p4(r));
      CHECK(std::abs(p.d[e.var] - c * p4_1(r)) < 1e-12);
      CHECK(std::abs(p.dd[e.var] - c * p4_2(r)) < 1e-12);
      // lopsided 4th-order upwind: exact for quartics, either direction of the shift
      CHECK(std::abs(p.adv[e.var] - p.f[Var::beta] * c * p4_1(r)) < 1e-11);
    }
  }
}

// Issue: the sinh grid of --N alone must refine. The map is fixed at the reference N, so the
// grid of 2N cells has every spacing halved: dr_2N(x) at x and x + dx/2 sums to dr_N at x's cell.
TEST_CASE("sinh grid spec: doubling N halves every spacing (one map for every N)") {
  GridSpec p;
  p.kind = GridKind::sinh;
  p.rmax = 100.0;
  p.dr_inner = 0.02;
  p.N = 300;
  const Grid coarse = make_grid(p);
  p.N = 600;
  const Grid fine = make_grid(p);
  CHECK(coarse.map().stretch() == fine.map().stretch());
  // the innermost cell at N = 400 is --dr-inner wide
  p.N = sinh_reference_N;
  CHECK(make_grid(p).map().dr_dx(0.0) * make_grid(p).dx() == doctest::Approx(0.02).epsilon(1e-12));
  // each coarse cell is the union of two fine cells: widths add up exactly in x, and the
  // cell-centre spacings of the fine grid are half the coarse one's to O(dx^2)
  for (std::size_t i = 0; i < coarse.n_interior(); ++i) {
    const std::size_t ic = coarse.first_interior() + i, jf = fine.first_interior() + 2 * i;
    const double width_coarse = coarse.map().r(coarse.x()[ic] + 0.5 * coarse.dx())
                                - coarse.map().r(coarse.x()[ic] - 0.5 * coarse.dx());
    const double width_fine = fine.map().r(fine.x()[jf + 1] + 0.5 * fine.dx())
                              - fine.map().r(fine.x()[jf] - 0.5 * fine.dx());
    CHECK(width_fine == doctest::Approx(width_coarse).epsilon(1e-12));
    CHECK(fine.dr()[jf] / coarse.dr()[ic] == doctest::Approx(0.5).epsilon(0.01));
  }
  CHECK(fine.min_spacing() / coarse.min_spacing() == doctest::Approx(0.5).epsilon(1e-4));
}

TEST_CASE("the inverse map x(r) in closed form undoes r(x) on both maps") {
  for (const RadialMap& map : {RadialMap::uniform(50.0), RadialMap::sinh(200.0, 0.01, 400)}) {
    for (double x : {1e-6, 0.01, 0.3, 0.77, 1.0})
      CHECK(map.x_of_r(map.r(x)) == doctest::Approx(x).epsilon(1e-14));
    CHECK(map.x_of_r(map.rmax()) == doctest::Approx(1.0).epsilon(1e-15));
  }
}

// grid/interpolation.hpp: 6-point Lagrange is exact for quintics, on any distinct nodes.
TEST_CASE("lagrange6: quintics are reproduced exactly on uneven nodes") {
  const std::vector<double> x{0.1, 0.25, 0.33, 0.6, 0.71, 1.0};
  auto q5 = [](double t) {
    return 0.3 - t + 2.0 * t * t - 0.5 * t * t * t + t * t * t * t - 0.7 * t * t * t * t * t;
  };
  std::vector<double> f;
  for (double t : x)
    f.push_back(q5(t));
  for (double t : {0.1, 0.17, 0.3, 0.5, 0.9, 1.0})
    CHECK(std::abs(lagrange6(x, f, 0, t) - q5(t)) < 1e-13);
  // a sextic is not: the error is the product of (t - x_k) times the leading coefficient
  std::vector<double> g;
  for (double t : x)
    g.push_back(std::pow(t, 6));
  double product = 1.0;
  for (double xk : x)
    product *= 0.5 - xk;
  CHECK(lagrange6(x, g, 0, 0.5) == doctest::Approx(std::pow(0.5, 6) - product).epsilon(1e-12));
}

// Lagrange6Newton: the same interpolant in Newton's form (the horizon finder's root-find)
TEST_CASE("Lagrange6Newton: quintics exactly, and lagrange6's values to round-off") {
  const std::vector<double> x{0.1, 0.25, 0.33, 0.6, 0.71, 1.0};
  auto q5 = [](double t) {
    return 0.3 - t + 2.0 * t * t - 0.5 * t * t * t + t * t * t * t - 0.7 * t * t * t * t * t;
  };
  std::vector<double> f;
  for (double t : x)
    f.push_back(q5(t));
  const Lagrange6Newton newton(x, f, 0);
  for (double t : {0.1, 0.17, 0.3, 0.5, 0.9, 1.0})
    CHECK(std::abs(newton(t) - q5(t)) < 1e-13);
  // at the nodes, the data
  for (std::size_t k = 0; k < x.size(); ++k)
    CHECK(newton(x[k]) == doctest::Approx(f[k]).epsilon(1e-14));
  // on a grid's stencil (uniform x, as the finder's), a non-polynomial: lagrange6's values, from
  // the 7th node of 12
  std::vector<double> xu, g;
  for (int k = 0; k < 12; ++k) {
    xu.push_back(0.5 + 0.01 * k);
    g.push_back(std::exp(-xu.back()) * std::sin(7.0 * xu.back()) - 0.2);
  }
  const Lagrange6Newton on_grid(xu, g, 6);
  for (double t = xu[6]; t <= xu[11]; t += 0.0013)
    CHECK(on_grid(t) == doctest::Approx(lagrange6(xu, g, 6, t)).epsilon(1e-13));
}

// interpolate_at_radius: between the points of a sinh grid, 6th order in the spacing.
TEST_CASE("interpolate_at_radius converges at 6th order on the sinh grid") {
  auto f = [](double r) { return std::exp(-0.1 * r * r) * std::cos(0.8 * r) + 0.05 * r; };
  std::vector<double> h, err;
  for (std::size_t n : {100, 200, 400}) {
    const Grid g(RadialMap::sinh(10.0, 2.0 / static_cast<double>(n), n), n);
    std::vector<double> values(g.n_total());
    for (std::size_t i = 0; i < g.n_total(); ++i)
      values[i] = f(g.r()[i]);
    double e = 0.0;
    for (double r = 0.37; r < 8.0; r += 0.291)
      e = std::max(e, std::abs(interpolate_at_radius(g, values, r) - f(r)));
    h.push_back(g.dx());
    err.push_back(e);
  }
  MESSAGE("interpolation order " << fit_order(h, err));
  CHECK(fit_order(h, err) == doctest::Approx(6.0).epsilon(0.1));
}
