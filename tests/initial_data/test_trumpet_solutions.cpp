// Tests of the trumpet slices (equations document, Sec. 9 item 5 and Sec. 13): the maximal
// trumpet against its closed form, the 1+log trumpet against (S1), (S2), the critical-point
// numbers of the document and the isotropic Schwarzschild asymptotics. Each check is done for
// M = 1 and M = 2 (R and r scale with M, alpha is invariant at fixed r/M).
#include "initial_data/initial_data.hpp"
#include "initial_data/trumpet_solutions.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

using gbssn1d::MaximalTrumpet;
using gbssn1d::OneLogTrumpet;
using gbssn1d::TrumpetSample;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr std::array<double, 2> masses = {1.0, 2.0};

double rel_diff(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

/// Residual of (S1), alpha^2 - 1 + 2M/R - C^2 e^alpha / R^4, written out plainly.
double s1_residual(double alpha, double R, double M, double C) {
  return alpha * alpha - 1.0 + 2.0 * M / R - C * C * std::exp(alpha) / (R * R * R * R);
}

/// Isotropic radius of the maximal trumpet from the closed form r(R) of Sec. 9 item 5.
double maximal_r_closed_form(double R, double M) {
  const double s2 = std::numbers::sqrt2;
  const double first = (2.0 * R + M + std::sqrt(4.0 * R * R + 4.0 * M * R + 3.0 * M * M)) / 4.0;
  const double second =
      (4.0 + 3.0 * s2) * (2.0 * R - 3.0 * M)
      / (8.0 * R + 6.0 * M + 3.0 * std::sqrt(8.0 * R * R + 8.0 * M * R + 6.0 * M * M));
  return first * std::pow(second, 1.0 / s2);
}

// Eighth-order central first derivative: f'(0) ~ sum_k w_k (f(kh) - f(-kh)) / h.
constexpr std::array<double, 4> fd8_weights = {4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0};
constexpr double fd_h = 0.01; // step in ln r

/// The 9-point stencil in s = ln r around each centre: r_c e^{k h}, k = -4..4, in one list.
std::vector<double> log_stencils(const std::vector<double>& centres) {
  std::vector<double> r;
  for (const double rc : centres)
    for (int k = -4; k <= 4; ++k)
      r.push_back(rc * std::exp(k * fd_h));
  return r;
}

/// d f / d ln r at stencil `j` from the values f(sample) laid out as in log_stencils.
template <class Get>
double fd_dlnr(const std::vector<TrumpetSample>& s, std::size_t j, Get f) {
  const std::size_t c = 9 * j + 4;
  double d = 0.0;
  for (std::size_t k = 1; k <= 4; ++k)
    d += fd8_weights[k - 1] * (f(s[c + k]) - f(s[c - k]));
  return d / fd_h;
}

/// Radii (units of M) for the finite-difference checks: near the puncture, both sides and the
/// middle of the critical point (r_c = 0.30345 M, R = R_c), across the edges of the region
/// around it where the implementation switches method (r = 0.2791 M and 0.3276 M), and out to
/// the asymptotic region.
const std::vector<double> fd_centres = {
    1e-3, 3e-3,         0.01, 0.05, 0.1, 0.2, 0.27, 0.2790778679, 0.29,  0.3034520427,
    0.31, 0.3276362578, 0.34, 0.5,  1.0, 2.0, 5.0,  10.0,         100.0, 1000.0};

std::vector<double> log_spaced(double lo, double hi, std::size_t n) {
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i)
    r[i] = lo * std::pow(hi / lo, static_cast<double>(i) / static_cast<double>(n - 1));
  return r;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Stationary 1+log trumpet (Sec. 13)

TEST_CASE("OneLogTrumpet: critical point, C and cylinder radius match Sec. 13") {
  for (const double M : masses) {
    CAPTURE(M);
    const OneLogTrumpet t(M);
    CHECK(t.mass() == M);
    // Numbers quoted in Sec. 13 for M = 1.
    CHECK(rel_diff(t.C() / (M * M), 1.2467195314978948) < 1e-13);
    CHECK(std::abs(t.R_critical() / M - 1.540569) < 5e-7);
    CHECK(std::abs(t.alpha_critical() - 0.162278) < 5e-7);
    CHECK(std::abs(t.R_cylinder() / M - 1.31240829) < 5e-9);

    // (S1) and both of its first derivatives vanish at the critical point.
    const double Rc = t.R_critical(), ac = t.alpha_critical(), C2 = t.C() * t.C();
    const double q = C2 * std::exp(ac) / std::pow(Rc, 4);
    CHECK(std::abs(s1_residual(ac, Rc, M, t.C())) < 1e-14);
    CHECK(std::abs(2.0 * ac - q) < 1e-14);                              // F_alpha
    CHECK(std::abs(M * (-2.0 * M / (Rc * Rc) + 4.0 * q / Rc)) < 1e-14); // M F_R
    // The cylinder is where alpha = 0 solves (S1).
    CHECK(std::abs(s1_residual(0.0, t.R_cylinder(), M, t.C())) < 1e-14);

    // Towards the puncture the slice approaches the cylinder, alpha ~ r^1.09.
    const std::vector<double> r = {1e-12 * M, 1e-10 * M};
    const auto s = t.at(r);
    CHECK(rel_diff(s[0].R, t.R_cylinder()) < 1e-12);
    CHECK(s[0].alpha > 0.0);
    CHECK(s[0].alpha < 1e-12);
    const double power = std::log(s[1].alpha / s[0].alpha) / std::log(100.0);
    CHECK(std::abs(power - 1.09) < 0.01);
  }
}

TEST_CASE("OneLogTrumpet: samples satisfy (S1), 0 < alpha < 1, alpha and R increase with r") {
  for (const double M : masses) {
    CAPTURE(M);
    const OneLogTrumpet t(M);
    // Radii 1e-3 M .. 1e3 M, handed over in a scrambled order.
    const std::vector<double> sorted = log_spaced(1e-3 * M, 1e3 * M, 3001);
    std::vector<double> r;
    for (std::size_t i = 0; i < sorted.size(); i += 2)
      r.push_back(sorted[i]);
    for (std::size_t i = sorted.size() - 2; i < sorted.size(); i -= 2)
      r.push_back(sorted[i]);
    const auto s = t.at(r);
    REQUIRE(s.size() == r.size());

    double max_residual = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      CHECK(s[i].r == r[i]);
      max_residual = std::max(max_residual, std::abs(s1_residual(s[i].alpha, s[i].R, M, t.C())));
    }
    CHECK(max_residual < 1e-12);

    const auto ordered = t.at(sorted);
    bool in_range = true, increasing = true;
    for (std::size_t i = 0; i < ordered.size(); ++i) {
      in_range = in_range && ordered[i].alpha > 0.0 && ordered[i].alpha < 1.0;
      in_range = in_range && ordered[i].R > t.R_cylinder() && ordered[i].dalpha_dR > 0.0;
      if (i > 0)
        increasing = increasing && ordered[i].alpha > ordered[i - 1].alpha
                     && ordered[i].R > ordered[i - 1].R;
    }
    CHECK(in_range);
    CHECK(increasing);

    // The answer at a radius does not depend on which other radii are asked for.
    double max_diff = 0.0;
    for (const std::size_t i : {0, 700, 1100, 1500, 1800, 3000}) {
      const auto single = t.at(std::vector<double>{sorted[i]});
      max_diff = std::max({max_diff, rel_diff(single[0].R, ordered[i].R),
                           rel_diff(single[0].alpha, ordered[i].alpha),
                           rel_diff(single[0].dalpha_dR, ordered[i].dalpha_dR)});
    }
    CHECK(max_diff < 1e-13);
  }
}

