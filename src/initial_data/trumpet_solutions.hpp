// Schwarzschild trumpet slices in isotropic radius r: the analytic maximal trumpet
// (Baumgarte & Naculich 2007) and the stationary 1+log trumpet (Hannam et al. 2008), as in the
// equations document, Sec. 9 item 5 and Sec. 13.
#pragma once

#include <span>
#include <vector>

namespace gbssn1d {

/// What a trumpet slice gives at one isotropic radius r > 0.
struct TrumpetSample {
  double r;         ///< isotropic radius
  double R;         ///< areal radius R(r)
  double alpha;     ///< lapse on the slice
  double dalpha_dR; ///< d alpha / d R along the slice
};

/// Baumgarte-Naculich maximal trumpet, C = 3 sqrt(3) M^2 / 4 (Sec. 9 item 5):
/// alpha = sqrt(f) = (2R - 3M) sqrt(4R^2 + 4MR + 3M^2) / (4R^2), with r(R) in closed form,
/// inverted numerically.
class MaximalTrumpet {
public:
  explicit MaximalTrumpet(double M);
  double mass() const { return M_; }
  double C() const { return C_; }
  /// Areal radius, lapse and dalpha/dR at isotropic radius r > 0.
  TrumpetSample at(double r) const;

private:
  double M_, C_;
};

/// Stationary 1+log trumpet (Sec. 13): alpha^2 = 1 - 2M/R + C^2 e^alpha / R^4, with C fixed
/// by the critical point; d ln r / dR = 1/(alpha R), r/R -> 1 as R -> infinity. Integrated
/// with Boost.Odeint.
class OneLogTrumpet {
public:
  explicit OneLogTrumpet(double M);
  double mass() const { return M_; }
  double C() const { return C_; }
  double R_critical() const { return Rc_; }
  double alpha_critical() const { return alpha_c_; }
  double R_cylinder() const { return R0_; } ///< areal radius of the limiting cylinder (alpha -> 0)
  /// Samples at the given isotropic radii (each > 0, any order).
  std::vector<TrumpetSample> at(std::span<const double> r) const;

private:
  double M_, C_, Rc_, alpha_c_, R0_;
  // The solution in units of M: v = (R - R_c)/M, rho = r/M.
  double delta_ = 0.0; ///< half-width in v of the Taylor region around the critical point
  double ln_rc_ = 0.0; ///< ln(r_c/M), isotropic radius of the critical point
  double ln_r_minus_ = 0.0, ln_r_plus_ = 0.0; ///< ln(r/M) at v = -delta_, +delta_
  std::vector<double> alpha_series_; ///< alpha(R_c + M v) = sum_k a_k v^k (physical branch)
  std::vector<double> lnr_series_;   ///< ln(r/r_c) = sum_k b_k v^k, from (S2)
  /// Sample inside the Taylor region, ln_rho in [ln_r_minus_, ln_r_plus_].
  TrumpetSample taylor_sample(double r, double ln_rho) const;
};

} // namespace gbssn1d
