// What the point-wise equations see at one grid point: every registry variable's value, its
// radial derivatives and its upwinded advection term, each indexed by the registry (p.f[chi],
// p.d[chi], p.dd[chi], p.adv[chi]), so that gathering, right-hand sides and tests loop over the
// registry instead of re-listing the variables.
#pragma once

#include "core/registry.hpp"

#include <array>

namespace gbssn1d {

/// Fields, their radial derivatives and the upwinded advection terms at one point.
struct PointData {
  double r, inv_r;
  double inv_dr = 0.0; ///< 1 / the cell width d_r at the point (gather; 0: not known)
  PerVar f;            ///< values
  PerVar d;            ///< centred first derivatives d_r f
  PerVar dd;           ///< centred second derivatives d_r^2 f
  PerVar adv;          ///< upwinded shift advection beta d_r f (with the beta of f[Var::beta])
};

/// Right-hand sides d_t f of the evolved variables.
using Rhs = PerVar;

/// The shift seen by a term: its value, derivatives and the upwinded beta d_r Delta^r it
/// produces. Separate from PointData so that the Gamma-driver can evaluate d_t Delta^r with a
/// part of the shift only (Sec. 14, (H2)).
struct Shift {
  double beta, d_beta, dd_beta, adv_Delta_r;
};

inline Shift full_shift(const PointData& p) {
  return {p.f[Var::beta], p.d[Var::beta], p.dd[Var::beta], p.adv[Var::Delta_r]};
}

} // namespace gbssn1d
