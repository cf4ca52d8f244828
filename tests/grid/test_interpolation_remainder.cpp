// grid/interpolation.hpp's 6-point Lagrange interpolation is centred on the interval it
// interpolates in: on x^6 its error is exactly the Lagrange remainder prod_m (xi - x_m) of the
// six nodes around the interval (two to its left, to its right, of the interval's own two), the
// smallest of any six nodes there; near the grid's ends the six nearest nodes.
#include "grid/interpolation.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

using namespace gbssn1d;

// Guards the stencil's start, lagrange6_start (k - 2): one node off centre is still exact for
// quintics, so only the remainder tells (M_AH at t = 0 moved from 1.0003 to 1.0014).
TEST_CASE("6-point interpolation at radius: the error on x^6 is the remainder of the centred "
          "six nodes, next to the ends too") {
  for (const bool sinh_map : {false, true}) {
    const Grid g(sinh_map ? RadialMap::sinh(2.0, 0.02, 40) : RadialMap::uniform(2.0), 40);
    const auto& x = g.x();
    const std::size_t n = g.n_total();
    const double x0 = x[n / 2]; // x^6 about the middle: the values stay of order one
    std::vector<double> f(n);
    for (std::size_t i = 0; i < n; ++i)
      f[i] = std::pow(x[i] - x0, 6);
    const double h6 = std::pow(g.dx(), 6);
    int tested = 0;
    for (std::size_t k = g.first_interior(); k + 1 < g.end_interior(); ++k)
      for (const double s : {0.1, 0.5, 0.85}) {
        const double xi = x[k] + s * (x[k + 1] - x[k]);
        const double r = g.map().r(xi);
        // the six nodes around [x_k, x_k+1], as far as the grid reaches (f - p = f^(6)/6! prod)
        const std::size_t first = std::min<std::size_t>(k >= 2 ? k - 2 : 0, n - 6);
        double remainder = 1.0;
        for (std::size_t m = first; m < first + 6; ++m)
          remainder *= xi - x[m];
        INFO((sinh_map ? std::string("sinh") : std::string("uniform"))
             << " grid, cell " << k << ", s = " << s);
        const double error = interpolate_at_radius(g, f, r) - std::pow(xi - x0, 6);
        CHECK(error == doctest::Approx(-remainder).epsilon(1e-6).scale(1e-6 * h6));
        if (s == 0.5 && k >= 2 && k + 4 <= n)
          CHECK(std::abs(error) == doctest::Approx(225.0 / 64.0 * h6).epsilon(1e-6));
        ++tested;
      }
    CHECK(tested > 100);
  }
}

// Exactness on quintics, at many points from the first cell to the last (any six distinct nodes
// around the point would do: this guards the stencil's reach, not its centring).
TEST_CASE("6-point interpolation at radius is exact for quintics in x, from end to end") {
  const Grid g(RadialMap::sinh(3.0, 0.03, 50), 50);
  const auto& x = g.x();
  auto poly = [](double t) {
    return 0.3 - 1.1 * t + 0.7 * t * t + 0.4 * std::pow(t, 3) - 0.25 * std::pow(t, 4)
           + 0.05 * std::pow(t, 5);
  };
  std::vector<double> f(g.n_total());
  for (std::size_t i = 0; i < f.size(); ++i)
    f[i] = poly(x[i]);
  for (int q = 0; q <= 400; ++q) {
    const double r = g.r()[g.first_interior()]
                     + (g.r()[g.end_interior() - 1] - g.r()[g.first_interior()]) * q / 400.0;
    INFO("r = " << r);
    CHECK(interpolate_at_radius(g, f, r)
          == doctest::Approx(poly(g.map().x_of_r(r))).epsilon(1e-11).scale(1.0));
  }
}