TEST_CASE("OneLogTrumpet: finite differences of R(r) and alpha(r) satisfy (S2)") {
  // (S2): dR / d ln r = alpha R; then d alpha / d ln r = alpha R dalpha/dR.
  for (const double M : masses) {
    CAPTURE(M);
    const OneLogTrumpet t(M);
    std::vector<double> centres;
    for (const double c : fd_centres)
      centres.push_back(c * M);
    const auto s = t.at(log_stencils(centres));
    double worst_R = 0.0, worst_alpha = 0.0;
    for (std::size_t j = 0; j < centres.size(); ++j) {
      const TrumpetSample& mid = s[9 * j + 4];
      const double dR = fd_dlnr(s, j, [](const TrumpetSample& x) { return x.R; });
      const double dalpha = fd_dlnr(s, j, [](const TrumpetSample& x) { return x.alpha; });
      worst_R = std::max(worst_R, rel_diff(dR, mid.alpha * mid.R));
      worst_alpha = std::max(worst_alpha, rel_diff(dalpha, mid.alpha * mid.R * mid.dalpha_dR));
    }
    CHECK(worst_R < 1e-9);
    CHECK(worst_alpha < 1e-9);
  }
}

TEST_CASE("OneLogTrumpet: r/R -> 1 with the isotropic Schwarzschild asymptotics") {
  // At large R, (S1) is alpha^2 = 1 - 2M/R + O(R^-4), so (S2) gives the isotropic Schwarzschild
  // radius R_S(r) = r (1 + M/2r)^2 up to R/R_S - 1 = -(C^2 e / 8) / R^4 + O(R^-5). A wrong
  // normalisation of r (the condition r/R -> 1) shows up as a constant relative error in R.
  for (const double M : masses) {
    CAPTURE(M);
    const OneLogTrumpet t(M);
    const std::vector<double> r = {30.0 * M, 100.0 * M, 300.0 * M, 1000.0 * M};
    const auto s = t.at(r);
    for (std::size_t i = 0; i < r.size(); ++i) {
      CAPTURE(r[i]);
      const double x = M / r[i];
      const double R_S = r[i] * (1.0 + 0.5 * x) * (1.0 + 0.5 * x);
      CHECK(std::abs(s[i].R / r[i] - 1.0) < 2.0 * x);
      CHECK(std::abs(s[i].R / R_S - 1.0) < std::pow(x, 4) + 1e-14);
      const double xR = M / s[i].R;
      const double predicted =
          -t.C() * t.C() * std::exp(1.0) / (8.0 * M * M * M * M) * std::pow(xR, 4);
      if (r[i] >= 100.0 * M && r[i] <= 300.0 * M)
        CHECK(std::abs((s[i].R / R_S - 1.0) / predicted - 1.0) < 0.02);
      // alpha - sqrt(1 - 2M/R) = (C^2 e^alpha / 2) / R^4 + ... from (S1).
      CHECK(std::abs(s[i].alpha - std::sqrt(1.0 - 2.0 * M / s[i].R)) < 3.0 * std::pow(xR, 4));
    }
  }
}

