// Transfer between neighbouring levels in space (mesh/hierarchy.hpp has the design note).
//
// Index conventions: a field is a span over all points of its level (ghosts included); the
// operators take interior indices (cell i at r = (i + 1/2) dr), and an interior index below 0
// reads its mirror -1-i times the variable's parity (registry), as the origin ghosts of the
// single grid are filled (gbssn/state.hpp). So the operators respect the parity at r = 0
// whatever the origin ghosts of their input hold.
#pragma once

#include "gbssn/state.hpp"
#include "grid/grid.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>

namespace gbssn1d::mesh {

/// Lagrange weights of the nodes first, first + 1, ..., first + n - 1 at x.
template <std::size_t n>
constexpr std::array<double, n> lagrange_weights(double first, double x) {
  std::array<double, n> w{};
  for (std::size_t m = 0; m < n; ++m) {
    double num = 1.0, den = 1.0;
    const double xm = first + static_cast<double>(m);
    for (std::size_t k = 0; k < n; ++k)
      if (k != m) {
        const double xk = first + static_cast<double>(k);
        num *= x - xk;
        den *= xm - xk;
      }
    w[m] = num / den;
  }
  return w;
}

/// Prolongation (coarse -> fine): the fine centre at +1/4 coarse spacing from coarse centre i
/// gets the 6-point Lagrange interpolant of coarse cells i-2 ... i+3 (the stencil centred on the
/// target's coarse interval, as Carpet's 5th-order vertex/cell operators and BAM's 6-point
/// Lagrange prolongation): exact for polynomials of degree 5; the interpolant minus f is
/// -f^(6) dr^6 prod_m (1/4 - x_m) / 6! = (10395 / 4096) dr^6 f^(6) / 720 to leading order
/// (test_transfer.cpp checks it). The point at -1/4 uses the mirror image (cells i-3 ... i+2).
inline constexpr std::array<double, 6> prolong_weights_plus = lagrange_weights<6>(-2.0, 0.25);
inline constexpr std::array<double, 6> prolong_weights_minus = lagrange_weights<6>(-3.0, -0.25);

/// Restriction (fine -> coarse): the coarse centre is the midpoint of fine centres 2i and
/// 2i+1; it gets the centred 6-point Lagrange interpolant of fine cells 2i-2 ... 2i+3, weights
/// (3, -25, 150, 150, -25, 3) / 256, exact for degree 5; the interpolant minus f is
/// (225 / 64) dr_f^6 f^(6) / 720 to leading order (6th order). The 2-point average (f_2i + f_2i+1)
/// / 2 would be exact for cell averages (finite volumes) but our fields are point values, for which
/// it is only 2nd order (error dr_f^2 f'' / 8): it would spoil the 4th-order scheme wherever the
/// coarse level feeds back (e.g. AMReX's average_down is the conservative cell average, right for
/// finite volumes, not here). 6 points also match the prolongation, so that restriction after
/// prolongation returns the coarse field to O(dr^6).
inline constexpr std::array<double, 6> restrict_weights = lagrange_weights<6>(-2.0, 0.5);

/// Value of interior index i (i < 0: the mirror times the parity); `f0` points at interior 0.
inline double at(const double* f0, long i, int parity) {
  return i >= 0 ? f0[i] : parity * f0[-1 - i];
}

/// fine[j] for interior j in [j_begin, j_end) (j may reach into the fine outer ghosts) from the
/// coarse field; the coarse cells read are floor(j/2) - 3 ... floor(j/2) + 3.
inline void prolong_field(std::span<const double> coarse, std::span<double> fine, int parity,
                          long j_begin, long j_end) {
  const double* c = coarse.data() + Grid::n_ghost;
  double* f = fine.data() + Grid::n_ghost;
  for (long j = j_begin; j < j_end; ++j) {
    const long i = j >= 0 ? j / 2 : -((-j + 1) / 2);
    const bool plus = (j - 2 * i) == 1; // odd j: +1/4 from coarse centre i
    const auto& w = plus ? prolong_weights_plus : prolong_weights_minus;
    const long first = plus ? i - 2 : i - 3;
    double s = 0.0;
    for (std::size_t m = 0; m < 6; ++m)
      s += w[m] * at(c, first + static_cast<long>(m), parity);
    f[j] = s;
  }
}

/// coarse[i] for interior i in [i_begin, i_end) from fine cells 2i-2 ... 2i+3.
inline void restrict_field(std::span<const double> fine, std::span<double> coarse, int parity,
                           long i_begin, long i_end) {
  const double* f = fine.data() + Grid::n_ghost;
  double* c = coarse.data() + Grid::n_ghost;
  // the cells whose stencil reaches the mirror (2i - 2 < 0) apart, so that the rest vectorises
  const long i_mirror = std::clamp(1L, i_begin, std::max(i_begin, i_end));
  for (long i = i_begin; i < i_mirror; ++i) {
    double s = 0.0;
    for (std::size_t m = 0; m < 6; ++m)
      s += restrict_weights[m] * at(f, 2 * i - 2 + static_cast<long>(m), parity);
    c[i] = s;
  }
  for (long i = i_mirror; i < i_end; ++i) {
    double s = 0.0;
    for (std::size_t m = 0; m < 6; ++m)
      s += restrict_weights[m] * f[2 * i - 2 + static_cast<long>(m)];
    c[i] = s;
  }
}

/// prolong_field for every registry variable, each with its parity.
inline void prolong(const State& coarse, const Grid& coarse_grid, State& fine,
                    const Grid& fine_grid, long j_begin, long j_end) {
  for (const auto& entry : coarse.vars())
    prolong_field(field(coarse, coarse_grid, entry.var), field(fine, fine_grid, entry.var),
                  entry.parity, j_begin, j_end);
}

/// restrict_field for every registry variable, then the coarse origin ghosts by parity.
inline void restrict_to(const State& fine, const Grid& fine_grid, State& coarse,
                        const Grid& coarse_grid, long i_begin, long i_end) {
  for (const auto& entry : fine.vars())
    restrict_field(field(fine, fine_grid, entry.var), field(coarse, coarse_grid, entry.var),
                   entry.parity, i_begin, i_end);
  fill_origin_ghosts(coarse, coarse_grid);
}

} // namespace gbssn1d::mesh
