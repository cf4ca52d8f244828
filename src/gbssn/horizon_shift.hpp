// The horizon-adjusting shift (equations document, Sec. 14), the method under study:
//   beta = beta_GD + beta_H,   beta_H = f(r) A (h_AH - h) s^r,
// with its profiles f, normals s^r, the strength ramp and the deliberately inconsistent variants
// of the study. The equations use it through GbssnRhs (gbssn/rhs.cpp); beta_H is written here,
// for output (horizon_shift_on) and within beta_GD + beta_H for the right-hand side
// (full_shift_on, declared in gbssn/full_shift.hpp), by one loop.
#pragma once

#include "gbssn/horizon_shift_params.hpp"
#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace gbssn1d {

/// The outer taper of beta_H at s = |r| / r_cut.
inline double outer_taper(double s, Taper taper = Taper::quartic) {
  if (taper == Taper::quartic) {
    const double x2 = 4.0 * s * s;
    return std::exp(-x2 * x2);
  }
  const double u = 2.0 * s - 1.0;
  if (u <= 0.0)
    return 1.0;
  if (u >= 1.0)
    return 0.0;
  const double a = std::exp(-1.0 / (1.0 - u)), b = std::exp(-1.0 / u);
  return a / (a + b);
}

/// f(r) of the profile, at r/w = q.
inline double shift_profile(ShiftProfile profile, double q) {
  switch (profile) {
  case ShiftProfile::rational3:
    return q * q * q / (1.0 + q * q * q * q);
  case ShiftProfile::gauss:
    return 0.5 * q * std::exp(0.5 * (1.0 - q * q));
  case ShiftProfile::gauss3:
    return 0.5 * q * q * q * std::exp(1.5 * (1.0 - q * q));
  case ShiftProfile::automatic: // resolved before use
  case ShiftProfile::rational:
  default:
    return q / (1.0 + q * q);
  }
}

/// sqrt(c / a) for c >= 0 and a > 0 without the divider (no division, no square root), in
/// operations that vectorise on any target. y = 1 / sqrt(c a) starts from the bits of c a
/// (exponent halved, relative error below 3.5%) and takes two third-order steps
/// y <- y + y e (1/2 + 3/8 e), e = 1 - c a y^2 (error about 4e-12); then s = c y takes one
/// Newton step of its own, s <- s + y (c - a s^2) / 2. The result is within 1 ulp of the
/// correctly rounded value with FMA contraction, 1.5 without (4e6 samples over 300 decades;
/// the tests require 2). If c a is below the smallest normal double, c is scaled by 2^108
/// first (the estimate reads the exponent, and a subnormal has lost bits). c = 0 gives 0 (y stays
/// finite at c a = 0); a <= 0, c < 0, a or c not finite, or c a beyond the doubles' range
/// (above the largest, or nonzero below 2^-1130) give NaN, so that a degenerate metric stops
/// the run instead of steering the shift.
inline double sqrt_quotient(double c, double a) {
  constexpr double smallest_normal = std::numeric_limits<double>::min();
  const bool tiny = c * a < smallest_normal;
  const double cs = c * (tiny ? 0x1p108 : 1.0); // sqrt(cs / a) = 2^54 sqrt(c / a) if tiny
  const double x = cs * a;
  double y = std::bit_cast<double>(std::uint64_t{0x5FE6EB50C7B537A9}
                                   - (std::bit_cast<std::uint64_t>(x) >> 1));
  for (int step = 0; step < 2; ++step) {
    const double e = 1.0 - x * y * y;
    y = y + y * e * (0.5 + 0.375 * e);
  }
  // a Newton step on s = sqrt(cs / a) itself: s <- s + (cs - a s^2) / (2 a s), 1 / (a s) = y
  double s = cs * y;
  s = s + 0.5 * y * (cs - a * s * s);
  // outside the domain NaN; one select per condition (a combined condition stops GCC from
  // vectorising the loops that call this: "control flow in loop")
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  double scale = tiny ? 0x1p-54 : 1.0;
  scale = c >= 0.0 ? scale : nan;
  scale = a > 0.0 ? scale : nan;
  scale = x <= std::numeric_limits<double>::max() ? scale : nan;
  scale = x >= smallest_normal || c == 0.0 ? scale : nan;
  return s * scale;
}

/// s^r of the chosen normal. chi < 0 (which a coarse evolution can produce in the innermost
/// cell) counts as 0, so that s^r stays finite. Formed by sqrt_quotient, not sqrt(chi / a):
/// the loop that writes beta_H ran at the divider's pace, a division and a square root a
/// point, 4.2 ns a point against 1.0 (docs/roofline.md Sec. 4).
inline double shift_normal(ShiftNormal normal, double chi, double a, double chi_smooth) {
  const double chi_pos = chi > 0.0 ? chi : 0.0;
  switch (normal) {
  case ShiftNormal::smooth:
    return sqrt_quotient(chi_pos + chi_smooth, a);
  case ShiftNormal::conformal:
    return sqrt_quotient(1.0, a);
  case ShiftNormal::unit:
  default:
    return sqrt_quotient(chi_pos, a);
  }
}

/// f(r_i / w) on every point of the grid (odd in r).
std::vector<double> profile_on(const Grid& grid, const HorizonShiftParams& params);

/// beta_H = f amplitude s^r (H3) on n points, f = profile_on(...), amplitude = A(t) (h_AH - h).
void horizon_shift_on(ShiftNormal normal, std::size_t n, const double* f, const double* chi,
                      const double* a, double amplitude, double chi_smooth, double* beta_H);

/// f(r) A (h_AH - h) s^r on every point (ghosts included; odd in r like beta), or zero
/// everywhere without a horizon radius.
void horizon_shift_profile(const State& u, const Grid& grid, const HorizonShiftParams& params,
                           std::optional<double> h_AH, std::vector<double>& beta_H,
                           double t = std::numeric_limits<double>::infinity());

} // namespace gbssn1d
