// The gauge (equations document, Sec. 4): 1+log slicing (G1) and the Gamma-driver shift
// (G2)-(G3), one type with defaulted parameters. Its characteristic speeds at infinity set the
// Sommerfeld speeds of the outer boundary (Sec. 8) through each variable's Wave in the registry.
#pragma once

#include "core/registry.hpp"
#include "gbssn/point_data.hpp"

#include <cmath>

namespace gbssn1d {

struct Gauge {
  /// (G1) d_t alpha = [beta d_r alpha] - mu_L alpha K; 1+log slicing is mu_L = 2
  /// (f(alpha) = mu_L / alpha in d_t alpha = -alpha^2 f(alpha) K).
  struct Slicing {
    double mu_L = 2.0;
    bool advective = true; ///< with the bracket beta d_r alpha
  };
  /// (G2) d_t beta = xi B [+ beta d_r beta],
  /// (G3) d_t B = d_t Delta^r - eta B [+ beta d_r B - beta d_r Delta^r].
  struct GammaDriver {
    double xi = 0.75;
    double eta = 2.0;       ///< damping (1/length); 2/M by default (config)
    bool advective = false; ///< with the brackets (moving-puncture shift)
  };
  Slicing slicing;
  GammaDriver shift;

  /// Speed at infinity (alpha, chi, a, b -> 1) of each characteristic family: the slicing mode
  /// sqrt(f(alpha) alpha^2 gamma^rr) = sqrt(mu_L) (Sec. 8), the Gamma-driver's longitudinal
  /// mode sqrt(4 xi / 3) (Alcubierre, Introduction to 3+1 Numerical Relativity, ch. 4), light 1.
  double speed(Wave wave) const {
    switch (wave) {
    case Wave::slicing:
      return std::sqrt(slicing.mu_L);
    case Wave::shift:
      return std::sqrt(4.0 * shift.xi / 3.0);
    case Wave::light:
    default:
      return 1.0;
    }
  }
};

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
