// BSSN with Brown's Eulerian volume choice (Brown 2009; docs/gbssn1d-equations.md Sec. 18):
// d_t gbar_ij without the -(2/3) gbar_ij Dbar.beta term, so that (C1), (E2), (E3) and (E6) lose
// their Dbar.beta terms (Volume::eulerian in gbssn/equations.hpp) and det(gbar) is carried by
// the shift: d_t ln(a b^2) = 2 Dbar.beta. The variables, gauge, constraints and diagnostics are
// BSSN's. --gbssn-volume eulerian.
#pragma once

#include "gbssn/equations.hpp"
#include "gbssn/rhs.hpp"

namespace gbssn1d {

/// The Eulerian choice as a policy of the point loop, beside Bssn (the Lagrangian one).
struct BssnEulerian {
  static constexpr Formulation formulation = Formulation::bssn_eulerian;
  template <class M = Vacuum>
  [[gnu::always_inline]] Rhs rhs(const PointData& p, const Gauge& gauge,
                                 const Shift& gauge_shift) const {
    return gbssn_rhs<Volume::eulerian, M>(p, gauge, gauge_shift);
  }
  // (no rhs_Delta_r for a given shift: only the Lagrangian choice's study variants take it)
};

template <>
struct PointEquations<Formulation::bssn_eulerian> {
  using type = BssnEulerian;
  static BssnEulerian make(const RhsParams&) { return {}; }
  static constexpr bool study_variants = false; ///< the study's variants are the Lagrangian's
  /// the default stencil only (a finding more than a tool: runs/gbssn-volume.sh), which keeps
  /// its compile time to one order's loops
  static constexpr bool offers(int p, fd::Upwind upwind) {
    return p == 4 && upwind == fd::Upwind::lopsided;
  }
};

} // namespace gbssn1d
