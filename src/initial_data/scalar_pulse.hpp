// Time-symmetric data of a scalar-field pulse (equations document, Sec. 19): K_ij = 0, Pi = 0,
// Phi = A exp(-((r - r0)/w)^2), a = b = 1, and the conformal factor psi = psi_0 + u solved from
// the Hamiltonian constraint (S6), psi'' + (2/r) psi' = -pi Phi'^2 psi, with psi_0 = 1 (flat
// data) or 1 + M/(2r) (a puncture) and u -> 0 at infinity.
#pragma once

#include "initial_data/initial_data_params.hpp"

#include <array>
#include <vector>

namespace gbssn1d {

class ScalarPulseData {
public:
  /// Solves for u (an ODE in r, to a relative tolerance of 1e-13: its error lies far below the
  /// grid's); `puncture_mass` 0 for flat data.
  ScalarPulseData(const ScalarPulse& pulse, double puncture_mass);

  double Phi(double r) const;
  /// psi at the radii `radii` (each >= 0, in increasing order).
  std::vector<double> psi(const std::vector<double>& radii) const;
  /// The ADM mass, -2 lim r^2 psi' (the puncture's M and the pulse's).
  double adm_mass() const { return adm_mass_; }

private:
  double dPhi(double r) const;
  /// The Hamiltonian constraint as d/dr of (u, u'): u'' = -(2/r) u' - pi Phi'^2 (psi_0 + u).
  void constraint(const std::array<double, 2>& x, std::array<double, 2>& dx, double r) const;
  ScalarPulse pulse_;
  double M_;
  double u0_ = 0.0;    ///< u at the centre (r -> 0)
  double r_far_ = 0.0; ///< beyond it Phi' vanishes to double precision: u = d/r
  double d_far_ = 0.0; ///< u = d_far / r beyond r_far
  double adm_mass_ = 0.0;
};

} // namespace gbssn1d
