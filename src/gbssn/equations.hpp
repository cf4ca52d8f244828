// Point-wise right-hand side of the spherically symmetric generalized BSSN equations
// (Brown's covariant form, Lagrangian choice d_t det(gbar) = 0, flat spherical reference
// metric), chi = e^{-4 phi} form, A_b = -A_a/2.
//
// Equation labels (A1), (E2), (C3), (G1) ... refer to docs/gbssn1d-equations.md; its verified
// symbolic reference is docs/verify_gbssn1d_equations.py.
// Everything here is a function of the fields and their radial derivatives at one point;
// derivatives, upwinded advection and dissipation are computed by the caller (gbssn/rhs.cpp).
#pragma once

#include <cmath>

namespace gbssn1d {

/// Fields, their radial derivatives and the upwinded advection terms at one point.
struct PointData {
  double r, inv_r;
  // values
  double alpha, beta, B, chi, a, b, K, A_a, Delta_r;
  // centred first derivatives d_r f
  double d_alpha, d_beta, d_B, d_chi, d_a, d_b, d_K, d_A_a, d_Delta_r;
  // centred second derivatives d_r^2 f
  double dd_alpha, dd_beta, dd_chi, dd_a, dd_b;
  // upwinded shift advection beta d_r f (same beta as `beta` above)
  double adv_alpha, adv_beta, adv_B, adv_chi, adv_a, adv_b, adv_K, adv_A_a, adv_Delta_r;
};

/// The shift seen by a term: its value, derivatives and the upwinded beta d_r Delta^r it
/// produces. Separate from PointData so that the Gamma-driver can evaluate d_t Delta^r with a
/// part of the shift only (Sec. 14, (H2)).
struct Shift {
  double beta, d_beta, dd_beta, adv_Delta_r;
};

inline Shift full_shift(const PointData& p) {
  return {p.beta, p.d_beta, p.dd_beta, p.adv_Delta_r};
}

/// Gauge choices (Sec. 4).
struct GaugeParams {
  double eta = 2.0;             ///< Gamma-driver damping (1/length); default 2/M
  bool advective_lapse = true;  ///< (G1) with beta alpha' (true) or d_t alpha = -2 alpha K
  bool advective_shift = false; ///< the optional brackets of (G2)/(G3)
};

/// Right-hand sides of the evolved variables, in registry order.
struct Rhs {
  double alpha, beta, B, chi, a, b, K, A_a, Delta_r;
};

/// Logarithmic derivatives and inverses used throughout.
struct MetricPieces {
  double inv_a, inv_b, inv_chi;
  double da_a, db_b, dchi_chi; ///< a'/a, b'/b, chi'/chi
  double a_b;                  ///< a/b
};

inline MetricPieces metric_pieces(const PointData& p) {
  MetricPieces m;
  m.inv_a = 1.0 / p.a;
  m.inv_b = 1.0 / p.b;
  m.inv_chi = 1.0 / p.chi;
  m.da_a = p.d_a * m.inv_a;
  m.db_b = p.d_b * m.inv_b;
  m.dchi_chi = p.d_chi * m.inv_chi;
  m.a_b = p.a * m.inv_b;
  return m;
}

/// (A1) conformal divergence of the shift, Dbar_k beta^k.
inline double divbeta(const PointData& p, const MetricPieces& m, const Shift& s) {
  return s.d_beta + s.beta * (0.5 * m.da_a + m.db_b + 2.0 * p.inv_r);
}

/// (A2) d_r (Dbar_k beta^k).
inline double divbeta_prime(const PointData& p, const MetricPieces& m, const Shift& s) {
  const double connection = 0.5 * m.da_a + m.db_b + 2.0 * p.inv_r;
  const double connection_prime = 0.5 * p.dd_a * m.inv_a - 0.5 * m.da_a * m.da_a + p.dd_b * m.inv_b
                                  - m.db_b * m.db_b - 2.0 * p.inv_r * p.inv_r;
  return s.dd_beta + s.d_beta * connection + s.beta * connection_prime;
}

/// (A3) Delta^r computed from the conformal metric.
inline double delta_gamma(const PointData& p, const MetricPieces& m) {
  return m.inv_a * (0.5 * m.da_a - m.db_b + 2.0 * p.inv_r * (m.a_b - 1.0));
}

/// (C2) physical Laplacian of the lapse, D^k D_k alpha.
inline double lap_alpha(const PointData& p, const MetricPieces& m) {
  return p.chi * m.inv_a
         * (p.dd_alpha - p.d_alpha * (0.5 * m.da_a - m.db_b - 2.0 * p.inv_r)
            - 0.5 * p.d_alpha * m.dchi_chi);
}

/// (C2) D^r D_r alpha - D^theta D_theta alpha.
inline double hessian_alpha_tracefree(const PointData& p, const MetricPieces& m) {
  return p.chi * m.inv_a
         * (p.dd_alpha - p.d_alpha * (0.5 * m.da_a + 0.5 * m.db_b + p.inv_r)
            + p.d_alpha * m.dchi_chi);
}

/// (C3) mixed Ricci component R^r_r, with the evolved Delta^r appearing as d_r Delta^r.
inline double ricci_rr(const PointData& p, const MetricPieces& m) {
  const double conformal_metric = -0.5 * p.dd_a * m.inv_a + m.da_a * m.da_a - 0.5 * m.da_a * m.db_b
                                  - 0.5 * m.db_b * m.db_b - m.da_a * p.inv_r
                                  + 2.0 * m.db_b * p.inv_r * (m.a_b - 1.0)
                                  + 2.0 * p.inv_r * p.inv_r * (m.a_b - 1.0);
  const double conformal_factor = p.dd_chi * m.inv_chi - m.dchi_chi * m.dchi_chi
                                  - 0.5 * m.dchi_chi * (m.da_a - m.db_b - 2.0 * p.inv_r);
  return p.chi * (p.d_Delta_r + m.inv_a * (conformal_metric + conformal_factor));
}

/// (C3) mixed Ricci component R^theta_theta, with the evolved Delta^r appearing as Delta^r/r.
inline double ricci_thth(const PointData& p, const MetricPieces& m) {
  const double conformal_metric = -0.5 * p.dd_b * m.inv_b + 0.25 * m.da_a * m.db_b
                                  - m.db_b * p.inv_r + p.inv_r * p.inv_r * (1.0 - m.a_b);
  const double conformal_factor = 0.5 * p.dd_chi * m.inv_chi - 0.75 * m.dchi_chi * m.dchi_chi
                                  - 0.25 * m.dchi_chi * (m.da_a - 3.0 * m.db_b - 6.0 * p.inv_r);
  return p.chi * (p.Delta_r * p.inv_r + m.inv_a * (conformal_metric + conformal_factor));
}

/// (C3)/(R4) scalar curvature from a, b, chi alone (no Delta^r): the Hamiltonian-constraint
/// diagnostic does not depend on the evolved Delta^r.
inline double ricci_scalar_metric(const PointData& p, const MetricPieces& m) {
  const double conformal_metric = -2.0 * p.dd_b * m.inv_b + 0.5 * m.db_b * m.db_b
                                  + m.da_a * (m.db_b + 2.0 * p.inv_r) - 6.0 * m.db_b * p.inv_r
                                  + 2.0 * p.inv_r * p.inv_r * (m.a_b - 1.0);
  const double conformal_factor = 2.0 * p.dd_chi * m.inv_chi - 2.5 * m.dchi_chi * m.dchi_chi
                                  + 2.0 * m.dchi_chi * (2.0 * p.inv_r + m.db_b - 0.5 * m.da_a);
  return p.chi * m.inv_a * (conformal_metric + conformal_factor);
}

/// (E6) with (C4) and A_b = -A_a/2: d_t Delta^r for the shift `s`; alpha, K, A_a terms as is.
inline double rhs_Delta_r(const PointData& p, const MetricPieces& m, const Shift& s) {
  const double div_beta = divbeta(p, m, s);
  const double lie_derivative = s.adv_Delta_r - p.Delta_r * s.d_beta;
  const double flat_laplacian_of_shift =
      s.dd_beta * m.inv_a + 2.0 * m.inv_b * (s.d_beta * p.inv_r - s.beta * p.inv_r * p.inv_r);
  const double lagrangian_terms =
      (2.0 / 3.0) * delta_gamma(p, m) * div_beta + (1.0 / 3.0) * m.inv_a * divbeta_prime(p, m, s);
  const double lapse_and_curvature =
      -2.0 * p.A_a * m.inv_a * (p.d_alpha + 1.5 * p.alpha * m.dchi_chi)
      + p.alpha * p.A_a * m.inv_a * (m.da_a + m.db_b + 2.0 * p.inv_r * (1.0 - m.a_b))
      - (4.0 / 3.0) * p.alpha * m.inv_a * p.d_K;
  return lie_derivative + flat_laplacian_of_shift + lagrangian_terms + lapse_and_curvature;
}

/// The complete right-hand side at one point: fields (C1), (E2)-(E6) with the full shift,
/// gauge (G1)-(G3). `gauge_shift` is the part of the shift whose d_t Delta^r drives B (Sec. 14,
/// (H2)); pass full_shift(p) for the plain Gamma-driver.
inline Rhs gbssn_rhs(const PointData& p, const GaugeParams& gauge, const Shift& gauge_shift) {
  const MetricPieces m = metric_pieces(p);
  const Shift shift = full_shift(p);
  const double div_beta = divbeta(p, m, shift);
  const double AA = 1.5 * p.A_a * p.A_a; // A_a^2 + 2 A_b^2

  Rhs rhs;
  // (C1)
  rhs.chi = p.adv_chi + (2.0 / 3.0) * p.chi * (p.alpha * p.K - div_beta);
  // (E2)
  rhs.a =
      p.adv_a + 2.0 * p.a * p.d_beta - (2.0 / 3.0) * p.a * div_beta - 2.0 * p.alpha * p.a * p.A_a;
  // (E3), with -2 alpha b A_b = + alpha b A_a
  rhs.b =
      p.adv_b + 2.0 * p.b * p.beta * p.inv_r - (2.0 / 3.0) * p.b * div_beta + p.alpha * p.b * p.A_a;
  // (E4)
  rhs.K = p.adv_K - lap_alpha(p, m) + p.alpha * (AA + p.K * p.K / 3.0);
  // (E5), trace-free form
  rhs.A_a = p.adv_A_a - (2.0 / 3.0) * hessian_alpha_tracefree(p, m)
            + (2.0 / 3.0) * p.alpha * (ricci_rr(p, m) - ricci_thth(p, m)) + p.alpha * p.K * p.A_a;
  // (E6)
  rhs.Delta_r = rhs_Delta_r(p, m, shift);

  // The gauge switches as 0/1 factors (branch-free, so point loops vectorise).
  const double lapse_advection = gauge.advective_lapse ? 1.0 : 0.0;
  const double shift_advection = gauge.advective_shift ? 1.0 : 0.0;
  // (G1) 1+log slicing
  rhs.alpha = lapse_advection * p.adv_alpha - 2.0 * p.alpha * p.K;
  // (G2), (G3) Gamma-driver; B is driven by d_t Delta^r of the gauge part of the shift.
  const double dt_Delta_gauge = rhs_Delta_r(p, m, gauge_shift);
  rhs.beta = 0.75 * p.B + shift_advection * p.adv_beta;
  rhs.B = dt_Delta_gauge - gauge.eta * p.B + shift_advection * (p.adv_B - gauge_shift.adv_Delta_r);
  return rhs;
}

inline Rhs gbssn_rhs(const PointData& p, const GaugeParams& gauge) {
  return gbssn_rhs(p, gauge, full_shift(p));
}

/// Constraints and geometric diagnostics at one point (Sec. 5, Sec. 6).
struct Constraints {
  double H;   ///< (H) Hamiltonian constraint, R from a, b, chi (R4)
  double M_r; ///< (M) radial momentum constraint, chi form
  double G_r; ///< (G) Gamma constraint Delta^r - Delta_gamma^r
};

inline Constraints constraints(const PointData& p) {
  const MetricPieces m = metric_pieces(p);
  Constraints c;
  c.H = ricci_scalar_metric(p, m) - 1.5 * p.A_a * p.A_a + (2.0 / 3.0) * p.K * p.K;
  c.M_r = p.d_A_a - (2.0 / 3.0) * p.d_K + 1.5 * p.A_a * (2.0 * p.inv_r + m.db_b - m.dchi_chi);
  c.G_r = p.Delta_r - delta_gamma(p, m);
  return c;
}

/// (T1) outgoing expansion of the sphere r = const, chi form.
inline double expansion_plus(const PointData& p) {
  const MetricPieces m = metric_pieces(p);
  return std::sqrt(p.chi * m.inv_a) * (2.0 * p.inv_r + m.db_b - m.dchi_chi) + p.A_a
         - (2.0 / 3.0) * p.K;
}

/// (T2) areal radius r sqrt(b/chi).
inline double areal_radius(const PointData& p) {
  return p.r * std::sqrt(p.b / p.chi);
}

} // namespace gbssn1d
