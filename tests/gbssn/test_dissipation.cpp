// Kreiss-Oliger dissipation in the point loop (gbssn/rhs_loop.hpp, ko_scale): the highest grid
// mode (-1)^j of one evolved field is damped at the rate sigma/dr, dr = (dr/dx) dx the cell's
// width in r at that point (the fd::Order normalisation times the map's dx/dr), that field alone,
// for every --fd-order, both formulations, on the uniform and the sinh grid. The dissipation is
// taken as the difference of the right-hand sides with and without it, and the mode's part as that
// difference with the mode added less it without: the equations' own terms cancel, and the
// dissipation is linear.
#include "gbssn/rhs.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <string>

using namespace gbssn1d;

namespace {

/// Smooth data of the right parities (not a solution: only the dissipation is compared).
State ko_smooth_state(const Grid& g, Formulation formulation) {
  State u = make_state(g, formulation);
  for (std::size_t i = 0; i < g.n_total(); ++i) {
    const double r = g.r()[i];
    for (const auto& e : evolved(formulation)) {
      const double c = 0.05 * static_cast<double>(index(e.var) + 1);
      field(u, g, e.var)[i] =
          e.parity > 0 ? 1.0 + c * std::exp(-r * r / 4.0) : c * r * std::exp(-r * r / 8.0);
    }
  }
  return u;
}

/// The dissipation's part of the right-hand side of `u` at strength sigma.
State ko_part(const Grid& g, RhsParams params, const State& u, double sigma) {
  State with, without;
  params.ko_sigma = sigma;
  GbssnRhs(g, params)(u, with, 0.0);
  params.ko_sigma = 0.0;
  GbssnRhs(g, params)(u, without, 0.0);
  for (std::size_t k = 0; k < with.size(); ++k)
    with[k] -= without[k];
  return with;
}

template <int p>
void check_ko_rate(const Grid& g, Formulation formulation) {
  RhsParams params;
  params.formulation = formulation;
  const double sigma = 0.3, eps = 1e-2;
  const State u = ko_smooth_state(g, formulation);
  const State smooth = ko_part(g, params, u, sigma);
  for (const auto& e : evolved(formulation)) {
    INFO("field " << e.name);
    State v = u;
    for (std::size_t i = 0; i < g.n_total(); ++i)
      field(v, g, e.var)[i] += (i % 2 == 0 ? eps : -eps);
    const State moded = ko_part(g, params, v, sigma);
    // away from the centre's ghosts and the outer boundary's points
    const std::size_t reach = fd::Order<p>::radius;
    for (std::size_t i = g.first_interior() + reach; i + reach + 2 < g.end_interior(); ++i) {
      const double expected = -sigma * g.inv_dr_dx()[i] / g.dx() * (i % 2 == 0 ? eps : -eps);
      for (const auto& other : evolved(formulation)) {
        const double got = field(moded, g, other.var)[i] - field(smooth, g, other.var)[i];
        if (other.var == e.var)
          REQUIRE(got == doctest::Approx(expected).epsilon(1e-9));
        else
          REQUIRE(std::abs(got) <= 1e-9 * std::abs(expected));
      }
    }
  }
}

template <int p>
void check_ko_order() {
  INFO("--fd-order " << p);
  const Grid uniform(RadialMap::uniform(10.0), 100, p);
  const Grid sinh(RadialMap::sinh(12.0, 0.1, 60), 60, p);
  for (const Formulation f : {Formulation::bssn, Formulation::z4c}) {
    INFO("formulation " << static_cast<int>(f));
    check_ko_rate<p>(uniform, f);
    check_ko_rate<p>(sinh, f);
  }
}

} // namespace

TEST_CASE("Kreiss-Oliger dissipation damps the highest grid mode of each field at sigma/dr, that "
          "field alone, every order, both formulations, uniform and sinh grids") {
  check_ko_order<2>();
  check_ko_order<4>();
  check_ko_order<6>();
  check_ko_order<8>();
}
