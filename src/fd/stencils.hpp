// Finite-difference stencils on the uniform computational coordinate x (spacing dx).
//
// Each takes a pointer to the value at the point and reads its neighbours f[k]. They are
// inline, branch-free where it matters, so that point loops vectorise. Radial derivatives
// follow by the chain rule (grid/grid.hpp).
#pragma once

namespace gbssn1d::fd {

/// 4th-order centred first derivative, times dx.
inline double d1_centred(const double* f) {
  return (f[-2] - 8.0 * f[-1] + 8.0 * f[1] - f[2]) * (1.0 / 12.0);
}

/// 4th-order centred second derivative, times dx^2.
inline double d2_centred(const double* f) {
  return (-f[-2] + 16.0 * f[-1] - 30.0 * f[0] + 16.0 * f[1] - f[2]) * (1.0 / 12.0);
}

/// 4th-order lopsided first derivative biased towards +x (use where the advecting velocity
/// is positive), times dx.
inline double d1_lopsided_plus(const double* f) {
  return (-3.0 * f[-1] - 10.0 * f[0] + 18.0 * f[1] - 6.0 * f[2] + f[3]) * (1.0 / 12.0);
}

/// 4th-order lopsided first derivative biased towards -x, times dx.
inline double d1_lopsided_minus(const double* f) {
  return (3.0 * f[1] + 10.0 * f[0] - 18.0 * f[-1] + 6.0 * f[-2] - f[-3]) * (1.0 / 12.0);
}

/// The sum of the two lopsided derivatives, times dx: d1_lopsided_plus + d1_lopsided_minus.
/// Their difference is ko6 / 12, so each is (lopsided_sum +/- ko6 / 6) / 2: an upwind
/// derivative costs one more stencil once ko6 is known (dissipation needs it anyway).
inline double lopsided_sum(const double* f) {
  return (f[3] - 6.0 * f[2] + 21.0 * f[1] - 21.0 * f[-1] + 6.0 * f[-2] - f[-3]) * (1.0 / 12.0);
}

/// advect() from lopsided_sum(f) and ko6(f), branch-free:
///   v (S/2 + sign(v) ko6/24) = v S/2 + |v| ko6/24.
inline double advect_from(double beta, double lopsided_sum, double ko6) {
  return 0.5 * beta * lopsided_sum + (1.0 / 24.0) * (beta < 0.0 ? -beta : beta) * ko6;
}

/// Upwinded advection v f_x: lopsided towards the direction the flow comes from, times dx.
/// The shift term beta d_r f of the equations is advection with velocity -beta, so the
/// stencil leans towards +x where beta > 0.
inline double advect(double beta, const double* f) {
  const double plus = d1_lopsided_plus(f);
  const double minus = d1_lopsided_minus(f);
  return beta * (beta > 0.0 ? plus : minus);
}

/// 4th-order one-sided (backward) first derivative, times dx; reads f[-4] ... f[0].
inline double d1_backward(const double* f) {
  return (25.0 * f[0] - 48.0 * f[-1] + 36.0 * f[-2] - 16.0 * f[-3] + 3.0 * f[-4]) * (1.0 / 12.0);
}

/// Kreiss-Oliger dissipation of the 6th difference, matched to a 4th-order scheme:
///   Q f = (sigma / (64 h)) (D+ D-)^3 f h^6,
/// which damps the highest grid mode at rate sigma / h. Returns the stencil sum (divide by
/// 64 h and multiply by sigma to get the rate).
inline double ko6(const double* f) {
  return f[-3] - 6.0 * f[-2] + 15.0 * f[-1] - 20.0 * f[0] + 15.0 * f[1] - 6.0 * f[2] + f[3];
}

} // namespace gbssn1d::fd
