// Matter as a policy of the formulations' right-hand sides (docs/gbssn1d-equations.md Sec. 19):
// the right-hand sides of its own rows, and its stress-energy, whose terms each formulation adds
// to its K (K-hat), A_a, Delta^r (and Z4c's Theta) before the gauge reads d_t Delta^r, and the
// constraints to H and M_r. Vacuum is the policy without rows or terms: the vacuum point loop is
// compiled as before it. A formulation's rhs<M>() takes the policy as a template parameter, as
// the point loop takes the formulation, so that each instance stays branch-free.
#pragma once

#include "gbssn/point_data.hpp"

#include <numbers>
#include <type_traits>

namespace gbssn1d {

/// (S3) rho = n^a n^b T_ab, j_r = -gamma_r^a n^b T_ab, S^r_r and the trace S of S_ij.
struct StressEnergy {
  double rho, j_r, S_rr, S;
};

/// No matter: no rows, and none of (S4)-(S6)'s terms.
struct Vacuum {
  static constexpr Matter matter = Matter::none;
};

/// The massless scalar field: Phi, and Pi = n^a d_a Phi = (d_t Phi - beta Phi')/alpha.
struct ScalarField {
  static constexpr Matter matter = Matter::scalar;

  /// (S3), chi form: with q = (chi/a) Phi'^2, rho = S^r_r = (Pi^2 + q)/2, j_r = -Pi Phi',
  /// S = (3/2) Pi^2 - q/2.
  [[gnu::always_inline]] static StressEnergy stress_energy(const PointData& p, double inv_a) {
    using enum Var;
    const double q = p.f[chi] * inv_a * p.d[Phi] * p.d[Phi], pi2 = p.f[Pi] * p.f[Pi];
    return {0.5 * (pi2 + q), -p.f[Pi] * p.d[Phi], 0.5 * (pi2 + q), 1.5 * pi2 - 0.5 * q};
  }

  /// (S1)-(S2) into `rhs`: d_t Phi = beta Phi' + alpha Pi, d_t Pi = beta Pi' + alpha K Pi +
  /// (chi/a) [alpha Phi'' + Phi' (alpha' + alpha (2/r + b'/b - a'/(2a) - chi'/(2chi)))], with K
  /// the ADM trace (`trace_K`) and the metric's logarithmic derivatives a'/a, b'/b, chi'/chi.
  [[gnu::always_inline]] static void rhs(const PointData& p, double inv_a, double da_a, double db_b,
                                         double dchi_chi, double trace_K, Rhs& rhs) {
    using enum Var;
    rhs[Phi] = p.adv[Phi] + p.f[alpha] * p.f[Pi];
    const double connection = 2.0 * p.inv_r + db_b - 0.5 * da_a - 0.5 * dchi_chi;
    rhs[Pi] = p.adv[Pi] + p.f[alpha] * trace_K * p.f[Pi]
              + p.f[chi] * inv_a
                    * (p.f[alpha] * p.dd[Phi] + p.d[Phi] * (p.d[alpha] + p.f[alpha] * connection));
  }
};

/// The policy of `matter`.
template <Matter matter>
using MatterPolicy = std::conditional_t<matter == Matter::scalar, ScalarField, Vacuum>;

/// (S4): the stress-energy's terms in d_t K (Z4c: K-hat) and d_t A_a.
[[gnu::always_inline]] inline void add_stress_energy(const PointData& p, const StressEnergy& s,
                                                     Rhs& rhs) {
  using enum Var;
  constexpr double pi = std::numbers::pi;
  rhs[K] += 4.0 * pi * p.f[alpha] * (s.rho + s.S);
  rhs[A_a] += -8.0 * pi * p.f[alpha] * (s.S_rr - s.S / 3.0);
}

/// (S4): the stress-energy's term in d_t Delta^r, -16 pi alpha j_r / a (added to the formulation's
/// d_t Delta^r and to the one that drives B).
[[gnu::always_inline]] inline double stress_energy_Delta_r(const PointData& p, double inv_a,
                                                           const StressEnergy& s) {
  return -16.0 * std::numbers::pi * p.f[Var::alpha] * s.j_r * inv_a;
}

/// What the matter adds that a formulation or its gauge reads further: its stress-energy and
/// the term of d_t Delta^r, which B's driver also takes.
struct MatterTerms {
  StressEnergy s;
  double Delta_r;
};

/// The matter M's part of a formulation's right-hand side, the same in every formulation:
/// (S1)-(S2), its rows (with `trace_K` the ADM K), and (S4), its terms in d_t K (Z4c: K-hat),
/// A_a and Delta^r. A formulation adds its own terms on top (Z4c's Theta, (S5)).
template <class M>
[[gnu::always_inline]] inline MatterTerms add_matter(const PointData& p, double inv_a, double da_a,
                                                     double db_b, double dchi_chi, double trace_K,
                                                     Rhs& rhs) {
  const StressEnergy s = M::stress_energy(p, inv_a);
  add_stress_energy(p, s, rhs);
  const double Delta_r = stress_energy_Delta_r(p, inv_a, s);
  rhs[Var::Delta_r] += Delta_r;
  M::rhs(p, inv_a, da_a, db_b, dchi_chi, trace_K, rhs);
  return {s, Delta_r};
}

} // namespace gbssn1d
