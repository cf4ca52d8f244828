// Delta^r's own advection term beta d_r Delta^r (E6), differenced by GbssnRhs's point loop with
// its own stencil weights (gbssn/rhs_loop.hpp, delta_derivative), against the upwind derivative
// of fd/stencils.hpp written out with its branch (fd::advect: the pair's plus or minus stencil,
// leaning towards where the flow comes from), for both upwind pairs and every order.
#include "fd/stencils.hpp"
#include "gbssn/rhs.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <string>

using namespace gbssn1d;

namespace {

/// Smooth data of the right parities: even fields near 1, a shift that changes sign, and a
/// Delta^r with every derivative non-zero (not a solution: only the advection term is compared).
State smooth_data(const Grid& g) {
  State u = make_state(g, Formulation::bssn);
  for (std::size_t i = 0; i < g.n_total(); ++i) {
    const double r = g.r()[i];
    for (const auto& e : evolved(Formulation::bssn)) {
      const double c = 0.05 * static_cast<double>(index(e.var) + 1);
      field(u, g, e.var)[i] =
          e.parity > 0 ? 1.0 + c * std::exp(-r * r / 4.0) : c * r * std::exp(-r * r / 8.0);
    }
    field(u, g, Var::beta)[i] = 0.4 * std::sin(1.3 * r) * std::exp(-r * r / 40.0);
    field(u, g, Var::Delta_r)[i] = r * std::exp(-r * r / 6.0) * (1.0 + 0.3 * r * r);
  }
  return u;
}

template <int p>
void check_order(fd::Upwind upwind) {
  INFO("--fd-order " << p << ", --upwind "
                     << (upwind == fd::Upwind::biased ? "biased" : "lopsided"));
  const Grid g(RadialMap::sinh(12.0, 0.1, 60), 60, p);
  const State u = smooth_data(g);
  RhsParams params;
  params.ko_sigma = 0.0;
  params.upwind = upwind;
  params.advection.delta = AdvectionStencil::upwind_full;
  State with_upwind, with_centred;
  GbssnRhs(g, params)(u, with_upwind, 0.0);
  params.advection.delta = AdvectionStencil::centred;
  GbssnRhs(g, params)(u, with_centred, 0.0);
  const auto Delta = field(u, g, Var::Delta_r), beta = field(u, g, Var::beta);
  const auto a = field(with_upwind, g, Var::Delta_r), b = field(with_centred, g, Var::Delta_r);
  int both_signs = 0;
  // (the outermost points are the outer boundary condition's)
  for (std::size_t i = g.first_interior(); i + 8 < g.end_interior(); ++i) {
    const double d1_scale = g.inv_dr_dx()[i] / g.dx();
    const double upwinded = upwind == fd::Upwind::biased
                                ? fd::advect<p, fd::Upwind::biased>(beta[i], &Delta[i])
                                : fd::advect<p, fd::Upwind::lopsided>(beta[i], &Delta[i]);
    const double expected = d1_scale * (upwinded - beta[i] * fd::d1_centred<p>(&Delta[i]));
    INFO("r = " << g.r()[i] << ", beta = " << beta[i]);
    // (round-off: the two right-hand sides hold terms of order one besides this one)
    CHECK(std::abs(a[i] - b[i] - expected) <= 1e-13 * (1.0 + std::abs(a[i]) + std::abs(b[i])));
    both_signs |= beta[i] > 0.0 ? 1 : 2;
  }
  CHECK(both_signs == 3); // the stencil leant both ways
}

} // namespace

// Guards the upwind ratio of Delta^r's stencil in the point loop: under --upwind biased it must
// be the biased pair's (a lopsided ratio with the biased sum is still 5th order, so no
// convergence test saw it: H_L2_ext doubled in a shifted run).
TEST_CASE("Delta^r's advection in the point loop is the upwind stencil of the pair asked, every "
          "order") {
  for (const fd::Upwind upwind : {fd::Upwind::lopsided, fd::Upwind::biased}) {
    check_order<2>(upwind);
    check_order<4>(upwind);
    check_order<6>(upwind);
    check_order<8>(upwind);
  }
}