TEST_CASE("OneLogTrumpet: scaling with M and invalid arguments") {
  const OneLogTrumpet t1(1.0), t2(2.0);
  const std::vector<double> rho = {1e-3, 0.1, 0.3034520427, 0.5, 10.0};
  std::vector<double> r2;
  for (const double x : rho)
    r2.push_back(2.0 * x);
  const auto s1 = t1.at(rho);
  const auto s2 = t2.at(r2);
  for (std::size_t i = 0; i < rho.size(); ++i) {
    CAPTURE(rho[i]);
    CHECK(rel_diff(s2[i].R, 2.0 * s1[i].R) < 1e-14);
    CHECK(rel_diff(s2[i].alpha, s1[i].alpha) < 1e-14);
    CHECK(rel_diff(s2[i].dalpha_dR, 0.5 * s1[i].dalpha_dR) < 1e-14);
  }
  CHECK(rel_diff(t2.C(), 4.0 * t1.C()) < 1e-15);
  CHECK(rel_diff(t2.R_critical(), 2.0 * t1.R_critical()) < 1e-15);
  CHECK(rel_diff(t2.R_cylinder(), 2.0 * t1.R_cylinder()) < 1e-15);

  CHECK_THROWS_AS(OneLogTrumpet(0.0), std::invalid_argument);
  CHECK_THROWS_AS(OneLogTrumpet(-1.0), std::invalid_argument);
  CHECK_THROWS_AS(t1.at(std::vector<double>{1.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(t1.at(std::vector<double>{-0.5}), std::invalid_argument);
  CHECK(t1.at(std::vector<double>{}).empty());
}

// ---------------------------------------------------------------------------------------------
// Maximal trumpet (Sec. 9 item 5)

TEST_CASE("MaximalTrumpet: inverse of the closed form r(R), alpha = sqrt(f)") {
  for (const double M : masses) {
    CAPTURE(M);
    const MaximalTrumpet t(M);
    CHECK(t.mass() == M);
    CHECK(rel_diff(t.C(), 3.0 * std::sqrt(3.0) * M * M / 4.0) < 1e-15);
    const double C2 = t.C() * t.C();
    double prev_R = 0.0, prev_alpha = -1.0;
    for (const double rho : log_spaced(1e-6, 1e6, 241)) {
      const double r = rho * M;
      CAPTURE(r);
      const TrumpetSample s = t.at(r);
      CHECK(s.r == r);
      // R is rounded to double, and d ln r / dR = 1/(alpha R): the closed form at the returned
      // R can only reproduce r to ~eps/(2 alpha).
      CHECK(rel_diff(maximal_r_closed_form(s.R, M), r) < 1e-13 + 2.0 * eps / s.alpha);
      const double f = 1.0 - 2.0 * M / s.R + C2 / std::pow(s.R, 4);
      CHECK(std::abs(s.alpha * s.alpha - f) < 1e-14);
      CHECK(s.alpha > 0.0);
      CHECK(s.alpha < 1.0);
      CHECK(s.R > 1.5 * M);
      CHECK(s.R > prev_R);
      CHECK(s.alpha > prev_alpha);
      prev_R = s.R;
      prev_alpha = s.alpha;
    }
    // Full precision where alpha is not small.
    for (const double rho : {0.1, 0.5, 1.0, 3.0, 1e2, 1e4}) {
      const TrumpetSample s = t.at(rho * M);
      CHECK(rel_diff(maximal_r_closed_form(s.R, M), rho * M) < 1e-13);
    }
  }
}

TEST_CASE("MaximalTrumpet: puncture limit, dR/dr = R sqrt(f)/r and dalpha/dR") {
  for (const double M : masses) {
    CAPTURE(M);
    const MaximalTrumpet t(M);
    // R -> 3M/2 as r -> 0; 2R - 3M ~ r^sqrt2 there.
    const TrumpetSample a = t.at(1e-8 * M), b = t.at(1e-6 * M);
    CHECK(std::abs(a.R - 1.5 * M) < 1e-10 * M);
    CHECK(a.alpha < 1e-10);
    CHECK(std::abs(std::log(b.alpha / a.alpha) / std::log(100.0) - std::numbers::sqrt2) < 1e-6);

    // Finite differences in ln r: dR / d ln r = R sqrt(f) (Sec. 9 item 5), and
    // d alpha / d ln r = (dalpha/dR) R alpha checks dalpha/dR.
    double worst_R = 0.0, worst_alpha = 0.0;
    for (const double rho : {1e-3, 0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0}) {
      std::vector<TrumpetSample> s;
      for (int k = -4; k <= 4; ++k)
        s.push_back(t.at(rho * M * std::exp(k * fd_h)));
      const TrumpetSample& mid = s[4];
      const double dR = fd_dlnr(s, 0, [](const TrumpetSample& x) { return x.R; });
      const double dalpha = fd_dlnr(s, 0, [](const TrumpetSample& x) { return x.alpha; });
      worst_R = std::max(worst_R, rel_diff(dR, mid.alpha * mid.R));
      worst_alpha = std::max(worst_alpha, rel_diff(dalpha, mid.alpha * mid.R * mid.dalpha_dR));
    }
    CHECK(worst_R < 1e-9);
    CHECK(worst_alpha < 1e-9);

    // Direct difference quotient of sqrt(f(R)) in R.
    for (const double R : {1.5001 * M, 1.6 * M, 2.0 * M, 5.0 * M, 50.0 * M}) {
      const double r = maximal_r_closed_form(R, M);
      const TrumpetSample s = t.at(r);
      const double h = 1e-3 * M;
      const auto sqrt_f = [&](double x) {
        return (2.0 * x - 3.0 * M) * std::sqrt(4.0 * x * x + 4.0 * M * x + 3.0 * M * M)
               / (4.0 * x * x);
      };
      const double R0 = s.R;
      const double d =
          (8.0 * (sqrt_f(R0 + h) - sqrt_f(R0 - h)) - (sqrt_f(R0 + 2.0 * h) - sqrt_f(R0 - 2.0 * h)))
          / (12.0 * h);
      CHECK(rel_diff(d, s.dalpha_dR) < 1e-8);
    }
  }
  CHECK_THROWS_AS(MaximalTrumpet(0.0), std::invalid_argument);
  CHECK_THROWS_AS(MaximalTrumpet(-2.0), std::invalid_argument);
  CHECK_THROWS_AS(MaximalTrumpet(1.0).at(0.0), std::invalid_argument);
  CHECK_THROWS_AS(MaximalTrumpet(1.0).at(-1.0), std::invalid_argument);
}

// Guards the switch to the puncture limit (maximal_trumpet.cpp, maximal_u): ln r = ln(k/4) +
// ln(k u / 36)/sqrt2 + O(u) with u = 2R/M - 3 is used only where its O(u) term is below double
// precision (u < 1e-17, r < 6.9e-13 M). Used from u < 1e-7 (r < 8.2e-6 M) on instead, alpha
// (proportional to u) was off by 2.1e-10 relative at r = 5e-7 M, and every test above passed
// (their tolerances are for r -> 0 and for finite differences). Here the closed form r(R) of
// Sec. 9 item 5, with 2R - 3M written as u so that it keeps its digits, is inverted by bisection
// in ln u in long double (64-bit mantissa), and the samples and the initial data's fields at
// radii from 1e-8 M to 1e-4 M, on both sides of r = 8.2e-6 M, must agree with it to round-off.
// Measured: 3.5e-15 relative at most (alpha); the bound 1e-13 is 30 times that, and 2000 times
// below the error of the early switch.
namespace {

/// u = 2R/M - 3 of the maximal trumpet at rho = r/M, in long double: the closed form
/// ln r(u) = ln[(2R + 1 + sqrt(4R^2 + 4R + 3))/4] + ln[(4 + 3 sqrt2) u / (8R + 6 +
/// 3 sqrt(8R^2 + 8R + 6))] / sqrt2 (M = 1, R = (3 + u)/2), increasing in u, bisected in ln u.
long double maximal_u_reference(long double rho) {
  const long double s2 = std::sqrt(2.0L);
  const auto ln_r = [s2](long double ln_u) {
    const long double u = std::exp(ln_u), R = 0.5L * (3.0L + u);
    const long double first = (2.0L * R + 1.0L + std::sqrt(4.0L * R * R + 4.0L * R + 3.0L)) / 4.0L;
    const long double second =
        (4.0L + 3.0L * s2) * u
        / (8.0L * R + 6.0L + 3.0L * std::sqrt(8.0L * R * R + 8.0L * R + 6.0L));
    return std::log(first) + std::log(second) / s2;
  };
  const long double target = std::log(rho);
  long double lo = -400.0L, hi = 40.0L; // u from e^-400 to e^40
  REQUIRE(ln_r(lo) < target);
  REQUIRE(ln_r(hi) > target);
  for (int i = 0; i < 200 && hi - lo > 0.0L; ++i) {
    const long double mid = 0.5L * (lo + hi);
    if (mid == lo || mid == hi)
      break;
    (ln_r(mid) < target ? lo : hi) = mid;
  }
  return std::exp(0.5L * (lo + hi));
}

} // namespace

TEST_CASE("MaximalTrumpet near the puncture: alpha, R and the initial data's fields to round-off "
          "across the switch to the puncture limit") {
  const std::vector<double> radii = {1e-8, 1e-7, 5e-7, 1e-6, 2e-6, 5e-6, 9e-6, 1e-5, 2e-5, 1e-4};
  double worst = 0.0;
  for (const double M : masses) {
    CAPTURE(M);
    const MaximalTrumpet t(M);
    const long double C = 3.0L * std::sqrt(3.0L) * M * M / 4.0L;
    for (const double rho : radii) {
      CAPTURE(rho);
      const long double u = maximal_u_reference(rho), R = 0.5L * (3.0L + u);
      const long double sqrt_A = std::sqrt(4.0L * R * R + 4.0L * R + 3.0L);
      // alpha = sqrt(f) = (2R - 3M) sqrt(4R^2 + 4MR + 3M^2) / (4R^2), invariant at fixed r/M
      const long double alpha = u * sqrt_A / (4.0L * R * R);
      // d sqrt(f)/dR = M (4R^2 + 6MR + 9M^2) / (2 R^3 sqrt(4R^2 + 4MR + 3M^2)), here over M
      const long double dalpha_dR = (4.0L * R * R + 6.0L * R + 9.0L) / (2.0L * R * R * R * sqrt_A);
      const TrumpetSample s = t.at(rho * M);
      const double e_alpha = rel_diff(s.alpha, static_cast<double>(alpha));
      CHECK(e_alpha < 1e-13);
      CHECK(rel_diff(s.R, static_cast<double>(M * R)) < 1e-15);
      CHECK(rel_diff(s.dalpha_dR, static_cast<double>(dalpha_dR / M)) < 1e-13);
      worst = std::max(worst, e_alpha);
      // the initial data's fields at a cell on rho M (Sec. 9 item 5): a grid of 4 cells whose
      // second cell's centre is r = 1.5 dr
      const gbssn1d::Grid grid(gbssn1d::RadialMap::uniform(rho * M / 1.5 * 4.0), 4);
      gbssn1d::InitialDataParams id;
      id.kind = gbssn1d::InitialDataKind::maximal_trumpet;
      id.M = M;
      const gbssn1d::State u0 = gbssn1d::initial_data(grid, id, gbssn1d::Formulation::bssn);
      const std::size_t i = grid.first_interior() + 1;
      const long double r = grid.r()[i], RM = M * R, R3 = RM * RM * RM;
      REQUIRE(rel_diff(grid.r()[i], rho * M) < 1e-15);
      auto at = [&](gbssn1d::Var v) { return gbssn1d::field(u0, grid, v)[i]; };
      CHECK(rel_diff(at(gbssn1d::Var::alpha), static_cast<double>(alpha)) < 1e-13);
      CHECK(rel_diff(at(gbssn1d::Var::chi), static_cast<double>((r / RM) * (r / RM))) < 1e-13);
      CHECK(rel_diff(at(gbssn1d::Var::beta), static_cast<double>(C * r / R3)) < 1e-13);
      CHECK(rel_diff(at(gbssn1d::Var::A_a), static_cast<double>(-2.0L * C / R3)) < 1e-13);
    }
  }
  MESSAGE("largest relative error of alpha: " << worst);
}
