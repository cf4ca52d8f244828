// The horizon-adjusting shift (equations document, Sec. 14), the method under study:
//   beta = beta_GD + beta_H,   beta_H = f(r) A (h_AH - h) s^r,
// with its profiles f, normals s^r, the strength ramp and the deliberately inconsistent variants
// of the study. The equations use it through GbssnRhs (gbssn/rhs.cpp); beta_H is written here
// once (horizon_shift_on), for the right-hand side and for output alike.
#pragma once

#include "gbssn/horizon_shift_params.hpp"
#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <algorithm>
#include <cmath>
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

/// s^r of the chosen normal. chi < 0 (which a coarse evolution can produce in the innermost
/// cell) counts as 0, so that s^r stays finite.
inline double shift_normal(ShiftNormal normal, double chi, double a, double chi_smooth) {
  const double chi_pos = chi > 0.0 ? chi : 0.0;
  switch (normal) {
  case ShiftNormal::smooth:
    return std::sqrt((chi_pos + chi_smooth) / a);
  case ShiftNormal::conformal:
    return 1.0 / std::sqrt(a);
  case ShiftNormal::unit:
  default:
    return std::sqrt(chi_pos / a);
  }
}

/// f(r_i / w) on every point of the grid (odd in r).
std::vector<double> profile_on(const Grid& grid, const HorizonShiftParams& params);

/// beta_H = f amplitude s^r (H3) on n points, f = profile_on(...), amplitude = A(t) (h_AH - h),
/// and beta_full = beta_GD + beta_H if beta_GD and beta_full are given.
void horizon_shift_on(ShiftNormal normal, std::size_t n, const double* f, const double* chi,
                      const double* a, double amplitude, double chi_smooth, double* beta_H,
                      const double* beta_GD = nullptr, double* beta_full = nullptr);

/// f(r) A (h_AH - h) s^r on every point (ghosts included; odd in r like beta), or zero
/// everywhere without a horizon radius.
void horizon_shift_profile(const State& u, const Grid& grid, const HorizonShiftParams& params,
                           std::optional<double> h_AH, std::vector<double>& beta_H,
                           double t = std::numeric_limits<double>::infinity());

} // namespace gbssn1d
