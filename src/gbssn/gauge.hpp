// The gauge's equations (equations document, Sec. 4): 1+log slicing (G1) and the Gamma-driver
// shift (G2)-(G3), with the parameters and characteristic speeds of Gauge
// (gbssn/rhs_params.hpp), as a policy that every formulation calls once (MovingPunctureGauge).
#pragma once

#include "core/registry.hpp"
#include "gbssn/point_data.hpp"
#include "gbssn/rhs_params.hpp"

#include <cmath>

namespace gbssn1d {

// Branch-free in the switches (0/1 factors), so that point loops vectorise.

/// (G1) 1+log slicing.
inline double rhs_alpha(const Gauge::Slicing& slicing, const PointData& p) {
  const double advection = slicing.advective ? 1.0 : 0.0;
  return advection * p.adv[Var::alpha] - slicing.mu_L * p.f[Var::alpha] * p.f[Var::K];
}

/// (G2) Gamma-driver shift.
inline double rhs_beta(const Gauge::GammaDriver& driver, const PointData& p) {
  const double advection = driver.advective ? 1.0 : 0.0;
  return driver.xi * p.f[Var::B] + advection * p.adv[Var::beta];
}

/// (G3) B, driven by d_t Delta^r = dt_Delta of the shift `gauge_shift` (Sec. 14, (H2)).
inline double rhs_B(const Gauge::GammaDriver& driver, const PointData& p, double dt_Delta,
                    const Shift& gauge_shift) {
  const double advection = driver.advective ? 1.0 : 0.0;
  return dt_Delta - driver.eta * p.f[Var::B]
         + advection * (p.adv[Var::B] - gauge_shift.adv_Delta_r);
}

/// The gauge as a policy of the formulations (gbssn/equations.hpp's Bssn, gbssn/z4c.hpp's Z4c):
/// each calls rhs() once, with what the gauge reads from it, and the gauge writes its own rows
/// (alpha, beta, B); their outer-boundary speeds come from Gauge::speed through the registry's
/// wave families. What a formulation hands over: d_t Delta^r of the part of the shift that drives
/// B (its own (E6) or (Z4) for `gauge_shift`, Sec. 14, (H2)), and a source of the lapse beyond K
/// (`lapse_K_extra`: -mu_L alpha lapse_K_extra is added to (G1); Z4c's Theta when the ADM K
/// drives the lapse). Another gauge is another type with this rhs() (and its parameters and
/// speeds beside Gauge's); the formulations then call it in the same place.
struct MovingPunctureGauge {
  /// (G1)-(G3) into the gauge rows of `out`.
  [[gnu::always_inline]] static void rhs(const Gauge& gauge, const PointData& p, double dt_Delta,
                                         const Shift& gauge_shift, Rhs& out) {
    out[Var::alpha] = rhs_alpha(gauge.slicing, p);
    out[Var::beta] = rhs_beta(gauge.shift, p);
    out[Var::B] = rhs_B(gauge.shift, p, dt_Delta, gauge_shift);
  }
  /// The same, with the lapse also driven by `lapse_K_extra` (a K-like source).
  [[gnu::always_inline]] static void rhs(const Gauge& gauge, const PointData& p, double dt_Delta,
                                         const Shift& gauge_shift, double lapse_K_extra, Rhs& out) {
    rhs(gauge, p, dt_Delta, gauge_shift, out);
    out[Var::alpha] -= gauge.slicing.mu_L * p.f[Var::alpha] * lapse_K_extra;
  }
};

} // namespace gbssn1d
