// The point-wise right-hand side against values computed independently from the verified
// symbolic equations (tests/reference/make_pointwise_reference.py), and flat space.
#include "gbssn/equations.hpp"

#include "../test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace gbssn1d;
using gbssn1d::testing::read_table;

namespace {

PointData point_from_row(const gbssn1d::testing::Table& t, std::size_t row) {
  auto v = [&](const std::string& c) { return t.at(row, c); };
  PointData p{};
  p.r = v("r");
  p.inv_r = 1.0 / p.r;
  p.alpha = v("alpha");
  p.beta = v("beta");
  p.B = v("B");
  p.chi = v("chi");
  p.a = v("a");
  p.b = v("b");
  p.K = v("K");
  p.A_a = v("A_a");
  p.Delta_r = v("Delta_r");
  p.d_alpha = v("d_alpha");
  p.d_beta = v("d_beta");
  p.d_B = v("d_B");
  p.d_chi = v("d_chi");
  p.d_a = v("d_a");
  p.d_b = v("d_b");
  p.d_K = v("d_K");
  p.d_A_a = v("d_A_a");
  p.d_Delta_r = v("d_Delta_r");
  p.dd_alpha = v("dd_alpha");
  p.dd_beta = v("dd_beta");
  p.dd_chi = v("dd_chi");
  p.dd_a = v("dd_a");
  p.dd_b = v("dd_b");
  // exact advection terms beta f'
  p.adv_alpha = p.beta * p.d_alpha;
  p.adv_beta = p.beta * p.d_beta;
  p.adv_B = p.beta * p.d_B;
  p.adv_chi = p.beta * p.d_chi;
  p.adv_a = p.beta * p.d_a;
  p.adv_b = p.beta * p.d_b;
  p.adv_K = p.beta * p.d_K;
  p.adv_A_a = p.beta * p.d_A_a;
  p.adv_Delta_r = p.beta * p.d_Delta_r;
  return p;
}

void check(double computed, double reference, const std::string& what, double r) {
  INFO(what << " at r = " << r << ": computed " << computed << ", reference " << reference);
  CHECK(std::abs(computed - reference) <= 1e-12 * (1.0 + std::abs(reference)));
}

} // namespace

TEST_CASE("point-wise RHS agrees with the symbolic reference (verify_gbssn1d_equations.py)") {
  const auto t = read_table(std::string(GBSSN1D_TEST_DATA_DIR) + "/pointwise_reference.dat");
  REQUIRE(t.rows.size() >= 8);
  for (std::size_t row = 0; row < t.rows.size(); ++row) {
    const PointData p = point_from_row(t, row);
    const double r = p.r;
    auto ref = [&](const std::string& c) { return t.at(row, c); };

    for (bool advective_shift : {false, true}) {
      GaugeParams gauge;
      gauge.eta = ref("eta");
      gauge.advective_lapse = true;
      gauge.advective_shift = advective_shift;
      const Rhs rhs = gbssn_rhs(p, gauge);
      const std::string sfx = advective_shift ? "_advective" : "";
      check(rhs.alpha, ref("rhs_alpha_advective"), "alpha", r);
      check(rhs.beta, ref("rhs_beta" + sfx), "beta" + sfx, r);
      check(rhs.B, ref("rhs_B" + sfx), "B" + sfx, r);
      check(rhs.chi, ref("rhs_chi"), "chi", r);
      check(rhs.a, ref("rhs_a"), "a", r);
      check(rhs.b, ref("rhs_b"), "b", r);
      check(rhs.K, ref("rhs_K"), "K", r);
      check(rhs.A_a, ref("rhs_A_a"), "A_a", r);
      check(rhs.Delta_r, ref("rhs_Delta_r"), "Delta_r", r);
    }
    GaugeParams non_advective;
    non_advective.eta = ref("eta");
    non_advective.advective_lapse = false;
    check(gbssn_rhs(p, non_advective).alpha, ref("rhs_alpha_nonadvective"), "alpha (non-adv.)", r);

    const Constraints c = constraints(p);
    check(c.H, ref("H"), "H", r);
    check(c.M_r, ref("M_r"), "M_r", r);
    check(c.G_r, ref("G_r"), "G_r", r);
    check(expansion_plus(p), ref("Theta_plus"), "Theta_plus", r);
    check(areal_radius(p), ref("R_areal"), "R_areal", r);
  }
}

TEST_CASE("flat space: every right-hand side and constraint is exactly zero") {
  for (double r : {0.01, 0.5, 3.0, 70.0}) {
    PointData p{};
    p.r = r;
    p.inv_r = 1.0 / r;
    p.alpha = p.chi = p.a = p.b = 1.0;
    for (bool adv : {false, true}) {
      GaugeParams gauge;
      gauge.advective_shift = adv;
      const Rhs rhs = gbssn_rhs(p, gauge);
      for (double v :
           {rhs.alpha, rhs.beta, rhs.B, rhs.chi, rhs.a, rhs.b, rhs.K, rhs.A_a, rhs.Delta_r})
        CHECK(v == 0.0);
    }
    const Constraints c = constraints(p);
    CHECK(c.H == 0.0);
    CHECK(c.M_r == 0.0);
    CHECK(c.G_r == 0.0);
  }
}
