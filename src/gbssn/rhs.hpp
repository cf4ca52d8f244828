// The right-hand side on the whole grid (method of lines):
//  - interior points: 4th-order centred derivatives (chain rule through the radial map),
//    4th-order lopsided derivatives for the beta d_r advection terms, the point-wise equations
//    of gbssn/equations.hpp, plus Kreiss-Oliger dissipation;
//  - outer ghost cells: Sommerfeld condition (Sec. 8) with one-sided derivatives, toward each
//    variable's asymptotic value from the registry;
//  - ghost cells at the origin: the mirror's right-hand side times the parity, so that every
//    Runge-Kutta stage stays parity-consistent.
#pragma once

#include "gbssn/equations.hpp"
#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

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

/// The radial vector s^r that beta_H points along.
enum class ShiftNormal {
  unit,      ///< sqrt(chi/a), the unit normal of (H3); ~ |r| at a trumpet's puncture (a kink)
  smooth,    ///< sqrt((chi + chi_s)/a): smooth and even at the puncture, close to `unit`
             ///< where chi >> chi_s (HorizonShiftParams::chi_smooth)
  conformal, ///< 1/sqrt(a), the unit normal of the conformal metric: smooth and even
};

/// How a term beta d_r Delta^r is differenced.
enum class AdvectionStencil {
  upwind_gd,   ///< lopsided towards where beta_GD comes from
  upwind_full, ///< lopsided towards where the full shift beta_GD + beta_H comes from
  centred,     ///< 4th-order centred
};

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
  ShiftProfile profile = ShiftProfile::rational;
  ShiftNormal normal = ShiftNormal::unit;
  double chi_smooth = 0.05; ///< chi_s of ShiftNormal::smooth
  /// true: h_AH is found on the state of every RK substage (the RHS is a function of the state
  /// alone); false: h_AH is held at the value set by set_horizon_radius() between searches.
  bool search_every_substage = true;
  double t_min = 0.0, t_max = -1.0; ///< substage searches only in this window (t_max < 0: none)
  /// Open loop: h_AH(t) prescribed as a function of time (no searches); empty: closed loop.
  std::function<double(double)> prescribed_h_AH;
  /// Deliberately inconsistent implementations, for the study of why a 3D code lost
  /// convergence; `consistent` is the method as specified above.
  enum class Variant {
    consistent,
    no_shift_derivatives,        ///< beta_H added to the shift's value only: derivatives of beta_GD
    no_shift_second_derivatives, ///< ... only the second derivatives of beta_GD
    delta_rhs_from_gd,           ///< d_t Delta^r computed with beta_GD (for B) reused for Delta^r
    driver_full_shift,           ///< B driven by d_t Delta^r of the full shift
    midstep_update,              ///< h_AH searched at the 2nd RK substage of every n-th step
  };
  Variant variant = Variant::consistent;
  long midstep_every = 1; ///< n of midstep_update
  /// The apparent horizon's radius on `u` near `seed` at time t (nullopt: none), for the
  /// searches inside the right-hand side. Set by the evolution (evolution/simulation.cpp), so
  /// that the equations do not depend on the finder; it may throw.
  std::function<std::optional<double>(const State& u, const Grid& grid, double seed, double t)>
      locate;
  bool active() const { return A != 0.0; }
  /// The strength at time t.
  double strength(double t) const {
    return ramp > 0.0 ? A * (1.0 - std::exp(-(t / ramp) * (t / ramp))) : A;
  }
  bool prescribed() const { return static_cast<bool>(prescribed_h_AH); }
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
  const bool stretch = params.h >= standard_horizon_radius * M;
  params.profile = stretch ? ShiftProfile::rational : ShiftProfile::gauss;
  params.width = (stretch ? 3.0 : 1.0) * M;
}

/// The differencing of the two beta d_r Delta^r terms: the one inside d_t Delta^r|beta_GD that
/// drives B (G3)/(H2), and Delta^r's own advection in (E6).
struct AdvectionParams {
  AdvectionStencil driver = AdvectionStencil::upwind_gd;
  AdvectionStencil delta = AdvectionStencil::upwind_full;
};

struct RhsParams {
  GaugeParams gauge;
  double ko_sigma = 0.1; ///< Kreiss-Oliger strength (0 switches dissipation off)
  AdvectionParams advection;
  HorizonShiftParams horizon_shift;
};

/// f(r) A (h_AH - h) s^r on every point (ghosts included; odd in r like beta), or zero
/// everywhere without a horizon radius.
void horizon_shift_profile(const State& u, const Grid& grid, const HorizonShiftParams& params,
                           std::optional<double> h_AH, std::vector<double>& beta_H,
                           double t = std::numeric_limits<double>::infinity());

/// Fields, derivatives and advection terms at grid point i (needs i - 3 ... i + 3).
PointData point_data(const State& u, const Grid& grid, std::size_t i);

class GbssnRhs {
public:
  GbssnRhs(const Grid& grid, RhsParams params);

  /// d u / dt at time t; the signature Boost.Odeint expects of a system.
  void operator()(const State& u, State& dudt, double t);

  const Grid& grid() const { return *grid_; }
  const RhsParams& params() const { return params_; }
  std::uint64_t evaluations() const { return evaluations_; }
  void set_evaluations(std::uint64_t n) { evaluations_ = n; } ///< for a resumed run

  /// The horizon radius h_AH used by the horizon shift: set between searches (held mode), or
  /// found by the last evaluation (substage mode). nullopt: no horizon, beta_H = 0.
  std::optional<double> horizon_radius() const { return h_AH_; }
  void set_horizon_radius(std::optional<double> h_AH) { h_AH_ = h_AH; }

private:
  /// The point loop; the horizon shift and its variant are template parameters, so that each
  /// instance is branch-free and vectorises (a run-time switch inside the loop stops it).
  template <bool with_horizon_shift,
            HorizonShiftParams::Variant variant = HorizonShiftParams::Variant::consistent>
  void interior(const State& u, State& dudt) const;
  void outer_boundary(const State& u, State& dudt) const;
  void origin_ghosts(State& dudt) const;
  /// beta_H_ and beta_full_ = beta_GD + beta_H_ for the current h_AH_ (H3).
  void split_shift(const State& u, double t);

  const Grid* grid_;
  RhsParams params_;
  std::uint64_t evaluations_ = 0;
  std::optional<double> h_AH_;
  std::vector<double> profile_;                  ///< f(r_i / w) on every point (fixed by the grid)
  static constexpr std::size_t block_size = 256; ///< points per block of the point loop
  std::vector<double> grid_blocks_;              ///< grid factors laid out per block (rhs.cpp)
  std::vector<double> beta_H_, beta_full_;       ///< scratch of the horizon shift
};

} // namespace gbssn1d
