// The gauge's equations (equations document, Sec. 4): 1+log slicing (G1) and the Gamma-driver
// shift (G2)-(G3), with the parameters of Gauge (gbssn/rhs_params.hpp).
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

} // namespace gbssn1d
