// The maximal trumpet slice of Schwarzschild in isotropic radius (equations document, Sec. 9
// item 5): the closed form r(R) inverted for R, in units of M and scaled on output.
#include "initial_data/trumpet_solutions.hpp"
#include "initial_data/trumpet_support.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gbssn1d {

namespace {

using trumpet::solve_bracketed;

constexpr double sqrt2 = std::numbers::sqrt2;

// Maximal trumpet (Sec. 9 item 5), units M = 1. The unknown is u = 2R - 3 > 0: near the
// puncture u ~ r^sqrt2, and alpha = sqrt(f) is proportional to u, so solving for u (rather than
// R) keeps full relative precision in alpha as r -> 0.

/// sqrt(4R^2 + 4R + 3), written so that it does not overflow for huge R.
double maximal_sqrt_A(double R) {
  return R * std::sqrt(4.0 + (4.0 + 3.0 / R) / R);
}

/// ln r of the closed form r(R), as a function of u = 2R - 3.
double maximal_ln_r(double u) {
  const double R = 0.5 * (3.0 + u);
  const double sqrt_A = maximal_sqrt_A(R);
  const double first = 0.25 * (2.0 * R + 1.0 + sqrt_A);
  // sqrt(8R^2 + 8R + 6) = sqrt2 sqrt_A.
  const double second = (4.0 + 3.0 * sqrt2) * u / (8.0 * R + 6.0 + 3.0 * sqrt2 * sqrt_A);
  return std::log(first) + std::log(second) / sqrt2;
}

/// u = 2R - 3 at ln r = ln_rho.
double maximal_u(double rho, double ln_rho) {
  constexpr double k = 4.0 + 3.0 * sqrt2;
  // Near the puncture ln r = ln(k/4) + ln(k u / 36) / sqrt2 + O(u): exact in double precision
  // once u < 1e-17 (this also covers radii where u underflows).
  const double ln_u_small = std::log(36.0 / k) + sqrt2 * (ln_rho - std::log(k / 4.0));
  if (ln_u_small < std::log(1e-17))
    return std::exp(ln_u_small);
  // First guess from that limit, or from r -> infinity (R ~ r + 1).
  const double u0 = rho < 1.0 ? std::exp(ln_u_small) : 2.0 * rho - 1.0;
  const double d = maximal_ln_r(u0) - ln_rho;
  if (d == 0.0)
    return u0;
  // d ln r / d ln u = 2R / sqrt(4R^2 + 4R + 3) lies in [1/sqrt2, 1), so ln u at the root lies
  // between ln u0 - d and ln u0 - sqrt2 d; widen a little for rounding.
  const double pad = 0.01 * std::abs(d) + 1e-12;
  double lo = u0 * std::exp(std::min(-d, -sqrt2 * d) - pad);
  double hi = u0 * std::exp(std::max(-d, -sqrt2 * d) + pad);
  const auto g = [ln_rho](double u) { return maximal_ln_r(u) - ln_rho; };
  double g_lo = g(lo), g_hi = g(hi);
  for (int i = 0; i < 60 && g_lo > 0.0; ++i)
    g_lo = g(lo *= 0.5);
  for (int i = 0; i < 60 && g_hi < 0.0; ++i)
    g_hi = g(hi *= 2.0);
  return solve_bracketed(g, lo, hi, g_lo, g_hi);
}

} // namespace

MaximalTrumpet::MaximalTrumpet(double M) : M_(M), C_(0.0) {
  trumpet::require_valid_mass(M, "MaximalTrumpet");
  C_ = 3.0 * std::sqrt(3.0) * M * M / 4.0;
}

TrumpetSample MaximalTrumpet::at(double r) const {
  trumpet::require_valid_radius(r, "MaximalTrumpet::at");
  const double rho = r / M_;
  const double u = maximal_u(rho, std::log(rho));
  const double R = 0.5 * (3.0 + u);
  const double sqrt_A = maximal_sqrt_A(R);
  TrumpetSample t;
  t.r = r;
  t.R = M_ * R;
  // sqrt(f) = (2R - 3M) sqrt(4R^2 + 4MR + 3M^2) / (4R^2), Sec. 9 item 5.
  t.alpha = 0.25 * (u / R) * (sqrt_A / R);
  // d sqrt(f) / dR = M (4R^2 + 6MR + 9M^2) / (2 R^3 sqrt(4R^2 + 4MR + 3M^2)).
  t.dalpha_dR = (4.0 + (6.0 + 9.0 / R) / R) / (2.0 * R * sqrt_A) / M_;
  return t;
}

} // namespace gbssn1d
