// Point-wise right-hand side of the spherically symmetric generalized BSSN equations
// (Brown's covariant form, Lagrangian choice d_t det(gbar) = 0, flat spherical reference
// metric), chi = e^{-4 phi} form, A_b = -A_a/2.
//
// Equation labels (A1), (E2), (C3), (G1) ... refer to docs/gbssn1d-equations.md; its verified
// symbolic reference is docs/verify_gbssn1d_equations.py.
// Everything here is a function of the fields and their radial derivatives at one point;
// derivatives, upwinded advection and dissipation are computed by the caller (gbssn/rhs_loop.hpp).
#pragma once

#include "gbssn/gauge.hpp"
#include "gbssn/matter.hpp"
#include "gbssn/point_data.hpp"

#include <cmath>
#include <numbers>

namespace gbssn1d {

/// Logarithmic derivatives and inverses used throughout.
struct MetricPieces {
  double inv_a, inv_b, inv_chi;
  double da_a, db_b, dchi_chi; ///< a'/a, b'/b, chi'/chi
  double a_b;                  ///< a/b
};

inline MetricPieces metric_pieces(const PointData& p) {
  using enum Var;
  MetricPieces m;
  m.inv_a = 1.0 / p.f[a];
  m.inv_b = 1.0 / p.f[b];
  m.inv_chi = 1.0 / p.f[chi];
  m.da_a = p.d[a] * m.inv_a;
  m.db_b = p.d[b] * m.inv_b;
  m.dchi_chi = p.d[chi] * m.inv_chi;
  m.a_b = p.f[a] * m.inv_b;
  return m;
}

/// (A1) conformal divergence of the shift, Dbar_k beta^k.
inline double divbeta(const PointData& p, const MetricPieces& m, const Shift& s) {
  return s.d_beta + s.beta * (0.5 * m.da_a + m.db_b + 2.0 * p.inv_r);
}

/// (A2) d_r (Dbar_k beta^k).
inline double divbeta_prime(const PointData& p, const MetricPieces& m, const Shift& s) {
  using enum Var;
  const double connection = 0.5 * m.da_a + m.db_b + 2.0 * p.inv_r;
  const double connection_prime = 0.5 * p.dd[a] * m.inv_a - 0.5 * m.da_a * m.da_a
                                  + p.dd[b] * m.inv_b - m.db_b * m.db_b - 2.0 * p.inv_r * p.inv_r;
  return s.dd_beta + s.d_beta * connection + s.beta * connection_prime;
}

/// (A3) Delta^r computed from the conformal metric.
inline double delta_gamma(const PointData& p, const MetricPieces& m) {
  return m.inv_a * (0.5 * m.da_a - m.db_b + 2.0 * p.inv_r * (m.a_b - 1.0));
}

/// (C2) physical Laplacian of the lapse, D^k D_k alpha.
inline double lap_alpha(const PointData& p, const MetricPieces& m) {
  using enum Var;
  return p.f[chi] * m.inv_a
         * (p.dd[alpha] - p.d[alpha] * (0.5 * m.da_a - m.db_b - 2.0 * p.inv_r)
            - 0.5 * p.d[alpha] * m.dchi_chi);
}

/// (C2) D^r D_r alpha - D^theta D_theta alpha.
inline double hessian_alpha_tracefree(const PointData& p, const MetricPieces& m) {
  using enum Var;
  return p.f[chi] * m.inv_a
         * (p.dd[alpha] - p.d[alpha] * (0.5 * m.da_a + 0.5 * m.db_b + p.inv_r)
            + p.d[alpha] * m.dchi_chi);
}

/// (C3) mixed Ricci component R^r_r, with the evolved Delta^r appearing as d_r Delta^r.
inline double ricci_rr(const PointData& p, const MetricPieces& m) {
  using enum Var;
  const double conformal_metric = -0.5 * p.dd[a] * m.inv_a + m.da_a * m.da_a - 0.5 * m.da_a * m.db_b
                                  - 0.5 * m.db_b * m.db_b - m.da_a * p.inv_r
                                  + 2.0 * m.db_b * p.inv_r * (m.a_b - 1.0)
                                  + 2.0 * p.inv_r * p.inv_r * (m.a_b - 1.0);
  const double conformal_factor = p.dd[chi] * m.inv_chi - m.dchi_chi * m.dchi_chi
                                  - 0.5 * m.dchi_chi * (m.da_a - m.db_b - 2.0 * p.inv_r);
  return p.f[chi] * (p.d[Delta_r] + m.inv_a * (conformal_metric + conformal_factor));
}

/// (C3) mixed Ricci component R^theta_theta, with the evolved Delta^r appearing as Delta^r/r.
inline double ricci_thth(const PointData& p, const MetricPieces& m) {
  using enum Var;
  const double conformal_metric = -0.5 * p.dd[b] * m.inv_b + 0.25 * m.da_a * m.db_b
                                  - m.db_b * p.inv_r + p.inv_r * p.inv_r * (1.0 - m.a_b);
  const double conformal_factor = 0.5 * p.dd[chi] * m.inv_chi - 0.75 * m.dchi_chi * m.dchi_chi
                                  - 0.25 * m.dchi_chi * (m.da_a - 3.0 * m.db_b - 6.0 * p.inv_r);
  return p.f[chi] * (p.f[Delta_r] * p.inv_r + m.inv_a * (conformal_metric + conformal_factor));
}

/// (C3)/(R4) scalar curvature from a, b, chi alone (no Delta^r): the Hamiltonian-constraint
/// diagnostic does not depend on the evolved Delta^r.
inline double ricci_scalar_metric(const PointData& p, const MetricPieces& m) {
  using enum Var;
  const double conformal_metric = -2.0 * p.dd[b] * m.inv_b + 0.5 * m.db_b * m.db_b
                                  + m.da_a * (m.db_b + 2.0 * p.inv_r) - 6.0 * m.db_b * p.inv_r
                                  + 2.0 * p.inv_r * p.inv_r * (m.a_b - 1.0);
  const double conformal_factor = 2.0 * p.dd[chi] * m.inv_chi - 2.5 * m.dchi_chi * m.dchi_chi
                                  + 2.0 * m.dchi_chi * (2.0 * p.inv_r + m.db_b - 0.5 * m.da_a);
  return p.f[chi] * m.inv_a * (conformal_metric + conformal_factor);
}

/// (E6) with (C4) and A_b = -A_a/2: d_t Delta^r for the shift `s`; alpha, K, A_a terms as is.
/// The Eulerian volume choice leaves out the Lagrangian terms (Volume).
template <Volume volume = Volume::lagrangian>
inline double rhs_Delta_r(const PointData& p, const MetricPieces& m, const Shift& s) {
  using enum Var;
  const double lie_derivative = s.adv_Delta_r - p.f[Delta_r] * s.d_beta;
  const double flat_laplacian_of_shift =
      s.dd_beta * m.inv_a + 2.0 * m.inv_b * (s.d_beta * p.inv_r - s.beta * p.inv_r * p.inv_r);
  const double lapse_and_curvature =
      -2.0 * p.f[A_a] * m.inv_a * (p.d[alpha] + 1.5 * p.f[alpha] * m.dchi_chi)
      + p.f[alpha] * p.f[A_a] * m.inv_a * (m.da_a + m.db_b + 2.0 * p.inv_r * (1.0 - m.a_b))
      - (4.0 / 3.0) * p.f[alpha] * m.inv_a * p.d[K];
  if constexpr (volume == Volume::lagrangian) {
    const double div_beta = divbeta(p, m, s);
    const double lagrangian_terms =
        (2.0 / 3.0) * delta_gamma(p, m) * div_beta + (1.0 / 3.0) * m.inv_a * divbeta_prime(p, m, s);
    return lie_derivative + flat_laplacian_of_shift + lagrangian_terms + lapse_and_curvature;
  } else {
    return lie_derivative + flat_laplacian_of_shift + lapse_and_curvature;
  }
}

/// (C1), (E2)-(E5): the right-hand sides of chi, a, b, K and A_a with the full shift, whose
/// divergence is `div_beta`, into `rhs`; `trace_K` is the K of the undifferentiated terms:
/// p.f[K] for BSSN, K-hat + 2 Theta for Z4c (Z1). The Eulerian volume choice leaves out the
/// div_beta terms (Volume).
template <Volume volume = Volume::lagrangian>
[[gnu::always_inline]] inline void metric_and_curvature_rhs(const PointData& p,
                                                            const MetricPieces& m, double div_beta,
                                                            double trace_K, Rhs& rhs) {
  using enum Var;
  const double AA = 1.5 * p.f[A_a] * p.f[A_a]; // A_a^2 + 2 A_b^2
  if constexpr (volume == Volume::lagrangian) {
    // (C1)
    rhs[chi] = p.adv[chi] + (2.0 / 3.0) * p.f[chi] * (p.f[alpha] * trace_K - div_beta);
    // (E2)
    rhs[a] = p.adv[a] + 2.0 * p.f[a] * p.d[beta] - (2.0 / 3.0) * p.f[a] * div_beta
             - 2.0 * p.f[alpha] * p.f[a] * p.f[A_a];
    // (E3), with -2 alpha b A_b = + alpha b A_a
    rhs[b] = p.adv[b] + 2.0 * p.f[b] * p.f[beta] * p.inv_r - (2.0 / 3.0) * p.f[b] * div_beta
             + p.f[alpha] * p.f[b] * p.f[A_a];
  } else {
    static_cast<void>(div_beta);
    // (C1e), (E2e), (E3e)
    rhs[chi] = p.adv[chi] + (2.0 / 3.0) * p.f[chi] * (p.f[alpha] * trace_K);
    rhs[a] = p.adv[a] + 2.0 * p.f[a] * p.d[beta] - 2.0 * p.f[alpha] * p.f[a] * p.f[A_a];
    rhs[b] = p.adv[b] + 2.0 * p.f[b] * p.f[beta] * p.inv_r + p.f[alpha] * p.f[b] * p.f[A_a];
  }
  // (E4)
  rhs[K] = p.adv[K] - lap_alpha(p, m) + p.f[alpha] * (AA + trace_K * trace_K / 3.0);
  // (E5), trace-free form
  rhs[A_a] = p.adv[A_a] - (2.0 / 3.0) * hessian_alpha_tracefree(p, m)
             + (2.0 / 3.0) * p.f[alpha] * (ricci_rr(p, m) - ricci_thth(p, m))
             + p.f[alpha] * trace_K * p.f[A_a];
}

/// The complete right-hand side at one point: fields (C1), (E2)-(E6) with the full shift,
/// gauge (G1)-(G3), and the matter M's rows with its stress-energy's terms (S1)-(S4) (Vacuum:
/// none). `gauge_shift` is the part of the shift whose d_t Delta^r drives B (Sec. 14, (H2));
/// pass full_shift(p) for the plain Gamma-driver. Always inlined: a call in the point loop stops
/// its vectorisation (GCC left it out of line in the biased pair's instances, which then ran 8
/// times slower).
template <Volume volume = Volume::lagrangian, class M = Vacuum>
[[gnu::always_inline]] inline Rhs gbssn_rhs(const PointData& p, const Gauge& gauge,
                                            const Shift& gauge_shift) {
  using enum Var;
  const MetricPieces m = metric_pieces(p);
  const Shift shift = full_shift(p);
  Rhs rhs;
  metric_and_curvature_rhs<volume>(p, m, divbeta(p, m, shift), p.f[K], rhs);
  // (E6)
  rhs[Delta_r] = rhs_Delta_r<volume>(p, m, shift);

  // (G1)-(G3), gbssn/gauge.hpp; B is driven by d_t Delta^r of the gauge part of the shift.
  if constexpr (M::matter == Matter::none) {
    MovingPunctureGauge::rhs(gauge, p, rhs_Delta_r<volume>(p, m, gauge_shift), gauge_shift, rhs);
  } else {
    // (S1)-(S4): the matter's rows, its terms in K, A_a and both d_t Delta^r
    const MatterTerms matter = add_matter<M>(p, m.inv_a, m.da_a, m.db_b, m.dchi_chi, p.f[K], rhs);
    MovingPunctureGauge::rhs(gauge, p, rhs_Delta_r<volume>(p, m, gauge_shift) + matter.Delta_r,
                             gauge_shift, rhs);
  }
  return rhs;
}

template <Volume volume = Volume::lagrangian>
inline Rhs gbssn_rhs(const PointData& p, const Gauge& gauge) {
  return gbssn_rhs<volume>(p, gauge, full_shift(p));
}

/// Constraints and geometric diagnostics at one point (Sec. 5, Sec. 6).
struct Constraints {
  double H;   ///< (H) Hamiltonian constraint, R from a, b, chi (R4); with matter (S6) - 16 pi rho
  double M_r; ///< (M) radial momentum constraint, chi form; with matter (S6) - 8 pi j_r
  double G_r; ///< (G) Gamma constraint Delta^r - Delta_gamma^r
};

template <class M = Vacuum>
inline Constraints constraints(const PointData& p) {
  using enum Var;
  const MetricPieces m = metric_pieces(p);
  Constraints c;
  c.H = ricci_scalar_metric(p, m) - 1.5 * p.f[A_a] * p.f[A_a] + (2.0 / 3.0) * p.f[K] * p.f[K];
  c.M_r = p.d[A_a] - (2.0 / 3.0) * p.d[K] + 1.5 * p.f[A_a] * (2.0 * p.inv_r + m.db_b - m.dchi_chi);
  c.G_r = p.f[Delta_r] - delta_gamma(p, m);
  if constexpr (M::matter != Matter::none) { // (S6)
    const StressEnergy s = M::stress_energy(p, m.inv_a);
    c.H -= 16.0 * std::numbers::pi * s.rho;
    c.M_r -= 8.0 * std::numbers::pi * s.j_r;
  }
  return c;
}

/// The BSSN formulation as a policy of the point loop (gbssn/rhs_loop.hpp: GbssnRhs::interior,
/// a template parameter like the differencing order and the upwind pair): the variables it
/// evolves and its right-hand sides at one point with the part of the shift that drives B.
/// Another formulation is another type with these members (gbssn/z4c.hpp,
/// gbssn/bssn_eulerian.hpp, and the study's variants in gbssn/rhs_study.cpp; docs/design.md,
/// "A formulation").
struct Bssn {
  static constexpr Formulation formulation = Formulation::bssn;
  /// With the matter M (gbssn/matter.hpp), whose rows follow the formulation's.
  template <class M = Vacuum>
  [[gnu::always_inline]] Rhs rhs(const PointData& p, const Gauge& gauge,
                                 const Shift& gauge_shift) const {
    return gbssn_rhs<Volume::lagrangian, M>(p, gauge, gauge_shift);
  }
};

/// (T1) outgoing expansion of the sphere r = const, chi form.
inline double expansion_plus(const PointData& p) {
  using enum Var;
  const MetricPieces m = metric_pieces(p);
  return std::sqrt(p.f[chi] * m.inv_a) * (2.0 * p.inv_r + m.db_b - m.dchi_chi) + p.f[A_a]
         - (2.0 / 3.0) * p.f[K];
}

/// (T2) areal radius r sqrt(b/chi).
inline double areal_radius(const PointData& p) {
  using enum Var;
  return p.r * std::sqrt(p.f[b] / p.f[chi]);
}

/// (T4) the Misner-Sharp mass (R_A/2) [1 - (chi/a) R_A'^2 + R_A^2 (K^th_th)^2], with
/// R_A' = R_A (1/r + b'/(2b) - chi'/(2chi)) from (T2) and K^th_th = A_b + K/3 = K/3 - A_a/2: the
/// mass inside the sphere through the point, M at every point of any slice of Schwarzschild.
inline double misner_sharp_mass(const PointData& p) {
  using enum Var;
  const MetricPieces m = metric_pieces(p);
  const double R = areal_radius(p);
  const double dR_R = p.inv_r + 0.5 * (m.db_b - m.dchi_chi); // R_A'/R_A
  const double K_thth = p.f[K] / 3.0 - 0.5 * p.f[A_a];
  const double RR = R * R;
  return 0.5 * R * (1.0 - RR * (p.f[chi] * m.inv_a * dR_R * dR_R - K_thth * K_thth));
}

/// (S7) the energy that leaves the sphere of constant areal radius through the point, per unit
/// coordinate time: F = -dm/dt at fixed R_A = 4 pi R_A^2 (alpha/Gamma) [Gamma U (rho + S^r_r) +
/// (Gamma^2 + U^2) j_e], with Gamma = (chi/a)^(1/2) R_A' and U = -R_A K^th_th the areal radius's
/// rates along the unit radial vector and the normal (1 - 2m/R_A = Gamma^2 - U^2, (T4)), and
/// j_e = (chi/a)^(1/2) j_r. Where Gamma = 0 (a throat) no sphere of fixed R_A moves through the
/// point, and F is not finite.
inline double energy_flux(const PointData& p, const StressEnergy& s) {
  using enum Var;
  const MetricPieces m = metric_pieces(p);
  const double R = areal_radius(p);
  const double e = std::sqrt(p.f[chi] * m.inv_a); // (chi/a)^(1/2) = 1/sqrt(gamma_rr)
  const double Gamma = e * R * (p.inv_r + 0.5 * (m.db_b - m.dchi_chi));
  const double U = -R * (p.f[K] / 3.0 - 0.5 * p.f[A_a]);
  const double j_e = e * s.j_r;
  return 4.0 * std::numbers::pi * R * R * p.f[alpha] / Gamma
         * (Gamma * U * (s.rho + s.S_rr) + (Gamma * Gamma + U * U) * j_e);
}

} // namespace gbssn1d
