// The horizon-adjusting shift's parameters (equations document, Sec. 14): its profiles,
// normals, taper and the study's variants as choices, for configurations; the functions that
// evaluate beta_H are in gbssn/horizon_shift.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbssn1d {

/// Radial profile f(r) of the horizon-adjusting shift, q = r/w. Each is odd in r with its
/// largest value 1/2 or about it, and falls off like 1/q (rational) or like a Gaussian.
enum class ShiftProfile {
  automatic, ///< chosen by the direction of the move: see resolve_automatic_profile()
  rational,  ///< q / (1 + q^2): the published f(r) of (H3); f ~ r at the origin
  rational3, ///< q^3 / (1 + q^4): the same fall-off, but f ~ r^3 at the origin
  gauss,     ///< (q/2) exp((1 - q^2)/2): concentrated at r ~ w, f ~ r at the origin
  gauss3,    ///< (q^3/2) exp(3 (1 - q^2)/2): concentrated at r ~ w, f ~ r^3 at the origin
};

/// How beta_H vanishes before the outer boundary (docs/horizon-shift-study.md, Sec. 7.1, 7.3).
enum class Taper {
  /// exp(-(2 s)^4): 0.94 at s = 1/4, 1/e at s = 1/2, 1.1e-7 at s = 1, 7e-112 at s = 2 (rmax
  /// with the default r_cut = rmax/2). Its largest 4th and 6th derivatives are
  /// 17 and 570 times smaller than the step's, so that coarse boxes resolve it.
  quartic,
  /// 1 for s <= 1/2, 0 for s >= 1, and in between the C-infinity step g(1 - u) / (g(1 - u) +
  /// g(u)), u = 2 s - 1, g(x) = exp(-1/x): compact, but its 6th derivative reaches 3e8 / r_cut^6,
  /// which boxes with rmax 128 do not resolve (Sec. 7.3).
  step,
};

/// The radial vector s^r that beta_H points along.
enum class ShiftNormal {
  unit,      ///< sqrt(chi/a), the unit normal of (H3); ~ |r| at a trumpet's puncture (a kink)
  smooth,    ///< sqrt((chi + chi_s)/a): smooth and even at the puncture, close to `unit`
             ///< where chi >> chi_s (HorizonShiftParams::chi_smooth)
  conformal, ///< 1/sqrt(a), the unit normal of the conformal metric: smooth and even
};

/// The horizon-adjusting shift (equations document, Sec. 14):
///   beta = beta_GD + beta_H,   beta_H = f(r) A (h_AH - h) s^r,
/// (H3) with f(r) = (r/w) / (1 + (r/w)^2) and s^r = sqrt(chi/a); other profiles and normals are
/// offered for the study of the method. The evolved shift variable is beta_GD; B is driven by
/// d_t Delta^r computed with beta_GD alone (H2), every other term sees the full beta.
struct HorizonShiftParams {
  double A = 0.0;     ///< strength; 0 switches the horizon shift off
  double h = 0.89;    ///< desired coordinate radius of the horizon
  double width = 1.0; ///< w
  double ramp = 0.0;  ///< T: the strength grows as A (1 - exp(-(t/T)^2)) (0: A from t = 0)
  /// r_cut: f(r) is multiplied by outer_taper(r / r_cut, taper), which falls smoothly to 0 by
  /// r_cut, so that beta_H vanishes before the outer boundary, where the boundary condition
  /// assumes the shift of the Gamma-driver alone (infinity: no taper).
  double r_cut = std::numeric_limits<double>::infinity();
  Taper taper = Taper::quartic;
  ShiftProfile profile = ShiftProfile::rational;
  ShiftNormal normal = ShiftNormal::unit;
  double chi_smooth = 0.05; ///< chi_s of ShiftNormal::smooth
  /// Deliberately inconsistent discretisations of the equations, for the study of why a 3D
  /// code lost convergence; `consistent` is the method as specified above. (When h_AH is
  /// searched is the tracker's schedule, evolution/evolution_config.hpp, not a variant here.)
  enum class Variant {
    consistent,
    no_shift_derivatives,        ///< beta_H added to the shift's value only: derivatives of beta_GD
    no_shift_second_derivatives, ///< ... only the second derivatives of beta_GD
    delta_rhs_from_gd,           ///< d_t Delta^r computed with beta_GD (for B) reused for Delta^r
    driver_full_shift,           ///< B driven by d_t Delta^r of the full shift
  };
  Variant variant = Variant::consistent;
  bool active() const { return A != 0.0; }
  /// The strength at time t.
  double strength(double t) const {
    return ramp > 0.0 ? A * (1.0 - std::exp(-(t / ramp) * (t / ramp))) : A;
  }
};

/// Coordinate radius of the apparent horizon of the stationary 1+log trumpet, 0.8304 M: where
/// 1+log slicing with the Gamma-driver puts the horizon of Schwarzschild in the end (all three
/// initial data sets approach it; the maximal trumpet slowly).
inline constexpr double standard_horizon_radius = 0.8304;

/// The profile and width that ShiftProfile::automatic stands for, chosen from the experiments
/// of docs/horizon-shift-study.md: to stretch (h >= 0.8304 M, the standard horizon), the
/// published rational profile with w = 3 M (wide: H outside stays at the standard gauge's); to
/// shrink (h < 0.8304 M), the Gaussian with w = 1 M (concentrated at the horizon; wider profiles
/// lose a clean convergence order there). Other profiles are left as they are.
inline void resolve_automatic_profile(HorizonShiftParams& params, double M) {
  if (params.profile != ShiftProfile::automatic)
    return;
  // docs/horizon-shift-study.md Sec. 3 and Sec. 8: a stretch to h takes w = 3 max(h, M), so that
  // the profile's peak (at r = w) stays outside the horizon it moves (w = 3 M at h = 2 M left H
  // 2.5 times the standard gauge's at M/8; w = 6 M: 1.2 times)
  const bool stretch = params.h >= standard_horizon_radius * M;
  params.profile = stretch ? ShiftProfile::rational : ShiftProfile::gauss;
  params.width = stretch ? 3.0 * std::max(params.h, M) : 1.0 * M;
}

} // namespace gbssn1d
