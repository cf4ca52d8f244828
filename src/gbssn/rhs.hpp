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
#include "horizon/apparent_horizon.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace gbssn1d {

/// The horizon-adjusting shift (equations document, Sec. 14):
///   beta = beta_GD + beta_H,   beta_H = f(r) A (h_AH - h) s^r,
///   s^r = sqrt(chi/a),   f(r) = (r/w) / (1 + (r/w)^2).
/// The evolved shift variable is beta_GD; B is driven by d_t Delta^r computed with beta_GD
/// alone (H2), every other term sees the full beta.
struct HorizonShiftParams {
  double A = 0.0;     ///< strength; 0 switches the horizon shift off
  double h = 0.89;    ///< desired coordinate radius of the horizon
  double width = 1.0; ///< w
  /// true: h_AH is found on the state of every RK substage (the RHS is a function of the state
  /// alone); false: h_AH is held at the value set by set_horizon_radius() between searches.
  bool search_every_substage = true;
  double t_min = 0.0, t_max = -1.0; ///< substage searches only in this window (t_max < 0: none)
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
  HorizonFinderParams finder;
  bool active() const { return A != 0.0; }
};

struct RhsParams {
  GaugeParams gauge;
  double ko_sigma = 0.1; ///< Kreiss-Oliger strength (0 switches dissipation off)
  HorizonShiftParams horizon_shift;
};

/// f(r) A (h_AH - h) sqrt(chi/a) on every point (ghosts included; odd in r like beta), or zero
/// everywhere without a horizon radius.
void horizon_shift_profile(const State& u, const Grid& grid, const HorizonShiftParams& params,
                           std::optional<double> h_AH, std::vector<double>& beta_H);

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

  /// The horizon radius h_AH used by the horizon shift: set between searches (held mode), or
  /// found by the last evaluation (substage mode). nullopt: no horizon, beta_H = 0.
  std::optional<double> horizon_radius() const { return h_AH_; }
  void set_horizon_radius(std::optional<double> h_AH) { h_AH_ = h_AH; }

private:
  template <bool with_horizon_shift>
  void interior(const State& u, State& dudt) const;
  void outer_boundary(const State& u, State& dudt) const;
  void origin_ghosts(State& dudt) const;

  const Grid* grid_;
  RhsParams params_;
  std::uint64_t evaluations_ = 0;
  std::optional<double> h_AH_;
  std::vector<double> beta_H_, beta_full_; ///< scratch of the horizon shift
};

} // namespace gbssn1d
