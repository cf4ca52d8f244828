// Point-wise right-hand side of the spherically symmetric Z4c equations with constraint damping
// (equations document, Sec. 17; Bernuzzi & Hilditch 2010, arXiv:0912.2920, and Hilditch et al.
// 2013, arXiv:1212.2901, in the covariant form of Sec. 2 with the same Lagrangian choice and the
// same placement of the evolved and the metric Delta^r as BSSN's (E6)). Its variables are
// BSSN's with K-hat = K - 2 Theta in K's row, plus Theta (core/registry.hpp); its symbolic
// reference is docs/verify_gbssn1d_equations.py, part V7.
#pragma once

#include "gbssn/equations.hpp"
#include "gbssn/gauge.hpp"
#include "gbssn/point_data.hpp"
#include "gbssn/rhs_params.hpp"

#include <algorithm>

namespace gbssn1d {

/// The point data with the ADM trace K = K-hat + 2 Theta in K's place, its value and
/// derivatives (Z1): what the constraints (Sec. 5), the expansion (T1) and every diagnostic
/// read as K.
inline PointData adm_trace(PointData p) {
  using enum Var;
  constexpr double w = traits(Formulation::z4c).adm_K_theta;
  p.f[K] += w * p.f[Theta];
  p.d[K] += w * p.d[Theta];
  p.dd[K] += w * p.dd[Theta];
  p.adv[K] += w * p.adv[Theta];
  return p;
}

/// The point data of formulation f as the constraints, the expansion and every diagnostic
/// read it: K the ADM K (adm_trace where K's row is not), Theta zero where f evolves none.
template <Formulation f>
PointData diagnosed(PointData p) {
  constexpr FormulationTraits t = traits(f);
  if constexpr (!t.evolves(Var::Theta)) {
    using enum Var;
    p.f[Theta] = p.d[Theta] = p.dd[Theta] = p.adv[Theta] = 0.0;
  }
  if constexpr (!t.K_is_adm()) {
    static_assert(t.adm_K_theta == traits(Formulation::z4c).adm_K_theta);
    p = adm_trace(p);
  }
  return p;
}

/// Z4c as a policy of the point loop, beside Bssn (gbssn/equations.hpp), with its damping.
struct Z4c {
  static constexpr Formulation formulation = Formulation::z4c;
  Z4cParams params;
  /// 2 where the lapse is driven by the ADM K = K-hat + 2 Theta, 0 for K-hat: a weight, not a
  /// switch, so that the point loop vectorises (a bool tested in the loop stopped it: 5 times
  /// slower)
  double lapse_theta;
  explicit Z4c(const Z4cParams& p) : params(p), lapse_theta(p.lapse_adm_K ? 2.0 : 0.0) {}

  /// The damping kappa1 at a point (Z4cParams): raised towards kappa1_hole inside the areal
  /// radius hole_radius, where the grid resolves it. Branch-free, so that the loop vectorises.
  [[gnu::always_inline]] double kappa1_at(const PointData& p) const {
    const double near =
        std::max(params.kappa1, std::min(params.kappa1_hole, Z4cParams::kappa1_dr_max * p.inv_dr));
    const double q = areal_radius(p) / params.hole_radius, q2 = q * q;
    return params.kappa1 + (near - params.kappa1) / (1.0 + q2 * q2);
  }

  /// (Z4) d_t Delta^r for the shift `s`: (E6), whose -(4/3) alpha/a d_r K acts on K-hat, plus
  /// -(2/3) alpha/a d_r Theta (together -(2/3) alpha/a d_r(2 K-hat + Theta)) and the damping
  /// -2 alpha kappa1 G^r of the Gamma constraint G^r = Delta^r - Delta_gamma^r.
  /// `kappa1` is kappa1_at(p), formed once per point by the caller (rhs() needs it thrice).
  [[gnu::always_inline]] double rhs_Delta_r(const PointData& p, const MetricPieces& m,
                                            const Shift& s, double kappa1) const {
    using enum Var;
    const double G_r = p.f[Delta_r] - delta_gamma(p, m);
    return gbssn1d::rhs_Delta_r(p, m, s) - (2.0 / 3.0) * p.f[alpha] * m.inv_a * p.d[Theta]
           - 2.0 * p.f[alpha] * kappa1 * G_r;
  }
  /// With the matter M (gbssn/matter.hpp): its rows, and its terms (S4)-(S5).
  template <class M = Vacuum>
  [[gnu::always_inline]] Rhs rhs(const PointData& p, const Gauge& gauge,
                                 const Shift& gauge_shift) const {
    using enum Var;
    const MetricPieces m = metric_pieces(p);
    const Shift shift = full_shift(p);
    // (Z1): chi, K-hat and A_a see K = K-hat + 2 Theta wherever (C1), (E4), (E5) have K
    // undifferentiated; d_t K-hat advects K-hat itself.
    const double theta = p.f[Theta], K_adm = p.f[K] + 2.0 * theta;
    Rhs rhs;
    metric_and_curvature_rhs(p, m, divbeta(p, m, shift), K_adm, rhs);
    // (Z2)
    const double kappa1 = kappa1_at(p);
    rhs[K] += p.f[alpha] * kappa1 * (1.0 - params.kappa2) * theta;
    // (Z3): R with the evolved Delta^r (R^r_r + 2 R^theta_theta, (C3)), A_ij A^ij = (3/2) A_a^2
    const double ricci = ricci_rr(p, m) + 2.0 * ricci_thth(p, m);
    rhs[Theta] =
        p.adv[Theta]
        + 0.5 * p.f[alpha] * (ricci - 1.5 * p.f[A_a] * p.f[A_a] + (2.0 / 3.0) * K_adm * K_adm)
        - p.f[alpha] * kappa1 * (2.0 + params.kappa2) * theta;
    // (Z4)
    rhs[Delta_r] = rhs_Delta_r(p, m, shift, kappa1);
    // (G1)-(G3): the lapse is driven by K-hat (p.f[K]), or by the ADM K (a 0 or 2 weight, so that
    // the loop stays branch-free); B by Z4c's d_t Delta^r of the gauge shift
    if constexpr (M::matter == Matter::none) {
      MovingPunctureGauge::rhs(gauge, p, rhs_Delta_r(p, m, gauge_shift, kappa1), gauge_shift,
                               lapse_theta * theta, rhs);
    } else {
      // (S1)-(S5): the matter's rows (K the ADM K), its terms in K-hat, A_a, Delta^r and Theta
      const MatterTerms matter = add_matter<M>(p, m.inv_a, m.da_a, m.db_b, m.dchi_chi, K_adm, rhs);
      rhs[Theta] += -8.0 * std::numbers::pi * p.f[alpha] * matter.s.rho;
      MovingPunctureGauge::rhs(gauge, p, rhs_Delta_r(p, m, gauge_shift, kappa1) + matter.Delta_r,
                               gauge_shift, lapse_theta * theta, rhs);
    }
    return rhs;
  }
};

} // namespace gbssn1d
